// Racks of every game played a few turns in, without the planner: what online play snapshots,
// hashes and heals. Each turn aims the striker's ball at a ball it may hit first, places the
// cue ball where the rules let it go when it must be placed, calls when a call is required,
// and answers a decision with "shoot".
#pragma once

#include <cmath>
#include <optional>
#include <vector>

#include "nineball/games.hpp"
#include "nineball/match.hpp"

namespace nineball::net_test {

inline std::optional<Vec2> ballAt(const std::vector<BallState>& balls, int id) {
  for (const BallState& b : balls) {
    if (b.id == id && !b.pocket) return b.pos;
  }
  return std::nullopt;
}

// The first point of a coarse grid over the table where the cue ball may be placed.
inline std::optional<Vec2> placement(const Match& m) {
  const TableDef& t = m.world().table().def;
  for (double fx = -0.45; fx <= 0.45; fx += 0.05) {
    for (double fy = -0.2; fy <= 0.2; fy += 0.05) {
      const Vec2 p{fx * t.length, fy * t.width};
      if (!m.cuePlacementProblem(p)) return p;
    }
  }
  return std::nullopt;
}

// Turn `i` of the rack as it stands: `spread` turns the heading a little off the ball, so the
// racks do not all repeat one shot.
inline TurnInput turnFor(const Match& m, int i) {
  TurnInput t;
  if (m.rack().awaitingDecision()) {
    t.kind = TurnInput::Kind::Decision;
    t.shoot = true;
    return t;
  }
  const std::vector<BallState> balls = m.balls();
  std::optional<Vec2> cue = ballAt(balls, m.rack().cueBall());
  if (m.cueMustBePlaced() || !cue) {
    t.cue = placement(m);
    cue = t.cue;
  }
  const std::vector<int> first = m.rack().legalFirstBalls();
  std::optional<Vec2> target;
  for (int id : first) {
    if ((target = ballAt(balls, id))) break;
  }
  if (!target) target = Vec2{0.5, 0.0};
  const Vec2 d = *target - cue.value_or(Vec2{});
  t.shot.heading_rad = std::atan2(d.y, d.x) + 0.01 * ((i % 3) - 1);
  t.shot.speed = i == 0 ? 6.0 : 2.0 + 0.5 * (i % 4);
  t.shot.tip = {0.1 * ((i % 5) - 2), 0.2};
  t.shot.elevation_rad = 0.05;
  if (m.rack().callRequired())
    t.call = rules::Call{first.empty() ? 1 : first[0], PocketId::TopRight};
  return t;
}

// The rack of `game` (seed `seed`) after `turns` turns, fewer when it ends before.
inline void playTurns(Match& m, int turns) {
  for (int i = 0; i < turns && !m.rack().over(); ++i) m.play(turnFor(m, i));
}

inline MatchSetup setupOf(rules::Game game, std::uint64_t seed = 3) {
  MatchSetup s;
  s.setGame(game);
  s.seed = seed;
  return s;
}

inline std::vector<rules::Game> everyGame() {
  return {rules::Game::NineBall, rules::Game::EightBall, rules::Game::TenBall,
          rules::Game::ThreeCushion, rules::Game::Snooker};
}

}  // namespace nineball::net_test
