#include "ai/carom/carom_judge.hpp"

#include <set>

#include "ai/thread_world.hpp"
#include "play/shot_summary.hpp"

namespace nineball::ai {
namespace {

// The point is decided once the shooter's ball has met a second object ball: scored or not,
// nothing after changes it.
bool decided(const std::vector<Event>& events, int cue) {
  std::set<int> touched;
  for (const Event& e : events) {
    if (e.type != EventType::BallBall || (e.a != cue && e.b != cue)) continue;
    touched.insert(e.a == cue ? e.b : e.a);
    if (touched.size() >= 2) return true;
  }
  return false;
}

}  // namespace

CaromJudge::CaromJudge(const PlanInput& in)
    : in_(in), cue_(in.rack.cueBall()), id_(newWorldOwner()) {}

CaromOutcome CaromJudge::run(const Shot& shot, bool to_rest) const {
  Engine& world = worldForThisThread(id_, in_.table, in_.physics, in_.step);
  for (const BallState& b : in_.balls) {
    if (!b.pocket) world.addBall(b);
  }
  world.strike(cue_, shot);
  const int cue = cue_;
  world.runUntilRest(
      [&](const std::vector<Event>& events) { return !to_rest && decided(events, cue); });
  const rules::ShotSummary summary = play::summarize(world.events(), cue_);
  CaromOutcome out;
  out.rack = in_.rack;
  const rules::Verdict v = out.rack.shoot(summary, false);
  out.point = v.points[0] + v.points[1] > 0;
  out.cushions = v.cushions;
  out.touched_both =
      std::set<int>(summary.cue_touches.begin(), summary.cue_touches.end()).size() >= 2;
  if (to_rest) out.balls = world.balls();
  return out;
}

}  // namespace nineball::ai
