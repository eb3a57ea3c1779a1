// The game chosen in the window: nine-, eight- or ten-ball from the menu, kept in the settings
// and the saved rack, racked by the session; the computer plays each of them.
#include <gtest/gtest.h>

#include "window/computer_player.hpp"
#include "window/frame_builder.hpp"
#include "window/game_help.hpp"
#include "window/game_session.hpp"
#include "window/menu.hpp"
#include "window/menu_rows.hpp"
#include "window/rack_save.hpp"
#include "window/settings.hpp"
#include "window/turn_message.hpp"

namespace nineball::window {
namespace {

TEST(GameChoice, TheMenuPicksTheGameAndOffersTheComputerInEach) {
  Settings s;
  s.last.opponent = ComputerSeat{ai::Level::Master};
  s.last.rules = rules::RuleSet::Paper;
  MenuModel m(s, std::nullopt);
  const int game = rowNamed(m, "Game");
  ASSERT_GE(game, 0);
  EXPECT_EQ(m.rows()[game].value, "Nine-ball");
  EXPECT_TRUE(m.rows()[rowNamed(m, "Opponent")].enabled);
  m.click(game);
  EXPECT_EQ(m.rows()[game].value, "Eight-ball");
  EXPECT_EQ(m.rows()[rowNamed(m, "Play eight-ball")].label, "Play eight-ball");
  const MenuRow versus = m.rows()[rowNamed(m, "Opponent")];
  EXPECT_TRUE(versus.enabled);
  EXPECT_EQ(versus.value, "Computer");
  EXPECT_TRUE(m.rows()[rowNamed(m, "Computer level")].enabled);
  EXPECT_FALSE(m.rows()[rowNamed(m, "Rules")].enabled);  // the paper's rules: nine-ball only
  EXPECT_FALSE(m.rows()[rowNamed(m, "Player 2 name")].enabled);
  EXPECT_EQ(m.rows()[rowNamed(m, "Player 2 name")].value, "Computer");
  m.click(game);
  EXPECT_EQ(m.rows()[game].value, "Ten-ball");
  m.click(rowNamed(m, "Play ten-ball"));
  ASSERT_EQ(m.outcome(), MenuModel::Outcome::Play);
  const MenuChoice c = m.choice();
  EXPECT_EQ(c.game, rules::Game::TenBall);
  EXPECT_EQ(c.mode, GameMode::Match);
  EXPECT_EQ(c.opponent, Seat(ComputerSeat{ai::Level::Master}));
  EXPECT_EQ(c.rules, rules::RuleSet::Wpa);
  EXPECT_EQ(m.settings().last.game, rules::Game::TenBall);
}

TEST(GameChoice, TheSettingsKeepTheGame) {
  Settings s;
  s.last.game = rules::Game::EightBall;
  std::string warnings;
  const Settings back = settingsFromJson(nlohmann::json::parse(settingsToJson(s).dump()), warnings);
  EXPECT_TRUE(warnings.empty()) << warnings;
  EXPECT_EQ(back.last.game, rules::Game::EightBall);
  EXPECT_EQ(back, s);
}

TEST(GameChoice, TheSavedRackKeepsTheGameAndTheCalls) {
  SavedRack r;
  r.game = rules::Game::TenBall;
  TurnInput t;
  t.shot.speed = 2.0;
  t.call = rules::Call{3, PocketId::BottomSide};
  r.turns = {t};
  std::string why;
  const auto back = rackFromJson(nlohmann::json::parse(rackToJson(r).dump()), why);
  ASSERT_TRUE(back) << why;
  EXPECT_EQ(back->game, rules::Game::TenBall);
  ASSERT_EQ(back->turns.size(), 1u);
  EXPECT_EQ(back->turns[0].call, t.call);
  // A save from before the games came is nine-ball's.
  nlohmann::ordered_json old = rackToJson(SavedRack{});
  old.erase("game");
  const auto nine = rackFromJson(nlohmann::json::parse(old.dump()), why);
  ASSERT_TRUE(nine) << why;
  EXPECT_EQ(nine->game, rules::Game::NineBall);
}

TEST(GameChoice, TheSessionRacksTheGameChosen) {
  for (auto [game, balls] : {std::pair{rules::Game::NineBall, 9u},
                             {rules::Game::EightBall, 15u},
                             {rules::Game::TenBall, 10u}}) {
    MatchSetup setup;
    setup.game = game;
    GameSession s(setup);
    EXPECT_EQ(s.match().rack().game(), game);
    EXPECT_EQ(s.match().rack().ballsOnTable().size(), balls);
    EXPECT_EQ(saveOf(s, HumanSeat{}).game, game);
    s.rematch();
    EXPECT_EQ(s.match().rack().game(), game);
  }
}

TEST(GameChoice, TheComputerTakesTheSeatInEveryGame) {
  for (rules::Game game : {rules::Game::EightBall, rules::Game::TenBall}) {
    SCOPED_TRACE(rules::gameName(game));
    MatchSetup setup;
    setup.game = game;
    GameSession s(setup);
    ComputerPlayer computer(1);
    computer.setOpponent(s, ComputerSeat{ai::Level::Club});
    EXPECT_EQ(computer.opponent(), Seat(ComputerSeat{ai::Level::Club}));
    EXPECT_EQ(s.seatName(1), "Computer");
  }
}

TEST(GameChoice, MessagesForTheNewDecisionsAndGroups) {
  TurnRecord r;
  r.kind = TurnInput::Kind::Decision;
  r.answered = rules::Decision::RerackOrPlayOn;
  r.shoot = false;
  EXPECT_NE(describeTurn(r, {}, 1, "Ann", "Bob").text.find("re-racked"), std::string::npos);
  r.shoot = true;
  EXPECT_NE(describeTurn(r, {}, 1, "Ann", "Bob").text.find("as it lies"), std::string::npos);

  TurnRecord g;
  g.verdict.pocketed = {3};
  g.verdict.next = rules::Player::A;
  g.verdict.groups = {rules::Group::Solids, rules::Group::Stripes};
  const std::string text = describeTurn(g, {}, 1, "Ann", "Bob", rules::Groups{}).text;
  EXPECT_NE(text.find("Ann has the solids, Bob the stripes"), std::string::npos) << text;

  TurnRecord b;
  b.verdict.pocketed = {4};
  b.verdict.next = rules::Player::B;
  b.verdict.call_breach = rules::Foul::WrongPocket;
  b.verdict.awaiting_decision = true;
  b.verdict.decision = rules::Decision::PlayOrPass;
  const std::string breach = describeTurn(b, {}, 1, "Ann", "Bob").text;
  EXPECT_NE(breach.find("not as called"), std::string::npos) << breach;
  EXPECT_NE(breach.find("Bob: play from there or pass it back"), std::string::npos) << breach;

  TurnRecord e;
  e.verdict.foul = rules::Foul::BadBreak;
  e.verdict.next = rules::Player::B;
  e.verdict.awaiting_decision = true;
  e.verdict.decision = rules::Decision::RerackOrPlayOn;
  rules::ShotSummary hit_the_5;  // any ball may be hit first on an eight-ball break
  hit_the_5.first_contact = 5;
  const std::string illegal = describeTurn(e, hit_the_5, 1, "Ann", "Bob").text;
  EXPECT_NE(illegal.find("Illegal break"), std::string::npos) << illegal;
  EXPECT_NE(illegal.find("re-rack"), std::string::npos) << illegal;
  EXPECT_NE(illegal.find("fewer than four reached a cushion"), std::string::npos) << illegal;
  EXPECT_EQ(illegal.find("must hit"), std::string::npos) << illegal;
}

TEST(GameChoice, TheHudShowsEightBallGroupsAndTheHelpTheGame) {
  EXPECT_EQ(groupLabel({}, rules::Player::A), "open table");
  const rules::Groups g{rules::Group::Stripes, rules::Group::Solids};
  EXPECT_EQ(groupLabel(g, rules::Player::A), "stripes");
  EXPECT_EQ(groupLabel(g, rules::Player::B), "solids");
  MatchSetup setup;
  setup.game = rules::Game::EightBall;
  const GameSession s(setup);
  const Seats seats(1);
  UiState ui;
  ui.help = true;
  const render::Frame f = buildFrame(s, ui, seats);
  EXPECT_TRUE(f.hud.split_groups);
  EXPECT_EQ(f.hud.ball_on, 0) << "any ball may be hit first on the eight-ball break";
  EXPECT_NE(f.hud.players[0].detail.find("open table"), std::string::npos);
  EXPECT_NE(f.hud.rules.find("eight-ball"), std::string::npos);
  ASSERT_FALSE(f.hud.overlay_lines.empty());
  EXPECT_NE(f.hud.overlay_lines.back().find("K"), std::string::npos);
  bool explained = false;
  for (const std::string& line : f.hud.overlay_lines) {
    if (line.rfind("Eight-ball:", 0) == 0) explained = true;
  }
  EXPECT_TRUE(explained);
  // Nine-ball's help ends as before.
  const GameSession nine{MatchSetup{}};
  const render::Frame n = buildFrame(nine, ui, seats);
  EXPECT_FALSE(n.hud.split_groups);
  EXPECT_EQ(n.hud.overlay_lines.back(), "Rules: hit the lowest ball first; the 9 wins the rack");
}

}  // namespace
}  // namespace nineball::window
