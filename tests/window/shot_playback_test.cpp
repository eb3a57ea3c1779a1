// The shot as the window plays it: the cue's strike heard once, with the shot's first frame;
// the picture's clock running on (fast-forwarded too) for a second at most once the balls rest;
// the stroke drawn from where the struck ball stood.
#include "window/shot_playback.hpp"

#include <gtest/gtest.h>

namespace nineball::window {
namespace {

struct Playback {
  MatchSetup setup;
  Match match{setup};
  ShotPlayback playback{FixedStepClock::forPlay(setup.step.dt(), setup.step.hz)};
  std::size_t frame(double seconds, bool rolling) {
    std::vector<audio::Impact> impacts;
    playback.advance(seconds, rolling, match, impacts);
    return impacts.size();
  }
};

TEST(ShotPlayback, TheStrikeIsHeardOnceWithTheShotsFirstFrame) {
  Playback p;
  p.playback.begin(p.match, kCueBall, 5.0);
  EXPECT_EQ(p.frame(1.0 / 60.0, false), 1u);
  EXPECT_EQ(p.frame(1.0 / 60.0, false), 0u);
}

TEST(ShotPlayback, ThePicturesClockRunsOnASecondAtMostAfterTheBallsRest) {
  Playback p;
  p.playback.settle(p.match);
  const double rest = p.playback.drawTime(false);
  p.frame(0.25, false);
  EXPECT_DOUBLE_EQ(p.playback.drawTime(false), rest + 0.25);
  p.playback.setPlayRate(2.0);  // fast-forward runs the picture's clock as fast
  p.frame(0.25, false);
  EXPECT_DOUBLE_EQ(p.playback.drawTime(false), rest + 0.75);
  p.frame(5.0, false);
  EXPECT_DOUBLE_EQ(p.playback.drawTime(false), rest + 1.0);
  p.playback.begin(p.match, kCueBall, 3.0);  // a new shot starts the after-rest again
  EXPECT_DOUBLE_EQ(p.playback.drawTime(false), rest);
}

TEST(ShotPlayback, TheStrokeIsDrawnFromWhereTheStruckBallStood) {
  Playback p;
  p.playback.begin(p.match, kCueBall, 3.0);
  Vec2 cue;
  for (const BallState& b : p.playback.balls()) {
    if (b.id == kCueBall) cue = b.pos;
  }
  p.playback.strikeFrom({9.0, 9.0});
  EXPECT_EQ(p.playback.struckFrom(), cue);
  p.playback.begin(p.match, 99, 3.0);  // no such ball: the spot given
  p.playback.strikeFrom({9.0, 9.0});
  EXPECT_EQ(p.playback.struckFrom(), (Vec2{9.0, 9.0}));
}

}  // namespace
}  // namespace nineball::window
