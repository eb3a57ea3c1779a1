// WPBSA section 3 rules cited by number: 3.4 end of frame and the re-spotted black, 3.5-3.7
// play, spotting, 3.10 penalties, 3.12 free ball, 3.13 touching ball, 3.14 foul and a miss,
// 3.15 after a foul. Wording checked against the WPBSA text as quoted at
// https://f1-forum.fi/goto/post?id=249082 (free ball) and the SRA's test paper at
// https://snooker.org/Doc/test_paper.shtml (spotting, the opening stroke).
#include "rules/snooker.hpp"

#include <algorithm>

#include "nineball/ball.hpp"
#include "rules/ball_list.hpp"
#include "rules/player_index.hpp"
#include "rules/snooker_balls.hpp"

namespace nineball::rules {
namespace {

using snooker::isColour;
using snooker::isRed;
using snooker::kBlack;
using snooker::value;

// WPBSA 3.10: a foul costs the value of the ball on or of the highest ball involved, and never
// less than four points (the black's seven is the most).
constexpr int kLeastPenalty = 4;
constexpr int kMostPenalty = 7;
// WPBSA 3.14(h): the third miss in a row with a ball on in view loses the frame.
constexpr int kMissesToLose = 3;

// What the stroke was played at: the balls on, the nomination and what it is worth.
struct Aim {
  std::vector<int> on;  // the balls on, without the free ball
  int nominated = 0;    // the colour after a red, or the free ball (0: none)
  int free_ball = 0;    // the nominated free ball when it is not itself on (0: none)
  int value_on = 0;     // what the ball on is worth
  bool reds_on = false;
  bool colour_on = false;

  bool isOn(int b) const {
    if (colour_on) return b == nominated;
    return contains(on, b) || (free_ball != 0 && b == free_ball);
  }
  int valueOf(int b) const { return b == free_ball ? value_on : value(b); }
};

// The first ball hit, or a touching ball on when the cue ball played away from it (3.13: it
// counts as hit).
std::optional<int> firstHit(const ShotSummary& shot, const std::vector<int>& on) {
  if (shot.first_contact) return shot.first_contact;
  for (int b : shot.touching_before) {
    if (contains(on, b)) return b;
  }
  return std::nullopt;
}

int nominationOf(const RackState& s, const ShotSummary& shot, std::optional<int> first,
                 bool free_ball) {
  const bool call_valid =
      shot.call && s.has(shot.call->ball) && (free_ball || isColour(shot.call->ball));
  if (call_valid) return shot.call->ball;
  if (first && (free_ball || isColour(*first))) return *first;
  return 0;
}

Aim aimOf(const RackState& s, const ShotSummary& shot, bool free_ball) {
  Aim a;
  a.on = snooker::ballsOn(s);
  a.colour_on = s.snooker.colour_on;
  a.reds_on = !a.colour_on && !s.snooker.respotted_black && snooker::redsRemain(s);
  const std::optional<int> first = firstHit(shot, a.on);
  if (a.colour_on || free_ball) a.nominated = nominationOf(s, shot, first, free_ball);
  if (free_ball && a.nominated != 0 && !contains(a.on, a.nominated)) a.free_ball = a.nominated;
  if (a.colour_on) {
    a.value_on = value(a.nominated);
  } else if (a.reds_on) {
    a.value_on = 1;
  } else if (!a.on.empty()) {
    a.value_on = value(a.on.front());
  }
  return a;
}

Foul foulOf(const ShotSummary& shot, const Aim& aim, std::optional<int> first,
            const std::vector<int>& pocketed) {
  // WPBSA: forcing a ball off the table is a foul (the cue ball too: in hand in the D).
  if (!shot.off_table.empty()) return Foul::JumpedBall;
  if (shot.cue_pocketed) return Foul::Scratch;
  // Section 3, "Fouls": a jump shot (the cue ball over an object ball before it hits one).
  if (!shot.jumped_over.empty()) return Foul::JumpShot;
  if (!first) return Foul::NoContact;
  if (!aim.isOn(*first)) return Foul::WrongBallFirst;
  // 3.12: a free ball nominated must be hit first (a ball on potted after it still scores).
  if (aim.free_ball != 0 && *first != aim.free_ball) return Foul::WrongBallFirst;
  for (int b : pocketed) {
    if (!aim.isOn(b)) return Foul::PottedNotOn;
  }
  return Foul::None;
}

int penaltyOf(const Aim& aim, std::optional<int> first, const std::vector<int>& pocketed) {
  int worth = std::max(kLeastPenalty, aim.value_on);
  if (first) worth = std::max(worth, aim.valueOf(*first));
  if (aim.nominated != 0) worth = std::max(worth, aim.valueOf(aim.nominated));
  for (int b : pocketed) worth = std::max(worth, aim.valueOf(b));
  return std::min(worth, kMostPenalty);
}

// 3.14: a foul in which the cue ball does not first hit a ball on is a miss, unless the striker
// was snookered before the stroke or needed snookers then (docs/cli.md, "Snooker": nineball's
// form).
bool isMiss(const RackState& s, const ShotSummary& shot, Foul foul, bool needed_snookers) {
  if (foul != Foul::NoContact && foul != Foul::WrongBallFirst) return false;
  if (s.snooker.respotted_black) return false;  // the frame ends on the foul
  return !shot.snookered_before && !needed_snookers;
}

// The frame's last ball settled it (3.4): the higher score wins, level scores re-spot the black.
void blackDecides(RackState& s, Verdict& v) {
  const int a = s.score[0] + v.points[0];  // the Rack adds v.points after judging
  const int b = s.score[1] + v.points[1];
  if (a != b) {
    v.winner = a > b ? Player::A : Player::B;
    v.next = v.shooter;
    return;
  }
  // Level: the black goes back on its spot and the cue ball in hand in the D. WPBSA has the
  // players draw lots for who plays first; nineball gives it to the player who did not play
  // the last stroke (deterministic; docs/cli.md, "Snooker").
  v.black_respotted = true;
  s.snooker.respotted_black = true;
  if (!contains(v.to_spot, kBlack)) v.to_spot.push_back(kBlack);
  if (!s.has(kBlack)) s.on_table.push_back(kBlack);
  v.next = other(v.shooter);
  v.ball_in_hand = true;
  v.decision = Decision::None;
}

void judgeFoul(RackState& s, Verdict& v, const ShotSummary& shot, const Aim& aim,
               std::optional<int> first, bool needed_snookers) {
  const Player striker = s.shooter;
  // A ball forced off the table counts as one potted in the foul: its value in the penalty; a
  // red stays off, a colour is spotted (WPBSA).
  std::vector<int> gone = v.pocketed;
  for (int b : shot.off_table) {
    if (b != kCueBall && s.has(b) && !contains(gone, b)) gone.push_back(b);
  }
  v.points[playerIndex(other(striker))] = penaltyOf(aim, first, gone);
  v.miss = isMiss(s, shot, v.foul, needed_snookers);
  int& misses = s.snooker.misses[playerIndex(striker)];
  misses = v.miss ? misses + 1 : 0;
  // Reds potted on a foul stay down; every colour goes back on its spot (3.6).
  std::vector<int> stay_down;
  for (int b : gone) {
    (isRed(b) ? stay_down : v.to_spot).push_back(b);
  }
  const bool black_was_last = s.on_table.size() == 1 && s.has(kBlack);
  s.remove(stay_down);
  s.run = 0;
  s.snooker.colour_on = false;
  v.next = other(striker);
  v.ball_in_hand = shot.cue_pocketed;
  if (misses >= kMissesToLose) {
    v.foul = Foul::ThreeMisses;
    v.winner = other(striker);
    return;
  }
  if (s.snooker.respotted_black) {  // 3.4: the first foul on the re-spotted black loses
    v.winner = other(striker);
    return;
  }
  if (black_was_last) {  // 3.4: with the black alone the first score or foul ends the frame
    blackDecides(s, v);
    return;
  }
  v.decision = v.miss ? Decision::PlayPutBackOrReplace : Decision::PlayOrPutBack;
}

void judgeLegal(RackState& s, Verdict& v, const Aim& aim) {
  const Player striker = s.shooter;
  s.snooker.misses[playerIndex(striker)] = 0;
  int points = 0;
  std::vector<int> stay_down;
  bool black_down = false;  // the last ball, potted in its turn
  if (aim.reds_on) {
    // Each red potted counts, and a free ball potted with them counts as one more (3.12).
    for (int b : v.pocketed) {
      ++points;
      (isRed(b) ? stay_down : v.to_spot).push_back(b);
    }
    s.snooker.colour_on = points > 0;
  } else if (aim.colour_on) {
    // The colour after a red goes back on its spot, the one after the last red too (3.6).
    for (int b : v.pocketed) {
      points += value(b);
      v.to_spot.push_back(b);
    }
    s.snooker.colour_on = false;
  } else {
    // The colours in order: the ball on stays down; a free ball scores the ball on's value
    // and is spotted, once however many go down (3.12(e)).
    for (int b : v.pocketed) {
      if (b == aim.free_ball) {
        v.to_spot.push_back(b);
      } else {
        stay_down.push_back(b);
        if (b == kBlack) black_down = true;
      }
    }
    if (!v.pocketed.empty()) points = aim.value_on;
  }
  s.remove(stay_down);
  v.points[playerIndex(striker)] = points;
  if (points > 0) {
    s.run += points;
    int& best = s.high_run[playerIndex(striker)];
    best = std::max(best, s.run);
    v.next = striker;
  } else {
    s.run = 0;
    v.next = other(striker);
  }
  if (s.snooker.respotted_black && points > 0) {
    v.winner = striker;  // 3.4: the first score on the re-spotted black wins
  } else if (black_down) {
    s.run = 0;
    blackDecides(s, v);
  }
}

}  // namespace

std::vector<int> SnookerRules::legalFirstBalls(const RackState& s) const {
  if (s.snooker.free_ball) return s.on_table;  // any ball may be nominated (3.12)
  return snooker::ballsOn(s);
}

int SnookerRules::pointsRemaining(const RackState& s) const {
  return snooker::pointsRemaining(s);
}

Verdict SnookerRules::judge(RackState& s, const ShotSummary& shot, bool) const {
  Verdict v;
  v.shooter = s.shooter;
  SnookerState& sn = s.snooker;
  sn.on_table_before = s.on_table;
  sn.colour_on_before = sn.colour_on;
  sn.free_ball_before = sn.free_ball;
  const bool free_ball = sn.free_ball;
  sn.free_ball = false;
  const bool needed_snookers = snooker::snookersRequired(s, s.shooter);
  const Aim aim = aimOf(s, shot, free_ball);
  const std::optional<int> first = firstHit(shot, aim.on);
  v.free_ball = free_ball;
  v.nominated = aim.nominated;
  v.pocketed = newlyPocketed(s.on_table, shot.pocketed);
  v.foul = foulOf(shot, aim, first, v.pocketed);
  if (v.legal()) {
    judgeLegal(s, v, aim);
  } else {
    judgeFoul(s, v, shot, aim, first, needed_snookers);
  }
  return v;
}

}  // namespace nineball::rules
