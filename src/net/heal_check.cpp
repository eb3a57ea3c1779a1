#include "net/heal_check.hpp"

#include <algorithm>
#include <cmath>

#include "common/limits.hpp"
#include "nineball/sim.hpp"

namespace nineball::net {
namespace {

// No turn scores more than this (a break pocketing a rack's every ball, a snooker foul).
constexpr int kMostPointsPerTurn = 30;

std::string ballText(const BallState& b) {
  return "ball " + std::to_string(b.id);
}

std::optional<std::string> motionProblem(const MatchSnapshot& s, double radius) {
  const double most_spin = limits::kMaxSurfaceSpeed / radius;
  for (const BallState& b : s.balls) {
    if (length(b.vel) > limits::kMaxSpeed) return ballText(b) + " moves faster than any cue";
    if (std::sqrt(b.w.x * b.w.x + b.w.y * b.w.y + b.w.z * b.w.z) > most_spin) {
      return ballText(b) + " spins faster than any cue";
    }
  }
  return std::nullopt;
}

std::optional<std::string> cueProblem(const MatchSnapshot& s) {
  const auto cue = std::find_if(s.balls.begin(), s.balls.end(),
                                [](const BallState& b) { return b.id == kCueBall; });
  if (cue == s.balls.end()) return std::string("no cue ball");
  if (s.cue_pocketed != cue->pocket.has_value()) {
    return std::string(s.cue_pocketed ? "the cue ball in hand is on the table"
                                      : "the cue ball is off the table but not in hand");
  }
  return std::nullopt;
}

std::optional<std::string> rulesProblem(const MatchSnapshot& s, const Match& match,
                                        std::size_t turns) {
  const rules::RackState& r = s.rack;
  const rules::RackState& own = match.rack().state();
  if (r.racked != own.racked) return std::string("the rack's balls are not this rack's");
  std::vector<int> on_table;
  for (const BallState& b : s.balls) {
    if (b.id != kCueBall && !b.pocket) on_table.push_back(b.id);
  }
  std::sort(on_table.begin(), on_table.end());
  if (r.on_table != on_table) return std::string("the balls on the table are not the rules'");
  if ((r.winner || r.draw) && !match.rack().over()) {
    return std::string("a winner before the rack is over");
  }
  const int most = static_cast<int>(turns) + 1;
  for (int i = 0; i < 2; ++i) {
    if (r.fouls[i] > most || r.innings[i] > most || r.high_run[i] > most) {
      return std::string("more fouls, innings or runs than turns played");
    }
    if (std::abs(r.score[i]) > most * kMostPointsPerTurn) {
      return std::string("a score no rack of ") + std::to_string(turns) + " turns makes";
    }
  }
  if (r.run > most) return std::string("a run longer than the turns played");
  return std::nullopt;
}

}  // namespace

std::optional<std::string> healProblem(const MatchSnapshot& healed, const MatchSetup& setup,
                                       const Match& match, std::size_t turns) {
  Scene scene;
  scene.table = setup.table;
  scene.physics = setup.physics;
  scene.step = setup.step;
  scene.balls = healed.balls;
  if (auto problem = validateScene(scene)) return problem;
  if (auto problem = motionProblem(healed, setup.physics.ball_radius)) return problem;
  if (auto problem = cueProblem(healed)) return problem;
  return rulesProblem(healed, match, turns);
}

}  // namespace nineball::net
