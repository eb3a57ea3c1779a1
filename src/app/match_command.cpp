#include "app/match_command.hpp"

#include <istream>
#include <ostream>

#include "app/exit_codes.hpp"
#include "app/read_input.hpp"
#include "io/match_json.hpp"
#include "nineball/log.hpp"

namespace nineball::app {

CLI::App* addMatchCommand(CLI::App& app, MatchOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "match", "Play a rack of nine-ball from a JSON script and print the result as JSON");
  cmd->add_option("script", options.script_path, "Script file, or - to read standard input")
      ->required();
  return cmd;
}

int runMatch(const MatchOptions& options, std::istream& in, std::ostream& out, std::ostream& err) {
  const std::string prefix = "nineball match: " + shownPath(options.script_path) + ": ";
  std::string why;
  const auto text = readInput(options.script_path, in, why);
  if (!text) {
    err << prefix << why << '\n';
    return kExitBadInput;
  }
  auto parsed = io::parseMatchScript(*text);
  if (const auto* refused = std::get_if<io::ParseError>(&parsed)) {
    err << prefix << refused->message << '\n';
    return kExitBadInput;
  }
  const io::MatchScript& script = std::get<io::MatchScript>(parsed);
  Match match(script.setup);
  std::vector<TurnRecord> records;
  for (std::size_t i = 0; i < script.turns.size(); ++i) {
    try {
      records.push_back(match.play(script.turns[i]));
    } catch (const IllegalAction& e) {
      err << prefix << "turns[" << i << "]: " << e.what() << '\n';
      return kExitBadInput;
    }
    const TurnRecord& r = records.back();
    logger("app")->info("turn {}: {} {}{}", i, rules::playerName(r.shooter),
                        r.verdict.legal() ? "legal" : "foul ",
                        r.verdict.legal() ? "" : rules::foulName(r.verdict.foul));
  }
  out << io::matchResultToJson(records, match.rack(), match.balls()).dump(2) << '\n' << std::flush;
  return out ? kExitOk : kExitInternal;
}

}  // namespace nineball::app
