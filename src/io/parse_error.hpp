#pragma once

#include <string>

namespace nineball::io {

/// Why an input was refused: the field path, a colon and the reason, e.g.
/// "balls[2].x: expected a number, found string".
struct ParseError {
  std::string message;
};

}  // namespace nineball::io
