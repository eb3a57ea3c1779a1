#include "io/match_play.hpp"

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "common/log.hpp"
#include "nineball/planner.hpp"
#include "nineball/seat.hpp"

namespace nineball::io {
namespace {

// However the players play, a rack stops after this many turns.
constexpr std::size_t kMaxTurns = 500;

int index(rules::Player p) {
  return p == rules::Player::A ? 0 : 1;
}

// Each computer player draws its cueing errors from its own stream, fixed by the script's seed.
std::uint64_t plannerSeed(std::uint64_t script_seed, rules::Player p) {
  return script_seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(index(p)) + 1;
}

}  // namespace

MatchPlayed playMatchScript(const MatchScript& script, int planner_threads) {
  std::array<std::unique_ptr<ai::Planner>, 2> planners;
  for (rules::Player p : {rules::Player::A, rules::Player::B}) {
    if (const auto level = computerLevel(script.players[index(p)])) {
      planners[index(p)] =
          std::make_unique<ai::Planner>(*level, plannerSeed(script.setup.seed, p), planner_threads);
    }
  }
  Match match(script.setup);
  std::vector<TurnRecord> records;
  std::vector<std::optional<ComputerTurn>> computer;
  std::size_t next_script_turn = 0;
  MatchPlayed played;
  while (records.size() < kMaxTurns) {
    ai::Planner* planner = planners[index(match.rack().shooter())].get();
    if (planner && !match.rack().over()) {
      const TurnInput turn = planner->turnFor(match);
      try {
        records.push_back(match.play(turn));
      } catch (const IllegalAction& e) {
        played.outcome = MatchPlayed::Outcome::ComputerRefused;
        played.why =
            "the computer's turn " + std::to_string(records.size()) + " was refused: " + e.what();
        return played;
      }
      computer.push_back(ComputerTurn{planner->level(), turn});
    } else if (next_script_turn < script.turns.size()) {
      const std::size_t i = next_script_turn++;
      try {
        records.push_back(match.play(script.turns[i]));
      } catch (const IllegalAction& e) {
        played.outcome = MatchPlayed::Outcome::BadTurn;
        played.why = "turns[" + std::to_string(i) + "]: " + e.what();
        return played;
      }
      computer.emplace_back();
    } else {
      break;
    }
    if (match.world().exhausted() || !match.world().atRest()) {
      played.outcome = MatchPlayed::Outcome::Partial;
      break;
    }
    const TurnRecord& r = records.back();
    logger("app")->info("turn {}: {} {}{}", records.size() - 1, rules::playerName(r.shooter),
                        r.verdict.legal() ? "legal" : "foul ",
                        r.verdict.legal() ? "" : rules::foulName(r.verdict.foul));
  }
  played.turns = records.size();
  played.doc = matchResultToJson(records, match.rack(), match.balls(), computer);
  played.doc["partial"] = played.outcome == MatchPlayed::Outcome::Partial;
  return played;
}

}  // namespace nineball::io
