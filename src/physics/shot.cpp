#include "nineball/shot.hpp"

#include <cmath>

#include "nineball/event.hpp"

namespace nineball {

Shot Shot::withSpeed(double heading_deg, double speed) {
  Shot s;
  // Reduced first: any finite angle is a direction (1e308 degrees would overflow in radians).
  s.heading_rad = degToRad(std::remainder(heading_deg, 360.0));
  s.speed = speed;
  return s;
}

Shot Shot::withImpulse(double heading_deg, double force, double contact_time, double mass) {
  return withSpeed(heading_deg, force * contact_time / mass);
}

const char* eventTypeName(EventType t) {
  switch (t) {
    case EventType::BallBall:
      return "ball";
    case EventType::Cushion:
      return "cushion";
    case EventType::Pocket:
      return "pocket";
    case EventType::AllAtRest:
      return "rest";
    case EventType::Miscue:
      return "miscue";
    case EventType::Airborne:
      return "airborne";
    case EventType::Land:
      return "land";
    case EventType::OffTable:
      return "off_table";
  }
  return "?";
}

}  // namespace nineball
