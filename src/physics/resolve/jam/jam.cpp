#include "physics/resolve/jam/jam.hpp"

#include <algorithm>

#include "physics/resolve/ball_ball/ball_contact.hpp"
#include "physics/resolve/ball_ball/collide.hpp"
#include "physics/resolve/cushion/contact.hpp"

namespace nineball::physics {

std::pair<std::vector<std::size_t>, std::vector<std::pair<std::size_t, std::size_t>>> jamAround(
    const std::vector<Vec2>& centres, const std::vector<bool>& on_table, std::size_t i,
    std::size_t j, double r) {
  std::vector<std::size_t> members{i, j};
  std::vector<int> at(centres.size(), -1);
  at[i] = 0;
  at[j] = 1;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t m = 0; m < members.size(); ++m) {
    for (std::size_t o = 0; o < centres.size(); ++o) {
      if (o == members[m] || !on_table[o]) continue;
      if (length(centres[o] - centres[members[m]]) - 2.0 * r > kTouchTolerance) continue;
      if (at[o] < 0) {
        at[o] = static_cast<int>(members.size());
        members.push_back(o);
      }
      if (static_cast<std::size_t>(at[o]) > m) pairs.emplace_back(m, at[o]);
    }
  }
  return {members, pairs};
}

void setJamApart(Jam& jam, const TableGeometry& table, double r) {
  // Setting one pair apart may press one of them into a third: a few sweeps settle most.
  for (int sweep = 0; sweep < 16; ++sweep) {
    double worst = 0.0;
    for (auto [x, y] : jam.pairs) {
      Kinematics& a = jam.balls[x].k;
      Kinematics& b = jam.balls[y].k;
      worst = std::max(worst, 2.0 * r - length(b.p - a.p));
      setApart(a, b, table, r);
    }
    if (worst <= 0.5 * kTouchTolerance) return;
  }
}

void settleJam(Jam& jam, const PhysicsParams& p) {
  PhysicsParams still = p;
  still.ball_restitution = 0.0;
  double unused = 0.0;
  for (int sweep = 0; sweep < 4000; ++sweep) {
    double closing = 0.0;
    for (auto [x, y] : jam.pairs) {
      JamBall& a = jam.balls[x];
      JamBall& b = jam.balls[y];
      const double c = dot(a.k.v - b.k.v, normalized(b.k.p - a.k.p));
      if (c <= 0.0) continue;
      closing = std::max(closing, c);
      collideBalls(a.k, b.k, a.mass, b.mass, still);
    }
    for (JamBall& b : jam.balls) {
      for (Vec2 f : b.faces) closing = std::max(closing, -dot(b.k.v, f));
      b.k = stopAgainst(b.k, b.faces, b.mass, unused);
    }
    if (closing <= kMinClosingSpeed) break;
  }
}

}  // namespace nineball::physics
