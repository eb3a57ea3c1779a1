#include "app/match_script_file.hpp"

#include <ostream>

#include "app/read_input.hpp"

namespace nineball::app {

std::optional<io::MatchScript> loadMatchScript(const std::string& path, std::istream& in,
                                               std::ostream& err, const std::string& prefix,
                                               std::string* text_out) {
  const std::string where = prefix + shownPath(path) + ": ";
  std::string why;
  const auto text = readInput(path, in, why);
  if (!text) {
    err << where << why << '\n';
    return std::nullopt;
  }
  auto parsed = io::parseMatchScript(*text);
  if (text_out) *text_out = *text;
  if (const auto* refused = std::get_if<io::ParseError>(&parsed)) {
    err << where << refused->message << '\n';
    return std::nullopt;
  }
  return std::get<io::MatchScript>(std::move(parsed));
}

}  // namespace nineball::app
