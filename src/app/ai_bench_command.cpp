#include "app/ai_bench_command.hpp"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "app/ai_bench_carom.hpp"
#include "app/ai_bench_common.hpp"
#include "app/ai_bench_positions.hpp"
#include "app/ai_bench_snooker.hpp"
#include "app/exit_codes.hpp"
#include "common/log.hpp"
#include "games/game_texts.hpp"
#include "nineball/games.hpp"
#include "nineball/match.hpp"
#include "nineball/planner.hpp"

namespace nineball::app {
namespace {

// Pool racks measured when --racks is not given.
constexpr int kDefaultRacks = 100;
// Snooker frames measured when --racks is not given: a frame takes 60 or more planned shots.
constexpr int kDefaultSnookerFrames = 4;
// A rack that lasts longer than this many turns of one player is not a run-out anyway.
constexpr int kMaxTurnsPerRack = 60;

struct Tally {
  int potted = 0;
  int potted_as_planned = 0;  // the same shots cued without error
  int attempted = 0;
  int fouls = 0;
  int runouts = 0;
  int break_pots = 0;
  int shots = 0;      // shots the computer played in its racks
  int succeeded = 0;  // ... that kept the turn legally or won the rack
  int balls_before_miss = 0;
  std::vector<double> think;  // s per planned shot
  long simulations = 0;       // shots the planners simulated
  double thinking = 0.0;      // s the planners spent
};

void addPlanner(const ai::Planner& planner, Tally& t) {
  t.simulations += planner.simulations();
  t.thinking += planner.thinkSeconds();
}

bool contains(const std::vector<int>& v, int x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

// Whether the shot did what a position asks: where players take groups, a ball dropped on a
// legal shot that keeps the table (any ball of the group, or of either on the open table);
// elsewhere the ball on dropped on a legal shot, as called where a pot must be.
bool madeIt(rules::Game game, const TurnRecord& r, int on) {
  const rules::Verdict& v = r.verdict;
  if (!v.legal()) return false;
  if (gameDef(game).groups) {
    return !v.pocketed.empty() && (v.next == r.shooter || v.winner == r.shooter);
  }
  return contains(v.pocketed, on) && v.call_breach == rules::Foul::None;
}

// A shot that keeps the turn legally, or wins the rack.
bool succeeded(const TurnRecord& r) {
  const rules::Verdict& v = r.verdict;
  return v.legal() && (v.next == r.shooter || v.winner == r.shooter);
}

void playPositions(const AiBenchOptions& o, rules::Game game, ai::Level level, Tally& t) {
  for (int i = 0; i < o.positions; ++i) {
    const std::uint64_t seed = o.seed + static_cast<std::uint64_t>(i);
    MatchSetup setup;
    setup.setGame(game);
    setup.balls = randomPosition(seed, setup.table, setup.physics, game);
    Match match(setup);
    const int on = match.rack().ballOn();
    ai::Planner planner = benchPlanner(o, level, seed);
    const ai::Plan plan = planner.plan(ai::planInputFrom(match));
    t.think.push_back(planner.lastThinkSeconds());
    if (plan.kind == ai::ShotKind::Pot || plan.kind == ai::ShotKind::Bank ||
        (plan.kind == ai::ShotKind::Jump && plan.pocket)) {
      ++t.attempted;
    }
    Match as_planned(setup);
    const TurnRecord exact = as_planned.play(plan.turn);
    if (madeIt(game, exact, on)) ++t.potted_as_planned;
    const TurnRecord r = match.play(planner.execute(plan));
    if (!r.verdict.legal()) ++t.fouls;
    if (madeIt(game, r, on)) ++t.potted;
    addPlanner(planner, t);
  }
}

void playRacks(const AiBenchOptions& o, rules::Game game, ai::Level level, Tally& t,
               std::ostream& err) {
  for (int i = 0; i < o.racks; ++i) {
    MatchSetup setup;
    setup.setGame(game);
    setup.seed = o.seed + static_cast<std::uint64_t>(i);
    Match match(setup);
    ai::Planner planner = benchPlanner(o, level, setup.seed);
    // The opponent only answers the breaker's push-outs and illegal breaks; when it passes the
    // table back the visit goes on, when it takes the table the run is over.
    ai::Planner opponent = benchPlanner(o, level, setup.seed + 1);
    int turns = 0;
    int pocketed = 0;
    while (!match.rack().over() && turns < kMaxTurnsPerRack) {
      if (match.rack().shooter() == rules::Player::B) {
        if (!match.rack().awaitingDecision()) break;
        match.play(opponent.turnFor(match));
        if (match.rack().shooter() == rules::Player::B) break;
        continue;
      }
      const TurnInput turn = planner.turnFor(match);
      t.think.push_back(planner.lastThinkSeconds());
      const TurnRecord r = match.play(turn);
      if (turn.kind == TurnInput::Kind::Shot) {
        ++t.shots;
        if (succeeded(r)) ++t.succeeded;
      }
      if (turns == 0 && r.verdict.legal() && !r.verdict.pocketed.empty()) ++t.break_pots;
      if (turns > 0) pocketed += static_cast<int>(r.verdict.pocketed.size());
      ++turns;
    }
    t.balls_before_miss += pocketed;
    addPlanner(planner, t);
    const bool ran_out = match.rack().winner() == rules::Player::A;
    if (ran_out) ++t.runouts;
    logger("app")->info("rack {}: {} after {} shots", setup.seed, ran_out ? "run out" : "missed",
                        turns);
    if ((i + 1) % 10 == 0) err << "ai-bench: " << (i + 1) << " racks\n" << std::flush;
  }
}

// CPU time of the whole process, every thread's (s).
double cpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Whole racks between two levels, the break alternating; a rack still open after kMaxRackTurns
// turns is won by neither.
constexpr int kMaxRackTurns = 300;

struct Versus {
  ai::Level a = ai::Level::Master, b = ai::Level::Master;
  int racks = 0;
  int wins_a = 0, wins_b = 0;
};

void playVersus(const AiBenchOptions& o, rules::Game game, Versus& v, Tally& t, std::ostream& err) {
  for (int i = 0; i < v.racks; ++i) {
    MatchSetup setup;
    setup.setGame(game);
    setup.seed = o.seed + static_cast<std::uint64_t>(i);
    Match match(setup);
    // The rack's breaker is seat A: level A sits there on even racks, level B on odd ones.
    const bool a_breaks = i % 2 == 0;
    ai::Planner seat_a = benchPlanner(o, a_breaks ? v.a : v.b, setup.seed);
    ai::Planner seat_b = benchPlanner(o, a_breaks ? v.b : v.a, setup.seed + 1);
    for (int turn = 0; turn < kMaxRackTurns && !match.rack().over(); ++turn) {
      ai::Planner& p = match.rack().shooter() == rules::Player::A ? seat_a : seat_b;
      match.play(p.turnFor(match));
      t.think.push_back(p.lastThinkSeconds());
    }
    addPlanner(seat_a, t);
    addPlanner(seat_b, t);
    if (const auto w = match.rack().winner()) {
      ((*w == rules::Player::A) == a_breaks ? v.wins_a : v.wins_b) += 1;
    }
    if ((i + 1) % 10 == 0) err << "ai-bench: " << (i + 1) << " racks\n" << std::flush;
  }
}

// The 95 % Wilson score interval of a share of wins.
std::pair<double, double> wilson(int wins, int n) {
  if (n <= 0) return {0.0, 1.0};
  const double z = 1.959964, p = static_cast<double>(wins) / n, z2n = z * z / n;
  const double centre = (p + z2n / 2.0) / (1.0 + z2n);
  const double half = z * std::sqrt(p * (1.0 - p) / n + z2n / (4.0 * n)) / (1.0 + z2n);
  return {centre - half, centre + half};
}

}  // namespace

CLI::App* addAiBenchCommand(CLI::App& app, AiBenchOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "ai-bench", "Measure the computer opponent: pot rate, run-outs, search speed, think time");
  cmd->add_option("--level", options.level, "Level to measure")
      ->check(CLI::IsMember(ai::levelNames()))
      ->capture_default_str();
  cmd->add_option("--game", options.game, "Game to play")
      ->check(CLI::IsMember(gameNames()))
      ->capture_default_str();
  cmd->add_option("--positions", options.positions, "Seeded positions to pot the ball on from")
      ->check(CLI::Range(0, 100000))
      ->capture_default_str();
  cmd->add_option("--racks", options.racks,
                  "Racks to break and try to run out (default 100); three-cushion: games to 25 "
                  "points between two players of the level (default none); snooker: frames "
                  "between two players of the level (default 4)")
      ->check(CLI::Range(0, 100000));
  cmd->add_option("--seed", options.seed, "First seed of positions and racks")
      ->capture_default_str();
  cmd->add_option("--threads", options.threads, "Workers simulating candidates")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  std::vector<std::string> noises{"level"};
  for (const std::string& name : ai::ExecutionNoise::names()) noises.push_back(name);
  cmd->add_option("--noise", options.noise,
                  "Cueing errors: the level's own, none, or the computer-pool tournaments' "
                  "(olympiad: 0.125 deg aim, 0.1 deg elevation, 0.075 m/s on the cue stick, "
                  "0.5 mm tip; olympiad-5x: five times each)")
      ->check(CLI::IsMember(noises))
      ->capture_default_str();
  cmd->add_flag("--json", options.json, "Print one JSON object instead of the report");
  cmd->add_option("--versus", options.versus,
                  "A,B: play --racks whole racks between two levels instead, the break "
                  "alternating, and report the wins");
  return cmd;
}

int runAiBench(const AiBenchOptions& given, std::ostream& out, std::ostream& err) {
  AiBenchOptions options = given;
  const auto level = ai::levelFromName(options.level);
  if (!level) {
    err << "nineball ai-bench: --level: unknown level \"" << options.level << "\"\n";
    return kExitBadInput;
  }
  if (options.noise != "level" && !ai::ExecutionNoise::named(options.noise)) {
    err << "nineball ai-bench: --noise: unknown noise \"" << options.noise << "\"\n";
    return kExitBadInput;
  }
  std::optional<Versus> versus;
  if (!options.versus.empty()) {
    const auto comma = options.versus.find(',');
    Versus v;
    const auto a = ai::levelFromName(options.versus.substr(0, comma));
    const auto b = ai::levelFromName(comma == std::string::npos ? std::string()
                                                                : options.versus.substr(comma + 1));
    if (!a || !b) {
      err << "nineball ai-bench: --versus: two levels as A,B (" << ai::levelNamesText()
          << "), not \"" << options.versus << "\"\n";
      return kExitBadInput;
    }
    v.a = *a;
    v.b = *b;
    v.racks = options.racks;
    versus = v;
  }
  const auto game = rules::gameFromName(options.game);
  if (!game) {
    err << "nineball ai-bench: --game: unknown game \"" << options.game << "\"\n";
    return kExitBadInput;
  }
  const bool carom = gameDef(*game).family == GameFamily::Carom;
  const bool snooker = *game == rules::Game::Snooker;
  if (options.racks < 0)
    options.racks = carom ? 0 : snooker ? kDefaultSnookerFrames : kDefaultRacks;
  if (versus) versus->racks = options.racks;
  if (snooker) {
    if (versus) {
      err << "nineball ai-bench: --versus: not for snooker (its frames report breaks)\n";
      return kExitBadInput;
    }
    return runSnookerBench(options, out, err);
  }
  if (carom) {
    if (versus) {
      err << "nineball ai-bench: --versus: not for " << options.game
          << " (its games report points per inning)\n";
      return kExitBadInput;
    }
    return runCaromBench(options, out, err);
  }
  const auto started = std::chrono::steady_clock::now();
  const double cpu_started = cpuSeconds();
  Tally positions, racks;
  playPositions(options, *game, *level, positions);
  if (versus) {
    playVersus(options, *game, *versus, racks, err);
  } else {
    playRacks(options, *game, *level, racks, err);
  }
  std::vector<double> think = positions.think;
  think.insert(think.end(), racks.think.begin(), racks.think.end());
  const long sims = positions.simulations + racks.simulations;
  const double thinking = positions.thinking + racks.thinking;
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const double cpu = cpuSeconds() - cpu_started;
  const double max_think = think.empty() ? 0.0 : *std::max_element(think.begin(), think.end());
  if (options.json) {
    nlohmann::ordered_json j;
    j["game"] = options.game;
    j["level"] = ai::levelName(*level);
    j["noise"] = options.noise;
    j["positions"] = {
        {"made", positions.potted}, {"fouls", positions.fouls}, {"of", options.positions}};
    j["racks"] = {{"runouts", racks.runouts},
                  {"of", versus ? 0 : options.racks},
                  {"ball_down_on_break", racks.break_pots}};
    j["shots"] = {{"succeeded", racks.succeeded}, {"attempted", racks.shots}};
    j["think_s"] = {{"median", medianOf(think)}, {"max", max_think}};
    j["shots_simulated_per_cpu_s"] = cpu > 0.0 ? static_cast<double>(sims) / cpu : 0.0;
    if (versus) {
      // An older name is reported as the level it stands for.
      j["versus"] = {{"A", ai::levelName(versus->a)},
                     {"B", ai::levelName(versus->b)},
                     {"racks", versus->racks},
                     {"wins", {{"A", versus->wins_a}, {"B", versus->wins_b}}}};
    }
    out << j.dump() << "\n" << std::flush;
    return out ? kExitOk : kExitInternal;
  }
  out << std::fixed << std::setprecision(2);
  out << "Computer opponent, " << options.game << ", level " << ai::levelName(*level) << ", "
      << options.threads << " threads, seeds from " << options.seed
      << (options.noise == "level" ? "" : ", " + options.noise + " noise") << "\n";
  const char* aim = gameTexts(*game).made;
  out << "positions: " << aim << " in " << positions.potted << " of " << options.positions
      << " (a pot attempted in " << positions.attempted << ", fouls " << positions.fouls
      << "; cued without error the same shots pot it in " << positions.potted_as_planned << ")\n";
  if (versus) {
    const auto [lo, hi] = wilson(versus->wins_a, versus->wins_a + versus->wins_b);
    out << "versus: " << ai::levelName(versus->a) << " won " << versus->wins_a << ", "
        << ai::levelName(versus->b) << " won " << versus->wins_b << " of " << versus->racks
        << " racks (the break alternating); " << ai::levelName(versus->a) << "'s share of the wins "
        << std::setprecision(3) << lo << "-" << hi << " (95 % Wilson interval)\n"
        << std::setprecision(2);
  } else {
    out << "racks: ran out " << racks.runouts << " of " << options.racks << " from the break ("
        << "a ball down on the break in " << racks.break_pots << ", " << racks.balls_before_miss
        << " balls potted after the break in all)\n";
    out << "shots in the racks: " << racks.succeeded << " of " << racks.shots
        << " kept the turn legally or won the rack\n";
  }
  out << "search: " << sims << " shots simulated in " << thinking
      << " s of thinking: " << std::setprecision(0) << (thinking > 0.0 ? sims / thinking : 0.0)
      << " shots per second\n"
      << std::setprecision(2);
  out << "think time per shot: median " << medianOf(think) << " s, max " << max_think << " s over "
      << think.size() << " shots\n";
  out << "wall time: " << wall << " s (thinking " << thinking << " s)\n" << std::flush;
  return out ? kExitOk : kExitInternal;
}

}  // namespace nineball::app
