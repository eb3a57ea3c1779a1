// The online lobby over the table: the host's join line and code while it waits, the joiner's
// connection; it leaves by itself once a friend has greeted the host, and Esc leaves the online
// game the way Esc's question would (to the menu, or out of the program).
#include "window/screens/online_lobby_screen.hpp"

#include <gtest/gtest.h>

#include <SFML/System/Clock.hpp>
#include <SFML/System/Sleep.hpp>
#include <memory>
#include <string>

#include "net/free_port.hpp"
#include "net/handshake.hpp"
#include "window/game_window.hpp"
#include "window/input_events.hpp"
#include "window/screens/window_stand_in.hpp"

namespace nineball::window {
namespace {

constexpr char kLobbyCode[] = "7KQ4-ZP2M";

bool says(const render::HudState& hud, const std::string& words) {
  for (const std::string& line : hud.overlay_lines) {
    if (line.find(words) != std::string::npos) return true;
  }
  return false;
}

// A table on the stand-in window's stack, hosting on a free port.
struct HostingTable {
  HostingTable() {
    auto screen = std::make_unique<TableScreen>(MatchSetup{}, false, false, true, window);
    table = screen.get();
    window.screens().push(std::move(screen));
    port = nineball::testing::freePort();
    OnlineConfig config;
    config.side = net::Side::Host;
    config.address.port = port;
    config.name = "Ann";
    config.code = kLobbyCode;
    config.match = onlineMatchOf(MatchSetup{});
    std::string why;
    EXPECT_TRUE(table->beginOnline(config, "Ann", why)) << why;
  }
  OnlineLobbyScreen* lobby() { return dynamic_cast<OnlineLobbyScreen*>(&window.screens().top()); }

  test::WindowStandIn window;
  TableScreen* table = nullptr;
  unsigned short port = 0;
};

TEST(OnlineLobby, TheHostWaitsOverTheTableWithTheLineItsFriendTypes) {
  HostingTable h;
  ASSERT_TRUE(h.table->online());
  OnlineLobbyScreen* lobby = h.lobby();
  ASSERT_NE(lobby, nullptr) << "the online game begins in its lobby";
  EXPECT_FALSE(lobby->covers());  // the table stays in sight beneath
  EXPECT_FALSE(lobby->finished());
  const render::HudState hud = lobbyDialog(*h.table->online());
  EXPECT_EQ(hud.overlay_title, "Hosting an online game");
  EXPECT_TRUE(says(hud, std::string("Your join code: ") + kLobbyCode));
  EXPECT_TRUE(says(hud, "--join ")) << "the line the friend types";
  EXPECT_TRUE(says(hud, "port " + std::to_string(h.port)));
  EXPECT_EQ(hud.button_right, "Cancel (Esc)");
}

TEST(OnlineLobby, LeavesByItselfOnceAFriendHasGreetedTheHost) {
  HostingTable h;
  ASSERT_NE(h.lobby(), nullptr);
  std::string why;
  auto socket = net::connectTo({"127.0.0.1", h.port}, 5.0, why);
  ASSERT_TRUE(socket) << why;
  sf::Clock clock;
  net::Connection friend_link(std::move(socket), 0.0);
  friend_link.send(net::toJson(net::helloFrom("Bob", kLobbyCode)));
  bool left = false;
  while (!left && clock.getElapsedTime().asSeconds() < 10.0) {
    h.window.screens().update(1.0 / 60.0);
    friend_link.pump(clock.getElapsedTime().asSeconds());
    left = h.window.screens().removeFinished();
    sf::sleep(sf::milliseconds(1));
  }
  EXPECT_TRUE(left) << "the lobby is still up: " << h.table->online()->banner();
  EXPECT_EQ(&h.window.screens().top(), h.table);
  EXPECT_TRUE(h.table->online()->started());
}

TEST(OnlineLobby, EscLeavesTheOnlineGameAsEscsQuestionWould) {
  for (const bool to_menu : {false, true}) {
    HostingTable h;
    h.table->ui().leave_to_menu = to_menu;
    ASSERT_NE(h.lobby(), nullptr);
    h.window.screens().event(key(sf::Keyboard::Escape));
    EXPECT_TRUE(h.window.screens().removeFinished());
    EXPECT_EQ(&h.window.screens().top(), h.table);
    const WindowRequests& asked = h.table->input().requests();
    EXPECT_EQ(asked.menu, to_menu);
    EXPECT_EQ(asked.quit, !to_menu);
  }
}

TEST(OnlineLobby, TheJoinerSaysWhereItConnects) {
  OnlineConfig config;
  config.side = net::Side::Joiner;
  config.address = {"127.0.0.1", nineball::testing::freePort()};
  config.name = "Bob";
  config.code = kLobbyCode;
  std::string why;
  auto online = OnlinePlay::start(config, why);
  ASSERT_TRUE(online) << why;
  const render::HudState hud = lobbyDialog(*online);
  EXPECT_EQ(hud.overlay_title, "Joining an online game");
  EXPECT_TRUE(says(hud, "Connecting to 127.0.0.1:" + std::to_string(config.address.port)));
}

}  // namespace
}  // namespace nineball::window
