// A race to N racks in the pool games: the menu offers it (or none, the racks adding up), the
// scoreboard and the rack's end say it, and the match is won at N.
#include <gtest/gtest.h>

#include "window/frame_builder.hpp"
#include "window/game_rolling.hpp"
#include "window/menu.hpp"

namespace nineball::window {
namespace {

std::string rowValue(const MenuModel& m, const std::string& label) {
  for (const MenuRow& r : m.rows()) {
    if (r.label == label) return r.value;
  }
  return "(no row " + label + ")";
}

TEST(PoolRace, TheMenuOffersARaceOrNone) {
  Settings settings;
  settings.last.game = rules::Game::NineBall;
  MenuModel m(settings, std::nullopt);
  EXPECT_EQ(rowValue(m, "Match"), "No limit (the racks add up)");
  EXPECT_EQ(m.choice().best_of, 0);
  settings.last.best_of = 9;
  const MenuModel race(settings, std::nullopt);
  EXPECT_EQ(rowValue(race, "Match"), "Race to 5 racks");
  EXPECT_EQ(race.choice().best_of, 9);
  // Snooker keeps its frames.
  settings.last.game = rules::Game::Snooker;
  settings.last.best_of = 5;
  EXPECT_EQ(rowValue(MenuModel(settings, std::nullopt), "Frames"), "Best of 5 (first to 3)");
}

TEST(PoolRace, TheScoreboardAndTheRacksEndSayTheRace) {
  // The 9 on the lip of the top-right pocket, the cue ball straight behind it.
  MatchSetup setup;
  setup.balls =
      std::vector<BallState>{BallState::at(kCueBall, {0.95, 0.32}), BallState::at(9, {1.18, 0.55})};
  GameSession s(setup);
  s.setBestOf(5);
  UiState ui;
  const Seats seats(1);
  EXPECT_NE(buildFrame(s, ui, seats).hud.rules.find("race to 3"), std::string::npos);
  s.setHeading(degToRad(45.0));
  s.setSpeed(0.9);
  s.setTip({0.0, -0.4});  // drawn back: the cue ball stays out of the pocket
  ASSERT_TRUE(s.shoot());
  ASSERT_TRUE(roll(s));
  ASSERT_EQ(s.phase(), Phase::GameOver);
  EXPECT_EQ(s.racksWon(0), 1);
  EXPECT_NE(s.status().find("race to 3"), std::string::npos) << s.status();
  const render::Frame f = buildFrame(s, ui, seats);
  EXPECT_EQ(f.hud.button_left, "Next rack (R)");
  EXPECT_NE(f.hud.overlay_lines.back().find("(race to 3)"), std::string::npos);
  EXPECT_FALSE(s.matchWinner());
}

}  // namespace
}  // namespace nineball::window
