#include "play/jump_flight.hpp"

#include <cmath>

#include "physics/model/slate.hpp"
#include "physics/resolve/cue/cue.hpp"

namespace nineball::play {
namespace {

// Points along a flight where its distance from a ball is checked, across the 4R round the ball.
constexpr int kClearanceSamples = 24;

bool flightClears(const Flight& f, const BallState& ball, double radius, double margin) {
  const double span = length(f.to - f.from);
  if (span <= 0.0) return true;
  const Vec2 dir = (f.to - f.from) / span;
  const Vec2 rel = ball.pos - f.from;
  const double along = dot(rel, dir);
  const double across = cross(dir, rel);
  const double need = 2.0 * radius + margin;
  if (std::abs(across) >= need || along < -need || along > span + need) return true;
  for (int i = 0; i <= kClearanceSamples; ++i) {
    const double x = along - need + 2.0 * need * i / kClearanceSamples;
    if (x < 0.0 || x > span) continue;
    const double dx = x - along;
    const double dz = f.heightAt(x) - ball.z;
    if (dx * dx + across * across + dz * dz < need * need) return false;
  }
  return true;
}

// A ball the flights clear that a ball rolling along their line would meet.
bool passesOver(const std::vector<Flight>& flights, const BallState& ball, double radius) {
  for (const Flight& f : flights) {
    const double span = length(f.to - f.from);
    if (span <= 0.0) continue;
    const Vec2 dir = (f.to - f.from) / span;
    const Vec2 rel = ball.pos - f.from;
    const double along = dot(rel, dir);
    if (along > 0.0 && along < span + 2.0 * radius && std::abs(cross(dir, rel)) < 2.0 * radius) {
      return flightsClear(flights, ball, radius);
    }
  }
  return false;
}

}  // namespace

double Flight::heightAt(double along) const {
  if (speed <= 0.0) return 0.0;
  const double t = along / speed;
  return vz * t - 0.5 * gravity * t * t;
}

std::vector<Flight> cueBallFlights(const PhysicsParams& p, Vec2 cue, const Shot& shot,
                                   int max_flights) {
  std::vector<Flight> out;
  if (!physics::airborneAllowed(p) || length(shot.tip) > p.miscue_limit) return out;
  const physics::Strike s = physics::cueStrike(shot, p.ball_mass, p);
  if (s.scoop || s.vz <= 0.0) return out;
  physics::Kinematics k{cue, s.v, s.w};
  k.vz = s.vz;
  while (k.vz > 0.0 && static_cast<int>(out.size()) < max_flights) {
    const double t = physics::landingTime(0.0, k.vz, p.gravity);
    Flight f{k.p, k.p + k.v * t, k.vz, p.gravity, length(k.v)};
    out.push_back(f);
    k.p = f.to;
    k.vz = -k.vz;  // it comes down as fast as it went up
    k = physics::bounceOffSlate(k, p);
  }
  return out;
}

AimGuide jumpAimGuide(const TableGeometry& table, const PhysicsParams& p,
                      const std::vector<BallState>& balls, Vec2 cue, const Shot& shot, int cue_id) {
  const std::vector<Flight> flights = cueBallFlights(p, cue, shot);
  if (flights.empty()) {
    return computeAimGuide(table, p.ball_radius, balls, cue, shot.heading_rad, cue_id);
  }
  std::vector<BallState> in_the_way;
  for (const BallState& b : balls) {
    if (b.id == cue_id || !passesOver(flights, b, p.ball_radius)) in_the_way.push_back(b);
  }
  AimGuide guide = computeAimGuide(table, p.ball_radius, in_the_way, cue, shot.heading_rad, cue_id);
  const double reach = length(guide.end - cue);
  for (const Flight& f : flights) {
    if (length(f.to - cue) < reach) guide.landings.push_back(f.to);
  }
  return guide;
}

bool flightsClear(const std::vector<Flight>& flights, const BallState& ball, double radius,
                  double margin) {
  for (const Flight& f : flights) {
    if (!flightClears(f, ball, radius, margin)) return false;
  }
  return true;
}

}  // namespace nineball::play
