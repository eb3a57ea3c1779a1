#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "nineball/games.hpp"
#include "nineball/match.hpp"
#include "nineball/race.hpp"
#include "nineball/seat.hpp"

namespace nineball::window {

class GameSession;

/// A rack left unfinished: how the session started, which rack it was, the score, the
/// players, and the turns of the rack so far. Replaying the turns through the physics gives
/// the position again, bit for bit (the physics is deterministic). No SFML.
struct SavedRack {
  rules::Game game = defaultGame().id;
  rules::RuleSet rules = rules::RuleSet::Wpa;
  std::uint64_t seed = 1;  ///< the session's seed (rack n racks with seed + n)
  int rack_index = 0;      ///< 0 for the session's first rack
  std::array<int, 2> racks_won{};
  int best_of = 0;  ///< the match's length in frames (GameSession::bestOf); 0: none
  BreakOrder breaks = BreakOrder::Alternate;
  /// The seat that broke the rack (files from before it was kept: the seats took turns).
  std::optional<int> breaker;
  /// A match of several racks whose every turn is known: the rack it began with (else -1) and
  /// its turns from there, this rack's last. The rack resumes by playing them all again.
  int first_rack = -1;
  std::vector<TurnInput> match_turns;
  std::array<std::string, 2> names = {"Player 1", "Player 2"};
  Seat opponent;  ///< who played Player 2
  std::vector<TurnInput> turns;
};

/// $XDG_STATE_HOME/nineball/rack.json, else $HOME/.local/state/nineball/rack.json; empty when
/// neither gives an absolute path.
std::string rackSavePath();

/// The rack of a session as it stands (its turns so far).
SavedRack saveOf(const GameSession& session, const Seat& opponent);

nlohmann::ordered_json rackToJson(const SavedRack& rack);
/// Nothing (and why) for a document that is not a saved rack.
std::optional<SavedRack> rackFromJson(const nlohmann::json& j, std::string& why);

/// Writes the file atomically, making its directory; false with `why` on failure.
bool saveRack(const SavedRack& rack, const std::string& path, std::string& why);
/// Reads the file; nothing when there is none, or (with a logged warning) when it is bad.
std::optional<SavedRack> loadRack(const std::string& path);
/// Removes the file if there is one (a finished rack has nothing to resume).
void forgetRack(const std::string& path);

/// A session at the saved position: the match's racks played again (or, for a rack alone, the
/// rack racked as it was), the turns replayed. Throws IllegalAction when a turn does not replay
/// or the match does not come back to the saved rack (a file from another version, edited by
/// hand).
void replayRack(GameSession& session, const SavedRack& rack);

}  // namespace nineball::window
