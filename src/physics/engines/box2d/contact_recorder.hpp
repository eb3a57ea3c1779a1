#pragma once

#include <box2d/box2d.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace nineball::physics {

/// What a fixture is, packed into its user data: kind in the high bits, ball index below.
enum class FixtureKind : std::uintptr_t { Ball = 1, Cushion = 2, Pocket = 3 };

std::uintptr_t fixtureTag(FixtureKind kind, std::size_t index);
FixtureKind fixtureKind(b2Fixture* f);
std::size_t fixtureIndex(b2Fixture* f);

/// Records contacts during a Box2D step; the world turns them into events after Step returns
/// (bodies are never created or destroyed inside the callbacks).
class ContactRecorder : public b2ContactListener {
 public:
  /// Restitution for ball-ball contacts when Box2D solves them (the Box2D contact model).
  void setBallRestitution(float e, float threshold) {
    ball_restitution_ = e;
    threshold_ = threshold;
  }
  /// Box2D resolves only what the world asks it to: the cushion contacts of one ball (a bounce
  /// the world predicted), or every ball-ball contact (the Box2D contact model). Every other
  /// contact is switched off for the step, since the world moves the balls itself.
  static constexpr std::size_t kNoBall = static_cast<std::size_t>(-1);
  std::size_t bouncing = kNoBall;
  bool ball_contacts = false;

  /// Balls per index currently overlapping a pocket sensor.
  void resize(std::size_t balls) { over_pocket_.resize(balls, 0); }

  void BeginContact(b2Contact* contact) override;
  void EndContact(b2Contact* contact) override;
  void PreSolve(b2Contact* contact, const b2Manifold* old_manifold) override;
  void PostSolve(b2Contact* contact, const b2ContactImpulse* impulse) override;

  /// A cushion pushing a ball: the unit normal from the ball towards the cushion and the
  /// normal impulse, in Box2D units.
  struct CushionPush {
    std::size_t ball;
    b2Vec2 normal;
    float impulse;
  };
  std::vector<CushionPush> cushion_pushes;  ///< this step, in solver order

  std::vector<std::pair<std::size_t, std::size_t>> ball_hits;  ///< pairs Box2D pushed apart
  bool overPocket(std::size_t ball) const { return over_pocket_[ball] > 0; }

 private:
  std::vector<int> over_pocket_;
  float ball_restitution_ = 0.0f;
  float threshold_ = 0.0f;
};

}  // namespace nineball::physics
