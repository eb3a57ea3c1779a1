#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "nineball/event.hpp"
#include "nineball/params.hpp"
#include "nineball/table.hpp"
#include "physics/model/contact_times.hpp"
#include "physics/model/motion.hpp"
#include "physics/model/next_event.hpp"
#include "physics/resolve/jam/jam_counter.hpp"

namespace nineball::physics {

/// A cushion's answer to a ball: its state after, the normal the impulse acted along, and the
/// size of that impulse (kg m/s).
struct CushionRebound {
  Kinematics k;
  Vec2 normal;
  double impulse = 0.0;
};

/// What an engine lends the resolver: its balls, by the engine's own index, and the solvers
/// of its own it may use instead of the resolver's.
class EngineBalls {
 public:
  virtual ~EngineBalls() = default;

  /// How many balls the engine numbers, on the table or not.
  virtual std::size_t count() const = 0;
  virtual bool onTable(std::size_t i) const = 0;
  virtual int id(std::size_t i) const = 0;
  virtual double mass(std::size_t i) const = 0;
  /// The ball's centre now, as the engine holds it.
  virtual Vec2 centre(std::size_t i) const = 0;
  /// The ball's state now (its centre as centre() gives it).
  virtual Kinematics now(std::size_t i) const = 0;
  /// The closed form the ball follows now.
  virtual const Arc& arc(std::size_t i) const = 0;
  /// From now on the ball follows `k`, moved to k.p first where that is not its centre.
  virtual void restart(std::size_t i, const Kinematics& k) = 0;
  /// The ball's motion passes into its next phase (slide to roll, roll to rest, spin dying).
  virtual void nextPhase(std::size_t i) = 0;
  /// The ball leaves the table into `pocket`, or over a rail when none (the resolver records
  /// the event).
  virtual void drop(std::size_t i, std::optional<PocketId> pocket) = 0;

  /// An engine with a ball solver of its own resolves the contact of i and j and says true;
  /// false leaves it to the resolver.
  virtual bool solvedBallContact(std::size_t i, std::size_t j);
  /// The paper's restitution law at a cushion of normal `predicted` (cushion models with no
  /// rebound of their own, and every model at a crawl): by default bounceOffCushion.
  virtual CushionRebound restitutionBounce(std::size_t i, const Kinematics& k, Vec2 predicted,
                                           const PhysicsParams& p);
};

/// The one place an event is resolved: a phase ending, a ball-ball contact (pairwise, or the
/// jam it belongs to), a cushion contact with the chosen cushion model, a ball dropping. Every
/// engine calls it for every event it finds, so both engines follow one physics.
class Resolver {
 public:
  /// `cushions` and `events` must outlive the resolver; events are appended to `events`.
  Resolver(const PhysicsParams& p, const TableGeometry& table, const Cushions& cushions,
           std::vector<Event>& events);

  /// Resolves `e` at its time e.t.
  void resolve(const NextEvent& e, EngineBalls& balls);

  /// Records a ball-ball contact at time t with the velocities just after it.
  void ballEvent(double t, const EngineBalls& balls, std::size_t i, std::size_t j, Vec2 va,
                 Vec2 vb);
  /// Balls pressed together are set back to touching (see setApart), and follow `sa`, `sb`.
  void placeApart(EngineBalls& balls, std::size_t i, std::size_t j, Kinematics sa,
                  Kinematics sb) const;

 private:
  void ballContact(double t, EngineBalls& balls, std::size_t i, std::size_t j);
  bool frozenContact(double t, EngineBalls& balls, std::size_t i, std::size_t j);
  bool cornerContact(double t, EngineBalls& balls, std::size_t i, const Kinematics& k,
                     Vec2 predicted);
  void cushionEvent(double t, const EngineBalls& balls, std::size_t i, Vec2 v, Vec2 at);
  void phaseEnd(double t, EngineBalls& balls, std::size_t i);
  void contactInAir(double t, EngineBalls& balls, std::size_t i, std::size_t j);
  void offTable(double t, EngineBalls& balls, std::size_t i);
  void ballEventOf(EventType type, double t, const EngineBalls& balls, std::size_t i, Vec2 v,
                   Vec2 at);
  void settleJam(double t, EngineBalls& balls, std::size_t i, std::size_t j);
  void cushionContact(double t, EngineBalls& balls, std::size_t i, Vec2 predicted);
  void settleOnCushion(double t, EngineBalls& balls, std::size_t i, Kinematics k, Vec2 normal,
                       Vec2 predicted, double impulse);
  void pocket(double t, EngineBalls& balls, std::size_t i, PocketId pocket);
  bool thrownBack(double t, EngineBalls& balls, std::size_t i, PocketId pocket);
  std::vector<Vec2> faces(Vec2 p) const;

  const PhysicsParams& p_;
  const TableGeometry& table_;
  const Cushions& cushions_;
  std::vector<Event>& events_;
  JamCounter jams_;

 public:
  /// As new: nothing counted towards a jam.
  void reset() { jams_.reset(); }
};

}  // namespace nineball::physics
