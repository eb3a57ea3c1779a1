#include "rules/eight_ball.hpp"

#include "rules/ball_list.hpp"
#include "rules/rotation_fouls.hpp"
#include "rules/wpa_break.hpp"

namespace nineball::rules {
namespace {

constexpr int kEight = 8;

bool onTheEight(const std::vector<int>& first_balls) {
  return first_balls.size() == 1 && first_balls.front() == kEight;
}

Foul shotFoul(const ShotSummary& shot, const std::vector<int>& first_balls,
              const std::vector<int>& pocketed) {
  // WPA General Rules, "Balls Jumped off the Table" and "Cue Ball Scratch or off the Table".
  if (!shot.off_table.empty()) return Foul::JumpedBall;
  if (shot.cue_pocketed) return Foul::Scratch;
  if (!shot.first_contact) return Foul::NoContact;
  if (!contains(first_balls, *shot.first_contact)) return Foul::WrongGroupFirst;
  if (pocketed.empty() && !shot.rail_after_contact) return Foul::NoRail;
  return Foul::None;
}

// Pocketing the 8: a win only when the group was cleared before the shot, nothing else went
// wrong and it dropped where it was called. Otherwise the foul that loses the rack.
Foul eightDownFoul(Foul foul, bool on_eight, const ShotSummary& shot) {
  if (foul != Foul::None) return foul;
  if (!on_eight) return Foul::EightEarly;
  if (!shot.call || shot.call->ball != kEight) return Foul::NoCall;
  if (shot.pocketOf(kEight) != shot.call->pocket) return Foul::WrongPocket;
  return Foul::None;
}

// The group an open table's first legal pot gives the shooter: the called ball's when it
// dropped, else the first ball's to drop.
std::optional<Group> groupChosen(const ShotSummary& shot, const std::vector<int>& pocketed) {
  if (shot.call && contains(pocketed, shot.call->ball)) {
    if (auto g = groupOf(shot.call->ball)) return g;
  }
  for (int b : pocketed) {
    if (auto g = groupOf(b)) return g;
  }
  return std::nullopt;
}

void assign(Groups& groups, Player p, Group g) {
  const Group rest = g == Group::Solids ? Group::Stripes : Group::Solids;
  groups.a = p == Player::A ? g : rest;
  groups.b = p == Player::A ? rest : g;
}

}  // namespace

std::vector<int> EightBallRules::legalFirstBalls(const RackState& s) const {
  std::vector<int> balls;
  const std::optional<Group> mine = s.groups.of(s.shooter);
  for (int b : s.on_table) {
    // On the break any ball; on an open table any but the 8; else the shooter's group.
    if (s.break_next || (mine ? groupOf(b) == mine : b != kEight)) balls.push_back(b);
  }
  if (balls.empty() && s.has(kEight)) balls.push_back(kEight);
  return balls;
}

bool EightBallRules::callRequired(const RackState& s) const {
  return !s.break_next && onTheEight(legalFirstBalls(s));
}

Verdict EightBallRules::judgeBreak(RackState& s, const ShotSummary& shot) const {
  Verdict v;
  v.shooter = s.shooter;
  v.pocketed = newlyPocketed(s.on_table, shot.pocketed);
  if (v.pocketed.empty() && shot.object_balls_to_rail < kBreakBallsToRail) {
    // Not a foul but not a break either: the opponent chooses. A scratch on it still hands
    // over the cue ball.
    v.foul = Foul::BadBreak;
    v.next = other(s.shooter);
    v.decision = Decision::RerackOrPlayOn;
    v.ball_in_hand = shot.cue_pocketed;
    return v;
  }
  std::vector<int> stay_down = v.pocketed;
  if (contains(v.pocketed, kEight)) {
    v.to_spot.push_back(kEight);
    erase(stay_down, kEight);
  }
  s.remove(stay_down);
  // Jumped on the break: a foul, and the balls are spotted (the 8 as when pocketed).
  for (int b : jumpedObjectBalls(shot, kCueBall)) {
    if (s.has(b)) v.to_spot.push_back(b);
  }
  if (!shot.off_table.empty()) {
    v.foul = Foul::JumpedBall;
    v.next = other(s.shooter);
    v.ball_in_hand = true;
  } else if (shot.cue_pocketed) {
    v.foul = Foul::Scratch;
    v.next = other(s.shooter);
    v.ball_in_hand = true;
  } else {
    v.next = v.pocketed.empty() ? other(s.shooter) : s.shooter;
  }
  return v;
}

Verdict EightBallRules::judge(RackState& s, const ShotSummary& shot, bool) const {
  if (s.break_next) return judgeBreak(s, shot);
  Verdict v;
  v.shooter = s.shooter;
  v.pocketed = newlyPocketed(s.on_table, shot.pocketed);
  const std::vector<int> first_balls = legalFirstBalls(s);
  const bool on_eight = onTheEight(first_balls);
  v.foul = shotFoul(shot, first_balls, v.pocketed);
  s.remove(v.pocketed);
  // WPA eight-ball: the 8 jumped off the table loses the rack; other jumped object balls are
  // spotted.
  const std::vector<int> jumped = jumpedObjectBalls(shot, kCueBall);
  if (contains(jumped, kEight)) {
    v.winner = other(s.shooter);
    v.next = *v.winner;
    return v;
  }
  for (int b : jumped) {
    if (s.has(b)) v.to_spot.push_back(b);
  }

  if (contains(v.pocketed, kEight)) {
    v.foul = eightDownFoul(v.foul, on_eight, shot);
    v.winner = v.legal() ? s.shooter : other(s.shooter);
    v.next = *v.winner;
    return v;
  }
  if (!v.legal()) {
    v.next = other(s.shooter);
    v.ball_in_hand = true;
    return v;
  }
  if (s.groups.open()) {
    if (auto g = groupChosen(shot, v.pocketed)) assign(s.groups, s.shooter, *g);
  }
  const std::optional<Group> mine = s.groups.of(s.shooter);
  bool own_ball_down = false;
  for (int b : v.pocketed) own_ball_down = own_ball_down || (mine && groupOf(b) == mine);
  v.next = own_ball_down ? s.shooter : other(s.shooter);
  return v;
}

}  // namespace nineball::rules
