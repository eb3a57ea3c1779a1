#include "net/lockstep.hpp"

#include "io/snapshot_json.hpp"
#include "net/heal_check.hpp"
#include "nineball/table.hpp"

namespace nineball::net {

rules::Player seatOf(Side side) {
  return side == Side::Host ? rules::Player::A : rules::Player::B;
}

Lockstep::Lockstep(Side side, const MatchSetup& setup) : side_(side), setup_(setup) {}

bool Lockstep::localToMove(const Match& match) const {
  return settled() && !match.rack().over() && match.rack().shooter() == localSeat();
}

CheckedTurn Lockstep::localTurn(const TurnInput& turn, const Seat& player,
                                TurnMessage& message) const {
  message.index = turns_.size();
  message.turn = wireTurn(turn, player, setup_.game);
  std::string why;
  // The wire form reads back to the very turn sent; playing the read-back turn on this side
  // too keeps both sides on the same bits.
  const auto read_back = parseWireTurn(message.turn, setup_, why);
  return {read_back ? *read_back : turn, player};
}

std::optional<CheckedTurn> Lockstep::peerTurn(const TurnMessage& message, const Match& match,
                                              std::string& why) const {
  if (message.index != turns_.size()) {
    why = "turn " + std::to_string(message.index) + " arrived when turn " +
          std::to_string(turns_.size()) + " was due";
    return std::nullopt;
  }
  if (!settled()) {
    why = "a turn before the last one was agreed";
    return std::nullopt;
  }
  if (match.rack().over()) {
    why = "a turn after the rack was over";
    return std::nullopt;
  }
  if (match.rack().shooter() == localSeat()) {
    why = "a turn out of turn (it is this side's move)";
    return std::nullopt;
  }
  if (peer_player_ && seatName(message.turn.player) != seatName(*peer_player_)) {
    why = "a turn labelled " + seatName(message.turn.player) + " from a seat its hello said " +
          seatName(*peer_player_) + " plays";
    return std::nullopt;
  }
  const auto input = parseWireTurn(message.turn, setup_, why);
  if (!input) return std::nullopt;
  return CheckedTurn{*input, message.turn.player};
}

HashMessage Lockstep::played(const WireTurn& turn, const MatchSnapshot& after) {
  turns_.push_back(turn);
  hashes_.push_back(snapshotHash(after));
  healing_ = false;
  return {turns_.size() - 1, hashes_.back()};
}

std::optional<HashVerdict> Lockstep::peerHash(const HashMessage& message, std::string& why) {
  if (turns_.empty() || message.index != turns_.size() - 1) {
    why = "a hash of turn " + std::to_string(message.index) + ", which is not the last played";
    return std::nullopt;
  }
  if (settled()) {
    why = "a second hash of turn " + std::to_string(message.index);
    return std::nullopt;
  }
  if (side_ == Side::Joiner && healing_) {
    why = "a hash while the host's state was due";
    return std::nullopt;
  }
  if (message.hash == hashes_.back()) {
    agreed_ = turns_.size();
    healing_ = false;
    return HashVerdict::Agreed;
  }
  if (healing_) return HashVerdict::Unhealed;  // the host, after sending its state
  healing_ = true;
  if (side_ == Side::Joiner) host_hash_ = message.hash;
  return HashVerdict::Mismatch;
}

StateMessage Lockstep::healMessage(const MatchSnapshot& own) {
  ++heals_;
  return {turns_.size() - 1, io::snapshotToJson(own)};
}

std::optional<MatchSnapshot> Lockstep::healState(const StateMessage& message, const Match& match,
                                                 std::string& why) const {
  if (side_ != Side::Joiner || !healing_ || message.index + 1 != turns_.size()) {
    why = "a state that was not asked for";
    return std::nullopt;
  }
  const TableDef& t = match.world().table().def;
  const double bound = 0.5 * std::max(t.length, t.width) + 1.0;
  try {
    MatchSnapshot s = io::parseSnapshot(message.state, match.balls(), bound);
    if (const auto problem = healProblem(s, setup_, match, turns_.size())) {
      why = "a state the rack cannot be in (" + *problem + ")";
      return std::nullopt;
    }
    return s;
  } catch (const io::ParseError& e) {
    why = "a state that does not fit the rack (" + e.message + ")";
    return std::nullopt;
  }
}

HashMessage Lockstep::healed(const MatchSnapshot& restored, bool& took) {
  ++heals_;
  hashes_.back() = snapshotHash(restored);
  took = hashes_.back() == host_hash_;
  if (took) agreed_ = turns_.size();
  healing_ = false;
  return {turns_.size() - 1, hashes_.back()};
}

std::optional<HashMessage> Lockstep::lastHash() const {
  if (turns_.empty()) return std::nullopt;
  return HashMessage{turns_.size() - 1, hashes_.back()};
}

void Lockstep::rejoined() {
  agreed_ = turns_.empty() ? 0 : turns_.size() - 1;
  healing_ = false;
}

void Lockstep::adopt(const std::vector<WireTurn>& turns, const std::vector<std::uint64_t>& hashes) {
  turns_ = turns;
  hashes_ = hashes;
  rejoined();
}

}  // namespace nineball::net
