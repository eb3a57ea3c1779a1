#include "app/read_input.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <istream>

#include "common/limits.hpp"

namespace nineball::app {
namespace {

std::optional<std::string> readAll(std::istream& in, std::string& why, std::size_t limit) {
  std::string text;
  char buffer[1 << 16];
  errno = 0;
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > limit) {
      why = limit == limits::kMaxInputBytes ? inputTooLarge()
                                            : "larger than " + std::to_string(limit >> 20) + " MiB";
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

std::string inputTooLarge() {
  return "larger than " + std::to_string(limits::kMaxInputBytes >> 20) +
         " MiB, more than any scene or script needs";
}

std::istream* openInput(const std::string& path, std::istream& stdin_stream, std::ifstream& file,
                        std::string& why) {
  if (path == "-") return &stdin_stream;
  errno = 0;
  file.open(path, std::ios::binary);
  if (!file) {
    why = std::string("cannot open: ") + (errno ? std::strerror(errno) : "open failed");
    return nullptr;
  }
  return &file;
}

std::optional<std::string> readInput(const std::string& path, std::istream& stdin_stream,
                                     std::string& why, std::size_t limit) {
  std::ifstream file;
  std::istream* source = openInput(path, stdin_stream, file, why);
  if (!source) return std::nullopt;
  return readAll(*source, why, limit);
}

}  // namespace nineball::app
