#include "app/match_command.hpp"

#include <istream>
#include <ostream>

#include "app/exit_codes.hpp"
#include "app/match_script_file.hpp"
#include "app/read_input.hpp"
#include "io/match_play.hpp"
#include "nineball/games.hpp"

namespace nineball::app {

CLI::App* addMatchCommand(CLI::App& app, MatchOptions& options) {
  CLI::App* cmd =
      app.add_subcommand("match", "Play a rack (or a race of racks) of " + gamesPlayedBy(rules::RuleSet::Wpa) +
                                      " from a JSON script and print the result as JSON");
  cmd->add_option("script", options.script_path, "Script file, or - to read standard input")
      ->required();
  return cmd;
}

int runMatch(const MatchOptions& options, std::istream& in, std::ostream& out, std::ostream& err) {
  const std::string prefix = "nineball match: " + shownPath(options.script_path) + ": ";
  const auto loaded = loadMatchScript(options.script_path, in, err, "nineball match: ");
  if (!loaded) return kExitBadInput;
  const io::MatchPlayed played = io::playMatchScript(*loaded);
  switch (played.outcome) {
    case io::MatchPlayed::Outcome::BadTurn:
      err << prefix << played.why << '\n';
      return kExitBadInput;
    case io::MatchPlayed::Outcome::ComputerRefused:
      err << prefix << played.why << '\n';
      return kExitInternal;
    case io::MatchPlayed::Outcome::Done:
    case io::MatchPlayed::Outcome::Partial:
      break;
  }
  out << played.doc.dump(2) << '\n' << std::flush;
  if (!out) return kExitInternal;
  if (played.outcome == io::MatchPlayed::Outcome::Partial) {
    err << prefix << "turn " << played.turns - 1
        << " stopped at step.max_time or the work budget with balls still moving: the match "
           "stops there and the result is partial\n";
    return kExitPartial;
  }
  return kExitOk;
}

}  // namespace nineball::app
