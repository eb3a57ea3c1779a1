#include "games/triangle.hpp"

#include <cmath>

namespace nineball::games {

std::vector<Vec2> triangleSpots(const TableDef& table, double ball_radius, double gap, int rows) {
  const double d = 2.0 * ball_radius + gap;  // centre to centre of neighbours
  const double row_step = d * std::sqrt(3.0) / 2.0;
  const Vec2 foot{table.length / 4.0, 0.0};
  std::vector<Vec2> spots;
  for (int row = 0; row < rows; ++row) {
    for (int i = 0; i <= row; ++i) spots.push_back({foot.x + row * row_step, (i - row / 2.0) * d});
  }
  return spots;
}

void put(std::vector<BallState>& balls, int id, Vec2 p) {
  balls.push_back(BallState::at(id, p));
}

}  // namespace nineball::games
