#include "physics/models/ball_contact.hpp"

#include <algorithm>

#include "physics/ball_collision.hpp"
#include "physics/models/cushion.hpp"

namespace nineball::physics {

void setApart(Kinematics& a, Kinematics& b, double mass_a, double mass_b,
              const TableGeometry& table, double r) {
  const Vec2 d = b.p - a.p;
  const double overlap = 2.0 * r - length(d);
  // Below half the tolerance an overlap is the rounding of a contact met on time.
  if (!(overlap > 0.5 * kTouchTolerance)) return;
  const Vec2 n = normalized(d);
  // A ball that its share of the move would sink into a cushion stays put; the other moves.
  auto sinks = [&](Vec2 from, Vec2 to) {
    return cushionSink(table, to, r) > std::max(cushionSink(table, from, r), 0.0);
  };
  const double total = mass_a + mass_b;
  const Vec2 move_a = n * (-overlap * mass_b / total), move_b = n * (overlap * mass_a / total);
  const bool hold_a = sinks(a.p, a.p + move_a), hold_b = sinks(b.p, b.p + move_b);
  if (hold_a && hold_b) return;
  if (hold_a) {
    b.p += n * overlap;
  } else if (hold_b) {
    a.p -= n * overlap;
  } else {
    a.p += move_a;
    b.p += move_b;
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
  a.v = out.v1;
  b.v = out.v2;
  if (dot(b.v - a.v, n) < kRestingSpeed) {
    a = stopPressing(a, n, p);
    b = stopPressing(b, -n, p);
  }
}

}  // namespace nineball::physics
