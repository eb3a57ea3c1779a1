// The mouse never moves the aim while it is over a control or calling a pocket: the pointer on
// its way to the spin icon, the tilt ring or the power gauge, or to a pocket to call it, leaves
// the line the player held; a new turn starts from its own aim, never an old one (the
// computer's last shot). K calls the ball that may be hit first, not a wrong ball aimed at.
#include <gtest/gtest.h>

#include "render/hud_layout.hpp"
#include "window/frame_builder.hpp"
#include "window/game_rolling.hpp"
#include "window/input_events.hpp"

namespace nineball::window {
namespace {

// Ten-ball after its break: every shot is called.
MatchSetup tenBall() {
  MatchSetup setup;
  setup.setGame(rules::Game::TenBall);
  return setup;
}

TEST(AimInput, ThePointerOnItsWayToTheSpinIconLeavesTheAim) {
  InputTable t;
  const Vec2 cue = t.s.cuePosition();
  t.mouseTo(cue + Vec2{0.6, 0.2});
  t.input.update(0.5);  // held still: the player's line
  const double aimed = t.s.heading();
  const render::HudLayout layout = render::HudLayout::of(t.view);
  const Vec2 from = t.view.toPixels(cue + Vec2{0.6, 0.2});
  // The pointer travels there in a quick sweep, a frame apart.
  for (int i = 1; i <= 12; ++i) {
    t.pointerAt(from + (layout.spin_centre - from) * (i / 12.0));
    t.input.update(1.0 / 60.0);
  }
  EXPECT_DOUBLE_EQ(t.s.heading(), aimed);
  // Resting on the icon, on the tilt ring, on the power gauge: the line stays.
  const double mid = 0.5 * (layout.tilt_inner + layout.tilt_outer);
  for (Vec2 px :
       {layout.spin_centre, layout.spin_centre + render::HudLayout::tiltDirection(0.5) * mid,
        Vec2{layout.power_bar.left + 5.0, layout.power_bar.top + 2.0}}) {
    t.pointerAt(px);
    t.input.update(0.5);
    EXPECT_DOUBLE_EQ(t.s.heading(), aimed);
  }
  // A click on the icon sets spin and leaves the line too.
  t.input.handle(mouse(sf::Event::MouseButtonPressed, layout.spin_centre + Vec2{10.0, 0.0}),
                 t.view);
  t.input.handle(mouse(sf::Event::MouseButtonReleased, layout.spin_centre + Vec2{10.0, 0.0}),
                 t.view);
  EXPECT_GT(t.s.tip().x, 0.0);
  EXPECT_DOUBLE_EQ(t.s.heading(), aimed);
}

TEST(AimInput, PointingAtAPocketToCallItKeepsTheTurnsOwnAim) {
  InputTable t(tenBall());
  // The break's line held still, as the computer's aim is held before its shot.
  t.s.setHeading(0.3);
  t.input.update(0.5);
  ASSERT_TRUE(t.s.shoot());
  for (int frame = 0; frame < 60 * 120 && t.s.phase() == Phase::Rolling; ++frame) {
    t.input.update(1.0 / 60.0);
    t.s.advance(1.0 / 60.0);
  }
  ASSERT_EQ(t.s.phase(), Phase::Aiming);
  ASSERT_TRUE(t.s.callRequired());
  t.input.update(1.0 / 60.0);
  const double turn_aim = t.s.heading();  // the new turn's: at the ball on
  ASSERT_NE(turn_aim, 0.3);
  // The pointer goes straight to a pocket and calls it.
  const Vec2 pocket = pocketCentre(t.s, PocketId::TopRight);
  t.mouseTo(pocket);
  t.input.update(1.0 / 60.0);
  EXPECT_DOUBLE_EQ(t.s.heading(), turn_aim);
  t.click(pocket, pocket);
  ASSERT_TRUE(t.s.call());
  EXPECT_DOUBLE_EQ(t.s.heading(), turn_aim);
}

TEST(AimInput, KCallsTheBallOnWhenTheAimIsAtAWrongBall) {
  InputTable t(tenBall());
  ASSERT_TRUE(t.s.shoot());
  ASSERT_TRUE(roll(t.s));
  ASSERT_TRUE(t.s.callRequired());
  const int on = t.s.match().rack().ballOn();
  // Aim straight at another ball on the table, one that may not be hit first, and that the
  // guide shows as the first ball met.
  const Vec2 cue = t.s.cuePosition();
  bool aimed_wrong = false;
  for (const BallState& b : t.s.match().balls()) {
    if (aimed_wrong || b.id == kCueBall || b.id == on || b.pocket) continue;
    t.s.setHeading(std::atan2(b.pos.y - cue.y, b.pos.x - cue.x));
    const AimGuide guide = t.s.aimGuide();
    aimed_wrong = guide.target == AimTarget::Ball && guide.ball == b.id;
  }
  ASSERT_TRUE(aimed_wrong);
  t.tap(sf::Keyboard::K);
  ASSERT_TRUE(t.s.call());
  EXPECT_EQ(t.s.call()->ball, on);
}

TEST(DialogButtons, SnookersReplaceAfterAMissHasAButtonOfItsOwn) {
  // A miss (the red in view, the cue ball played away from it): the fouled player may play,
  // put the offender back in, or have the balls replaced.
  MatchSetup setup;
  setup.setGame(rules::Game::Snooker);
  setup.balls = std::vector<BallState>{BallState::at(kCueBall, {0.0, 0.0}),
                                       BallState::at(1, {0.8, 0.0}), BallState::at(20, {0.3, 0.3})};
  InputTable t(setup);
  t.s.playTurn([] {
    TurnInput miss;
    miss.shot = Shot::withSpeed(180.0, 0.1);
    return miss;
  }());
  ASSERT_EQ(t.s.match().rack().pendingDecision(), rules::Decision::PlayPutBackOrReplace);
  const render::Frame f = buildFrame(t.s, t.ui, t.seats);
  EXPECT_EQ(f.hud.button_middle, "Replace (R)");
  const render::HudLayout layout =
      render::HudLayout::of(t.view, f.hud.dialog, dialogKeepClear(t.s), true);
  // Three buttons side by side inside the dialog.
  EXPECT_LT(layout.button_left.left + layout.button_left.width, layout.button_middle.left);
  EXPECT_LT(layout.button_middle.left + layout.button_middle.width, layout.button_right.left);
  EXPECT_GE(layout.button_left.left, layout.panel.left);
  EXPECT_LE(layout.button_right.left + layout.button_right.width,
            layout.panel.left + layout.panel.width);
  const Vec2 middle{layout.button_middle.left + layout.button_middle.width / 2.0,
                    layout.button_middle.top + layout.button_middle.height / 2.0};
  const std::size_t turns = t.s.rackTurns().size();
  // The push-out choice's screen answers the click (the window routes it there).
  t.send(mouse(sf::Event::MouseButtonPressed, middle));
  t.send(mouse(sf::Event::MouseButtonReleased, middle));
  ASSERT_EQ(t.s.rackTurns().size(), turns + 1);
  EXPECT_TRUE(t.s.rackTurns().back().replace);
}

}  // namespace
}  // namespace nineball::window
