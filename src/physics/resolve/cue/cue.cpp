#include "physics/resolve/cue/cue.hpp"

#include <algorithm>
#include <cmath>

#include "physics/model/slate.hpp"

namespace nineball::physics {

double squirtAngle(double b, double mass, double end_mass) {
  if (end_mass <= 0.0 || b == 0.0) return 0.0;
  const double rest = 1.0 - b * b;
  const double size =
      std::atan(2.5 * std::abs(b) * std::sqrt(rest) / (1.0 + mass / end_mass + 2.5 * rest));
  return b > 0.0 ? size : -size;  // struck right of centre, the ball goes left
}

Strike cueStrike(const Shot& shot, double mass, const PhysicsParams& p) {
  const Vec2 d = fromAngle(shot.heading_rad);
  const double tilt = shot.elevation_rad;
  const double side = shot.tip.x, height = shot.tip.y;
  Strike s;
  const double heading = shot.heading_rad + squirtAngle(side, mass, p.cue_end_mass);
  s.v = fromAngle(heading) * (shot.speed * std::cos(tilt));
  s.vz = strikeRebound(-shot.speed * std::sin(tilt), p);
  if (!p.spin()) return s;
  const double r = p.ball_radius;
  const Vec3 axis{std::cos(tilt) * d.x, std::cos(tilt) * d.y, -std::sin(tilt)};
  const Vec3 left{-d.y, d.x, 0.0};
  const Vec3 up{std::sin(tilt) * d.x, std::sin(tilt) * d.y, std::cos(tilt)};
  const double depth = std::sqrt(std::max(0.0, 1.0 - side * side - height * height));
  // The contact point's height above the centre, as a fraction of R.
  s.scoop = s.vz > 0.0 && std::cos(tilt) * height + std::sin(tilt) * depth < 0.0;
  const Vec3 contact = (left * -side + up * height - axis * depth) * r;
  const Vec3 impulse = axis * (mass * shot.speed);
  s.w = cross(contact, impulse) * (1.0 / (0.4 * mass * r * r));
  return s;
}

std::optional<Kinematics> strokeBall(int id, double t, Vec2 at, const Shot& shot, double mass,
                                     const PhysicsParams& p, std::vector<Event>& events) {
  Event e;
  e.t = t;
  e.a = id;
  const Strike s = cueStrike(shot, mass, p);
  if (length(shot.tip) > p.miscue_limit || s.scoop) {
    e.type = EventType::Miscue;
    events.push_back(e);
    return std::nullopt;
  }
  Kinematics k{at, s.v, s.w};
  k.vz = s.vz;
  if (k.vz > 0.0) {
    e.type = EventType::Airborne;
    e.va = k.v;
    e.at = at;
    events.push_back(e);
  }
  return k;
}

}  // namespace nineball::physics
