#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "io/match_json.hpp"
#include "net/clock.hpp"
#include "net/connection.hpp"
#include "net/host_gate.hpp"
#include "net/lockstep.hpp"
#include "net/rack_allowance.hpp"

// One rack over the network without a window: `nineball online`. Each side takes its own
// seat's turns from its match script (or plays it as the computer), both play every turn,
// and the result is `nineball match`'s for the whole rack plus the state hash after each turn.
namespace nineball::net {

struct OnlineRackOptions {
  Side side = Side::Host;
  /// Host: the port to listen on (address.port). Joiner: where the host is.
  Address address;
  /// This side's script: its turns, and in "players" whether the computer plays its seat. The
  /// host's setup ("game", "rules", "seed", ...) is the match; the joiner's setup is ignored.
  io::MatchScript script;
  /// Host: the script's setup as JSON (matchPart), what the joiner is sent.
  nlohmann::json match;
  std::string name = "Player";
  /// Host: the join code every hello must carry (made at random when empty). Joiner: the code
  /// sent.
  std::string code;
  /// Joiner: the seat token of an earlier welcome, to take the seat back (a new process).
  std::string seat_token;
  /// Joiner: called with the seat token each welcome hands out (to keep it for a restart).
  std::function<void(const std::string&)> on_seat_token;
  double wait_s = 300.0;    ///< host: how long to wait for the joiner
  double rejoin_s = 60.0;   ///< a lost link: how long to wait for (or keep trying) a rejoin
  double connect_s = 10.0;  ///< joiner: each attempt to connect
  /// How long the other player may take over a turn (while its link answers) before the rack
  /// is given up.
  double turn_s = 300.0;
  /// Heals and rejoins a rack may take; one more ends it (out of step, or the link lost).
  int most_heals = kMostHealsPerRack;
  int most_rejoins = kMostRejoinsPerRack;
  LinkLimits limits;
  GateLimits gate;
  /// What every timeout reads (tests: a fake clock); never null.
  const Clock* clock = &steadyClock();
  /// Raised (by Ctrl-C, say) to leave: the other side is told, and the rack ends.
  const std::atomic<bool>* quit = nullptr;
  /// Tests: called after each turn is played on this side (a test knocks a peer out of step).
  std::function<void(Match&, std::size_t turn)> after_turn;
  /// Tests: called on a heal's state before the joiner restores it.
  std::function<void(MatchSnapshot&)> on_heal;
  /// Tests: called when this side is about to send turn `index`; returning true drops the link
  /// instead (the joiner then rejoins).
  std::function<bool(std::size_t index)> drop_before_turn;
};

struct OnlineRackResult {
  enum class Outcome {
    InStep,     ///< the rack was played (won, a script out of turns, the turn limit)
    Partial,    ///< a shot stopped with balls still moving (as `nineball match`)
    OutOfStep,  ///< the two states differed and a heal did not make them agree
    Refused,    ///< the handshake refused the peer (another build), or the peer refused us
    BadTurn,    ///< this side's script turn was refused by the rules
    LinkLost,   ///< the peer left, stopped answering, misbehaved, or did not come back in time
    NoPeer,     ///< nobody joined, or nobody answered the join
    Quit,       ///< this side left (OnlineRackOptions::quit)
  };
  Outcome outcome = Outcome::InStep;
  std::string why;
  /// The result: `nineball match`'s document, "partial", and "hashes" (16 hex digits per turn).
  /// Set whenever the rack began.
  nlohmann::ordered_json doc;
  int heals = 0;
};

/// Plays the rack, blocking until it is over or the link fails.
OnlineRackResult playOnlineRack(const OnlineRackOptions& options);

}  // namespace nineball::net
