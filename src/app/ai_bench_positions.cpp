#include "app/ai_bench_positions.hpp"

#include <algorithm>

#include "nineball/games.hpp"
#include "nineball/random.hpp"

namespace nineball::app {
namespace {

// Clearance (m) between balls and from the cushions, so that no ball starts frozen.
constexpr double kGap = 0.005;
constexpr int kMinObjectBalls = 3;
constexpr int kMaxObjectBalls = 5;

}  // namespace

std::vector<BallState> randomPosition(std::uint64_t seed, const TableDef& table,
                                      const PhysicsParams& physics, rules::Game game) {
  std::uint64_t state = seed * 0x2545F4914F6CDD1Dull + 0x1234567ull;
  const TableGeometry geo = buildTable(table, physics.ball_radius);
  const double r = physics.ball_radius;
  // The balls a layout must hold are always there; the others are drawn from the rest.
  const GameDef& def = gameDef(game);
  std::vector<int> numbers;
  for (int b : def.balls) {
    if (std::find(def.required_balls.begin(), def.required_balls.end(), b) ==
        def.required_balls.end()) {
      numbers.push_back(b);
    }
  }
  for (std::size_t i = numbers.size(); i > 1; --i) {
    std::swap(numbers[i - 1], numbers[splitmix64(state) % i]);
  }
  // A set with no balls to leave out (carom's three) is laid out whole.
  const int drawn = kMinObjectBalls +
                    static_cast<int>(splitmix64(state) % (kMaxObjectBalls - kMinObjectBalls + 1));
  const int count = std::min(drawn, static_cast<int>(numbers.size()));
  std::vector<int> ids = {kCueBall};
  for (int b : def.required_balls) ids.push_back(b);
  ids.insert(ids.end(), numbers.begin(), numbers.begin() + count);
  std::vector<BallState> balls;
  for (int id : ids) {
    for (;;) {
      const Vec2 p{uniform(state, -table.length / 2.0, table.length / 2.0),
                   uniform(state, -table.width / 2.0, table.width / 2.0)};
      if (!geo.ballFits(p, r + kGap)) continue;
      const bool clear = std::all_of(balls.begin(), balls.end(), [&](const BallState& b) {
        return length(b.pos - p) >= 2.0 * r + kGap;
      });
      if (!clear) continue;
      BallState b;
      b.id = id;
      b.pos = p;
      balls.push_back(b);
      break;
    }
  }
  return balls;
}

}  // namespace nineball::app
