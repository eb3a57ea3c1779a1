#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace nineball::window {

/// A player's name holds at most this many bytes of UTF-8 (what the HUD has room for).
constexpr std::size_t kMaxNameBytes = 24;

/// True when `s` is well-formed UTF-8 (no stray continuation bytes, overlong forms,
/// surrogates or code points past U+10FFFF).
bool validUtf8(const std::string& s);

/// A name as it may be shown and saved: valid UTF-8, cut to kMaxNameBytes on a character
/// boundary. Nothing for an empty or malformed name (JSON cannot hold malformed UTF-8: the
/// library throws when such a name is written).
std::optional<std::string> playerName(const std::string& raw);

}  // namespace nineball::window
