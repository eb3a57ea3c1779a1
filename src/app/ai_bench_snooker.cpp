#include "app/ai_bench_snooker.hpp"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <ostream>
#include <vector>

#include "app/ai_bench_common.hpp"
#include "app/exit_codes.hpp"
#include "nineball/games.hpp"
#include "nineball/match.hpp"
#include "nineball/planner.hpp"

namespace nineball::app {
namespace {

// A frame still open after this many turns is left unfinished (a professional frame takes
// about 30 to 60 visits; safety exchanges between weak players run longer).
constexpr int kMostTurnsPerFrame = 600;
constexpr int kCentury = 100;

struct Breaks {
  std::vector<int> breaks;  // every visit that scored, in points
  int frames = 0;
  int unfinished = 0;
  int won_by_breaker = 0;
  std::vector<double> think;  // s per planned shot

  int highest() const {
    return breaks.empty() ? 0 : *std::max_element(breaks.begin(), breaks.end());
  }
  int centuries() const {
    return static_cast<int>(
        std::count_if(breaks.begin(), breaks.end(), [](int b) { return b >= kCentury; }));
  }
  double mean() const {
    if (breaks.empty()) return 0.0;
    double sum = 0.0;
    for (int b : breaks) sum += b;
    return sum / static_cast<double>(breaks.size());
  }
};

int index(rules::Player p) {
  return p == rules::Player::A ? 0 : 1;
}

// A visit: the points one player scores from his own pots before the table passes. Points
// from the opponent's fouls are not part of a break.
class VisitCounter {
 public:
  explicit VisitCounter(Breaks& b) : b_(b) {}
  void after(const TurnRecord& r, rules::Player next) {
    if (r.kind != TurnInput::Kind::Shot) return;
    if (r.verdict.legal()) run_ += r.verdict.points[index(r.shooter)];
    if (!r.verdict.legal() || next != r.shooter) close();
  }
  void close() {
    if (run_ > 0) b_.breaks.push_back(run_);
    run_ = 0;
  }

 private:
  Breaks& b_;
  int run_ = 0;
};

void playFrame(const AiBenchOptions& o, ai::Level level, std::uint64_t seed, Breaks& b) {
  MatchSetup setup;
  setup.setGame(rules::Game::Snooker);
  setup.seed = seed;
  Match match(setup);
  ai::Planner seat_a = benchPlanner(o, level, seed);
  ai::Planner seat_b = benchPlanner(o, level, seed + 1);
  const rules::Player breaker = match.rack().shooter();
  VisitCounter visits(b);
  int turns = 0;
  for (; turns < kMostTurnsPerFrame && !match.rack().over(); ++turns) {
    ai::Planner& p = match.rack().shooter() == rules::Player::A ? seat_a : seat_b;
    const TurnRecord r = match.play(p.turnFor(match));
    if (r.kind == TurnInput::Kind::Shot) b.think.push_back(p.lastThinkSeconds());
    visits.after(r, match.rack().shooter());
  }
  visits.close();
  ++b.frames;
  if (!match.rack().over()) ++b.unfinished;
  if (match.rack().winner() == breaker) ++b.won_by_breaker;
}

}  // namespace

int runSnookerBench(const AiBenchOptions& options, std::ostream& out, std::ostream& err) {
  const auto level = ai::levelFromName(options.level);
  const auto started = std::chrono::steady_clock::now();
  Breaks b;
  for (int i = 0; i < options.racks; ++i) {
    playFrame(options, *level, options.seed + 2 * static_cast<std::uint64_t>(i), b);
    err << "ai-bench: " << (i + 1) << " frames\n" << std::flush;
  }
  const double max_think =
      b.think.empty() ? 0.0 : *std::max_element(b.think.begin(), b.think.end());
  if (options.json) {
    nlohmann::ordered_json j;
    j["game"] = options.game;
    j["level"] = ai::levelName(*level);
    j["frames"] = b.frames;
    j["mean_break"] = b.mean();
    j["high_break"] = b.highest();
    j["centuries"] = b.centuries();
    j["think_s"] = {{"median", medianOf(b.think)}, {"max", max_think}};
    out << j.dump() << "\n" << std::flush;
    return out ? kExitOk : kExitInternal;
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const double per100 = b.frames > 0 ? 100.0 * b.centuries() / b.frames : 0.0;
  out << std::fixed << std::setprecision(2);
  out << "Computer opponent, snooker, level " << ai::levelName(*level) << " against itself, "
      << options.threads << " threads, seeds from " << options.seed
      << (options.noise == "level" ? "" : ", " + options.noise + " noise") << "\n";
  out << "frames: " << b.frames << " (" << b.unfinished << " unfinished after "
      << kMostTurnsPerFrame << " turns), won by the player who broke off: " << b.won_by_breaker
      << "\n";
  out << "breaks: " << b.breaks.size() << " scoring visits, mean " << b.mean() << ", highest "
      << b.highest() << ", centuries " << b.centuries() << " (" << per100 << " per 100 frames)\n";
  out << "think time per shot: median " << medianOf(b.think) << " s, max " << max_think
      << " s over " << b.think.size() << " shots\n"
      << "wall time: " << wall << " s\n"
      << std::flush;
  return out ? kExitOk : kExitInternal;
}

}  // namespace nineball::app
