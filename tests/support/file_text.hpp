#pragma once

#include <fstream>
#include <sstream>
#include <string>

namespace nineball::testing {

/// The whole of the file at `path`, byte for byte ("" when it cannot be read).
inline std::string fileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace nineball::testing
