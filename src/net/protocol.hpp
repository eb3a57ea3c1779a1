#pragma once

#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "nineball/match.hpp"
#include "nineball/seat.hpp"

// The messages two nineballs exchange (docs/online.md lists them). Each is read into a value
// type only after its shape, its keys and every number's range have been checked; what a
// message means for the rack (whose turn, which balls) is checked by who plays it.
namespace nineball::net {

/// Longest player name carried (longer ones are cut); control characters are dropped.
constexpr std::size_t kMostNameChars = 24;
/// Most turns a rack may hold (as `nineball match` plays at most 500).
constexpr std::size_t kMostTurns = 500;
/// Longest text a peer may send (a reason, a build name): what either side reads. A refusal or
/// a goodbye longer than this is cut to it before it is sent, never dropped.
constexpr std::size_t kMostText = 200;
/// Longest join code a hello may carry.
constexpr std::size_t kMostCodeChars = 32;
/// A seat token's length: 32 hexadecimal digits (128 random bits).
constexpr std::size_t kSeatTokenChars = 32;

/// The joiner's first words.
struct Hello {
  int protocol = 0;
  std::string build;
  std::string name;
  /// The host's join code as the joiner typed it (compared without case and dashes).
  std::string code;
  /// The seat token a welcome handed this player before, to take the seat back after a drop;
  /// empty for a first join.
  std::string token;
  /// Who plays the joiner's seat: a human, or the computer at a level. Every turn it sends
  /// must say the same.
  Seat player = HumanSeat{};
};

/// The match a host plays: its setup as a match script without "turns" and "players", and
/// (for the window's matches of several racks) where the match stands.
struct Race {
  int best_of = 1;  ///< racks (frames) of the match; 1 for a single rack
  int rack = 0;     ///< the rack being played, from 0
  std::array<int, 2> racks_won{};
};

/// One turn as it travels: the script's turn, the angles in exact radians beside it, and who
/// played it ("human" or "ai:<level>").
struct WireTurn {
  nlohmann::json turn;  ///< as a match script's turn (checked against the match by parseWireTurn)
  Seat player;
};

/// The host's answer to a Hello: the match, and the rack's turns so far with the state hash
/// after each (a rejoining peer replays them to the same position).
struct Welcome {
  int protocol = 0;
  std::string build;
  std::string name;
  nlohmann::json match;
  Race race;
  std::vector<WireTurn> turns;
  std::vector<std::uint64_t> hashes;
  /// The joiner's seat token: a hello carrying it takes the seat back after a drop.
  std::string token;
};

struct Refuse {
  std::string reason;
};
struct TurnMessage {
  std::size_t index = 0;  ///< the turn's number in the rack, from 0
  WireTurn turn;
};
struct HashMessage {
  std::size_t index = 0;
  std::uint64_t hash = 0;
};
/// The host's state after turn `index`, sent whole when the hashes disagree.
struct StateMessage {
  std::size_t index = 0;
  nlohmann::json state;  ///< io::snapshotToJson; read by io::parseSnapshot
};
/// Where the player to move holds the cue now (a few a second, for the other screen).
struct Aim {
  double heading_rad = 0.0;
  double speed = 0.0;  ///< m/s the cue would give
  Vec2 tip;            ///< fraction of R
  double elevation_rad = 0.0;
  std::optional<Vec2> cue;  ///< the cue ball in hand, where it is being placed
};
/// An offer of another match; when both have offered, it starts.
struct Rematch {};
/// The other side leaves.
struct Bye {
  std::string reason;
  /// The sender's rack is played out (won, its script over, the turn limit): not a quit.
  bool finished = false;
};

using Message =
    std::variant<Hello, Welcome, Refuse, TurnMessage, HashMessage, StateMessage, Aim, Rematch, Bye>;

/// The message as sent.
nlohmann::json toJson(const Message& message);
/// Reads a message (an object with "type"); nothing, with `why`, for an unknown type, a
/// missing or extra key, or a value out of range.
std::optional<Message> readMessage(const nlohmann::json& j, std::string& why);

/// The wire form of a turn of `game`: the script's turn plus "heading_rad" and
/// "elevation_rad", which keep every bit (degrees would round).
WireTurn wireTurn(const TurnInput& turn, const Seat& player, rules::Game game);
/// The turn a wire turn carries, checked as `nineball match` checks a script's turn (plus the
/// radians agreeing with the degrees); nothing, with `why`, when it is refused.
std::optional<TurnInput> parseWireTurn(const WireTurn& wire, const MatchSetup& setup,
                                       std::string& why);

/// "0123456789abcdef".
std::string hashText(std::uint64_t hash);
/// A name as shown to the other side: printable, at most kMostNameChars.
std::string cleanName(const std::string& name);
/// Text from (or for) a peer as it may be logged, shown or sent: control characters (C0, C1,
/// DEL: a terminal's escape sequences, a forged line) and bytes that are not UTF-8 dropped,
/// cut at a whole character to at most `most_bytes`.
std::string cleanText(const std::string& text, std::size_t most_bytes = kMostText);
/// True for a seat token's form: kSeatTokenChars lowercase hexadecimal digits.
bool isSeatToken(const std::string& text);

}  // namespace nineball::net
