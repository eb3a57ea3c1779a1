// Eight-ball and ten-ball racks played through the real physics: the rack, the golden break of
// each game, the calls and the choices the rules hand the opponent.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "nineball/match.hpp"
#include "nineball/scenes.hpp"
#include "play/match_turns.hpp"

namespace nineball {
namespace {

using play_test::decision;
using play_test::shot;
using rules::Decision;
using rules::Foul;
using rules::Game;
using rules::Group;
using rules::Player;

constexpr double kBallR = 0.028575;

TurnInput called(TurnInput t, int ball, PocketId pocket) {
  t.call = rules::Call{ball, pocket};
  return t;
}

MatchSetup racked(Game game, std::uint64_t seed = 1) {
  MatchSetup s;
  s.game = game;
  s.seed = seed;
  return s;
}

// The cue ball at (0.4, 0), `object` 0.3 m on towards the bottom-right pocket, the rest of
// `others` out of the way on the head side; the shot along that line.
struct InLine {
  MatchSetup setup;
  TurnInput shot;
};
InLine inLine(Game game, int object, std::vector<int> others) {
  const Vec2 pocket = buildTable(TableDef{}, kBallR).pockets[3].drop_centre;
  const Vec2 cue{0.4, 0.0};
  const Vec2 dir = normalized(pocket - cue);
  InLine line;
  line.setup.game = game;
  line.setup.balls = {BallState::at(0, cue), BallState::at(object, cue + dir * 0.3)};
  double y = -0.4;
  for (int b : others) {
    line.setup.balls->push_back(BallState::at(b, {-0.9, y}));
    y += 0.1;
  }
  line.shot = shot(radToDeg(std::atan2(dir.y, dir.x)), 2.0);
  return line;
}

std::uint64_t fnv(std::uint64_t h, std::uint64_t bits) {
  for (int i = 0; i < 8; ++i) {
    h ^= (bits >> (8 * i)) & 0xFF;
    h *= 0x100000001B3ULL;
  }
  return h;
}

// The balls after a shot, bit for bit, and the verdict's outline.
std::uint64_t hashAfter(const Match& m, const TurnRecord& r) {
  std::uint64_t h = 0xCBF29CE484222325ULL;
  for (const BallState& b : m.balls()) {
    std::uint64_t x = 0, y = 0;
    std::memcpy(&x, &b.pos.x, sizeof x);
    std::memcpy(&y, &b.pos.y, sizeof y);
    h = fnv(fnv(fnv(h, static_cast<std::uint64_t>(b.id)), x), y);
    h = fnv(h, b.pocket ? static_cast<std::uint64_t>(*b.pocket) : 99);
  }
  h = fnv(h, static_cast<std::uint64_t>(r.verdict.foul));
  h = fnv(h, static_cast<std::uint64_t>(r.verdict.next));
  for (int b : r.verdict.pocketed) h = fnv(h, static_cast<std::uint64_t>(b));
  return h;
}

TEST(MatchGames, RacksEachGamesBalls) {
  EXPECT_EQ(Match(racked(Game::NineBall)).balls().size(), 10u);
  const Match eight(racked(Game::EightBall));
  EXPECT_EQ(eight.balls().size(), 16u);
  EXPECT_EQ(eight.rack().game(), Game::EightBall);
  EXPECT_EQ(eight.rack().ballsOnTable().size(), 15u);
  EXPECT_TRUE(eight.rack().isBreak());
  const Match ten(racked(Game::TenBall));
  EXPECT_EQ(ten.balls().size(), 11u);
  EXPECT_EQ(ten.rack().ballsOnTable().back(), 10);
  EXPECT_THROW(Match([] {
                 MatchSetup s = racked(Game::EightBall);
                 s.rules = rules::RuleSet::Paper;
                 return s;
               }()),
               std::invalid_argument);
}

TEST(MatchGames, GoldenEightBallBreak) {
  Match m(racked(Game::EightBall));
  const TurnRecord r = m.play(shot(0.0, 10.0));
  constexpr std::uint64_t kPinned = 0x61566067e47a28afULL;
  EXPECT_EQ(hashAfter(m, r), kPinned)
      << "eight-ball break hash is now 0x" << std::hex << hashAfter(m, r);
  EXPECT_TRUE(r.verdict.groups.open());
}

TEST(MatchGames, GoldenTenBallBreak) {
  Match m(racked(Game::TenBall));
  const TurnRecord r = m.play(shot(0.0, 10.0));
  constexpr std::uint64_t kPinned = 0xf65da31caa35c629ULL;
  EXPECT_EQ(hashAfter(m, r), kPinned)
      << "ten-ball break hash is now 0x" << std::hex << hashAfter(m, r);
}

TEST(MatchGames, SameBreakSameBits) {
  for (Game g : {Game::EightBall, Game::TenBall}) {
    Match a(racked(g, 5)), b(racked(g, 5));
    EXPECT_EQ(hashAfter(a, a.play(shot(1.0, 9.0))), hashAfter(b, b.play(shot(1.0, 9.0))));
  }
}

TEST(MatchTenBall, EveryShotAfterTheBreakNeedsACall) {
  InLine line = inLine(Game::TenBall, 1, {2, 10});
  Match m(line.setup);
  EXPECT_TRUE(m.rack().callRequired());
  EXPECT_THROW(m.play(line.shot), IllegalAction);
  EXPECT_THROW(m.play(called(line.shot, 7, PocketId::BottomRight)), IllegalAction);  // not there
  const TurnRecord r = m.play(called(line.shot, 1, PocketId::BottomRight));
  EXPECT_EQ(r.verdict.pocketed, std::vector<int>{1});
  EXPECT_EQ(r.verdict.call_breach, Foul::None);
  EXPECT_EQ(r.verdict.next, Player::A);
  ASSERT_TRUE(r.call);
  EXPECT_EQ(r.call->ball, 1);
}

TEST(MatchTenBall, WrongPocketHandsTheOpponentTheChoice) {
  InLine line = inLine(Game::TenBall, 1, {2, 10});
  Match m(line.setup);
  const TurnRecord r = m.play(called(line.shot, 1, PocketId::TopLeft));
  EXPECT_EQ(r.verdict.call_breach, Foul::WrongPocket);
  EXPECT_EQ(r.verdict.decision, Decision::PlayOrPass);
  EXPECT_FALSE(m.cueInHand());
  EXPECT_THROW(m.play(called(shot(180.0, 1.0), 2, PocketId::TopLeft)), IllegalAction);
  const TurnRecord d = m.play(decision(false));
  EXPECT_EQ(d.answered, Decision::PlayOrPass);
  EXPECT_EQ(m.rack().shooter(), Player::A);
}

TEST(MatchEightBall, APotSetsTheGroupsThenTheEightNeedsACall) {
  InLine line = inLine(Game::EightBall, 2, {8, 12});
  Match m(line.setup);
  EXPECT_FALSE(m.rack().callRequired());
  const TurnRecord r = m.play(line.shot);
  EXPECT_EQ(r.verdict.groups.a, Group::Solids);
  EXPECT_EQ(r.verdict.groups.b, Group::Stripes);
  EXPECT_EQ(r.verdict.next, Player::A);
  EXPECT_TRUE(m.rack().callRequired());  // the solids are cleared: on the 8
  EXPECT_THROW(m.play(shot(180.0, 1.0)), IllegalAction);
}

TEST(MatchEightBall, IllegalBreakRerackOrPlayOn) {
  for (bool play_on : {true, false}) {
    Match m(racked(Game::EightBall));
    const auto start = m.balls();
    const TurnRecord r = m.play(shot(0.0, 0.6));  // a tap: nothing drops, few reach a cushion
    EXPECT_EQ(r.verdict.foul, Foul::BadBreak);
    EXPECT_EQ(r.verdict.decision, Decision::RerackOrPlayOn);
    EXPECT_THROW(m.play(shot(0.0, 1.0)), IllegalAction);
    const TurnRecord d = m.play(decision(play_on));
    EXPECT_EQ(d.answered, Decision::RerackOrPlayOn);
    EXPECT_EQ(m.rack().shooter(), Player::B);
    EXPECT_EQ(m.rack().isBreak(), !play_on);
    if (!play_on) {
      const auto after = m.balls();
      for (std::size_t i = 0; i < start.size(); ++i) {
        EXPECT_EQ(after[i].pos.x, start[i].pos.x) << after[i].id;
        EXPECT_EQ(after[i].pos.y, start[i].pos.y) << after[i].id;
      }
      EXPECT_TRUE(m.cueInHand());
    }
  }
}

}  // namespace
}  // namespace nineball
