#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "net/lockstep.hpp"
#include "net/protocol.hpp"
#include "net/rack_allowance.hpp"

// The lockstep of a rack written once for both drivers (the window's OnlinePlay and the
// headless `nineball online`): what every message from the peer means for the rack, the heal
// and its limit, the count of lost links, and the belief in a `bye`. It sends what the protocol
// answers itself (hashes, the state whole, the bye of an end) and reports the rest as values;
// the driver owns the table, plays the turns and says what the player sees.
namespace nineball::net {

/// The table a driver plays the rack on, as the lockstep needs it.
class RackTable {
 public:
  virtual const Match& match() const = 0;
  /// Sets the table to `state` (a heal); throws std::exception when it cannot.
  virtual void restore(const MatchSnapshot& state) = 0;

 protected:
  ~RackTable() = default;
};

/// The peer's turn, checked: the driver plays it on its table, then calls played().
struct TurnReceived {
  CheckedTurn turn;
  TurnMessage message;
};
/// Both sides agree on turn `index`.
struct TurnAgreed {
  std::size_t index;
};
/// The two tables differed after turn `index`: the host has sent its state whole (and
/// restored it too); the joiner waits for it.
struct HealStarted {
  std::size_t index;
};
/// The joiner: the host's state after turn `index` restored, and now both agree.
struct Healed {
  std::size_t index;
};
/// The peer said bye; `finished` only where its rack can end (else it is a quit).
struct ByeHeard {
  std::string reason;
  bool finished = false;
};
/// The peer's aim (the driver shows it while the peer's move is due).
struct AimHeard {
  Aim aim;
};
/// The peer offers a rematch.
struct RematchHeard {};
/// The host: a newcomer's hello (the peer linked it); welcome() it or refuse it.
struct HelloHeard {
  Hello hello;
};
/// The joiner: the host's welcome; the driver replays its turns and calls welcomed().
struct WelcomeHeard {
  Welcome welcome;
};
/// The peer refused this side (`busy`: try again later).
struct RefuseHeard {
  std::string reason;
  bool busy = false;
};
/// The peer sent `what` (a turn, a hash, a state ...) this rack refuses, `why`: the driver
/// refuses and drops it (the window ends the game; `nineball online` waits for a rejoin).
struct PeerBroke {
  std::string what;
  std::string why;  ///< whole: "turn 3 arrived when turn 1 was due", "a hello at the wrong time"
  bool out_of_place = false;  ///< a message this moment does not take (why says so)
};
/// The rack ends here; the bye the protocol owes (if any) has been sent.
struct LockstepEnded {
  enum class Why {
    Unhealed,      ///< the tables still differed after the heal
    HealsSpent,    ///< one mismatch more than the rack may heal
    RejoinsSpent,  ///< one lost link more than the rack may take
  };
  Why why;
  std::size_t index = 0;  ///< the turn (Unhealed, HealsSpent)
  int count = 0;          ///< heals (HealsSpent) or the most rejoins (RejoinsSpent)
  std::string reason;     ///< in `nineball online`'s words
};
using LockstepEvent =
    std::variant<TurnReceived, TurnAgreed, HealStarted, Healed, ByeHeard, AimHeard, RematchHeard,
                 HelloHeard, WelcomeHeard, RefuseHeard, PeerBroke, LockstepEnded>;

class LockstepDriver {
 public:
  using Send = std::function<void(const Message&)>;

  LockstepDriver(Side side, Send send, int most_heals = kMostHealsPerRack,
                 int most_rejoins = kMostRejoinsPerRack);

  Side side() const { return side_; }
  /// The rack's lockstep; null before the rack began.
  const Lockstep* lockstep() const { return lockstep_ ? &*lockstep_ : nullptr; }
  bool begun() const { return lockstep_.has_value(); }
  bool settled() const { return lockstep_ && lockstep_->settled(); }
  int heals() const { return lockstep_ ? lockstep_->heals() : 0; }
  const RackAllowance& allowance() const { return allowance_; }

  /// A new rack on this table (the host's first, or a rematch: its lost links count anew).
  void newRack(const MatchSetup& setup);
  /// Who plays the peer's seat, as its hello said (kept for a rematch's rack).
  void setPeerPlayer(const Seat& player);
  /// Tests: called on a heal's state before the joiner restores it.
  void setOnHeal(std::function<void(MatchSnapshot&)> on_heal) { on_heal_ = std::move(on_heal); }

  /// What a message from the peer means for the rack on `table` (null before the rack).
  /// `handshaking`: the link is new and the hello / welcome is under way.
  std::vector<LockstepEvent> hear(const Message& message, RackTable* table, bool handshaking);

  /// This side's turn: the message to send and the input to play (as read back from the wire).
  CheckedTurn localTurn(const TurnInput& turn, const Seat& player, TurnMessage& message) const;
  /// A turn (either side's) has been played on the table: its hash goes out.
  void played(const WireTurn& turn, const MatchSnapshot& after);
  /// True when it is this side's move in `match` (and the last turn is settled).
  bool localToMove(const Match& match) const;

  /// The host, its newcomer let in: the welcome goes out (with the rack so far), and, when the
  /// rack is under way, the last turn's hash to be agreed again. `setup` starts the rack if
  /// none is on. The peer's handshake must be marked done by the caller first.
  void welcome(const Hello& hello, const MatchSetup& setup, const std::string& name,
               const nlohmann::json& match, const Race& race, const std::string& token);
  /// The joiner, its welcome's turns replayed on a fresh table to `hashes`: the rack as the
  /// host has it, and the last turn's hash to be agreed again.
  void welcomed(const MatchSetup& setup, const std::vector<WireTurn>& turns,
                const std::vector<std::uint64_t>& hashes);

  /// The link with the peer was lost (or replaced by its new one) during the rack: counted
  /// once per link; an end when it is one loss more than the rack may take.
  std::optional<LockstepEnded> linkLost(const std::string& reason);
  /// The host: a newcomer came back to a rack whose link was not seen lost (its new link
  /// replaced the old one): counted as that loss.
  std::optional<LockstepEnded> rejoinHeard();

 private:
  std::vector<LockstepEvent> hearInRack(const Message& message, RackTable& table);
  std::vector<LockstepEvent> onHash(const HashMessage& message, RackTable& table);
  std::vector<LockstepEvent> onState(const StateMessage& message, RackTable& table);
  bool byeBelieved(const Match& match) const;

  Side side_;
  Send send_;
  std::optional<Lockstep> lockstep_;
  std::optional<Seat> peer_player_;
  RackAllowance allowance_;
  bool loss_counted_ = false;  // the current link's loss has been counted
  std::function<void(MatchSnapshot&)> on_heal_;
};

}  // namespace nineball::net
