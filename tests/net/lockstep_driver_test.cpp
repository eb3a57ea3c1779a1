// The lockstep both drivers share (net::LockstepDriver), without sockets or clocks: a host and
// a joiner, each with its own table, their messages carried by the test. What each message
// means (a turn to play, agreement, a heal, an end), the heal limit, the count of lost links
// and the belief in a bye, as values.
#include "net/lockstep_driver.hpp"

#include <gtest/gtest.h>

#include <deque>
#include <string>
#include <vector>

#include "net/handshake.hpp"
#include "nineball/match.hpp"
#include "support/turn_input.hpp"

namespace nineball::net {
namespace {

// One side: its table, its driver, and what it sent (not yet delivered).
struct DriverSide final : RackTable {
  DriverSide(Side side, const MatchSetup& setup, int most_heals, int most_rejoins)
      : table(setup),
        driver(
            side, [this](const Message& m) { outbox.push_back(m); }, most_heals, most_rejoins) {}

  const Match& match() const override { return table; }
  void restore(const MatchSnapshot& state) override { table.restore(state); }

  Match table;
  LockstepDriver driver;
  std::deque<Message> outbox;
};

class LockstepDriverTest : public ::testing::Test {
 protected:
  void begin(int most_heals = kMostHealsPerRack, int most_rejoins = kMostRejoinsPerRack) {
    host_ = std::make_unique<DriverSide>(Side::Host, setup_, most_heals, most_rejoins);
    joiner_ = std::make_unique<DriverSide>(Side::Joiner, setup_, most_heals, most_rejoins);
    host_->driver.welcome(helloFrom("Bob", "CODE"), setup_, "Ann", nlohmann::json::object(), Race{},
                          "token");
    ASSERT_TRUE(std::holds_alternative<Welcome>(host_->outbox.front()));
    host_->outbox.clear();
    joiner_->driver.welcomed(setup_, {}, {});
  }

  // Delivers what `from` sent to `to` (at most `count` messages): the events it made there.
  std::vector<LockstepEvent> deliver(DriverSide& from, DriverSide& to, std::size_t count = 99) {
    std::vector<LockstepEvent> out;
    for (; count > 0 && !from.outbox.empty(); --count) {
      const Message m = from.outbox.front();
      from.outbox.pop_front();
      for (LockstepEvent& e : to.driver.hear(m, &to, false)) out.push_back(std::move(e));
    }
    return out;
  }

  // The side to move plays `turn` on its table and sends it.
  DriverSide& playLocal(const TurnInput& turn) {
    DriverSide& mover = host_->driver.localToMove(host_->table) ? *host_ : *joiner_;
    TurnMessage message;
    const CheckedTurn checked = mover.driver.localTurn(turn, HumanSeat{}, message);
    mover.outbox.push_back(message);
    mover.table.play(checked.input);
    mover.driver.played(message.turn, mover.table.snapshot());
    return mover;
  }

  // The other side plays what it received (nudged by `nudge` m after it).
  void playReceived(DriverSide& side, const std::vector<LockstepEvent>& events,
                    double nudge = 0.0) {
    ASSERT_FALSE(events.empty());
    const auto* turn = std::get_if<TurnReceived>(&events.front());
    ASSERT_NE(turn, nullptr);
    side.table.play(turn->turn.input);
    if (nudge != 0.0) {
      MatchSnapshot nudged = side.table.snapshot();
      nudged.balls.back().pos.x += nudge;
      side.table.restore(nudged);
    }
    side.driver.played(turn->message.turn, side.table.snapshot());
  }

  DriverSide& other(DriverSide& side) { return &side == host_.get() ? *joiner_ : *host_; }

  MatchSetup setup_;
  std::unique_ptr<DriverSide> host_;
  std::unique_ptr<DriverSide> joiner_;
};

template <class T>
bool sawEvent(const std::vector<LockstepEvent>& events) {
  for (const LockstepEvent& e : events) {
    if (std::holds_alternative<T>(e)) return true;
  }
  return false;
}

template <class T>
const T* firstEvent(const std::vector<LockstepEvent>& events) {
  for (const LockstepEvent& e : events) {
    if (const T* t = std::get_if<T>(&e)) return t;
  }
  return nullptr;
}

TEST_F(LockstepDriverTest, TurnsArePlayedOnBothTablesAndAgreed) {
  begin();
  for (double heading : {0.0, 2.0, -1.0}) {
    DriverSide& mover = playLocal(test::strokeTurn(heading, 4.0));
    DriverSide& peer = other(mover);
    playReceived(peer, deliver(mover, peer, 1));
    EXPECT_TRUE(sawEvent<TurnAgreed>(deliver(peer, mover)));
    EXPECT_TRUE(sawEvent<TurnAgreed>(deliver(mover, peer)));
    EXPECT_TRUE(host_->driver.settled());
    EXPECT_TRUE(joiner_->driver.settled());
  }
  EXPECT_EQ(snapshotHash(host_->table.snapshot()), snapshotHash(joiner_->table.snapshot()));
}

TEST_F(LockstepDriverTest, AMismatchIsHealedByTheHostsStateAndReportedOnBothSides) {
  begin();
  DriverSide& mover = playLocal(test::strokeTurn(0.0, 5.0));
  ASSERT_EQ(&mover, host_.get());
  playReceived(*joiner_, deliver(*host_, *joiner_, 1), 1e-9);
  const auto at_host = deliver(*joiner_, *host_);  // the joiner's differing hash
  ASSERT_NE(firstEvent<HealStarted>(at_host), nullptr);
  EXPECT_EQ(firstEvent<HealStarted>(at_host)->index, 0u);
  const auto at_joiner = deliver(*host_, *joiner_);  // the host's hash, then its state
  EXPECT_TRUE(sawEvent<HealStarted>(at_joiner));
  ASSERT_NE(firstEvent<Healed>(at_joiner), nullptr);
  EXPECT_TRUE(sawEvent<TurnAgreed>(deliver(*joiner_, *host_)));
  EXPECT_EQ(host_->driver.heals(), 1);
  EXPECT_EQ(joiner_->driver.heals(), 1);
  EXPECT_EQ(snapshotHash(host_->table.snapshot()), snapshotHash(joiner_->table.snapshot()));
}

TEST_F(LockstepDriverTest, OneMismatchMoreThanTheRackMayHealEndsItWithABye) {
  begin(/*most_heals=*/0);
  playLocal(test::strokeTurn(0.0, 5.0));
  playReceived(*joiner_, deliver(*host_, *joiner_, 1), 1e-9);
  const auto at_host = deliver(*joiner_, *host_);
  const auto* ended = firstEvent<LockstepEnded>(at_host);
  ASSERT_NE(ended, nullptr);
  EXPECT_EQ(ended->why, LockstepEnded::Why::HealsSpent);
  EXPECT_EQ(ended->reason, "out of step after turn 0, healed 0 times in this rack already");
  ASSERT_EQ(host_->outbox.size(), 2u);  // its hash, and the bye instead of a state
  const auto* bye = std::get_if<Bye>(&host_->outbox.back());
  ASSERT_NE(bye, nullptr);
  EXPECT_EQ(bye->reason, ended->reason);
  EXPECT_FALSE(bye->finished);
  // The joiner, told the host's hash, finds its own allowance spent the same way.
  const auto at_joiner = deliver(*host_, *joiner_);
  ASSERT_NE(firstEvent<LockstepEnded>(at_joiner), nullptr);
  EXPECT_EQ(firstEvent<LockstepEnded>(at_joiner)->why, LockstepEnded::Why::HealsSpent);
}

TEST_F(LockstepDriverTest, AHealThatDoesNotTakeEndsBothSides) {
  begin();
  joiner_->driver.setOnHeal([](MatchSnapshot& s) { s.balls.front().pos.x += 1e-9; });
  playLocal(test::strokeTurn(0.0, 5.0));
  playReceived(*joiner_, deliver(*host_, *joiner_, 1), 1e-9);
  deliver(*joiner_, *host_);
  const auto at_joiner = deliver(*host_, *joiner_);
  ASSERT_NE(firstEvent<LockstepEnded>(at_joiner), nullptr);
  EXPECT_EQ(firstEvent<LockstepEnded>(at_joiner)->why, LockstepEnded::Why::Unhealed);
  const auto at_host = deliver(*joiner_, *host_);
  const auto* ended = firstEvent<LockstepEnded>(at_host);
  ASSERT_NE(ended, nullptr);
  EXPECT_EQ(ended->why, LockstepEnded::Why::Unhealed);
  EXPECT_EQ(ended->reason,
            "the peers fell out of step after turn 0 and the host's state did not heal it");
  const auto* bye = std::get_if<Bye>(&host_->outbox.back());
  ASSERT_NE(bye, nullptr);
  EXPECT_EQ(bye->reason, "out of step after turn 0, and the heal did not take");
}

TEST_F(LockstepDriverTest, EachLostLinkCountsOnceAndOneMoreThanAllowedEndsTheRack) {
  LockstepDriver before(
      Side::Host, [](const Message&) {}, kMostHealsPerRack, 0);
  EXPECT_FALSE(before.linkLost("cable").has_value()) << "no rack yet: nothing to count";
  begin(kMostHealsPerRack, /*most_rejoins=*/2);
  EXPECT_FALSE(host_->driver.linkLost("cable").has_value());
  EXPECT_FALSE(host_->driver.linkLost("cable").has_value()) << "the same link, counted once";
  EXPECT_FALSE(host_->driver.rejoinHeard().has_value()) << "its rejoin is that loss";
  EXPECT_EQ(host_->driver.allowance().rejoins(), 1);
  host_->driver.welcome(helloFrom("Bob", "CODE"), setup_, "Ann", nlohmann::json::object(), Race{},
                        "token");
  // A new link replacing a live one is that link lost.
  EXPECT_FALSE(host_->driver.rejoinHeard().has_value());
  EXPECT_EQ(host_->driver.allowance().rejoins(), 2);
  host_->driver.welcome(helloFrom("Bob", "CODE"), setup_, "Ann", nlohmann::json::object(), Race{},
                        "token");
  const auto ended = host_->driver.linkLost("Wi-Fi");
  ASSERT_TRUE(ended.has_value());
  EXPECT_EQ(ended->why, LockstepEnded::Why::RejoinsSpent);
  EXPECT_EQ(ended->reason, "the link was lost (Wi-Fi) more than 2 times in this rack");
  // The joiner counts its losses the same way.
  EXPECT_FALSE(joiner_->driver.linkLost("cable").has_value());
  EXPECT_EQ(joiner_->driver.allowance().rejoins(), 1);
}

TEST_F(LockstepDriverTest, AFinishedByeIsBelievedOnlyWhereThePeersRackCanEnd) {
  begin();
  // The host's break is due: a joiner's "finished" is a quit.
  const auto early = host_->driver.hear(Bye{"played out", true}, host_.get(), false);
  ASSERT_NE(firstEvent<ByeHeard>(early), nullptr);
  EXPECT_FALSE(firstEvent<ByeHeard>(early)->finished);
  // After an agreed turn at the joiner's move, its script may have run out.
  DriverSide& mover = playLocal(test::strokeTurn(0.0, 2.0));
  playReceived(other(mover), deliver(mover, other(mover), 1));
  deliver(other(mover), mover);
  deliver(mover, other(mover));
  DriverSide& waiting = host_->driver.localToMove(host_->table) ? *joiner_ : *host_;
  const auto late = waiting.driver.hear(Bye{"played out", true}, &waiting, false);
  ASSERT_NE(firstEvent<ByeHeard>(late), nullptr);
  EXPECT_TRUE(firstEvent<ByeHeard>(late)->finished);
}

TEST_F(LockstepDriverTest, MessagesOutOfPlaceAreReportedAsBroken) {
  begin();
  const auto hello = joiner_->driver.hear(helloFrom("Eve", "CODE"), joiner_.get(), false);
  ASSERT_NE(firstEvent<PeerBroke>(hello), nullptr);
  EXPECT_EQ(firstEvent<PeerBroke>(hello)->why, "a hello at the wrong time");
  EXPECT_TRUE(firstEvent<PeerBroke>(hello)->out_of_place);
  const auto hash = host_->driver.hear(HashMessage{5, 42}, host_.get(), false);
  ASSERT_NE(firstEvent<PeerBroke>(hash), nullptr);
  EXPECT_EQ(firstEvent<PeerBroke>(hash)->what, "a state hash");
  LockstepDriver fresh(Side::Host, [](const Message&) {});
  EXPECT_NE(firstEvent<PeerBroke>(fresh.hear(Rematch{}, nullptr, false)), nullptr);
  EXPECT_NE(firstEvent<HelloHeard>(fresh.hear(helloFrom("Bob", "CODE"), nullptr, true)), nullptr);
  EXPECT_NE(firstEvent<RematchHeard>(host_->driver.hear(Rematch{}, host_.get(), false)), nullptr);
  const auto busy = host_->driver.hear(Refuse{"busy: later"}, host_.get(), false);
  ASSERT_NE(firstEvent<RefuseHeard>(busy), nullptr);
  EXPECT_TRUE(firstEvent<RefuseHeard>(busy)->busy);
}

}  // namespace
}  // namespace nineball::net
