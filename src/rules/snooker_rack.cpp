#include "nineball/snooker_rack.hpp"

#include <stdexcept>

namespace nineball::rules {

namespace {

int scoreOf(const RackState& s, Player p) {
  return s.score[p == Player::A ? 0 : 1];
}

}  // namespace

bool snookersRequired(const Rack& rack, Player p) {
  return scoreOf(rack.state(), other(p)) - scoreOf(rack.state(), p) > rack.pointsRemaining();
}

bool freeBall(const Rack& rack) {
  return rack.state().snooker.free_ball;
}

void stateFreeBall(Rack& rack, bool snookered) {
  RackState s = rack.state();
  const bool after_foul =
      s.decision == Decision::PlayOrPutBack || s.decision == Decision::PlayPutBackOrReplace;
  s.snooker.free_ball = after_foul && snookered && !rack.over();
  rack.setState(s);
}

bool respottedBlack(const Rack& rack) {
  return rack.state().snooker.respotted_black;
}

void replaceAfterMiss(Rack& rack) {
  RackState s = rack.state();
  if (s.decision != Decision::PlayPutBackOrReplace) {
    throw std::logic_error("no miss is waiting for the balls to be replaced");
  }
  s.decision = Decision::None;
  s.shooter = other(s.shooter);
  s.on_table = s.snooker.on_table_before;
  s.snooker.colour_on = s.snooker.colour_on_before;
  s.snooker.free_ball = s.snooker.free_ball_before;
  s.ball_in_hand = false;
  rack.setState(s);
}

}  // namespace nineball::rules
