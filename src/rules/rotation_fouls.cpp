#include "rules/rotation_fouls.hpp"

#include <algorithm>

#include "rules/ball_list.hpp"
#include "rules/wpa_break.hpp"

namespace nineball::rules {
namespace {

constexpr int kFoulsToLose = 3;

}  // namespace

int lowestOnTable(const RackState& s) {
  return s.on_table.empty() ? 0 : s.on_table.front();
}

Foul rotationFoul(const RackState& s, const ShotSummary& shot, const std::vector<int>& pocketed,
                  int on, bool push_out) {
  // WPA General Rules, "Balls Jumped off the Table" and "Cue Ball Scratch or off the Table".
  if (!shot.off_table.empty()) return Foul::JumpedBall;
  if (shot.cue_pocketed) return Foul::Scratch;
  if (s.break_next) {
    if (shot.first_contact != on) return Foul::BadBreak;
    if (pocketed.empty() && shot.object_balls_to_rail < kBreakBallsToRail) return Foul::BadBreak;
    return Foul::None;
  }
  if (push_out) return Foul::None;
  if (!shot.first_contact) return Foul::NoContact;
  if (*shot.first_contact != on) return Foul::WrongBallFirst;
  if (pocketed.empty() && !shot.rail_after_contact) return Foul::NoRail;
  return Foul::None;
}

void countFoul(RackState& s, Verdict& v) {
  if (!v.legal()) {
    if (++s.foulCount(s.shooter) >= kFoulsToLose) v.foul = Foul::ThreeFouls;
  } else {
    s.foulCount(s.shooter) = 0;
  }
}

std::vector<int> jumpedObjectBalls(const ShotSummary& shot, int cue) {
  std::vector<int> balls;
  for (int b : shot.off_table) {
    if (b != cue) balls.push_back(b);
  }
  return balls;
}

void jumpedStayOff(RackState& s, Verdict& v, const ShotSummary& shot, int game_ball) {
  for (int b : jumpedObjectBalls(shot, kCueBall)) {
    if (!s.has(b)) continue;
    if (b == game_ball) {
      v.to_spot.push_back(b);
    } else {
      s.remove({b});
    }
  }
}

int rotationGameBall(const std::vector<int>& on_table, int wanted) {
  if (contains(on_table, wanted) || on_table.empty()) return wanted;
  return *std::max_element(on_table.begin(), on_table.end());
}

}  // namespace nineball::rules
