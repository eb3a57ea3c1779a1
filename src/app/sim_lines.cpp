// `nineball sim --jsonl`: many scenes in one process, one per line, so that batch work pays
// the start-up and the table's set-up once.
#include <cerrno>
#include <cstring>
#include <istream>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "app/exit_codes.hpp"
#include "app/read_input.hpp"
#include "app/sim_command.hpp"
#include "io/result_json.hpp"
#include "io/scene_json.hpp"
#include "nineball/limits.hpp"

namespace nineball::app {
namespace {

bool blank(const std::string& line) {
  return line.find_first_not_of(" \t\r") == std::string::npos;
}

// What one line gives: a result, or the reason it was refused.
struct LineOutcome {
  nlohmann::ordered_json json;
  bool refused = false;
  bool partial = false;
  std::string note;  ///< a line for stderr about a result that stands (a trace cut short)
};

LineOutcome simulateLine(const std::string& line, long number) {
  auto refuse = [&](const std::string& why) {
    return LineOutcome{{{"error", why}, {"line", number}}, true, false, {}};
  };
  if (line.size() > limits::kMaxInputBytes) return refuse(inputTooLarge());
  auto parsed = io::parseScene(line);
  if (const auto* bad = std::get_if<io::ParseError>(&parsed)) return refuse(bad->message);
  const Scene& scene = std::get<Scene>(parsed);
  const SimResult result = simulate(scene);
  if (const auto fault = resultFault(scene, result)) return refuse("internal error: " + *fault);
  std::string note;
  if (result.trace && result.trace->truncated) note = traceTruncatedNote(*result.trace);
  return {io::resultToJson(result), false, result.partial(), note};
}

}  // namespace

int runSimLines(const SimOptions& options, std::istream& in, std::ostream& out, std::ostream& err) {
  const std::string prefix = "nineball sim: " + shownPath(options.scene_path) + ": ";
  std::ifstream file;
  std::string why;
  std::istream* source = openInput(options.scene_path, in, file, why);
  if (!source) {
    err << prefix << why << '\n';
    return kExitBadInput;
  }
  long number = 0, refused = 0, partial = 0, results = 0;
  std::string line;
  while (std::getline(*source, line)) {
    ++number;
    if (blank(line)) continue;
    const LineOutcome o = simulateLine(line, number);
    out << o.json.dump() << '\n';
    if (o.refused) {
      ++refused;
      err << prefix << "line " << number << ": " << o.json["error"].get<std::string>() << '\n';
    } else {
      if (!o.note.empty()) err << prefix << "line " << number << ": " << o.note << '\n';
      ++results;
      partial += o.partial ? 1 : 0;
    }
  }
  out << std::flush;
  if (source->bad()) {
    err << prefix << "cannot read: " << (errno ? std::strerror(errno) : "read error") << '\n';
    return kExitBadInput;
  }
  if (!out) return kExitInternal;
  if (refused > 0) {
    err << prefix << refused << " of " << refused + results << " scenes refused\n";
    return kExitBadInput;
  }
  if (partial > 0) {
    err << prefix << partial << " of " << results << " results partial\n";
    return kExitPartial;
  }
  return kExitOk;
}

}  // namespace nineball::app
