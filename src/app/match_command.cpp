#include "app/match_command.hpp"

#include <array>
#include <istream>
#include <memory>
#include <ostream>

#include "app/exit_codes.hpp"
#include "app/match_script_file.hpp"
#include "app/read_input.hpp"
#include "common/log.hpp"
#include "io/match_json.hpp"
#include "nineball/games.hpp"
#include "nineball/planner.hpp"
#include "nineball/seat.hpp"

namespace nineball::app {
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

CLI::App* addMatchCommand(CLI::App& app, MatchOptions& options) {
  CLI::App* cmd =
      app.add_subcommand("match", "Play a rack of " + gamesPlayedBy(rules::RuleSet::Wpa) +
                                      " from a JSON script and print the result as JSON");
  cmd->add_option("script", options.script_path, "Script file, or - to read standard input")
      ->required();
  return cmd;
}

int runMatch(const MatchOptions& options, std::istream& in, std::ostream& out, std::ostream& err) {
  const std::string prefix = "nineball match: " + shownPath(options.script_path) + ": ";
  const auto loaded = loadMatchScript(options.script_path, in, err, "nineball match: ");
  if (!loaded) return kExitBadInput;
  const io::MatchScript& script = *loaded;
  std::array<std::unique_ptr<ai::Planner>, 2> planners;
  for (rules::Player p : {rules::Player::A, rules::Player::B}) {
    if (const auto level = computerLevel(script.players[index(p)])) {
      planners[index(p)] = std::make_unique<ai::Planner>(*level, plannerSeed(script.setup.seed, p));
    }
  }
  Match match(script.setup);
  std::vector<TurnRecord> records;
  std::vector<std::optional<io::ComputerTurn>> computer;
  std::size_t next_script_turn = 0;
  bool partial = false;  // a shot stopped at max_time or at the work budget, balls still moving
  while (records.size() < kMaxTurns) {
    ai::Planner* planner = planners[index(match.rack().shooter())].get();
    if (planner && !match.rack().over()) {
      const TurnInput turn = planner->turnFor(match);
      try {
        records.push_back(match.play(turn));
      } catch (const IllegalAction& e) {
        err << prefix << "the computer's turn " << records.size() << " was refused: " << e.what()
            << '\n';
        return kExitInternal;
      }
      computer.push_back(io::ComputerTurn{planner->level(), turn});
    } else if (next_script_turn < script.turns.size()) {
      const std::size_t i = next_script_turn++;
      try {
        records.push_back(match.play(script.turns[i]));
      } catch (const IllegalAction& e) {
        err << prefix << "turns[" << i << "]: " << e.what() << '\n';
        return kExitBadInput;
      }
      computer.emplace_back();
    } else {
      break;
    }
    if (match.world().exhausted() || !match.world().atRest()) {
      partial = true;
      break;
    }
    const TurnRecord& r = records.back();
    logger("app")->info("turn {}: {} {}{}", records.size() - 1, rules::playerName(r.shooter),
                        r.verdict.legal() ? "legal" : "foul ",
                        r.verdict.legal() ? "" : rules::foulName(r.verdict.foul));
  }
  auto doc = io::matchResultToJson(records, match.rack(), match.balls(), computer);
  doc["partial"] = partial;
  out << doc.dump(2) << '\n' << std::flush;
  if (!out) return kExitInternal;
  if (partial) {
    err << prefix << "turn " << records.size() - 1
        << " stopped at step.max_time or the work budget with balls still moving: the match "
           "stops there and the result is partial\n";
    return kExitPartial;
  }
  return kExitOk;
}

}  // namespace nineball::app
