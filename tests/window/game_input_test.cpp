// The mouse on the HUD: the tilt ring beside the spin icon raises and lowers the cue.
#include "window/game_input.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "render/hud_layout.hpp"
#include "window/game_rolling.hpp"
#include "window/game_session.hpp"
#include "window/input_events.hpp"
#include "window/seats/seats.hpp"

namespace nineball::window {
namespace {

TEST(TiltRing, AClickAndADragOnTheRingTiltTheCue) {
  GameSession s{MatchSetup{}};
  UiState ui;
  Seats seats(1);
  GameInput input(s, ui, seats);
  const render::ViewTransform view(s.match().world().table().def, 1280, 800);
  const render::HudLayout layout = render::HudLayout::of(view);
  const double mid = 0.5 * (layout.tilt_inner + layout.tilt_outer);
  auto on_ring = [&](double deg) {
    return layout.spin_centre + render::HudLayout::tiltDirection(degToRad(deg)) * mid;
  };
  // A pixel is a degree or so at this size.
  constexpr double kPixelDeg = 2.0;
  input.handle(mouse(sf::Event::MouseButtonPressed, on_ring(30.0)), view);
  EXPECT_NEAR(radToDeg(s.elevation()), 30.0, kPixelDeg);
  input.handle(mouse(sf::Event::MouseMoved, on_ring(10.0)), view);
  EXPECT_NEAR(radToDeg(s.elevation()), 10.0, kPixelDeg);
  // Dragged past the top the cue stops at its steepest.
  input.handle(mouse(sf::Event::MouseMoved, on_ring(85.0)), view);
  EXPECT_DOUBLE_EQ(radToDeg(s.elevation()), GameSession::kMaxElevationDeg);
  input.handle(mouse(sf::Event::MouseButtonReleased, on_ring(85.0)), view);
  // Moving after the release aims again and leaves the tilt alone.
  input.handle(mouse(sf::Event::MouseMoved, on_ring(5.0)), view);
  EXPECT_DOUBLE_EQ(radToDeg(s.elevation()), GameSession::kMaxElevationDeg);
  EXPECT_EQ(ui.drag, Drag::None);
}

TEST(TiltRing, OnlyTheRingTilts) {
  const render::ViewTransform view(TableDef{}, 1280, 800);
  const render::HudLayout layout = render::HudLayout::of(view);
  const double mid = 0.5 * (layout.tilt_inner + layout.tilt_outer);
  const Vec2 c = layout.spin_centre;
  EXPECT_TRUE(layout.tiltAt(c + Vec2{-mid, 0.0}));
  EXPECT_FALSE(layout.tiltAt(c));                                // the icon sets the tip
  EXPECT_FALSE(layout.tiltAt(c + Vec2{mid, 0.0}));               // right of the icon
  EXPECT_FALSE(layout.tiltAt(c + Vec2{-mid * 0.7, mid * 0.7}));  // below it
  EXPECT_FALSE(layout.tiltAt(c + Vec2{-3.0 * mid, 0.0}));        // far off
}

}  // namespace
}  // namespace nineball::window

namespace nineball::window {
namespace {

using Table = InputTable;

TEST(SpinKeys, LAndRGiveSideSpinTAndBTopAndBackCCentres) {
  GameSession s{MatchSetup{}};
  UiState ui;
  Seats seats(1);
  GameInput input(s, ui, seats);
  const render::ViewTransform view(s.match().world().table().def, 1280, 800);
  auto press = [&](sf::Keyboard::Key k) {
    input.handle(key(k), view);
    input.handle(release(k), view);
  };
  press(sf::Keyboard::L);
  press(sf::Keyboard::L);
  EXPECT_NEAR(s.tip().x, -0.2, 1e-12);
  press(sf::Keyboard::R);
  EXPECT_NEAR(s.tip().x, -0.1, 1e-12);
  press(sf::Keyboard::T);
  EXPECT_NEAR(s.tip().y, 0.1, 1e-12);
  press(sf::Keyboard::B);
  press(sf::Keyboard::B);
  EXPECT_NEAR(s.tip().y, -0.1, 1e-12);
  for (int i = 0; i < 20; ++i) press(sf::Keyboard::R);
  EXPECT_LE(length(s.tip()), s.maxTip());  // held inside the useful range
  EXPECT_GT(s.tip().x, 0.0);
  press(sf::Keyboard::C);
  EXPECT_EQ(s.tip(), Vec2{});
}

TEST(ReplayKey, VReplaysTheLastShotAndAnyKeyReturns) {
  GameSession s{MatchSetup{}};
  UiState ui;
  Seats seats(1);
  GameInput input(s, ui, seats);
  const render::ViewTransform view(s.match().world().table().def, 1280, 800);
  input.handle(key(sf::Keyboard::V), view);
  input.handle(release(sf::Keyboard::V), view);
  EXPECT_FALSE(s.replaying());  // nothing to replay before the break
  ASSERT_TRUE(s.shoot());
  for (int i = 0; i < 60 * 120 && s.phase() == Phase::Rolling; ++i) s.advance(1.0 / 60.0);
  input.handle(key(sf::Keyboard::V, true), view);
  input.handle(release(sf::Keyboard::V), view);
  ASSERT_TRUE(s.replaying());
  EXPECT_NE(s.status().find("Slow replay"), std::string::npos);
  const double heading = s.heading();
  input.handle(key(sf::Keyboard::Left), view);  // returns, and does not aim
  EXPECT_FALSE(s.replaying());
  EXPECT_EQ(s.heading(), heading);
}

TEST(FineAim, TheWheelAndCtrlOrAltWithTheArrowsTurnAHundredthOfADegree) {
  Table t;
  const double h0 = t.s.heading();
  t.input.handle(wheel(1.0f), t.view);
  EXPECT_NEAR(radToDeg(t.s.heading() - h0), 0.01, 1e-9);
  t.input.handle(wheel(-3.0f), t.view);
  EXPECT_NEAR(radToDeg(t.s.heading() - h0), -0.02, 1e-9);
  const double h1 = t.s.heading();
  sf::Event ctrl_left = key(sf::Keyboard::Left);
  ctrl_left.key.control = true;
  t.input.handle(ctrl_left, t.view);
  t.input.handle(release(sf::Keyboard::Left), t.view);
  EXPECT_NEAR(radToDeg(t.s.heading() - h1), 0.01, 1e-9);
  sf::Event alt_right = key(sf::Keyboard::Right);
  alt_right.key.alt = true;
  t.input.handle(alt_right, t.view);
  t.input.handle(release(sf::Keyboard::Right), t.view);
  EXPECT_NEAR(radToDeg(t.s.heading() - h1), 0.0, 1e-9);
  t.tap(sf::Keyboard::Left);  // without them, a tenth of a degree
  EXPECT_NEAR(radToDeg(t.s.heading() - h1), 0.1, 1e-9);
}

TEST(MouseAim, APressOverTheScoreBandAimsAndShoots) {
  Table t;
  const render::PixelRect band = t.view.topBand();
  const Vec2 in_band = t.view.toWorld({band.left + band.width * 0.3, band.top + band.height / 2});
  t.mouseTo(in_band);
  const Vec2 dir = fromAngle(t.s.heading());
  t.click(in_band, in_band - dir * 0.2);  // drawn back 20 cm
  EXPECT_EQ(t.s.phase(), Phase::Rolling);
}

TEST(CueDrop, ARefusalIsInWordsGoesAwayAfterAGoodDropAndTheCueKeepsFacingTheRack) {
  Table t;  // the break: the cue ball in hand behind the head string
  ASSERT_TRUE(t.s.cueInHand());
  const double head = t.s.match().world().table().headStringX();
  EXPECT_FALSE(t.s.placeCue({head + 0.3, 0.0}));
  EXPECT_NE(t.s.message().find("behind the head string"), std::string::npos) << t.s.message();
  EXPECT_EQ(t.s.message().find("x <="), std::string::npos) << t.s.message();
  EXPECT_EQ(t.s.message().find('('), std::string::npos) << t.s.message();
  // Dragged to a good spot and let go on it; the pointer then twitches on the ball.
  const Vec2 from = t.s.cuePosition();
  const Vec2 to{head - 0.2, 0.25};
  t.click(from, to);
  const double pixel = 1.0 / t.view.px(1.0);
  EXPECT_NEAR(length(t.s.cuePosition() - to), 0.0, pixel);
  EXPECT_EQ(t.s.message(), "");
  for (Vec2 twitch : {Vec2{-0.004, 0.0}, {0.0, -0.004}, {-0.003, 0.003}}) {
    t.mouseTo(to + twitch);
    EXPECT_GT(std::cos(t.s.heading()), 0.5)
        << "the cue swung back, heading " << radToDeg(t.s.heading());
  }
}

TEST(CallClick, CallingAPocketKeepsTheAim) {
  MatchSetup setup;
  setup.setGame(rules::Game::TenBall);
  Table t(setup);
  ASSERT_TRUE(t.s.shoot());  // the break; then every shot is called
  ASSERT_TRUE(roll(t.s));
  ASSERT_EQ(t.s.phase(), Phase::Aiming);
  ASSERT_TRUE(t.s.callRequired());
  // Aim somewhere and hold still; then the pointer travels to a pocket and clicks it.
  const Vec2 cue = t.s.cuePosition();
  const Vec2 aim = cue + Vec2{0.3, 0.1};
  t.mouseTo(aim);
  t.input.update(1.0 / 60.0);
  t.input.update(0.5);
  const double aimed = t.s.heading();
  Vec2 pocket;
  for (const Pocket& p : t.s.match().world().table().pockets) {
    if (p.id == PocketId::TopRight) pocket = p.drop_centre;
  }
  for (int i = 1; i <= 10; ++i) {
    t.mouseTo(aim + (pocket - aim) * (i / 10.0));
    t.input.update(1.0 / 60.0);
  }
  t.click(pocket, pocket);
  ASSERT_TRUE(t.s.call());
  EXPECT_EQ(t.s.call()->pocket, PocketId::TopRight);
  EXPECT_DOUBLE_EQ(t.s.heading(), aimed);
}

TEST(PracticeMouse, APressOnABallAimsAndShootsAndShiftDragsIt) {
  MatchSetup setup;
  setup.balls = {BallState::at(0, {-0.6, 0.0}), BallState::at(1, {0.4, 0.0})};
  Table t(setup, true);
  // The pointer on the 1, pressed and drawn back: a shot at the 1, the 1 not moved.
  t.mouseTo({0.4, 0.0});
  t.click({0.4, 0.0}, {0.2, 0.0});
  EXPECT_EQ(t.s.phase(), Phase::Rolling);
  ASSERT_TRUE(roll(t.s));
  t.s.undoShot();
  // With Shift held the press picks the ball up and the release puts it down.
  t.input.handle(key(sf::Keyboard::LShift, true), t.view);
  t.click({0.4, 0.0}, {0.5, 0.3});
  t.input.handle(release(sf::Keyboard::LShift), t.view);
  EXPECT_EQ(t.s.phase(), Phase::Aiming);
  const double pixel = 1.0 / t.view.px(1.0);
  bool moved = false;
  for (const BallState& b : t.s.ballsToDraw()) {
    moved |= b.id == 1 && length(b.pos - Vec2{0.5, 0.3}) < pixel;
  }
  EXPECT_TRUE(moved);
  t.tap(sf::Keyboard::U);  // and U takes the move back
  for (const BallState& b : t.s.ballsToDraw()) {
    if (b.id == 1) {
      EXPECT_EQ(b.pos, (Vec2{0.4, 0.0}));
    }
  }
}

TEST(EscapeKey, LeavesForTheMenuWhenTheRackIsKeptElseAsks) {
  Table t;
  t.ui.leave_to_menu = true;
  t.ui.rack_kept = true;
  ASSERT_TRUE(t.s.shoot());
  ASSERT_TRUE(roll(t.s));
  t.tap(sf::Keyboard::Escape);
  EXPECT_TRUE(t.input.requests().menu);
  EXPECT_FALSE(t.input.requests().quit);
  EXPECT_FALSE(t.ui.confirm_quit);
  // Without a menu (a scripted run) Esc asks, and Yes quits.
  Table u;
  u.tap(sf::Keyboard::Escape);
  EXPECT_TRUE(u.ui.confirm_quit);
  u.tap(sf::Keyboard::Y);
  EXPECT_TRUE(u.input.requests().quit);
}

TEST(FastForward, HoldingFRunsTheSameStepsFourTimesAsFast) {
  Table normal, fast;
  ASSERT_TRUE(normal.s.shoot());
  ASSERT_TRUE(fast.s.shoot());
  int normal_frames = 0, fast_frames = 0;
  for (; normal.s.phase() == Phase::Rolling && normal_frames < 60 * 120; ++normal_frames) {
    normal.input.update(1.0 / 60.0);
    normal.s.advance(1.0 / 60.0);
  }
  fast.input.handle(key(sf::Keyboard::F), fast.view);
  for (; fast.s.phase() == Phase::Rolling && fast_frames < 60 * 120; ++fast_frames) {
    fast.input.update(1.0 / 60.0);
    fast.s.advance(1.0 / 60.0);
  }
  EXPECT_LE(fast_frames, normal_frames / 4 + 2) << normal_frames;
  const auto a = normal.s.match().balls(), b = fast.s.match().balls();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].pos, b[i].pos) << a[i].id;
    EXPECT_EQ(a[i].pocket, b[i].pocket) << a[i].id;
  }
  fast.input.handle(release(sf::Keyboard::F), fast.view);
  fast.input.update(1.0 / 60.0);
  EXPECT_EQ(fast.s.playRate(), 1.0);
}

TEST(CueStrike, TheShotsFirstFrameSoundsTheStrikeAsHardAsTheShot) {
  Table t;
  t.s.setSpeed(7.5);
  ASSERT_TRUE(t.s.shoot());
  const auto impacts = t.s.advance(1.0 / 60.0);
  ASSERT_FALSE(impacts.empty());
  EXPECT_EQ(impacts.front().kind, audio::ImpactKind::Cue);
  EXPECT_DOUBLE_EQ(impacts.front().strength, 7.5);
  for (const auto& i : t.s.advance(1.0 / 60.0)) EXPECT_NE(i.kind, audio::ImpactKind::Cue);
}

}  // namespace
}  // namespace nineball::window
