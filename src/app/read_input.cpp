#include "app/read_input.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <istream>

#include "nineball/limits.hpp"

namespace nineball::app {
namespace {

std::optional<std::string> readAll(std::istream& in, std::string& why) {
  std::string text;
  char buffer[1 << 16];
  errno = 0;
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > limits::kMaxInputBytes) {
      why = "larger than " + std::to_string(limits::kMaxInputBytes >> 20) +
            " MiB, more than any scene or script needs";
      return std::nullopt;
    }
  }
  if (in.bad()) {
    why = std::string("cannot read: ") + (errno ? std::strerror(errno) : "read error");
    return std::nullopt;
  }
  return text;
}

}  // namespace

std::optional<std::string> readInput(const std::string& path, std::istream& stdin_stream,
                                     std::string& why) {
  if (path == "-") return readAll(stdin_stream, why);
  errno = 0;
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    why = std::string("cannot open: ") + (errno ? std::strerror(errno) : "open failed");
    return std::nullopt;
  }
  return readAll(file, why);
}

}  // namespace nineball::app
