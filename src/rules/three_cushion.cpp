#include "rules/three_cushion.hpp"

#include <algorithm>

#include "rules/player_index.hpp"

namespace nineball::rules {
namespace {

constexpr int kCushionsForAPoint = 3;

// UMB art. 23: the starting cannon is played directly onto the red: the first thing the cue
// ball meets is the red, before any cushion or the other ball.
bool openedOnTheRed(const ShotSummary& shot) {
  return !shot.cue_touches.empty() && shot.cue_touches.front() == ThreeCushionRules::kRed &&
         shot.cue_cushions_before.front() == 0;
}

// The inning ends: the next player comes to the table, or the game ends.
void endInning(RackState& s, Verdict& v) {
  s.run = 0;
  s.inning_open = false;
  if (s.equalising) {
    // The other's last inning is over without reaching the distance: the opener has won.
    v.winner = Player::A;
    v.next = s.shooter;
    return;
  }
  v.next = other(s.shooter);
}

// The shooter has just reached the distance.
void reachedTheDistance(RackState& s, Verdict& v) {
  if (s.shooter == Player::A) {
    // Equal innings (UMB art. 29): the player who did not open plays one last inning.
    s.equalising = true;
    s.run = 0;
    s.inning_open = false;
    v.next = Player::B;
    return;
  }
  if (s.equalising) {
    v.draw = true;  // both reached the distance in as many innings
  } else {
    v.winner = Player::B;
  }
  v.next = s.shooter;
}

}  // namespace

std::vector<int> ThreeCushionRules::legalFirstBalls(const RackState& s) const {
  if (s.break_next) return {kRed};
  const int cue = cueBall(s);
  std::vector<int> balls;
  for (int b : {kWhite, kYellow, kRed}) {
    if (b != cue) balls.push_back(b);
  }
  return balls;
}

int ThreeCushionRules::ballOn(const RackState&) const {
  return kRed;
}

int ThreeCushionRules::cueBall(const RackState& s) const {
  return s.shooter == Player::A ? kWhite : kYellow;
}

int ThreeCushionRules::cushionsBeforeSecond(const ShotSummary& shot, int cue, bool& touched_both) {
  std::optional<int> first;
  for (std::size_t i = 0; i < shot.cue_touches.size(); ++i) {
    const int ball = shot.cue_touches[i];
    if (ball == cue) continue;
    if (!first) {
      first = ball;
    } else if (ball != *first) {
      touched_both = true;
      return shot.cue_cushions_before[i];
    }
  }
  touched_both = false;
  return shot.cue_cushions;
}

Verdict ThreeCushionRules::judge(RackState& s, const ShotSummary& shot, bool) const {
  Verdict v;
  v.shooter = s.shooter;
  if (!s.inning_open) {
    ++s.innings[playerIndex(s.shooter)];
    s.inning_open = true;
  }
  bool touched_both = false;
  v.cushions = cushionsBeforeSecond(shot, cueBall(s), touched_both);
  if (s.break_next && !openedOnTheRed(shot)) v.foul = Foul::WrongBallFirst;
  // UMB: a ball that leaves the table is a foul (no point, the inning ends); it is spotted.
  if (!shot.off_table.empty()) {
    v.foul = Foul::JumpedBall;
    v.to_spot = shot.off_table;
  }
  const bool point = v.legal() && !shot.miscue && touched_both && v.cushions >= kCushionsForAPoint;
  if (!point) {
    endInning(s, v);
    return v;
  }
  v.points[playerIndex(s.shooter)] = 1;
  ++s.run;
  int& best = s.high_run[playerIndex(s.shooter)];
  best = std::max(best, s.run);
  v.next = s.shooter;
  const int score = s.score[playerIndex(s.shooter)] + 1;  // the Rack adds v.points after judging
  if (s.target > 0 && score >= s.target) reachedTheDistance(s, v);
  return v;
}

}  // namespace nineball::rules
