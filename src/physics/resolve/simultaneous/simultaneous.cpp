#include "physics/resolve/simultaneous/simultaneous.hpp"

#include <algorithm>
#include <cmath>

#include "physics/resolve/ball_ball/collide.hpp"
#include "physics/resolve/ball_ball/registry.hpp"
#include "physics/resolve/cushion/contact.hpp"
#include "physics/resolve/cushion/registry.hpp"
#include "physics/resolve/cushion/simple/simple.hpp"

namespace nineball::physics {
namespace {

// Rounding allowed in checking a candidate set of pushing contacts (m/s and kg m/s).
constexpr double kSlack = 1e-12;

double energy(const Kinematics& k, double mass, double r) {
  return 0.5 * mass * dot(k.v, k.v) + 0.2 * mass * r * r * dot(k.w, k.w);
}

// The nose's Coulomb impulse on a ball whose cushion pushed with `normal_impulse`, as
// cushionFriction applies it: against the slip of the contact point, capped where it stops.
Vec2 noseFriction(const Kinematics& k, Vec2 normal, double normal_impulse, double mass,
                  const PhysicsParams& p) {
  if (!p.spin() || p.cushion_friction <= 0.0 || normal_impulse <= 0.0) return {};
  const Vec3 arm = lift(normal * -p.ball_radius);
  const Vec2 at_contact = flat(lift(k.v) + cross(k.w, arm));
  const Vec2 sliding = at_contact - normal * dot(at_contact, normal);
  const double speed = length(sliding);
  if (speed < 1e-12) return {};
  const double grip = 2.0 / 7.0 * mass * speed;
  return sliding * (-std::min(p.cushion_friction * normal_impulse, grip) / speed);
}

// The same two contacts once friction has acted, perfectly inelastic (e = 0): whatever
// friction turned back into a contact is stopped there, taking energy only.
std::array<double, 2> stopInelastic(const TwoContacts& c, double u0, double u1) {
  TwoContacts again = c;
  again.u[0] = u0;
  again.u[1] = u1;
  again.e[0] = again.e[1] = 0.0;
  return solveTwoContacts(again);
}

}  // namespace

std::array<double, 2> solveTwoContacts(const TwoContacts& c) {
  const double target[2] = {std::max(0.0, -c.e[0] * c.u[0]), std::max(0.0, -c.e[1] * c.u[1])};
  const double need[2] = {target[0] - c.u[0], target[1] - c.u[1]};
  // Both push: M P = need.
  const double det = c.m[0][0] * c.m[1][1] - c.m[0][1] * c.m[1][0];
  if (det > 0.0) {
    const double p0 = (need[0] * c.m[1][1] - c.m[0][1] * need[1]) / det;
    const double p1 = (c.m[0][0] * need[1] - c.m[1][0] * need[0]) / det;
    if (p0 >= 0.0 && p1 >= 0.0) return {p0, p1};
  }
  // One pushes, the other parts fast enough on its own.
  for (int i = 0; i < 2; ++i) {
    const int o = 1 - i;
    const double pi = std::max(0.0, need[i] / c.m[i][i]);
    if (c.u[o] + c.m[o][i] * pi >= target[o] - kSlack) {
      std::array<double, 2> out{0.0, 0.0};
      out[static_cast<std::size_t>(i)] = pi;
      return out;
    }
  }
  return {0.0, 0.0};
}

double cushionRestitutionAt(double speed, double mass, const PhysicsParams& p) {
  if (!(speed > kRestingSpeed)) return 0.0;
  const CushionModelDef& model = cushionModel(p.cushion);
  if (!model.bounce) return p.cushion_restitution;
  const Vec2 inward{0.0, 1.0};
  const Kinematics in{{0.0, 0.0}, {0.0, -speed}, {0.0, 0.0, 0.0}};
  double impulse = 0.0;
  const double ratio = dot(model.bounce(in, inward, mass, p, impulse).v, inward) / speed;
  return std::clamp(ratio, 0.0, 1.0);
}

FrozenStrike strikeFrozen(Kinematics a, Kinematics b, double mass_a, double mass_b, Vec2 face,
                          const PhysicsParams& p) {
  const double r = p.ball_radius;
  const double before = energy(a, mass_a, r) + energy(b, mass_b, r);
  const Vec2 n = normalized(b.p - a.p);
  const double s = dot(n, face);
  TwoContacts c;
  c.m[0][0] = 1.0 / mass_a + 1.0 / mass_b;
  c.m[0][1] = c.m[1][0] = s / mass_b;
  c.m[1][1] = 1.0 / mass_b;
  c.u[0] = dot(b.v - a.v, n);
  c.u[1] = dot(b.v, face);
  // As a pair met alone: slower than a ball can bounce, they stay together.
  c.e[0] = -c.u[0] > kRestingSpeed ? p.ball_restitution : 0.0;
  c.e[1] = cushionRestitutionAt(-c.u[1], mass_b, p);
  const auto impulse = solveTwoContacts(c);
  FrozenStrike out;
  out.ball_impulse = impulse[0];
  out.cushion_impulse = impulse[1];
  a.v -= n * (impulse[0] / mass_a);
  b.v += (n * impulse[0] + face * impulse[1]) / mass_b;
  out.a = a;
  out.b = b;
  // Friction: the ball-ball model's grip, then the nose's; each alone takes energy away.
  if (const BallGrip grip = ballBallModel(p.ball_ball).grip) {
    grip(out.a, out.b, mass_a, mass_b, n, impulse[0], p);
  }
  out.b = cushionFriction(out.b, face, impulse[1], mass_b, p);
  const auto stop = stopInelastic(c, dot(out.b.v - out.a.v, n), dot(out.b.v, face));
  out.a.v -= n * (stop[0] / mass_a);
  out.b.v += (n * stop[0] + face * stop[1]) / mass_b;
  if (energy(out.a, mass_a, r) + energy(out.b, mass_b, r) > before) {
    out.a = a;
    out.b = b;
  }
  if (dot(out.b.v - out.a.v, n) < kRestingSpeed) {
    out.a = stopPressing(out.a, n, p);
    out.b = stopPressing(out.b, -n, p);
  }
  out.b = stopPressing(out.b, -face, p);
  return out;
}

CornerBounce intoCorner(Kinematics k, Vec2 first, Vec2 second, double mass,
                        const PhysicsParams& p) {
  const double r = p.ball_radius;
  const double before = energy(k, mass, r);
  const double cosine = dot(first, second);
  TwoContacts c;
  c.m[0][0] = c.m[1][1] = 1.0 / mass;
  c.m[0][1] = c.m[1][0] = cosine / mass;
  c.u[0] = dot(k.v, first);
  c.u[1] = dot(k.v, second);
  c.e[0] = cushionRestitutionAt(-c.u[0], mass, p);
  c.e[1] = cushionRestitutionAt(-c.u[1], mass, p);
  const auto impulse = solveTwoContacts(c);
  CornerBounce out;
  out.impulse[0] = impulse[0];
  out.impulse[1] = impulse[1];
  const Kinematics normal = {k.p, k.v + (first * impulse[0] + second * impulse[1]) / mass, k.w};
  Kinematics chosen = normal;
  // Friction: the nose's Coulomb law (the paper cushion's, cushionFriction) for every cushion
  // model, both faces' from the same state: at a symmetric corner their spins cancel and the
  // ball leaves along the line it came in on. (A model's own rebound is worked out for one
  // contact; two of them added, each as if alone, count the slate's friction twice.)
  const Vec2 j0 = noseFriction(normal, first, impulse[0], mass, p);
  const Vec2 j1 = noseFriction(normal, second, impulse[1], mass, p);
  const double inertia = 0.4 * mass * r * r;
  chosen.v += (j0 + j1) / mass;
  chosen.w = chosen.w + (cross(lift(first * -r), lift(j0)) + cross(lift(second * -r), lift(j1))) *
                            (1.0 / inertia);
  const auto stop = stopInelastic(c, dot(chosen.v, first), dot(chosen.v, second));
  chosen.v += (first * stop[0] + second * stop[1]) / mass;
  if (energy(chosen, mass, r) > before) chosen = normal;
  chosen = stopPressing(chosen, -first, p);
  chosen = stopPressing(chosen, -second, p);
  out.k = chosen;
  return out;
}

std::optional<Vec2> secondFace(const Kinematics& k, Vec2 first, double r, const Cushions& cushions,
                               double within) {
  std::optional<Vec2> best;
  double soonest = 0.0;
  auto consider = [&](Vec2 normal, double gap) {
    if (dot(normal, first) > 0.999) return;  // the same face (2.6 degrees)
    const double closing = -dot(k.v, normal);
    if (!(closing > kMinClosingSpeed) || gap < -r) return;
    const double when = std::max(gap, 0.0) / closing;
    if (!(when <= within) || (best && !(when < soonest))) return;
    soonest = when;
    best = normal;
  };
  for (const Cushions::Segment& seg : cushions.segments) {
    const double foot = dot(k.p - seg.a, seg.along);
    if (foot < 0.0 || foot > seg.length) continue;
    consider(seg.inward, dot(k.p - seg.a, seg.inward) - r);
  }
  for (Vec2 corner : cushions.corners) {
    const Vec2 d = k.p - corner;
    const double distance = length(d);
    if (distance > 0.0) consider(d / distance, distance - r);
  }
  for (const Cushions::Arc& arc : cushions.arcs) {
    const Vec2 d = k.p - arc.centre;
    const double distance = length(d);
    if (distance > 0.0 && arc.covers(d)) consider(d / distance, distance - arc.radius - r);
  }
  return best;
}

}  // namespace nineball::physics
