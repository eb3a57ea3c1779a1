#include "nineball/games.hpp"
#include "nineball/scenes.hpp"

namespace nineball {

std::vector<BallState> rackFor(rules::Game game, const TableDef& table, double ball_radius,
                               std::uint64_t seed, double gap) {
  return gameDef(game).rack(table, ball_radius, seed, gap);
}

Scene breakScene(std::uint64_t seed, double speed) {
  Scene s;
  BallState cue;
  cue.id = kCueBall;
  cue.pos = {-s.table.length / 4.0, 0.0};
  s.balls.push_back(cue);
  for (const BallState& b : defaultGame().rack(s.table, s.physics.ball_radius, seed, 0.0)) {
    s.balls.push_back(b);
  }
  s.shot = Shot::withSpeed(0.0, speed);
  return s;
}

}  // namespace nineball
