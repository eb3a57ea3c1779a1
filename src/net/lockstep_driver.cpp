#include "net/lockstep_driver.hpp"

#include <exception>

#include "common/log.hpp"
#include "net/handshake.hpp"
#include "net/host_gate.hpp"

namespace nineball::net {
namespace {

PeerBroke outOfPlace(const std::string& what) {
  return {what, what + " at the wrong time", true};
}

// The words of an end, in `nineball online`'s terms (the peer reads the bye's).
std::string unhealedReason(std::size_t index) {
  return "the peers fell out of step after turn " + std::to_string(index) +
         " and the host's state did not heal it";
}

std::string healsSpentReason(std::size_t index, int heals) {
  return "out of step after turn " + std::to_string(index) + ", healed " + std::to_string(heals) +
         " times in this rack already";
}

}  // namespace

LockstepDriver::LockstepDriver(Side side, Send send, int most_heals, int most_rejoins)
    : side_(side), send_(std::move(send)), allowance_(most_heals, most_rejoins) {}

void LockstepDriver::newRack(const MatchSetup& setup) {
  lockstep_.emplace(side_, setup);
  if (peer_player_) lockstep_->setPeerPlayer(*peer_player_);
  allowance_.newRack();
}

void LockstepDriver::setPeerPlayer(const Seat& player) {
  peer_player_ = player;
  if (lockstep_) lockstep_->setPeerPlayer(player);
}

// --- what the peer says ---

std::vector<LockstepEvent> LockstepDriver::hear(const Message& message, RackTable* table,
                                                bool handshaking) {
  if (const auto* hello = std::get_if<Hello>(&message)) {
    if (side_ != Side::Host || !handshaking) return {outOfPlace("a hello")};
    return {HelloHeard{*hello}};
  }
  if (const auto* welcome = std::get_if<Welcome>(&message)) {
    if (side_ != Side::Joiner || !handshaking) {
      return {outOfPlace("a welcome")};
    }
    return {WelcomeHeard{*welcome}};
  }
  if (const auto* refuse = std::get_if<Refuse>(&message)) {
    return {RefuseHeard{refuse->reason, isBusyRefusal(refuse->reason)}};
  }
  if (const auto* bye = std::get_if<Bye>(&message)) {
    const bool finished = bye->finished && table && byeBelieved(table->match());
    return {ByeHeard{bye->reason, finished}};
  }
  if (!lockstep_ || !table || handshaking) {
    return {outOfPlace(std::holds_alternative<TurnMessage>(message)    ? "a turn"
                       : std::holds_alternative<HashMessage>(message)  ? "a state hash"
                       : std::holds_alternative<StateMessage>(message) ? "a state"
                       : std::holds_alternative<Aim>(message)          ? "an aim"
                                                                       : "a rematch")};
  }
  return hearInRack(message, *table);
}

std::vector<LockstepEvent> LockstepDriver::hearInRack(const Message& message, RackTable& table) {
  if (const auto* turn = std::get_if<TurnMessage>(&message)) {
    std::string why;
    auto checked = lockstep_->peerTurn(*turn, table.match(), why);
    if (!checked) return {PeerBroke{"a turn", why}};
    return {TurnReceived{std::move(*checked), *turn}};
  }
  if (const auto* hash = std::get_if<HashMessage>(&message)) return onHash(*hash, table);
  if (const auto* state = std::get_if<StateMessage>(&message)) return onState(*state, table);
  if (const auto* aim = std::get_if<Aim>(&message)) return {AimHeard{*aim}};
  if (std::holds_alternative<Rematch>(message)) return {RematchHeard{}};
  return {};  // every message is one of the above
}

// A mismatch is healed by the host's state, within the rack's allowance; a mismatch after the
// heal (the host's verdict) ends the rack.
std::vector<LockstepEvent> LockstepDriver::onHash(const HashMessage& message, RackTable& table) {
  std::string why;
  const std::optional<HashVerdict> verdict = lockstep_->peerHash(message, why);
  if (!verdict) return {PeerBroke{"a state hash", why}};
  const std::size_t index = message.index;
  switch (*verdict) {
    case HashVerdict::Waiting:
      return {};
    case HashVerdict::Agreed:
      return {TurnAgreed{index}};
    case HashVerdict::Unhealed:
      send_(Bye{"out of step after turn " + std::to_string(index) + ", and the heal did not take",
                false});
      return {LockstepEnded{LockstepEnded::Why::Unhealed, index, heals(), unhealedReason(index)}};
    case HashVerdict::Mismatch:
      break;
  }
  if (allowance_.healsSpent(lockstep_->heals())) {
    // Disagreeing, dropping and rejoining must not keep two sides healing for ever.
    const std::string reason = healsSpentReason(index, lockstep_->heals());
    send_(Bye{reason, false});
    return {LockstepEnded{LockstepEnded::Why::HealsSpent, index, lockstep_->heals(), reason}};
  }
  if (side_ == Side::Host) {
    logger("net")->warn("out of step after turn {}: sending this side's state whole", index);
    const MatchSnapshot own = table.match().snapshot();
    send_(lockstep_->healMessage(own));
    table.restore(own);
  } else {
    logger("net")->warn("out of step after turn {}: waiting for the host's state", index);
  }
  return {HealStarted{index}};
}

std::vector<LockstepEvent> LockstepDriver::onState(const StateMessage& message, RackTable& table) {
  std::string why;
  std::optional<MatchSnapshot> state = lockstep_->healState(message, table.match(), why);
  if (!state) return {PeerBroke{"a state", why}};
  if (on_heal_) on_heal_(*state);
  try {
    table.restore(*state);
  } catch (const std::exception& e) {
    return {PeerBroke{"a state", std::string("a state that does not restore: ") + e.what()}};
  }
  bool took = false;
  send_(lockstep_->healed(table.match().snapshot(), took));
  if (!took) {
    return {LockstepEnded{LockstepEnded::Why::Unhealed, message.index, heals(),
                          unhealedReason(message.index)}};
  }
  logger("net")->warn("took the host's state after turn {}", message.index);
  return {Healed{message.index}};
}

// A peer's "finished" is believed only where a rack can end for it: the rack is over here
// too (or at its length), or the peer's own script ran out at its move.
bool LockstepDriver::byeBelieved(const Match& match) const {
  if (match.rack().over()) return true;
  if (!lockstep_) return false;
  if (lockstep_->turns().size() >= kMostTurns) return true;
  return lockstep_->settled() && match.rack().shooter() != lockstep_->localSeat();
}

// --- this side ---

CheckedTurn LockstepDriver::localTurn(const TurnInput& turn, const Seat& player,
                                      TurnMessage& message) const {
  return lockstep_->localTurn(turn, player, message);
}

void LockstepDriver::played(const WireTurn& turn, const MatchSnapshot& after) {
  send_(lockstep_->played(turn, after));
}

bool LockstepDriver::localToMove(const Match& match) const {
  return lockstep_ && lockstep_->localToMove(match);
}

// --- the handshake and lost links ---

void LockstepDriver::welcome(const Hello& hello, const MatchSetup& setup, const std::string& name,
                             const nlohmann::json& match, const Race& race,
                             const std::string& token) {
  if (!lockstep_) newRack(setup);
  setPeerPlayer(hello.player);
  send_(welcomeFrom(name, match, race, *lockstep_, token));
  lockstep_->rejoined();
  if (const auto h = lockstep_->lastHash()) send_(*h);
  loss_counted_ = false;
}

void LockstepDriver::welcomed(const MatchSetup& setup, const std::vector<WireTurn>& turns,
                              const std::vector<std::uint64_t>& hashes) {
  lockstep_.emplace(side_, setup);
  lockstep_->adopt(turns, hashes);
  if (const auto h = lockstep_->lastHash()) send_(*h);
  loss_counted_ = false;
}

std::optional<LockstepEnded> LockstepDriver::linkLost(const std::string& reason) {
  if (!lockstep_ || loss_counted_) return std::nullopt;
  loss_counted_ = true;
  if (allowance_.takeRejoin()) return std::nullopt;
  const int most = allowance_.mostRejoins();
  return LockstepEnded{LockstepEnded::Why::RejoinsSpent, 0, most,
                       "the link was lost (" + reason + ") more than " + std::to_string(most) +
                           " times in this rack"};
}

std::optional<LockstepEnded> LockstepDriver::rejoinHeard() {
  return linkLost("the other player connected again");
}

}  // namespace nineball::net
