#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "net/protocol.hpp"
#include "nineball/match.hpp"

// One rack played in lockstep by two nineballs, without the sockets: the turns and hashes so
// far, what may be played now, the checks on what the peer sends, the heal. The window and
// `nineball online` both drive a Match through it, so they speak the same protocol.
namespace nineball::net {

/// Either side of the table.
enum class Side { Host, Joiner };

/// The seat a side plays: the host A, the joiner B.
rules::Player seatOf(Side side);

/// What a turn checked by Lockstep gives the driver to play.
struct CheckedTurn {
  TurnInput input;  ///< as both sides play it (the wire's exact form)
  Seat player;      ///< who chose it
};

/// How two hashes of one turn compared.
enum class HashVerdict {
  Waiting,   ///< one of the two is not known yet
  Agreed,    ///< both sides have the same state
  Mismatch,  ///< they differ: the host sends its state whole (heal)
  Unhealed,  ///< they differed, the state was sent, and they still differ: out of step
};

class Lockstep {
 public:
  Lockstep(Side side, const MatchSetup& setup);

  Side side() const { return side_; }
  rules::Player localSeat() const { return seatOf(side_); }
  /// The turns of the rack so far, as sent, and the state hash this side found after each.
  const std::vector<WireTurn>& turns() const { return turns_; }
  const std::vector<std::uint64_t>& hashes() const { return hashes_; }
  /// Both sides agree on every turn so far: the next may be played.
  bool settled() const { return agreed_ == turns_.size(); }
  /// True when it is this side's move in `match` (and the last turn is settled).
  bool localToMove(const Match& match) const;

  /// A turn this side plays: its exact wire form, the message to send, and the input to play.
  CheckedTurn localTurn(const TurnInput& turn, const Seat& player, TurnMessage& message) const;
  /// A turn the peer sent: checked for its index, its turn (the peer's move, the last turn
  /// settled) and its fields; nothing, with `why`, when refused.
  std::optional<CheckedTurn> peerTurn(const TurnMessage& message, const Match& match,
                                      std::string& why) const;
  /// Records a turn played (by either side) and the state it left: the hash message to send.
  HashMessage played(const WireTurn& turn, const MatchSnapshot& after);

  /// The peer's hash of turn `index`; Error (nothing, with `why`) for a turn not played.
  std::optional<HashVerdict> peerHash(const HashMessage& message, std::string& why);
  /// The host: the state to send whole after a mismatch (its own state, which it restores too).
  StateMessage healMessage(const MatchSnapshot& own);
  /// The joiner: a state the host sent after a mismatch, checked against `match` (balls, ranges);
  /// nothing, with `why`, when refused. The caller restores it and calls healed().
  std::optional<MatchSnapshot> healState(const StateMessage& message, const Match& match,
                                         std::string& why) const;
  /// The joiner after restoring a healed state: its hash message (sent again for the turn);
  /// `took` says whether it now equals the host's.
  HashMessage healed(const MatchSnapshot& restored, bool& took);
  /// Heals so far in this rack.
  int heals() const { return heals_; }
  /// Who plays the peer's seat, as its hello said: a turn labelled otherwise is refused (a
  /// person's turn cannot pass for the computer's). Unset: any label.
  void setPeerPlayer(const Seat& player) { peer_player_ = player; }

  /// The hash of the last turn again, after a rejoin (nothing before the first turn).
  std::optional<HashMessage> lastHash() const;
  /// After a rejoin: every turn but the last is taken as agreed; the two sides exchange the
  /// last one's hash again (lastHash()).
  void rejoined();
  /// The joiner's rejoin: the turns the host sent (replayed by the caller) and the hashes this
  /// side found replaying them become the record; then rejoined().
  void adopt(const std::vector<WireTurn>& turns, const std::vector<std::uint64_t>& hashes);

 private:
  Side side_;
  MatchSetup setup_;
  std::vector<WireTurn> turns_;
  std::vector<std::uint64_t> hashes_;
  std::vector<std::optional<std::uint64_t>> peer_hashes_;
  std::size_t agreed_ = 0;
  bool healing_ = false;         // a mismatch is being healed (the index is the last turn)
  std::uint64_t host_hash_ = 0;  // the joiner: the host's hash of the turn being healed
  int heals_ = 0;
  std::optional<Seat> peer_player_;
};

}  // namespace nineball::net
