#pragma once

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

/// One shot to try: where the cue ball goes first (ball in hand) and the strike.
struct Candidate {
  ShotKind kind = ShotKind::Safety;
  Shot shot;
  std::optional<Vec2> cue;
  int target = 0;
  std::optional<PocketId> pocket;
  double prior = 0.0;  ///< how promising it looks before any simulation; orders ties
};

/// Plays shots from one position through the physics and scores each outcome for the shooter
/// with the rules: a win 1, a loss 0; a legal pot 0.55 + 0.4 x the chance of potting the next
/// ball from where the cue ball stops; a legal miss 0.45 - 0.4 x the opponent's chance; a foul
/// below any legal shot. Safe to call from several threads: every call builds its own world.
class Evaluator {
 public:
  /// `judging_aim_deg`: the aim error of the player whose chances a position is judged by.
  Evaluator(const PlanInput& in, const TableGeometry& table,
            double judging_aim_deg = kReferenceAimDeg);

  /// The worth of the outcome of `shot` (after placing the cue ball at `cue`, if given).
  double value(const Shot& shot, std::optional<Vec2> cue) const;

  /// The balls on the table with the cue ball at `cue` (added if it was pocketed or absent).
  std::vector<BallState> ballsWithCueAt(Vec2 cue) const;

 private:
  double score(const std::vector<BallState>& after, const rules::Rack& rack,
               const rules::Verdict& verdict, bool cue_pocketed) const;

  const PlanInput& in_;
  const TableGeometry& table_;
  StepParams step_;
  double sigma_rad_;
};

}  // namespace nineball::ai
