#include "physics/resolve/ball_ball/ball_contact.hpp"

#include <algorithm>

#include "physics/resolve/ball_ball/collide.hpp"
#include "physics/resolve/ball_ball/registry.hpp"
#include "physics/resolve/cushion/contact.hpp"

namespace nineball::physics {

void setApart(Kinematics& a, Kinematics& b, const TableGeometry& table, double r) {
  // Each moves half the overlap whatever the masses: positions carry no energy, and a light
  // ball pressed between two heavy ones is set free in a few contacts, not thousands. A ball
  // that its half would sink into a cushion is lifted back out (it keeps the part along the
  // rail) and the other, if free, makes up what it could not do. Lifting can close the gap
  // a little again (two balls in a corner, each on its own rail): a few rounds settle it.
  auto moved = [&](Vec2 from, Vec2 move, bool& held) {
    const Vec2 to = from + move;
    held = cushionSink(table, to, r) > std::max(cushionSink(table, from, r), 0.0);
    return held ? outOfCushions(table, to, r) : to;
  };
  for (int round = 0; round < 8; ++round) {
    const Vec2 d = b.p - a.p;
    const double overlap = 2.0 * r - length(d);
    // Below half the tolerance an overlap is the rounding of a contact met on time.
    if (!(overlap > 0.5 * kTouchTolerance)) return;
    const Vec2 n = normalized(d);
    bool held_a = false, held_b = false;
    Vec2 to_a = moved(a.p, n * (-0.5 * overlap), held_a);
    Vec2 to_b = moved(b.p, n * (0.5 * overlap), held_b);
    const double short_a = 0.5 * overlap + dot(to_a - a.p, n);
    const double short_b = 0.5 * overlap - dot(to_b - b.p, n);
    if (!held_b) to_b += n * short_a;
    if (!held_a) to_a -= n * short_b;
    a.p = to_a;
    b.p = to_b;
  }
}

void collideBalls(Kinematics& a, Kinematics& b, double mass_a, double mass_b,
                  const PhysicsParams& p) {
  const Vec2 n = normalized(b.p - a.p);
  // Balls that meet slower than a ball can bounce stay together, as at a cushion: else a
  // jammed crowd passes micrometre-per-second bounces round for ever.
  const double closing = dot(a.v - b.v, n);
  const double e = closing > kRestingSpeed ? p.ball_restitution : 0.0;
  const auto out = collide(a.v, b.v, mass_a, mass_b, e, n);
  const double normal_impulse = mass_b * dot(out.v2 - b.v, n);
  a.v = out.v1;
  b.v = out.v2;
  if (const BallGrip grip = ballBallModel(p.ball_ball).grip) {
    grip(a, b, mass_a, mass_b, n, normal_impulse, p);
  }
  if (dot(b.v - a.v, n) < kRestingSpeed) {
    a = stopPressing(a, n, p);
    b = stopPressing(b, -n, p);
  }
}

}  // namespace nineball::physics
