// `nineball sim --jsonl`: many scenes in one process, one per line, so that batch work pays
// the start-up and the table's set-up once.
#include <cerrno>
#include <cstring>
#include <istream>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>

#include "app/exit_codes.hpp"
#include "app/read_input.hpp"
#include "app/sim_command.hpp"
#include "common/limits.hpp"
#include "io/result_json.hpp"
#include "io/scene_json.hpp"

namespace nineball::app {
namespace {

// The rest of an over-long line is skipped up to this much more input: a line that never ends
// (/dev/zero) stops the run there rather than reading for ever.
constexpr std::size_t kMaxSkipped = std::size_t{1} << 30;

bool blank(const std::string& line) {
  return line.find_first_not_of(" \t\r") == std::string::npos;
}

enum class LineRead { Line, TooLong, Endless, End };

// One line, never holding more than limits::kMaxInputBytes of it: a longer one is skipped to
// its end (TooLong), or stops the input when no end comes within kMaxSkipped (Endless).
LineRead readLine(std::istream& in, std::string& line) {
  line.clear();
  std::streambuf* buf = in.rdbuf();
  std::size_t skipped = 0;
  bool too_long = false;
  for (;;) {
    const int c = buf->sbumpc();
    if (c == std::char_traits<char>::eof()) {
      in.setstate(std::ios::eofbit);
      if (too_long) return LineRead::TooLong;
      return line.empty() ? LineRead::End : LineRead::Line;
    }
    if (c == '\n') return too_long ? LineRead::TooLong : LineRead::Line;
    if (too_long) {
      if (++skipped > kMaxSkipped) return LineRead::Endless;
      continue;
    }
    line.push_back(static_cast<char>(c));
    if (line.size() > limits::kMaxInputBytes) {
      too_long = true;
      std::string().swap(line);
    }
  }
}

// What one line gives: a result, or the reason it was refused.
struct LineOutcome {
  std::optional<SimResult> result;  ///< written as it is, its trace streamed
  nlohmann::ordered_json error;     ///< {"error", "line"} when refused
  bool partial = false;
  std::string note;  ///< a line for stderr about a result that stands (a trace cut short)
};

LineOutcome refusal(const std::string& why, long number) {
  LineOutcome o;
  o.error = {{"error", why}, {"line", number}};
  return o;
}

LineOutcome simulateLine(const std::string& line, long number) {
  auto parsed = io::parseScene(line);
  if (const auto* bad = std::get_if<io::ParseError>(&parsed)) return refusal(bad->message, number);
  const Scene& scene = std::get<Scene>(parsed);
  SimResult result = simulate(scene);
  if (const auto fault = resultFault(scene, result)) {
    return refusal("internal error: " + *fault, number);
  }
  LineOutcome o;
  if (result.trace && result.trace->truncated) o.note = traceTruncatedNote(*result.trace);
  o.partial = result.partial();
  o.result = std::move(result);
  return o;
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
  for (LineRead read; (read = readLine(*source, line)) != LineRead::End;) {
    ++number;
    if (read == LineRead::Endless) {
      const LineOutcome o =
          refusal(inputTooLarge() + "; no end of line within " + std::to_string(kMaxSkipped >> 20) +
                      " MiB more, so the input is read no further",
                  number);
      out << o.error.dump() << '\n';
      err << prefix << "line " << number << ": " << o.error["error"].get<std::string>() << '\n';
      ++refused;
      break;
    }
    if (read == LineRead::Line && blank(line)) continue;
    const LineOutcome o =
        read == LineRead::TooLong ? refusal(inputTooLarge(), number) : simulateLine(line, number);
    if (!o.result) {
      out << o.error.dump() << '\n';
      ++refused;
      err << prefix << "line " << number << ": " << o.error["error"].get<std::string>() << '\n';
    } else {
      io::writeResult(out, *o.result, false);
      out << '\n';
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
