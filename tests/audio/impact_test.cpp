// Sounds from physics events: how hard each impact was, how loud it plays, the samples.
#include "audio/impact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "audio/synth.hpp"

using nineball::BallState;
using nineball::Event;
using nineball::EventType;
using nineball::Vec2;
using nineball::audio::Impact;
using nineball::audio::ImpactKind;
using nineball::audio::impactsFromEvents;
using nineball::audio::impactVolume;

namespace {

BallState moving(int id, Vec2 v) {
  BallState b;
  b.id = id;
  b.vel = v;
  return b;
}

}  // namespace

TEST(Impacts, StrengthIsTheSpeedChangeOfTheEvent) {
  const std::vector<BallState> before = {moving(0, {2.0, 0.0}), moving(1, {0.0, 0.0}),
                                         moving(2, {0.0, 1.0})};
  Event click;
  click.type = EventType::BallBall;
  click.a = 0;
  click.b = 1;
  click.va = {0.05, 0.0};
  click.vb = {1.95, 0.0};
  Event thud;
  thud.type = EventType::Cushion;
  thud.a = 2;
  thud.va = {0.0, -0.8};
  Event drop;
  drop.type = EventType::Pocket;
  drop.a = 2;
  const auto impacts = impactsFromEvents({click, thud, drop}, before);
  ASSERT_EQ(impacts.size(), 3u);
  EXPECT_EQ(impacts[0].kind, ImpactKind::Ball);
  EXPECT_NEAR(impacts[0].strength, 1.95, 1e-12);
  EXPECT_EQ(impacts[1].kind, ImpactKind::Cushion);
  EXPECT_NEAR(impacts[1].strength, 1.8, 1e-12);
  EXPECT_EQ(impacts[2].kind, ImpactKind::Pocket);
  EXPECT_NEAR(impacts[2].strength, 1.0, 1e-12);
}

TEST(Impacts, LouderForHarderUpToFull) {
  double last = -1.0;
  for (double v : {0.0, 0.05, 0.3, 1.0, 3.0, 6.0, 20.0}) {
    const double vol = impactVolume({ImpactKind::Ball, v});
    EXPECT_GE(vol, last) << v;
    EXPECT_LE(vol, 100.0);
    last = vol;
  }
  EXPECT_EQ(impactVolume({ImpactKind::Ball, 0.0}), 0.0);
  EXPECT_EQ(impactVolume({ImpactKind::Ball, 20.0}), 100.0);
}

TEST(Synth, SoundsAreShortAndNotSilent) {
  for (const auto& samples : {nineball::audio::synthClick(), nineball::audio::synthThud(),
                              nineball::audio::synthPocketDrop()}) {
    ASSERT_FALSE(samples.empty());
    EXPECT_LT(samples.size(), nineball::audio::kSampleRate);  // under a second
    int peak = 0;
    for (auto s : samples) peak = std::max(peak, std::abs(static_cast<int>(s)));
    EXPECT_GT(peak, 20000);
  }
}
