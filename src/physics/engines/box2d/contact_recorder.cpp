#include "physics/engines/box2d/contact_recorder.hpp"

namespace nineball::physics {
namespace {

constexpr unsigned kKindShift = 24;

struct Pair {
  b2Fixture* ball;
  b2Fixture* other;
  FixtureKind other_kind;
};

// Orders a contact as (ball, other); a contact between two non-balls gives nothing.
bool asBallPair(b2Contact* c, Pair& out) {
  b2Fixture* a = c->GetFixtureA();
  b2Fixture* b = c->GetFixtureB();
  if (fixtureKind(a) == FixtureKind::Ball) {
    out = {a, b, fixtureKind(b)};
    return true;
  }
  if (fixtureKind(b) == FixtureKind::Ball) {
    out = {b, a, fixtureKind(a)};
    return true;
  }
  return false;
}

}  // namespace

std::uintptr_t fixtureTag(FixtureKind kind, std::size_t index) {
  return (static_cast<std::uintptr_t>(kind) << kKindShift) | index;
}

FixtureKind fixtureKind(b2Fixture* f) {
  return static_cast<FixtureKind>(f->GetUserData().pointer >> kKindShift);
}

std::size_t fixtureIndex(b2Fixture* f) {
  return f->GetUserData().pointer & ((std::uintptr_t{1} << kKindShift) - 1);
}

void ContactRecorder::BeginContact(b2Contact* contact) {
  Pair p{};
  if (!asBallPair(contact, p)) return;
  const std::size_t i = fixtureIndex(p.ball);
  if (p.other_kind == FixtureKind::Pocket) ++over_pocket_[i];
}

void ContactRecorder::EndContact(b2Contact* contact) {
  Pair p{};
  if (asBallPair(contact, p) && p.other_kind == FixtureKind::Pocket) {
    --over_pocket_[fixtureIndex(p.ball)];
  }
}

void ContactRecorder::PreSolve(b2Contact* contact, const b2Manifold* /*old_manifold*/) {
  Pair p{};
  if (!asBallPair(contact, p)) return;
  if (p.other_kind == FixtureKind::Ball) {
    contact->SetEnabled(ball_contacts);
    contact->SetRestitution(ball_restitution_);
    contact->SetRestitutionThreshold(threshold_);
  } else if (p.other_kind == FixtureKind::Cushion) {
    contact->SetEnabled(fixtureIndex(p.ball) == bouncing);
  }
}

void ContactRecorder::PostSolve(b2Contact* contact, const b2ContactImpulse* impulse) {
  Pair p{};
  if (!asBallPair(contact, p)) return;
  if (impulse->count < 1 || impulse->normalImpulses[0] <= 0.0f) return;
  if (p.other_kind == FixtureKind::Ball) {
    ball_hits.emplace_back(fixtureIndex(contact->GetFixtureA()),
                           fixtureIndex(contact->GetFixtureB()));
    return;
  }
  if (p.other_kind != FixtureKind::Cushion) return;
  b2WorldManifold wm;
  contact->GetWorldManifold(&wm);
  // Box2D's normal points from fixture A to fixture B.
  const b2Vec2 towards_cushion = p.ball == contact->GetFixtureA() ? wm.normal : -wm.normal;
  cushion_pushes.push_back({fixtureIndex(p.ball), towards_cushion, impulse->normalImpulses[0]});
}

}  // namespace nineball::physics
