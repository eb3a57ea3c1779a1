#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "nineball/planner.hpp"
#include "nineball/table.hpp"

namespace nineball::ai {

/// The aim error (degrees) of the player a position is judged for: what a position leaves to
/// the shooter or to the opponent is the chance such a player pots the ball on from it.
constexpr double kReferenceAimDeg = 0.3;
/// That chance when the player to move has the cue ball in hand.
constexpr double kInHandChance = 0.9;
/// Every foul is worth at most this much; every legal shot more.
constexpr double kFoulValueTop = 0.04;

/// A legal shot that keeps the table is worth at least this much; anything less lost it.
constexpr double kContinueBase = 0.55;
constexpr double kContinueSpread = 0.4;

/// One shot to try: where the cue ball goes first (ball in hand), the strike, and the call.
struct Candidate {
  ShotKind kind = ShotKind::Safety;
  Shot shot;
  std::optional<Vec2> cue;
  int target = 0;
  std::optional<PocketId> pocket;
  int first = 0;  ///< the ball meant to be hit first (0: none in particular)
  std::optional<rules::Call> call;
  double prior = 0.0;  ///< how promising it looks before any simulation; orders ties
};

/// Where a simulated shot left the rack: the balls (spotted ones back on the table), the
/// rules' state and their verdict.
struct Outcome {
  std::vector<BallState> balls;
  rules::Rack rack;
  rules::Verdict verdict;
  bool cue_pocketed = false;
};

/// Plays shots from one position through the physics and scores each outcome for the shooter
/// with the rules: a win 1, a loss 0; a legal pot 0.55 + 0.4 x the chance of potting a ball
/// on next from where the cue ball stops; a legal miss 0.45 - 0.4 x the opponent's chance; a
/// position the opponent may play or pass back (a push-out, a pot not as called) the lesser
/// of its worth to either player, since the opponent takes the better; a foul below any legal
/// shot. Safe to call from several threads: every call builds its own world.
class Evaluator {
 public:
  /// `judging_aim_deg`: the aim error of the player whose chances a position is judged by.
  /// `group_sense`: eight-ball positions are also judged by the groups' open balls.
  Evaluator(const PlanInput& in, const TableGeometry& table,
            double judging_aim_deg = kReferenceAimDeg, bool group_sense = false);

  /// The worth of the outcome of the candidate struck with `shot` (its own, or one with
  /// cueing errors): the cue ball placed first when it says so, its call, a push-out if it is.
  double value(const Candidate& c, const Shot& shot) const;
  double value(const Candidate& c) const { return value(c, c.shot); }

  /// The same shot's outcome, for a look further ahead; nothing when the rules take no shot.
  std::optional<Outcome> outcome(const Candidate& c, const Shot& shot) const;
  /// The worth of an outcome as `value` scores it.
  double score(const Outcome& o) const;

  /// The balls on the table with the cue ball at `cue` (added if it was pocketed or absent).
  std::vector<BallState> ballsWithCueAt(Vec2 cue) const;

  /// The aim error (rad) positions are judged by.
  double judgingSigma() const { return sigma_rad_; }

 private:
  // Eight-ball with the groups set: the shooter's balls open to a pocket against the
  // opponent's (kGroupWeight times the difference of their shares); 0 otherwise.
  double groupBalance(const Outcome& o) const;
  // The best chance of potting any ball `rack` allows first, from a cue ball at `cue`.
  double chanceFrom(const std::vector<BallState>& after, const rules::Rack& rack, Vec2 cue) const;
  // Puts the balls the verdict spots back: where the game's GameDef::spot says (snooker's
  // colours, the highest first, as the match does), else on the foot spot.
  void respotBalls(Outcome& o) const;

  // Snooker (snooker_value.cpp): points, position on the next ball on, the reds' spread,
  // safeties judged by what they leave, fouls by the penalty and the leave.
  double snookerScore(const Outcome& o) const;
  // The chance of the player to move in `o`: from where the cue ball stopped, or with it in
  // hand the best of a few places in the D.
  double snookerChance(const Outcome& o) const;
  // The best chance with the cue ball in hand in the D: a few places on its line and arc.
  double chanceFromTheD(const std::vector<BallState>& after, const rules::Rack& rack) const;

  const PlanInput& in_;
  const TableGeometry& table_;
  StepParams step_;
  std::uint64_t id_ = 0;  // which evaluator a thread's kept engine was made for
  Engine& engineForThisThread() const;
  double sigma_rad_;
  bool group_sense_;
  std::vector<int> legal_first_;  // what the cue ball may hit first, found once per position
};

}  // namespace nineball::ai
