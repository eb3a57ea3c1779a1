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

Hello helloFrom(const std::string& name);
/// Why the host refuses this hello (another protocol, another build), or nothing.
std::optional<std::string> refusalOf(const Hello& hello);
/// The same check of the host's welcome, on the joiner's side.
std::optional<std::string> refusalOf(const Welcome& welcome);

/// The host's welcome: its name, the match (a script without turns and players), where the
/// race stands, and the rack's turns and hashes so far.
Welcome welcomeFrom(const std::string& name, const nlohmann::json& match, const Race& race,
                    const Lockstep& lockstep);

/// The match a welcome carries, read as `nineball match` reads a script; nothing, with `why`.
std::optional<MatchSetup> setupOf(const Welcome& welcome, std::string& why);

/// A match script's setup as the welcome carries it: the script without "turns" and "players".
nlohmann::json matchPart(const nlohmann::json& script);

}  // namespace nineball::net
