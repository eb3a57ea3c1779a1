#include "window/remote_aim.hpp"

#include <cmath>

namespace nineball::window {
namespace {

constexpr double kPi = 3.14159265358979323846;

double lerp(double a, double b, double f) {
  return a + (b - a) * f;
}

Vec2 lerp(Vec2 a, Vec2 b, double f) {
  return {lerp(a.x, b.x, f), lerp(a.y, b.y, f)};
}

bool samePose(const AimPose& a, const AimPose& b) {
  return a.heading_rad == b.heading_rad && a.speed == b.speed && a.tip.x == b.tip.x &&
         a.tip.y == b.tip.y && a.elevation_rad == b.elevation_rad &&
         a.cue.has_value() == b.cue.has_value() &&
         (!a.cue || (a.cue->x == b.cue->x && a.cue->y == b.cue->y));
}

}  // namespace

double easeAngle(double from, double to, double fraction) {
  double d = std::remainder(to - from, 2.0 * kPi);  // -pi..pi: the short way round
  return std::remainder(from + d * fraction, 2.0 * kPi);
}

void AimSmoother::heard(const AimPose& pose) {
  target_ = pose;
  if (!shown_) shown_ = pose;
}

std::optional<AimPose> AimSmoother::advance(double seconds) {
  if (!target_ || !shown_) return std::nullopt;
  const double f = 1.0 - std::exp(-std::max(0.0, seconds) / kEase);
  AimPose& s = *shown_;
  const AimPose& t = *target_;
  s.heading_rad = easeAngle(s.heading_rad, t.heading_rad, f);
  s.speed = lerp(s.speed, t.speed, f);
  s.tip = lerp(s.tip, t.tip, f);
  s.elevation_rad = lerp(s.elevation_rad, t.elevation_rad, f);
  // A ball picked up is carried smoothly; one just put in hand appears where it is held.
  if (t.cue && s.cue) {
    s.cue = lerp(*s.cue, *t.cue, f);
  } else {
    s.cue = t.cue;
  }
  return s;
}

void AimSmoother::reset() {
  target_.reset();
  shown_.reset();
}

bool AimThrottle::due(const AimPose& pose, double now) {
  if (last_ && (now - sent_at_ < kPeriod || samePose(*last_, pose))) return false;
  last_ = pose;
  sent_at_ = now;
  return true;
}

}  // namespace nineball::window
