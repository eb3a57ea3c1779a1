#include "games/ten_ball/ten_ball.hpp"

#include <array>

#include "games/triangle.hpp"
#include "nineball/scenes.hpp"

namespace nineball {

std::vector<BallState> rackTenBall(const TableDef& table, double ball_radius, std::uint64_t seed,
                                   double gap) {
  const std::vector<Vec2> spots = games::triangleSpots(table, ball_radius, gap, 4);
  constexpr int kApex = 0;
  constexpr int kCentre = 4;  // the middle of the third row
  std::uint64_t state = seed;
  std::array<int, 8> others{2, 3, 4, 5, 6, 7, 8, 9};
  games::shuffle(others, state);
  std::vector<BallState> balls;
  games::put(balls, 1, spots[kApex]);
  games::put(balls, 10, spots[kCentre]);
  std::size_t next = 0;
  for (int i = 0; i < static_cast<int>(spots.size()); ++i) {
    if (i == kApex || i == kCentre) continue;
    games::put(balls, others[next++], spots[i]);
  }
  return balls;
}

namespace games {

GameEntry tenBall() {
  GameDef g;
  GameTexts t;
  g.id = rules::Game::TenBall;
  g.name = "ten-ball";
  g.balls = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  g.highest_ball = 10;
  g.rack = rackTenBall;
  t.help = {"Ten-ball: hit the lowest ball first; every shot after the break is called,",
            "  a pot not as called ends the turn (play or pass); the 10 called wins",
            "Calling: click a ball (default: the ball on), then a pocket; K: the obvious shot"};
  g.call_any_ball = true;
  g.pot_not_as_called_passes = true;
  g.called_shots = "shot after the break";
  g.push_outs = true;
  // A race to 3, 4, 5, 7 or 9 racks, or none (the racks simply add up, the first choice).
  t.best_of_choices = {0, 5, 7, 9, 13, 17};
  g.takes_calls = true;
  g.decision.about = "the choice after a push-out or a pot not as called";
  g.break_from_every_spot = true;
  t.made = "potted the ball on as called";
  return {g, t};
}

}  // namespace games
}  // namespace nineball
