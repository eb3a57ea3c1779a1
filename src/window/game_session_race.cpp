// The session's racks as a match: who breaks each, the racks won, the match's turns, and a
// script's turns carried on into the next rack of a race.
#include <utility>

#include "common/log.hpp"
#include "window/game_session.hpp"

namespace nineball::window {

int GameSession::seatOf(rules::Player p) const {
  // The rack's breaker is its Player A (online, the host is always A).
  const int a = fixed_seats_ ? 0 : breaker_seat_;
  return p == rules::Player::A ? a : 1 - a;
}

int GameSession::breakerOfRack() {
  if (const std::optional<int> forced = std::exchange(resumed_breaker_, std::nullopt)) {
    return *forced;
  }
  std::optional<rules::Player> last;
  if (last_winner_seat_) last = *last_winner_seat_ == 0 ? rules::Player::A : rules::Player::B;
  return rackOpener(breaks_, rack_ - match_first_rack_, last) == rules::Player::A ? 0 : 1;
}

std::optional<int> GameSession::matchWinner() const {
  const int needed = framesToWinMatch(best_of_);
  for (int seat = 0; seat < 2; ++seat) {
    if (needed > 0 && racks_won_[seat] >= needed) return seat;
  }
  return std::nullopt;
}

std::uint64_t GameSession::matchSeed() const {
  return setup_.seed + static_cast<std::uint64_t>(match_first_rack_);
}

void GameSession::rematch() {
  if (practice_) return;
  if (relay_.rematch && !relay_.rematch()) return;
  if (matchWinner()) {
    startMatchAt(rack_ + 1);
    return;
  }
  ++rack_;
  startRack();
}

void GameSession::startMatchAt(int first_rack) {
  rack_ = std::max(0, first_rack);
  match_first_rack_ = rack_;
  racks_won_[0] = racks_won_[1] = 0;
  last_winner_seat_.reset();
  match_turns_.clear();
  match_known_ = true;
  startRack();
}

void GameSession::resumeRack(int rack_index, int racks_won0, int racks_won1,
                             std::optional<int> breaker_seat) {
  rack_ = std::max(0, rack_index);
  racks_won_[0] = racks_won0;
  racks_won_[1] = racks_won1;
  // Saves from before the break order was kept: the seats took turns from the first rack.
  resumed_breaker_ = breaker_seat.value_or(rack_ % 2);
  match_turns_.clear();
  match_known_ = false;
  startRack();
}

void GameSession::nextRackForScript() {
  if (phase_ != Phase::GameOver || practice_) return;
  if (best_of_ == 0) throw IllegalAction("the game is over");
  if (matchWinner()) throw IllegalAction("the match is over");
  if (relay_.rematch) throw IllegalAction("the next rack waits for both players");
  ++rack_;
  startRack();
  logger("game")->info("the script plays on into rack {}", rackNumber());
}

}  // namespace nineball::window
