#include "window/cue_setup.hpp"

#include <algorithm>

namespace nineball::window {

void CueSetup::setSpeed(double mps) {
  speed_ = std::clamp(mps, kMinSpeed, kMaxSpeed);
}

void CueSetup::setPower(double fraction) {
  setSpeed(kMinSpeed + std::clamp(fraction, 0.0, 1.0) * (kMaxSpeed - kMinSpeed));
}

void CueSetup::setTip(Vec2 tip, double max_tip) {
  const double len = length(tip);
  const double limit = max_tip * (1.0 - 1e-12);
  tip_ = len > limit ? tip * (limit / len) : tip;
}

void CueSetup::setElevation(double radians) {
  elevation_ = std::clamp(radians, 0.0, degToRad(kMaxElevationDeg));
}

void CueSetup::take(double heading, double speed, Vec2 tip, double elevation) {
  heading_ = heading;
  setSpeed(speed);
  tip_ = tip;
  elevation_ = elevation;
}

void CueSetup::newTurn() {
  tip_ = {};
  elevation_ = 0.0;
  spot_.reset();
}

}  // namespace nineball::window
