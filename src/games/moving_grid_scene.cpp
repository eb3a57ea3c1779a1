#include <cmath>

#include "nineball/random.hpp"
#include "nineball/scenes.hpp"
#include "nineball/vec2.hpp"

namespace nineball {

Scene movingGridScene(int n, std::uint64_t seed) {
  Scene scene;
  const TableDef& table = scene.table;
  const double r = scene.physics.ball_radius;
  const int cols = static_cast<int>(std::ceil(std::sqrt(2.0 * n)));
  const int rows = (n + cols - 1) / cols;
  for (int i = 0; i < n; ++i) {
    const double x = -table.length / 2 + (table.length * ((i % cols) + 0.5)) / cols;
    const double y = -table.width / 2 + (table.width * ((i / cols) + 0.5)) / rows;
    const double angle = uniform(seed, 0.0, 2.0 * kPi);
    const Vec2 v = fromAngle(angle) * 3.0;
    BallState b = BallState::at(i, {x, y}, v);
    b.w = {-v.y / r, v.x / r, 0.0};  // rolling
    scene.balls.push_back(b);
  }
  return scene;
}

}  // namespace nineball
