// The window's online player without a window: a host and a joiner driven frame by frame
// against a peer that this test speaks for over loopback, well-behaved or not. Whatever the
// peer sends, the game never crashes: a refused message ends the game with its reason.
#include "window/online_play.hpp"

#include <gtest/gtest.h>

#include <SFML/Network/TcpListener.hpp>
#include <SFML/System/Clock.hpp>
#include <SFML/System/Sleep.hpp>
#include <functional>

#include "net/free_port.hpp"
#include "net/handshake.hpp"
#include "window/game_window.hpp"

namespace nineball::window {
namespace {

using nineball::testing::freePort;

constexpr double kFrame = 1.0 / 60.0;
constexpr char kCode[] = "7KQ4-ZP2M";

double clockNow() {
  static sf::Clock clock;
  return clock.getElapsedTime().asSeconds();
}

MatchSetup nineBall() {
  MatchSetup setup;
  setup.setGame(*rules::gameFromName("nine-ball"));
  setup.seed = 3;
  return setup;
}

TurnInput shot(double heading_deg, double speed) {
  TurnInput t;
  t.shot.heading_rad = heading_deg * 3.14159265358979323846 / 180.0;
  t.shot.speed = speed;
  return t;
}

// The other side, spoken by the test.
struct FakePeer {
  std::unique_ptr<net::Connection> link;
  std::vector<net::Message> got;

  void pump() {
    if (!link) return;
    for (const nlohmann::json& j : link->pump(clockNow())) {
      std::string why;
      const auto m = net::readMessage(j, why);
      ASSERT_TRUE(m.has_value()) << why;
      got.push_back(*m);
    }
  }
  void send(const net::Message& m) { link->send(net::toJson(m)); }
  template <class T>
  std::optional<T> take() {
    for (auto it = got.begin(); it != got.end(); ++it) {
      if (const T* t = std::get_if<T>(&*it)) {
        T out = *t;
        got.erase(it);
        return out;
      }
    }
    return std::nullopt;
  }
};

// Runs frames (the game and the peer) until `done` or the time is up.
bool runUntil(OnlinePlay& play, GameSession& session, FakePeer& peer,
              const std::function<bool()>& done, double seconds = 20.0) {
  const double until = clockNow() + seconds;
  while (clockNow() < until) {
    play.update(session, kFrame);
    session.advance(kFrame);
    peer.pump();
    if (done()) return true;
    sf::sleep(sf::milliseconds(1));
  }
  return false;
}

class OnlineHost : public ::testing::Test {
 protected:
  void SetUp() override {
    port_ = freePort();
    ASSERT_NE(port_, 0);
    OnlineConfig config;
    config.side = net::Side::Host;
    config.address.port = port_;
    config.name = "Ann";
    config.code = kCode;
    config.match = onlineMatchOf(nineBall());
    config.scripted = true;
    config.script = {shot(0.4, 9.0), shot(10.0, 3.0)};
    std::string why;
    play_ = OnlinePlay::start(config, why);
    ASSERT_TRUE(play_) << why;
    std::string cwhy;
    auto socket = net::connectTo({"127.0.0.1", port_}, 5.0, cwhy);
    ASSERT_TRUE(socket) << cwhy;
    peer_.link = std::make_unique<net::Connection>(std::move(socket), clockNow());
  }

  // The hello, and the welcome back.
  net::Welcome join() {
    peer_.send(net::helloFrom("Bob", kCode));
    std::optional<net::Welcome> welcome;
    EXPECT_TRUE(runUntil(*play_, session_, peer_,
                         [&] { return (welcome = peer_.take<net::Welcome>()).has_value(); }));
    return welcome.value_or(net::Welcome{});
  }

  // The host's next message of type T, or nothing when none came in time.
  template <class T>
  std::optional<T> await() {
    std::optional<T> got;
    runUntil(*play_, session_, peer_, [&] { return (got = peer_.take<T>()).has_value(); });
    return got;
  }

  // The friend plays the host's next turn on its own table (a ball moved `nudge` m after it),
  // answers with its hash, and judges the host's: the verdict, or nothing (with a failure).
  std::optional<net::HashVerdict> friendPlaysHostsTurn(Match& match, net::Lockstep& lockstep,
                                                       double nudge = 0.0) {
    std::string why;
    const auto sent = await<net::TurnMessage>();
    const auto checked = sent ? lockstep.peerTurn(*sent, match, why) : std::nullopt;
    if (!checked) {
      ADD_FAILURE() << "no turn from the host, or a refused one: " << why;
      return std::nullopt;
    }
    match.play(checked->input);
    if (nudge != 0.0) {
      MatchSnapshot nudged = match.snapshot();
      nudged.balls.front().pos.x += nudge;
      match.restore(nudged);
    }
    peer_.send(lockstep.played(sent->turn, match.snapshot()));
    const auto hash = await<net::HashMessage>();
    const auto verdict = hash ? lockstep.peerHash(*hash, why) : std::nullopt;
    if (!verdict) ADD_FAILURE() << "no hash from the host, or a refused one: " << why;
    return verdict;
  }

  unsigned short port_ = 0;
  GameSession session_{nineBall()};
  std::unique_ptr<OnlinePlay> play_;
  FakePeer peer_;
};

TEST_F(OnlineHost, WelcomesAFriendAndPlaysTheRackInStepWithIt) {
  const net::Welcome welcome = join();
  EXPECT_EQ(welcome.name, "Ann");
  EXPECT_TRUE(welcome.turns.empty());
  EXPECT_EQ(session_.seatName(1), "Bob");
  // The friend's own copy of the rack, played from the turns the host sends.
  std::string why;
  const auto setup = net::setupOf(welcome, why);
  ASSERT_TRUE(setup) << why;
  Match match(*setup);
  net::Lockstep lockstep(net::Side::Joiner, *setup);
  // The host's script: the break, then (the 6 down) its second shot, a foul.
  for (int turn = 0; turn < 2; ++turn) {
    EXPECT_EQ(friendPlaysHostsTurn(match, lockstep), net::HashVerdict::Agreed) << "turn " << turn;
  }
  // Now it is the friend's move: the host's input is blocked, and its table is the friend's.
  EXPECT_TRUE(play_->controls(session_));
  EXPECT_EQ(snapshotHash(session_.match().snapshot()), snapshotHash(match.snapshot()));
  EXPECT_EQ(play_->stage(), OnlinePlay::Stage::Playing);
}

// The friend's table differs after the break (a ball moved a micrometre): the host sends its
// state whole, restores it itself, and once the friend has taken it the game goes on in step.
TEST_F(OnlineHost, ATableOutOfStepIsHealedWithTheHostsState) {
  const net::Welcome welcome = join();
  std::string why;
  const auto setup = net::setupOf(welcome, why);
  ASSERT_TRUE(setup) << why;
  Match match(*setup);
  net::Lockstep lockstep(net::Side::Joiner, *setup);
  ASSERT_EQ(friendPlaysHostsTurn(match, lockstep, 1e-6), net::HashVerdict::Mismatch);
  const auto state = await<net::StateMessage>();
  ASSERT_TRUE(state);
  const auto healed = lockstep.healState(*state, match, why);
  ASSERT_TRUE(healed) << why;
  match.restore(*healed);
  bool took = false;
  peer_.send(lockstep.healed(*healed, took));
  EXPECT_TRUE(took);
  EXPECT_EQ(snapshotHash(session_.match().snapshot()), snapshotHash(match.snapshot()));
  // The host's second shot comes once the heal is agreed, and both tables agree after it.
  EXPECT_EQ(friendPlaysHostsTurn(match, lockstep), net::HashVerdict::Agreed);
  EXPECT_EQ(play_->stage(), OnlinePlay::Stage::Playing);
}

TEST_F(OnlineHost, ATurnOutOfTurnEndsTheGameWithItsReason) {
  join();
  // Player A breaks: a turn from B now is out of turn.
  net::TurnMessage t;
  t.index = 0;
  t.turn = net::wireTurn(shot(180.0, 3.0), HumanSeat{}, rules::Game::NineBall);
  peer_.send(t);
  ASSERT_TRUE(
      runUntil(*play_, session_, peer_, [&] { return play_->stage() == OnlinePlay::Stage::Over; }));
  EXPECT_TRUE(play_->failed());
  EXPECT_NE(play_->why().find("refuses"), std::string::npos) << play_->why();
}

TEST_F(OnlineHost, AHashOfATurnNotPlayedIsRefused) {
  join();
  peer_.send(net::HashMessage{5, 42});
  ASSERT_TRUE(
      runUntil(*play_, session_, peer_, [&] { return play_->stage() == OnlinePlay::Stage::Over; }));
  EXPECT_NE(play_->why().find("hash"), std::string::npos) << play_->why();
}

TEST_F(OnlineHost, AnotherBuildIsRefusedByNameAndTheHostWaitsOn) {
  net::Hello hello = net::helloFrom("Eve", kCode);
  hello.build = "nineball 0.0.1 (elsewhere)";
  peer_.send(hello);
  std::optional<net::Refuse> refused;
  ASSERT_TRUE(runUntil(*play_, session_, peer_,
                       [&] { return (refused = peer_.take<net::Refuse>()).has_value(); }));
  EXPECT_NE(refused->reason.find("elsewhere"), std::string::npos) << refused->reason;
  EXPECT_EQ(play_->stage(), OnlinePlay::Stage::Waiting);
}

TEST_F(OnlineHost, AFriendWhoQuitsEndsTheGameWithoutAFailure) {
  join();
  peer_.send(net::Bye{"dinner", false});
  ASSERT_TRUE(
      runUntil(*play_, session_, peer_, [&] { return play_->stage() == OnlinePlay::Stage::Over; }));
  EXPECT_FALSE(play_->failed());
  EXPECT_NE(play_->why().find("dinner"), std::string::npos) << play_->why();
}

TEST_F(OnlineHost, ALostLinkPausesTheGameAndCountsDown) {
  join();
  peer_.link.reset();  // the friend's cable pulled
  ASSERT_TRUE(
      runUntil(*play_, session_, peer_, [&] { return play_->stage() == OnlinePlay::Stage::Lost; }));
  EXPECT_NE(play_->banner().find("Connection lost - waiting for Bob to rejoin (1:00)"),
            std::string::npos)
      << play_->banner();
  // The break under way rolls on; then nobody plays until the friend is back.
  ASSERT_TRUE(
      runUntil(*play_, session_, peer_, [&] { return session_.phase() != Phase::Rolling; }));
  EXPECT_TRUE(play_->controls(session_));
  EXPECT_EQ(play_->stage(), OnlinePlay::Stage::Lost);
}

// Issue 46: the window's host lets in only a friend with the code, and nobody else into a
// taken seat; it shows the code beside its address.
TEST_F(OnlineHost, AStrangerWithoutTheCodeIsRefusedAndTheHostWaitsOn) {
  EXPECT_NE(play_->banner().find("--code 7KQ4-ZP2M"), std::string::npos) << play_->banner();
  peer_.send(net::helloFrom("Eve", "AAAA-BBBB"));
  std::optional<net::Refuse> refused;
  ASSERT_TRUE(runUntil(*play_, session_, peer_,
                       [&] { return (refused = peer_.take<net::Refuse>()).has_value(); }));
  EXPECT_NE(refused->reason.find("wrong join code"), std::string::npos) << refused->reason;
  EXPECT_EQ(play_->stage(), OnlinePlay::Stage::Waiting);
}

TEST_F(OnlineHost, AnIntruderWithTheCodeCannotTakeTheSeat) {
  const net::Welcome welcome = join();
  EXPECT_TRUE(net::isSeatToken(welcome.token));
  FakePeer intruder;
  std::string why;
  auto socket = net::connectTo({"127.0.0.1", port_}, 5.0, why);
  ASSERT_TRUE(socket) << why;
  intruder.link = std::make_unique<net::Connection>(std::move(socket), clockNow());
  intruder.send(net::helloFrom("Mallory", kCode));
  std::optional<net::Refuse> refused;
  ASSERT_TRUE(runUntil(*play_, session_, peer_, [&] {
    intruder.pump();
    return (refused = intruder.take<net::Refuse>()).has_value();
  }));
  EXPECT_NE(refused->reason.find("the seat is taken"), std::string::npos) << refused->reason;
  EXPECT_EQ(play_->stage(), OnlinePlay::Stage::Playing);
  EXPECT_EQ(play_->peerName(), "Bob");
}

TEST_F(OnlineHost, AFriendWhoLeftAndComesBackIsToldTheGameIsOver) {
  join();
  peer_.send(net::Bye{"dinner", false});
  ASSERT_TRUE(
      runUntil(*play_, session_, peer_, [&] { return play_->stage() == OnlinePlay::Stage::Over; }));
  FakePeer back;
  std::string why;
  auto socket = net::connectTo({"127.0.0.1", port_}, 5.0, why);
  ASSERT_TRUE(socket) << why;
  back.link = std::make_unique<net::Connection>(std::move(socket), clockNow());
  back.send(net::helloFrom("Bob", kCode));
  std::optional<net::Refuse> refused;
  ASSERT_TRUE(runUntil(
      *play_, session_, peer_,
      [&] {
        back.pump();
        return (refused = back.take<net::Refuse>()).has_value();
      },
      5.0))
      << "the restarted joiner heard nothing";
  EXPECT_NE(refused->reason.find("the game is over"), std::string::npos) << refused->reason;
}

TEST_F(OnlineHost, AFinishedByeBeforeTheRackIsOverIsAQuit) {
  join();
  // The host breaks: its move, not the friend's; "finished" cannot be true here.
  peer_.send(net::Bye{"played out", true});
  ASSERT_TRUE(
      runUntil(*play_, session_, peer_, [&] { return play_->stage() == OnlinePlay::Stage::Over; }));
  EXPECT_NE(play_->why().find("left the game"), std::string::npos) << play_->why();
}

// Two players of one name ("Player 1" on both sides, say) are told apart by their seats.
TEST_F(OnlineHost, AFriendOfTheHostsNameIsToldApartBySeat) {
  peer_.send(net::helloFrom("Ann", kCode));
  ASSERT_TRUE(
      runUntil(*play_, session_, peer_, [&] { return peer_.take<net::Welcome>().has_value(); }));
  EXPECT_EQ(play_->peerName(), "Ann (B)");
  EXPECT_EQ(session_.seatName(0), "Ann");
  EXPECT_EQ(session_.seatName(1), "Ann (B)");
}

TEST(OnlineJoiner, AHostWhoseMatchIsNonsenseIsRefused) {
  const unsigned short port = freePort();
  ASSERT_NE(port, 0);
  std::string why;
  auto listener = net::Listener::open(port, why);
  ASSERT_TRUE(listener) << why;
  OnlineConfig config;
  config.side = net::Side::Joiner;
  config.address = {"127.0.0.1", port};
  config.name = "Bob";
  // The session outlives the online game, which lets go of it when it ends (as in TableScreen).
  GameSession session(nineBall());
  auto play = OnlinePlay::start(config, why);
  ASSERT_TRUE(play) << why;
  FakePeer host;
  ASSERT_TRUE(runUntil(*play, session, host, [&] {
    if (!host.link) {
      if (auto s = listener->accept())
        host.link = std::make_unique<net::Connection>(std::move(s), clockNow());
    }
    return host.take<net::Hello>().has_value();
  }));
  net::Welcome w;
  w.protocol = net::kProtocolVersion;
  w.build = net::buildId();
  w.name = "Mallory";
  w.token = net::makeSeatToken();
  w.match = {{"game", "nine-ball"}, {"seed", 3}, {"table", {{"length", -4}}}};
  host.send(w);
  ASSERT_TRUE(
      runUntil(*play, session, host, [&] { return play->stage() == OnlinePlay::Stage::Over; }));
  EXPECT_TRUE(play->failed());
  EXPECT_NE(play->why().find("match"), std::string::npos) << play->why();
}

}  // namespace
}  // namespace nineball::window
