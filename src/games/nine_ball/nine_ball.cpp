#include "games/nine_ball/nine_ball.hpp"

#include <array>
#include <cmath>

#include "games/triangle.hpp"
#include "nineball/scenes.hpp"

namespace nineball {

std::vector<BallState> rackNineBall(const TableDef& table, double ball_radius, std::uint64_t seed,
                                    double gap) {
  const double d = 2.0 * ball_radius + gap;  // centre to centre of neighbours
  const double row_step = d * std::sqrt(3.0) / 2.0;
  const Vec2 foot{table.length / 4.0, 0.0};
  constexpr std::array<int, 5> kRowSize{1, 2, 3, 2, 1};
  std::vector<Vec2> spots;
  for (int row = 0; row < 5; ++row) {
    const int n = kRowSize[row];
    // Rows 3 and 4 narrow again: they sit under the middle of the wider row before them.
    for (int i = 0; i < n; ++i) {
      spots.push_back({foot.x + row * row_step, (i - (n - 1) / 2.0) * d});
    }
  }
  // spots: 0 apex, 1-2 second row, 3-5 third row (4 is the centre), 6-7, 8 back.
  std::array<int, 7> others{2, 3, 4, 5, 6, 7, 8};
  std::uint64_t state = seed;
  for (std::size_t i = others.size() - 1; i > 0; --i) {
    const std::size_t j = splitmix64(state) % (i + 1);
    std::swap(others[i], others[j]);
  }
  std::vector<BallState> balls;
  auto put = [&](int id, Vec2 p) {
    BallState b;
    b.id = id;
    b.pos = p;
    balls.push_back(b);
  };
  put(1, spots[0]);
  put(9, spots[4]);
  const std::array<int, 7> free_spots{1, 2, 3, 5, 6, 7, 8};
  for (std::size_t i = 0; i < others.size(); ++i) put(others[i], spots[free_spots[i]]);
  return balls;
}

namespace games {

GameEntry nineBall() {
  GameDef g;
  GameTexts t;
  g.id = rules::Game::NineBall;
  g.name = "nine-ball";
  g.balls = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  g.rule_sets = {rules::RuleSet::Wpa, rules::RuleSet::Paper};
  g.rack = rackNineBall;
  g.push_outs = true;
  // A race to 3, 4, 5, 7 or 9 racks, or none (the racks simply add up, the first choice).
  t.best_of_choices = {0, 5, 7, 9, 13, 17};
  t.help = {"Rules: hit the lowest ball first; the 9 wins the rack"};
  return {g, t};
}

}  // namespace games
}  // namespace nineball
