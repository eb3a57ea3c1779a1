#pragma once

#include "physics/engines/registry.hpp"

namespace nineball::reference {

/// "reference": the exact event-based engine (reference_engine.cpp), with no Box2D and no time
/// step; it reads no field of "step" but max_time.
physics::EngineDef referenceEngine();

}  // namespace nineball::reference
