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

using nlohmann::ordered_json;

// However the players play, a rack stops after this many turns.
constexpr std::size_t kMaxTurns = 500;

using Planners = std::array<std::unique_ptr<ai::Planner>, 2>;

int index(rules::Player p) {
  return p == rules::Player::A ? 0 : 1;
}

// Each computer player draws its cueing errors from its own stream, fixed by the script's seed.
std::uint64_t plannerSeed(std::uint64_t script_seed, rules::Player p) {
  return script_seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(index(p)) + 1;
}

// One rack played from the script's turns (from `next_turn` on) and the computer's.
struct RackPlayed {
  MatchPlayed::Outcome outcome = MatchPlayed::Outcome::Done;
  std::string why;
  std::vector<TurnRecord> records;
  std::vector<std::optional<ComputerTurn>> computer;
};

RackPlayed playRack(Match& match, const Planners& planners, const std::vector<TurnInput>& turns,
                    std::size_t& next_turn) {
  RackPlayed played;
  std::vector<TurnRecord>& records = played.records;
  while (records.size() < kMaxTurns && !match.rack().over()) {
    ai::Planner* planner = planners[index(match.rack().shooter())].get();
    if (planner) {
      const TurnInput turn = planner->turnFor(match);
      try {
        records.push_back(match.play(turn));
      } catch (const IllegalAction& e) {
        played.outcome = MatchPlayed::Outcome::ComputerRefused;
        played.why = std::string("was refused: ") + e.what();
        return played;
      }
      played.computer.push_back(ComputerTurn{planner->level(), turn});
    } else if (next_turn < turns.size()) {
      const std::size_t i = next_turn++;
      try {
        records.push_back(match.play(turns[i]));
      } catch (const IllegalAction& e) {
        played.outcome = MatchPlayed::Outcome::BadTurn;
        played.why = "turns[" + std::to_string(i) + "]: " + e.what();
        return played;
      }
      played.computer.emplace_back();
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
  return played;
}

// A rack's result turned into one rack of a race: its turns numbered with the rack, the rest
// (who broke, who won, snooker's score) in the race's list of racks.
void addRack(ordered_json rack_doc, int rack, const MatchSetup& setup, ordered_json& turns,
             ordered_json& racks) {
  for (const ordered_json& turn : rack_doc["turns"]) {
    ordered_json numbered = {{"rack", rack}};
    numbered.update(turn);
    turns.push_back(numbered);
  }
  ordered_json entry = {{"rack", rack},
                        {"seed", setup.seed},
                        {"breaker", rules::playerName(setup.opener)},
                        {"winner", rack_doc["winner"]},
                        {"turns", rack_doc["turns"].size()}};
  for (const char* key : {"turns", "balls", "winner", "partial"}) rack_doc.erase(key);
  entry.update(rack_doc);
  racks.push_back(entry);
}

ordered_json raceDocument(const Race& race, ordered_json turns, ordered_json racks,
                          const RaceScore& score, ordered_json balls) {
  ordered_json doc;
  doc["race_to"] = race.race_to;
  doc["breaks"] = breakOrderName(race.breaks);
  doc["turns"] = std::move(turns);
  doc["racks"] = std::move(racks);
  doc["racks_won"] = {{"A", score.won[0]}, {"B", score.won[1]}};
  const auto winner = score.winner(race);
  doc["winner"] = winner ? ordered_json(rules::playerName(*winner)) : ordered_json(nullptr);
  doc["balls"] = std::move(balls);
  return doc;
}

}  // namespace

MatchPlayed playMatchScript(const MatchScript& script, int planner_threads) {
  Planners planners;
  for (rules::Player p : {rules::Player::A, rules::Player::B}) {
    if (const auto level = computerLevel(script.players[index(p)])) {
      planners[index(p)] =
          std::make_unique<ai::Planner>(*level, plannerSeed(script.setup.seed, p), planner_threads);
    }
  }
  MatchPlayed played;
  RaceScore score;
  std::optional<rules::Player> last_winner;
  ordered_json turns = ordered_json::array();
  ordered_json racks = ordered_json::array();
  std::size_t next_turn = 0;
  for (int rack = 0;; ++rack) {
    const MatchSetup setup =
        rackSetup(script.setup, rack, rackOpener(script.race.breaks, rack, last_winner));
    Match match(setup);
    RackPlayed r = playRack(match, planners, script.turns, next_turn);
    if (r.outcome == MatchPlayed::Outcome::ComputerRefused) {
      r.why =
          "the computer's turn " + std::to_string(played.turns + r.records.size()) + " " + r.why;
    }
    played.turns += r.records.size();
    if (r.outcome == MatchPlayed::Outcome::BadTurn ||
        r.outcome == MatchPlayed::Outcome::ComputerRefused) {
      played.outcome = r.outcome;
      played.why = r.why;
      return played;
    }
    ordered_json rack_doc = matchResultToJson(r.records, match.rack(), match.balls(), r.computer);
    if (script.race.race_to == 0) {
      played.doc = std::move(rack_doc);
      played.outcome = r.outcome;
      break;
    }
    ordered_json balls = rack_doc["balls"];
    addRack(std::move(rack_doc), rack, setup, turns, racks);
    if (match.rack().over()) {
      score.count(match.rack().winner());
      last_winner = match.rack().winner();
    }
    // The next rack is racked when the race is undecided and someone will play it.
    const rules::Player next_opener = rackOpener(script.race.breaks, rack + 1, last_winner);
    const bool more = next_turn < script.turns.size() || planners[index(next_opener)];
    if (r.outcome == MatchPlayed::Outcome::Partial || !match.rack().over() ||
        score.winner(script.race) || !more) {
      played.outcome = r.outcome;
      played.doc =
          raceDocument(script.race, std::move(turns), std::move(racks), score, std::move(balls));
      break;
    }
  }
  if (played.outcome == MatchPlayed::Outcome::Done && next_turn < script.turns.size()) {
    played.outcome = MatchPlayed::Outcome::BadTurn;
    played.why = "turns[" + std::to_string(next_turn) +
                 "]: " + (script.race.race_to > 0 ? "the match is over" : "the game is over");
    return played;
  }
  played.doc["partial"] = played.outcome == MatchPlayed::Outcome::Partial;
  return played;
}

}  // namespace nineball::io
