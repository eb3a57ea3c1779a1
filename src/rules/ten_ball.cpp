#include "rules/ten_ball.hpp"

#include "rules/ball_list.hpp"
#include "rules/rotation_fouls.hpp"

namespace nineball::rules {
namespace {

constexpr int kTen = 10;

// Why a legal called shot's pot does not count: the called ball in another pocket, or some
// ball down that was not called. None when the called ball dropped where it was called (the
// other balls then count too) or nothing dropped.
Foul callBreach(const ShotSummary& shot, const std::vector<int>& pocketed) {
  if (pocketed.empty()) return Foul::None;
  if (!shot.call || !contains(pocketed, shot.call->ball)) return Foul::NoCall;
  if (shot.pocketOf(shot.call->ball) != shot.call->pocket) return Foul::WrongPocket;
  return Foul::None;
}

}  // namespace

std::vector<int> TenBallRules::legalFirstBalls(const RackState& s) const {
  if (s.on_table.empty()) return {};
  return {lowestOnTable(s)};
}

Verdict TenBallRules::judge(RackState& s, const ShotSummary& shot, bool push_out) const {
  Verdict v;
  v.shooter = s.shooter;
  v.pocketed = newlyPocketed(s.on_table, shot.pocketed);
  const int game_ball = rotationGameBall(s.on_table, kTen);
  const bool was_break = s.break_next;
  v.foul = rotationFoul(s, shot, v.pocketed, lowestOnTable(s), push_out);
  countFoul(s, v);
  const bool called_shot = !was_break && !push_out && v.legal();
  if (called_shot) v.call_breach = callBreach(shot, v.pocketed);
  const bool made_as_called = called_shot && !v.pocketed.empty() && v.call_breach == Foul::None;
  const bool game_ball_down = contains(v.pocketed, game_ball);
  // The 10 wins only when it was the ball called and made; otherwise it goes back up.
  const bool wins = game_ball_down && made_as_called && shot.call->ball == game_ball;

  std::vector<int> stay_down = v.pocketed;
  if (game_ball_down && !wins) {
    v.to_spot.push_back(game_ball);
    erase(stay_down, game_ball);
  }
  s.remove(stay_down);
  jumpedStayOff(s, v, shot, game_ball);

  if (v.foul == Foul::ThreeFouls) {
    v.winner = other(s.shooter);
    v.next = other(s.shooter);
  } else if (!v.legal()) {
    v.next = other(s.shooter);
    v.ball_in_hand = true;
  } else if (push_out || v.call_breach != Foul::None) {
    v.next = other(s.shooter);
    v.decision = Decision::PlayOrPass;
  } else if (wins) {
    v.winner = s.shooter;
    v.next = s.shooter;
  } else {
    const bool continues = was_break ? !v.pocketed.empty() : made_as_called;
    v.next = continues ? s.shooter : other(s.shooter);
  }
  v.push_out_available = was_break && !v.winner;
  return v;
}

}  // namespace nineball::rules
