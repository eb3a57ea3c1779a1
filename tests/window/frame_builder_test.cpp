// The picture of the game: what the leave dialog says, the aim guide's foul warning, the
// balls a dialog keeps clear of.
#include "window/frame_builder.hpp"

#include <gtest/gtest.h>

#include "window/game_rolling.hpp"
#include "window/screens/dialog_contents.hpp"

namespace nineball::window {
namespace {

std::string leaveLine(const GameSession& s, const UiState& ui) {
  UiState open = ui;
  open.confirm_quit = true;
  const render::Frame f = buildFrame(s, open, Seats(1));
  EXPECT_EQ(dialogCalledFor(s, open), DialogKind::ConfirmQuit);
  EXPECT_TRUE(f.hud.dialog.has_value());
  return f.hud.overlay_lines.empty() ? "" : f.hud.overlay_lines.front();
}

TEST(FrameBuilder, TheLeaveDialogSaysWhatBecomesOfTheRack) {
  GameSession s{MatchSetup{}};
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(roll(s));
  UiState kept;
  kept.leave_to_menu = true;
  kept.rack_kept = true;
  EXPECT_NE(leaveLine(s, kept).find("saved"), std::string::npos) << leaveLine(s, kept);
  EXPECT_EQ(leaveLine(s, kept).find("lost"), std::string::npos) << leaveLine(s, kept);
  EXPECT_TRUE(leavingLosesNothing(s, kept));
  UiState scripted;  // no menu, nothing saved: the rack is lost, and the dialog says so
  EXPECT_NE(leaveLine(s, scripted).find("will be lost"), std::string::npos);
  EXPECT_FALSE(leavingLosesNothing(s, scripted));
  const GameSession practice(MatchSetup{}, true);
  EXPECT_NE(leaveLine(practice, kept).find("practice table is not kept"), std::string::npos);
}

TEST(FrameBuilder, TheGuideWarnsWhenItsFirstBallWouldBeAFoul) {
  MatchSetup setup;
  setup.balls = {BallState::at(0, {-0.6, 0.0}), BallState::at(1, {0.5, 0.4}),
                 BallState::at(3, {0.3, 0.0})};
  GameSession s(setup);
  UiState ui;
  s.setHeading(0.0);  // straight at the 3
  const render::Frame foul = buildFrame(s, ui, Seats(1));
  ASSERT_TRUE(foul.guide);
  EXPECT_EQ(foul.guide->ball, 3);
  EXPECT_EQ(foul.guide_foul, "foul: the 3 is not the ball on");
  s.setHeading(std::atan2(0.4, 1.1));  // at the 1
  const render::Frame fine = buildFrame(s, ui, Seats(1));
  ASSERT_TRUE(fine.guide);
  EXPECT_EQ(fine.guide->ball, 1);
  EXPECT_EQ(fine.guide_foul, "");
}

TEST(FrameBuilder, ARaisedCueShowsItsTiltAndWhereTheJumpLands) {
  // The 1 straight ahead beyond the 3: a jump at 45 degrees and 3.5 m/s clears the 3.
  MatchSetup setup;
  setup.balls = {BallState::at(0, {-0.6, 0.0}), BallState::at(3, {-0.3, 0.0}),
                 BallState::at(1, {0.5, 0.0})};
  GameSession s(setup);
  UiState ui;
  s.setHeading(0.0);
  const render::Frame level = buildFrame(s, ui, Seats(1));
  ASSERT_TRUE(level.guide && level.cue);
  EXPECT_EQ(level.guide->ball, 3) << "on the cloth the 3 is in the way";
  EXPECT_TRUE(level.guide->landings.empty());
  EXPECT_EQ(level.cue->elevation_rad, 0.0);

  s.setElevation(degToRad(45.0));
  s.setSpeed(3.5);
  const render::Frame raised = buildFrame(s, ui, Seats(1));
  ASSERT_TRUE(raised.guide && raised.cue);
  EXPECT_DOUBLE_EQ(raised.cue->elevation_rad, degToRad(45.0));
  EXPECT_EQ(raised.guide->ball, 1) << "the jump passes over the 3 to the 1";
  ASSERT_FALSE(raised.guide->landings.empty());
  // The first landing beyond the 3 and short of the ghost ball, on the line of aim; each later
  // one further on.
  const Vec2 first = raised.guide->landings.front();
  EXPECT_GT(first.x, -0.3 + 2.0 * setup.physics.ball_radius);
  EXPECT_LT(first.x, raised.guide->end.x);
  EXPECT_NEAR(first.y, 0.0, 1e-12);
  for (std::size_t i = 1; i < raised.guide->landings.size(); ++i) {
    EXPECT_GT(raised.guide->landings[i].x, raised.guide->landings[i - 1].x);
  }
}

TEST(FrameBuilder, DialogsKeepClearOfEveryBallOnTheTable) {
  GameSession s{MatchSetup{}};
  std::size_t on_table = 0;
  for (const BallState& b : s.ballsToDraw()) on_table += b.pocket ? 0 : 1;
  EXPECT_EQ(dialogKeepClear(s).size(), on_table);
  EXPECT_GT(on_table, 1u);
}

}  // namespace
}  // namespace nineball::window

namespace nineball::window {
namespace {

TEST(FrameBuilder, TheRacksEndSaysHowItEndedOnceAndTheHelpNamesTheLevels) {
  // The 9 on the lip of the top-right pocket, the cue ball drawn back from it.
  MatchSetup setup;
  setup.balls =
      std::vector<BallState>{BallState::at(kCueBall, {0.95, 0.32}), BallState::at(9, {1.18, 0.55})};
  GameSession s(setup);
  s.setHeading(degToRad(45.0));
  s.setSpeed(0.9);
  s.setTip({0.0, -0.4});
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(roll(s));
  ASSERT_EQ(s.phase(), Phase::GameOver);
  UiState ui;
  const render::Frame over = buildFrame(s, ui, Seats(1));
  ASSERT_EQ(dialogCalledFor(s, ui), DialogKind::GameOver);
  ASSERT_TRUE(over.hud.dialog.has_value());
  EXPECT_TRUE(over.hud.dialog->win);  // the rack's end titled in the win colour
  EXPECT_EQ(over.hud.message, s.message());
  for (const std::string& line : over.hud.overlay_lines) EXPECT_NE(line, s.message());
  // The help names the computer's seven levels, not the old three.
  ui.help = true;
  const render::Frame help = buildFrame(s, ui, Seats(1));
  bool levels = false;
  for (const std::string& line : help.hud.overlay_lines) {
    EXPECT_EQ(line.find("easy"), std::string::npos) << line;
    levels |= line.find("beginner to master") != std::string::npos;
  }
  EXPECT_TRUE(levels);
}

}  // namespace
}  // namespace nineball::window
