// Practice mode: no rules, any ball anywhere, undo and retry.
#include <gtest/gtest.h>

#include <cmath>

#include "window/game_rolling.hpp"
#include "window/game_session.hpp"
#include "window/practice_mode.hpp"
#include "window/practice_table.hpp"

namespace nineball::window {
namespace {

constexpr double kR = 0.028575;

const BallState* find(const std::vector<BallState>& balls, int id) {
  for (const BallState& b : balls) {
    if (b.id == id && !b.pocket) return &b;
  }
  return nullptr;
}

TEST(PracticeTable, PlacesRemovesAndRefusesOverlaps) {
  MatchSetup setup;
  const Match m(setup);
  PracticeTable t(m.world().table(), kR,
                  {BallState::at(0, {-0.6, 0.0}), BallState::at(3, {0.2, 0.0})});
  EXPECT_TRUE(t.has(0));
  EXPECT_TRUE(t.has(3));
  EXPECT_TRUE(t.place(5, {0.5, 0.3}));
  EXPECT_TRUE(t.has(5));
  // On another ball, or off the table: refused, and the reason named.
  EXPECT_FALSE(t.place(5, {0.2 + kR, 0.0}));
  EXPECT_EQ(t.placementProblem(5, {0.2 + kR, 0.0}).value_or(""), "on the 3");
  EXPECT_FALSE(t.place(5, {2.0, 0.0}));
  EXPECT_EQ(t.placementProblem(5, {2.0, 0.0}).value_or(""), "off the table");
  EXPECT_TRUE(t.remove(3));
  EXPECT_FALSE(t.has(3));
  EXPECT_FALSE(t.remove(0));                        // the cue ball always stays
  const auto spot = t.freeSpotNear(7, {0.5, 0.3});  // taken by the 5: the nearest free spot
  ASSERT_TRUE(spot);
  EXPECT_FALSE(t.placementProblem(7, *spot));
  EXPECT_NEAR(length(*spot - Vec2{0.5, 0.3}), 2.0 * kR, 0.011);
}

TEST(Practice, ShotsHaveNoRulesAndCanBeUndoneAndRetried) {
  MatchSetup setup;
  setup.physics.ball_restitution = 0.0;
  setup.balls = {BallState::at(0, {0.6, 0.0}), BallState::at(1, {0.9, 0.3}),
                 BallState::at(5, {-0.8, -0.3})};
  GameSession s(setup, true);
  ASSERT_TRUE(s.practice());
  EXPECT_FALSE(s.cueInHand());
  EXPECT_FALSE(s.pushOutAvailable());
  // Any ball moves by hand: the 5 to a new spot, and not onto the 1.
  EXPECT_TRUE(s.moveBall(5, {-0.5, 0.2}));
  EXPECT_FALSE(s.moveBall(5, {0.9 + kR, 0.3}));
  EXPECT_EQ(find(s.ballsToDraw(), 5)->pos, (Vec2{-0.5, 0.2}));
  // The 5 first would be a foul in a game; here the cue ball follows the 1 into the pocket.
  s.setHeading(std::atan2(0.3, 0.3));
  s.setSpeed(4.0);
  s.setTip({0.0, 0.2});
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(roll(s));
  EXPECT_EQ(s.phase(), Phase::Aiming);
  EXPECT_EQ(s.seatToMove(), 0);  // no turns
  EXPECT_EQ(find(s.ballsToDraw(), 1), nullptr);
  EXPECT_NE(s.message().find("The 1 down."), std::string::npos) << s.message();
  // The cue ball dropped too: it is back where it was struck from.
  ASSERT_NE(find(s.ballsToDraw(), 0), nullptr);
  EXPECT_EQ(find(s.ballsToDraw(), 0)->pos, (Vec2{0.6, 0.0}));
  EXPECT_NE(s.message().find("back where it was struck from"), std::string::npos);
  EXPECT_EQ(s.pocketedThisRack(), (std::vector<int>{1, 2, 3, 4, 6, 7, 8, 9}));

  // Retry: the same position and cue, and the same shot gives the same end, bit for bit.
  const auto after_first = s.ballsToDraw();
  s.setHeading(0.0);
  s.setTip({});
  s.retryShot();
  ASSERT_NE(find(s.ballsToDraw(), 1), nullptr);
  EXPECT_DOUBLE_EQ(s.heading(), std::atan2(0.3, 0.3));
  EXPECT_EQ(s.tip(), (Vec2{0.0, 0.2}));
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(roll(s));
  const auto after_second = s.ballsToDraw();
  ASSERT_EQ(after_first.size(), after_second.size());
  for (std::size_t i = 0; i < after_first.size(); ++i) {
    EXPECT_EQ(after_first[i].pos, after_second[i].pos) << after_first[i].id;
  }
  // Undo twice: back past both shots (the retry was a shot of its own) to the start.
  s.undoShot();
  s.undoShot();
  ASSERT_NE(find(s.ballsToDraw(), 1), nullptr);
  EXPECT_EQ(find(s.ballsToDraw(), 5)->pos, (Vec2{-0.5, 0.2}));
  // Then the 5's move by hand, which undo takes back too.
  s.undoShot();
  EXPECT_EQ(find(s.ballsToDraw(), 5)->pos, (Vec2{-0.8, -0.3}));
  s.undoShot();
  EXPECT_NE(s.message().find("Nothing to undo"), std::string::npos);
}

TEST(Practice, UndoTakesBackABallMovedOrTakenAwayAndRetryFollowsAnUndo) {
  MatchSetup setup;
  setup.balls = {BallState::at(0, {-0.6, 0.0}), BallState::at(1, {0.4, 0.1}),
                 BallState::at(5, {-0.8, -0.3})};
  GameSession s(setup, true);
  s.retryShot();
  EXPECT_NE(s.message().find("no shot played yet"), std::string::npos) << s.message();
  ASSERT_TRUE(s.moveBall(1, {0.5, 0.3}));
  s.toggleBall(5, {});
  EXPECT_EQ(find(s.ballsToDraw(), 5), nullptr);
  EXPECT_EQ(s.practiceSteps(), 2u);
  s.undoShot();  // the 5 comes back
  ASSERT_NE(find(s.ballsToDraw(), 5), nullptr);
  EXPECT_EQ(find(s.ballsToDraw(), 5)->pos, (Vec2{-0.8, -0.3}));
  s.undoShot();  // the 1 goes back where it was
  EXPECT_EQ(find(s.ballsToDraw(), 1)->pos, (Vec2{0.4, 0.1}));

  // A shot, undone: Y then sets that shot up again rather than finding none.
  s.setHeading(0.1);
  s.setSpeed(2.0);
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(roll(s));
  s.undoShot();
  s.setHeading(1.0);
  s.retryShot();
  EXPECT_EQ(s.message().find("no shot played yet"), std::string::npos) << s.message();
  EXPECT_DOUBLE_EQ(s.heading(), 0.1);
  EXPECT_EQ(find(s.ballsToDraw(), 1)->pos, (Vec2{0.4, 0.1}));
}

TEST(Practice, BallsComeAndGoWithTheirNumbers) {
  GameSession s(MatchSetup{}, true);  // the rack, to practise the break
  ASSERT_NE(find(s.ballsToDraw(), 9), nullptr);
  s.toggleBall(9, {});
  EXPECT_EQ(find(s.ballsToDraw(), 9), nullptr);
  EXPECT_EQ(s.pocketedThisRack(), std::vector<int>{9});
  s.toggleBall(9, {-0.3, 0.2});
  ASSERT_NE(find(s.ballsToDraw(), 9), nullptr);
  EXPECT_EQ(find(s.ballsToDraw(), 9)->pos, (Vec2{-0.3, 0.2}));
  // A practice shot can be replayed like any other, bit for bit.
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(roll(s));
  ShotReplay replay(s.rackSetup(), s.rackTurns(), 1.0);
  for (int i = 0; i < 60 * 120 && !replay.finished(); ++i) replay.advance(1.0 / 60.0);
  const auto end = replay.balls();
  for (const BallState& b : s.match().balls()) {
    const BallState* r = find(end, b.id);
    if (r) {
      EXPECT_EQ(r->pos, b.pos) << b.id;
    }
  }
}

TEST(Practice, TheTrayHoldsEveryBallOfTheGamesRackThatIsOffTheTable) {
  // Eight-ball's rack has fifteen balls: one beyond the 9 taken off is in the tray too.
  MatchSetup eight;
  eight.game = rules::Game::EightBall;
  GameSession s(eight, true);
  EXPECT_TRUE(s.pocketedThisRack().empty());
  PracticeMode practice{Match(eight)};
  ASSERT_TRUE(practice.table().has(15));
  EXPECT_TRUE(practice.offTable().empty());
  struct QuietHost : PracticeHost {
    bool aiming() const override { return true; }
    void rebuildPractice() override { ++rebuilt; }
    void takeCue(const PracticeShot&) override {}
    void say(const std::string&, render::Tone) override {}
    int rebuilt = 0;
  } host;
  practice.toggleBall(host, 15, {});
  practice.toggleBall(host, 12, {});
  EXPECT_EQ(practice.offTable(), (std::vector<int>{12, 15}));
  EXPECT_EQ(host.rebuilt, 2);
}

}  // namespace
}  // namespace nineball::window
