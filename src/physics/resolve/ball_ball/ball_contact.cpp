#include "physics/resolve/ball_ball/ball_contact.hpp"

#include <algorithm>

#include "physics/resolve/ball_ball/collide.hpp"
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

namespace {

// Ball-ball friction (Alciatore, TP A.14): a tangential impulse against the sliding of the
// contact points, mu(sliding speed) times the normal impulse, capped where they stop sliding.
// The sliding includes the vertical part topspin and draw give it, so a rolling ball throws
// less. Each ball's contact point answers a surface impulse J by J/m + J R^2/I = 7/2 J/m, so
// sliding stops at |u| / (7/2 (1/m_a + 1/m_b)): 1/7 of m|u| for equal balls. The vertical part
// of the impulse goes into the slate (or a hop this 2-D game leaves out); its spin stays.
void grip(Kinematics& a, Kinematics& b, double mass_a, double mass_b, Vec2 n, double normal_impulse,
          const PhysicsParams& p) {
  const double r = p.ball_radius;
  const Vec3 n3 = lift(n), arm_a = n3 * r, arm_b = n3 * -r;
  Vec3 u = (lift(a.v) + cross(a.w, arm_a)) - (lift(b.v) + cross(b.w, arm_b));
  u = u - n3 * dot(u, n3);
  const double sliding = length(u);
  if (sliding < 1e-12 || normal_impulse <= 0.0) return;
  const double stop = sliding / (3.5 * (1.0 / mass_a + 1.0 / mass_b));
  const double size = std::min(p.ball_friction.at(sliding) * normal_impulse, stop);
  const Vec3 on_a = u * (-size / sliding);
  a.v += flat(on_a) / mass_a;
  b.v -= flat(on_a) / mass_b;
  if (!p.spin()) return;  // the other cloths carry no spin
  a.w = a.w + cross(arm_a, on_a) * (1.0 / (0.4 * mass_a * r * r));
  b.w = b.w + cross(arm_b, on_a * -1.0) * (1.0 / (0.4 * mass_b * r * r));
}

}  // namespace

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
  if (p.ball_ball == BallBallModel::Frictional) grip(a, b, mass_a, mass_b, n, normal_impulse, p);
  if (dot(b.v - a.v, n) < kRestingSpeed) {
    a = stopPressing(a, n, p);
    b = stopPressing(b, -n, p);
  }
}

}  // namespace nineball::physics
