#include "rules/nine_ball.hpp"

#include "rules/ball_list.hpp"
#include "rules/rotation_fouls.hpp"

namespace nineball::rules {
namespace {

constexpr int kNine = 9;

}  // namespace

std::vector<int> NineBallRules::legalFirstBalls(const RackState& s) const {
  if (s.on_table.empty()) return {};
  return {lowestOnTable(s)};
}

Verdict NineBallRules::judge(RackState& s, const ShotSummary& shot, bool push_out) const {
  return rules_ == RuleSet::Wpa ? judgeWpa(s, shot, push_out) : judgePaper(s, shot);
}

Verdict NineBallRules::judgeWpa(RackState& s, const ShotSummary& shot, bool push_out) const {
  Verdict v;
  v.shooter = s.shooter;
  v.pocketed = newlyPocketed(s.on_table, shot.pocketed);
  const int game_ball = rotationGameBall(s.on_table, kNine);
  const bool game_ball_down = contains(v.pocketed, game_ball);
  const bool was_break = s.break_next;
  v.foul = rotationFoul(s, shot, v.pocketed, lowestOnTable(s), push_out);
  countFoul(s, v);

  // The game ball goes back on the spot after a foul or a push-out; the rest stay down.
  std::vector<int> stay_down = v.pocketed;
  if (game_ball_down && (!v.legal() || push_out)) {
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
  } else if (push_out) {
    v.next = other(s.shooter);
    v.decision = Decision::PlayOrPass;
  } else if (game_ball_down) {
    v.winner = s.shooter;
    v.next = s.shooter;
  } else {
    v.next = v.pocketed.empty() ? other(s.shooter) : s.shooter;
  }
  v.push_out_available = was_break && !v.winner;
  return v;
}

Verdict NineBallRules::judgePaper(RackState& s, const ShotSummary& shot) const {
  Verdict v;
  v.shooter = s.shooter;
  v.pocketed = newlyPocketed(s.on_table, shot.pocketed);
  const int on = lowestOnTable(s);
  const bool nine_down = contains(v.pocketed, rotationGameBall(s.on_table, kNine));
  if (!shot.off_table.empty()) {
    v.foul = Foul::JumpedBall;
  } else if (shot.cue_pocketed) {
    v.foul = Foul::Scratch;
  } else if (!shot.first_contact) {
    v.foul = Foul::NoContact;
  } else if (*shot.first_contact != on) {
    v.foul = Foul::WrongBallFirst;
  }
  s.remove(v.pocketed);
  jumpedStayOff(s, v, shot, rotationGameBall(s.on_table, kNine));
  if (!v.legal()) {
    v.next = other(s.shooter);
    v.cue_to_head_spot = shot.cue_pocketed;
    if (nine_down) v.winner = other(s.shooter);
  } else if (nine_down || s.on_table.empty()) {
    v.winner = s.shooter;
    v.next = s.shooter;
  } else {
    v.next = v.pocketed.empty() ? other(s.shooter) : s.shooter;
  }
  return v;
}

}  // namespace nineball::rules
