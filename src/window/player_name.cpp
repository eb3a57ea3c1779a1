#include "window/player_name.hpp"

namespace nineball::window {
namespace {

// The length of the UTF-8 sequence starting at `s[i]`, or 0 when it is malformed.
std::size_t sequenceAt(const std::string& s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char b = byte(i);
  std::size_t n = 0;
  char32_t c = 0;
  if (b < 0x80) return 1;
  if ((b & 0xE0) == 0xC0) {
    n = 2;
    c = b & 0x1F;
  } else if ((b & 0xF0) == 0xE0) {
    n = 3;
    c = b & 0x0F;
  } else if ((b & 0xF8) == 0xF0) {
    n = 4;
    c = b & 0x07;
  } else {
    return 0;
  }
  if (i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    c = (c << 6) | (byte(i + k) & 0x3F);
  }
  const char32_t least[] = {0, 0, 0x80, 0x800, 0x10000};
  if (c < least[n] || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) return 0;
  return n;
}

}  // namespace

bool validUtf8(const std::string& s) {
  for (std::size_t i = 0; i < s.size();) {
    const std::size_t n = sequenceAt(s, i);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

std::optional<std::string> playerName(const std::string& raw) {
  if (raw.empty() || !validUtf8(raw)) return std::nullopt;
  std::size_t end = 0;
  while (end < raw.size()) {
    const std::size_t n = sequenceAt(raw, end);
    if (end + n > kMaxNameBytes) break;
    end += n;
  }
  return raw.substr(0, end);
}

}  // namespace nineball::window
