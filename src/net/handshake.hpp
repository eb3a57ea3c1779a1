#pragma once

#include <optional>
#include <string>

#include "io/match_json.hpp"
#include "net/lockstep.hpp"
#include "net/protocol.hpp"
#include "net/wire.hpp"

// The first words of a link, the same for the window and `nineball online`: the joiner says
// hello, the host welcomes it with the match and the rack so far, or refuses it by name.
namespace nineball::net {

/// The joiner's hello: its name, the host's join code as typed, the seat token of an earlier
/// welcome (empty for a first join) and who plays its seat.
Hello helloFrom(const std::string& name, const std::string& code = "",
                const std::string& token = "", const Seat& player = HumanSeat{});
/// Why the host refuses this hello (another protocol, another build), or nothing.
std::optional<std::string> refusalOf(const Hello& hello);
/// The same check of the host's welcome, on the joiner's side.
std::optional<std::string> refusalOf(const Welcome& welcome);

/// The host's welcome: its name, the match (a script without turns and players), where the
/// race stands, and the rack's turns and hashes so far.
Welcome welcomeFrom(const std::string& name, const nlohmann::json& match, const Race& race,
                    const Lockstep& lockstep, const std::string& token);

/// A new join code: 8 characters of an alphabet without look-alikes (no 0/O, 1/I/L), drawn
/// from the system's random source, written as two groups: "7KQ4-ZP2M" (40 bits).
std::string makeJoinCode();
/// A new seat token: kSeatTokenChars hexadecimal digits (128 random bits).
std::string makeSeatToken();
/// A join code as compared: upper case, without dashes and spaces, so "7kq4 zp2m" is
/// "7KQ4-ZP2M".
std::string normalCode(const std::string& code);
/// True when `typed` is the host's `code` (normalCode of both); compared in time independent
/// of where they differ.
bool codeMatches(const std::string& typed, const std::string& code);
/// True when `offered` is the seat's `token` (both non-empty); compared as codeMatches.
bool tokenMatches(const std::string& offered, const std::string& token);

/// The match a welcome carries, read as `nineball match` reads a script; nothing, with `why`.
std::optional<MatchSetup> setupOf(const Welcome& welcome, std::string& why);

/// A match script's setup as the welcome carries it: the script without "turns" and "players".
nlohmann::json matchPart(const nlohmann::json& script);

}  // namespace nineball::net
