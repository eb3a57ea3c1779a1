#pragma once

#include <array>
#include <optional>

#include "nineball/params.hpp"
#include "physics/model/contact_times.hpp"
#include "physics/model/motion.hpp"

namespace nineball::physics {

/// Two frictionless contacts met together, as a linear complementarity problem on their normal
/// impulses P (Baraff, "Analytical methods for dynamic simulation of non-penetrating rigid
/// bodies", SIGGRAPH 1989; Newton's restitution at each contact): the normal velocities after,
/// u+ = u + M P, must reach at least each contact's target, max(0, -e u), with P >= 0, and a
/// contact that pushes (P > 0) reaches exactly its target. u is each contact's normal velocity
/// before (parting > 0), M the inverse mass the impulses see. M is positive definite for the
/// contacts nineball puts together, so the problem has one answer; it is found by trying the
/// four sets of pushing contacts. With u <= 0 at every pushing contact the energy falls by
/// sum P_i (1 - e_i) (-u_i) / 2: never rises.
struct TwoContacts {
  double m[2][2];
  double u[2];
  double e[2];
};
std::array<double, 2> solveTwoContacts(const TwoContacts& c);

/// The normal rebound ratio the chosen cushion model gives a ball without spin straight in at
/// `speed` (m/s): the restitution of that cushion in a contact solved together with another.
/// 0 at a crawl (at most kRestingSpeed), as every cushion.
double cushionRestitutionAt(double speed, double mass, const PhysicsParams& p);

/// A ball b touching a cushion (inward normal `face`) struck by a ball a: the ball-ball and the
/// ball-cushion normal impulses solved together (solveTwoContacts), then the ball-ball model's
/// grip with the ball-ball impulse and the nose's Coulomb friction (cushionFriction) with the
/// cushion's; whatever friction turns back into a contact is stopped there (e = 0). Friction
/// that would raise the energy is left out (the normal impulses alone never do). Positions are
/// kept.
struct FrozenStrike {
  Kinematics a, b;
  double ball_impulse = 0.0;     ///< kg m/s, along the line of centres
  double cushion_impulse = 0.0;  ///< kg m/s, from the cushion on b
};
FrozenStrike strikeFrozen(Kinematics a, Kinematics b, double mass_a, double mass_b, Vec2 face,
                          const PhysicsParams& p);

/// A ball meeting two cushions (inward normals `first` and `second`) within one contact: both
/// normal impulses solved together, each cushion's restitution as cushionRestitutionAt gives it
/// at that cushion's normal speed. Then both noses' Coulomb friction (cushionFriction's law)
/// with those impulses, from the same state; whatever friction turns back into a face is
/// stopped there (e = 0); friction that would raise the energy is left out. Position kept.
struct CornerBounce {
  Kinematics k;
  double impulse[2] = {0.0, 0.0};
};
CornerBounce intoCorner(Kinematics k, Vec2 first, Vec2 second, double mass, const PhysicsParams& p);

/// The other cushion face (segment or jaw point) a ball of radius r meeting the face `first`
/// reaches within `within` seconds on its straight path, moving into it: its inward normal, the
/// soonest met if several. Faces within 2.6 degrees of `first` are the same face.
std::optional<Vec2> secondFace(const Kinematics& k, Vec2 first, double r, const Cushions& cushions,
                               double within);

}  // namespace nineball::physics
