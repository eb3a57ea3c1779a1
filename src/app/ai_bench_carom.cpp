#include "app/ai_bench_carom.hpp"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <ostream>
#include <vector>

#include "app/ai_bench_common.hpp"
#include "app/ai_bench_positions.hpp"
#include "app/exit_codes.hpp"
#include "nineball/carom_rack.hpp"
#include "nineball/games.hpp"
#include "nineball/match.hpp"
#include "nineball/planner.hpp"

namespace nineball::app {
namespace {

// An inning that goes on this long is cut (a world-class high run is about 20).
constexpr int kMostPointsPerInning = 60;
// A game still open after this many shots is left unfinished.
constexpr int kMostShotsPerGame = 2000;

struct Innings {
  int points = 0;
  int innings = 0;
  int high_run = 0;
  std::vector<double> think;  // s per planned shot
};

// One inning from the position: shots until one does not score.
void playInning(Match& match, ai::Planner& planner, Innings& t) {
  const rules::Player shooter = match.rack().shooter();
  int run = 0;
  while (!match.rack().over() && match.rack().shooter() == shooter && run < kMostPointsPerInning) {
    const TurnInput turn = planner.turnFor(match);
    t.think.push_back(planner.lastThinkSeconds());
    const TurnRecord r = match.play(turn);
    if (r.verdict.points[0] + r.verdict.points[1] == 0) break;
    ++run;
  }
  t.points += run;
  ++t.innings;
  t.high_run = std::max(t.high_run, run);
}

void playPositions(const AiBenchOptions& o, rules::Game game, ai::Level level, Innings& t) {
  for (int i = 0; i < o.positions; ++i) {
    const std::uint64_t seed = o.seed + static_cast<std::uint64_t>(i);
    MatchSetup setup;
    setup.setGame(game);
    setup.seed = seed;
    if (i % 2 == 1) setup.balls = randomPosition(seed, setup.table, setup.physics, game);
    Match match(setup);
    ai::Planner planner = benchPlanner(o, level, seed);
    playInning(match, planner, t);
  }
}

void playGames(const AiBenchOptions& o, rules::Game game, ai::Level level, Innings& t,
               std::ostream& err) {
  for (int i = 0; i < o.racks; ++i) {
    MatchSetup setup;
    setup.setGame(game);
    setup.seed = o.seed + static_cast<std::uint64_t>(i);
    Match match(setup);
    ai::Planner seat_a = benchPlanner(o, level, setup.seed);
    ai::Planner seat_b = benchPlanner(o, level, setup.seed + 1);
    for (int shot = 0; shot < kMostShotsPerGame && !match.rack().over(); ++shot) {
      ai::Planner& p = match.rack().shooter() == rules::Player::A ? seat_a : seat_b;
      match.play(p.turnFor(match));
      t.think.push_back(p.lastThinkSeconds());
    }
    for (rules::Player p : {rules::Player::A, rules::Player::B}) {
      t.points += match.rack().score(p);
      t.innings += rules::innings(match.rack(), p);
      t.high_run = std::max(t.high_run, rules::highRun(match.rack(), p));
    }
    if ((i + 1) % 10 == 0) err << "ai-bench: " << (i + 1) << " games\n" << std::flush;
  }
}

double average(const Innings& t) {
  return t.innings > 0 ? static_cast<double>(t.points) / t.innings : 0.0;
}

}  // namespace

int runCaromBench(const AiBenchOptions& options, std::ostream& out, std::ostream& err) {
  const auto level = ai::levelFromName(options.level);
  const auto game = rules::gameFromName(options.game);
  const auto started = std::chrono::steady_clock::now();
  Innings positions, games;
  playPositions(options, *game, *level, positions);
  playGames(options, *game, *level, games, err);
  Innings all = positions;
  all.points += games.points;
  all.innings += games.innings;
  all.high_run = std::max(all.high_run, games.high_run);
  all.think.insert(all.think.end(), games.think.begin(), games.think.end());
  const double max_think =
      all.think.empty() ? 0.0 : *std::max_element(all.think.begin(), all.think.end());
  if (options.json) {
    nlohmann::ordered_json j;
    j["game"] = options.game;
    j["level"] = ai::levelName(*level);
    j["points"] = all.points;
    j["innings"] = all.innings;
    j["average"] = average(all);
    j["high_run"] = all.high_run;
    j["think_s"] = {{"median", medianOf(all.think)}, {"max", max_think}};
    out << j.dump() << "\n" << std::flush;
    return out ? kExitOk : kExitInternal;
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  out << std::fixed << std::setprecision(3);
  out << "Computer opponent, " << options.game << ", level " << ai::levelName(*level) << ", "
      << options.threads << " threads, seeds from " << options.seed
      << (options.noise == "level" ? "" : ", " + options.noise + " noise") << "\n";
  out << "positions: " << positions.points << " points in " << positions.innings
      << " innings (opening and random positions, one inning each): average " << average(positions)
      << ", high run " << positions.high_run << "\n";
  if (options.racks > 0) {
    out << "games: " << options.racks << " to " << gameDef(*game).default_points << " points, "
        << games.points << " points in " << games.innings << " innings: average " << average(games)
        << ", high run " << games.high_run << "\n";
  }
  out << std::setprecision(2) << "think time per shot: median " << medianOf(all.think) << " s, max "
      << max_think << " s over " << all.think.size() << " shots\n"
      << "wall time: " << wall << " s\n"
      << std::flush;
  return out ? kExitOk : kExitInternal;
}

}  // namespace nineball::app
