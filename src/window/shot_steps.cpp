#include "window/shot_steps.hpp"

namespace nineball::window {

void ShotSteps::begin(const Match& match) {
  current = previous = match.balls();
  events_heard = 0;
  start = previous_time = current_time = match.world().time();
}

bool ShotSteps::take(Match& match, int steps, std::vector<audio::Impact>& impacts) {
  const Engine& world = match.world();
  for (int i = 0; i < steps; ++i) {
    previous = current;
    previous_time = current_time;
    // The match's own steps: a rack played in the window ends as the same rack played headless.
    const bool over = match.stepShot();
    current = match.balls();
    current_time = world.time();
    const auto& events = world.events();
    if (events.size() > events_heard) {
      const std::vector<Event> fresh(events.begin() + static_cast<long>(events_heard),
                                     events.end());
      const auto more = audio::impactsFromEvents(fresh, previous);
      impacts.insert(impacts.end(), more.begin(), more.end());
      events_heard = events.size();
    }
    if (over) return true;
  }
  return false;
}

std::vector<BallState> ShotSteps::between(double alpha) const {
  std::vector<BallState> out = current;
  for (std::size_t i = 0; i < out.size() && i < previous.size(); ++i) {
    if (out[i].pocket || previous[i].pocket) continue;
    const BallState& a = previous[i];
    out[i].pos = a.pos + (out[i].pos - a.pos) * alpha;
    out[i].vel = a.vel + (out[i].vel - a.vel) * alpha;
    out[i].w = a.w + (out[i].w - a.w) * alpha;
    out[i].z = a.z + (out[i].z - a.z) * alpha;
  }
  return out;
}

double ShotSteps::timeBetween(double alpha) const {
  return previous_time + (current_time - previous_time) * alpha;
}

}  // namespace nineball::window
