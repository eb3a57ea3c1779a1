#pragma once

#include "nineball/sim.hpp"

namespace nineball::reference {

/// Runs a checked scene (see validateScene) with the exact event-based solver: no Box2D and
/// no time step. Between events every ball follows the closed form of its phase; each event
/// (a contact, a phase ending, a pocket) is the root of a polynomial in time, found to full
/// precision, and resolved by the same models as the Box2D engine. It is the yardstick the
/// Box2D engine is measured against. `steps` in the result is 0.
SimResult simulate(const Scene& scene);

}  // namespace nineball::reference
