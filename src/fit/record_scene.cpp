#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "nineball/fit.hpp"
#include "nineball/motion.hpp"
#include "nineball/random.hpp"

namespace nineball {

Recording recordScene(const Scene& scene, const std::vector<std::string>& names,
                      const Tracker& tracker, const std::string& id) {
  if (names.size() != scene.balls.size()) {
    throw std::invalid_argument("recordScene: one name for each ball of the scene");
  }
  Scene traced = scene;
  traced.trace = TraceRequest{1.0, false};
  const SimResult run = simulate(traced);
  Recording r;
  r.id = id;
  r.table = scene.table;
  r.physics = scene.physics;
  std::uint64_t state = tracker.seed;
  const double hx = scene.table.length / 2.0 - scene.physics.ball_radius;
  const double hy = scene.table.width / 2.0 - scene.physics.ball_radius;
  const long frames = static_cast<long>(std::floor((tracker.strike + run.time) * tracker.hz));
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    RecordedPath p;
    p.name = names[i];
    for (long k = 0; k <= frames; ++k) {
      const double t = static_cast<double>(k) / tracker.hz;
      // Events fall between a tracker's frames: each frame is read off the run exactly.
      const Vec2 at = t < tracker.strike
                          ? scene.balls[i].pos
                          : tracedState(run.trace->balls[i], t - tracker.strike, scene.physics).pos;
      p.t.push_back(t);
      p.x.push_back(std::clamp(at.x + tracker.noise * gaussian(state), -hx, hx));
      p.y.push_back(std::clamp(at.y + tracker.noise * gaussian(state), -hy, hy));
    }
    r.balls.push_back(p);
  }
  return r;
}

}  // namespace nineball
