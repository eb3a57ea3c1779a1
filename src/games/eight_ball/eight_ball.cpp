#include "games/eight_ball/eight_ball.hpp"

#include <array>

#include "games/triangle.hpp"
#include "nineball/scenes.hpp"

namespace nineball {

std::vector<BallState> rackEightBall(const TableDef& table, double ball_radius, std::uint64_t seed,
                                     double gap) {
  const std::vector<Vec2> spots = games::triangleSpots(table, ball_radius, gap, 5);
  constexpr int kCentre = 4;                          // the middle of the third row
  constexpr std::array<int, 2> kBackCorners{10, 14};  // the ends of the fifth row
  std::uint64_t state = seed;
  std::array<int, 7> solids{1, 2, 3, 4, 5, 6, 7};
  std::array<int, 7> stripes{9, 10, 11, 12, 13, 14, 15};
  games::shuffle(solids, state);
  games::shuffle(stripes, state);
  const bool solid_left = (splitmix64(state) & 1) == 0;
  std::vector<BallState> balls;
  games::put(balls, 8, spots[kCentre]);
  games::put(balls, solids[0], spots[kBackCorners[solid_left ? 0 : 1]]);
  games::put(balls, stripes[0], spots[kBackCorners[solid_left ? 1 : 0]]);
  // The other six of each group fill the twelve spots left, in an order from the seed.
  std::array<int, 12> rest{};
  for (std::size_t i = 0; i < 6; ++i) {
    rest[i] = solids[i + 1];
    rest[i + 6] = stripes[i + 1];
  }
  games::shuffle(rest, state);
  std::size_t next = 0;
  for (int i = 0; i < static_cast<int>(spots.size()); ++i) {
    if (i == kCentre || i == kBackCorners[0] || i == kBackCorners[1]) continue;
    games::put(balls, rest[next++], spots[i]);
  }
  return balls;
}

namespace games {

GameEntry eightBall() {
  GameDef g;
  GameTexts t;
  g.id = rules::Game::EightBall;
  g.name = "eight-ball";
  g.balls = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
  g.required_balls = {8};
  g.required_why = "an eight-ball layout needs the 8 (the rack is won on it)";
  g.highest_ball = 15;
  g.rack = rackEightBall;
  t.help = {"Eight-ball: the first legal pot takes its group (solids 1-7 or stripes 9-15);",
            "  hit your own group first, clear it, then call the 8 to win (8 early loses)",
            "Calling: click a pocket, or K for the obvious shot; the call shows on the table"};
  g.groups = true;
  g.called_shots = "shot at the 8";
  g.takes_calls = true;
  // A race to 3, 4, 5, 7 or 9 racks, or none (the racks simply add up, the first choice).
  t.best_of_choices = {0, 5, 7, 9, 13, 17};
  g.decision = {"play-on", "rerack", "eight-ball's choice after an illegal break"};
  t.made = "potted a ball and kept the table";
  return {g, t};
}

}  // namespace games
}  // namespace nineball
