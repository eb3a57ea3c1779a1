#pragma once

#include <string>

// The joiner's seat tokens, kept beside the settings ($XDG_CONFIG_HOME/nineball/online_seat.json)
// by the host each is for (the last 16): a window restarted in the middle of an online rack
// (after a crash) gives its token in its hello and takes its seat back.
namespace nineball::window {

/// The file; empty when the environment names no home for it.
std::string seatTokenPath();
/// The token kept for the host at `address` ("HOST:PORT"); empty when none (or unreadable).
std::string loadSeatToken(const std::string& path, const std::string& address);
/// Keeps `token` for `address` (best effort: a failure is logged, the game goes on).
void keepSeatToken(const std::string& path, const std::string& address, const std::string& token);

}  // namespace nineball::window
