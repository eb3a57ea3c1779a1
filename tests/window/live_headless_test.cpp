// A rack played in the window's session, frame by frame with a fixed frame time, and the same
// turns played headless through Match::play (what `nineball match`, "Resume rack", --script and
// the replay use) give the same state bit for bit after every turn. The racks are played by
// the computer on one or both seats, at easy and medium, in all three games, so they hold fouls,
// scratches and ball in hand, push-outs, spotted balls and calls; the test checks that they do.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/cli_runner.hpp"
#include "io/match_json.hpp"
#include "nineball/planner.hpp"
#include "nineball/state_hash.hpp"
#include "window/computer_player.hpp"
#include "window/game_session.hpp"
#include "window/shot_replay.hpp"

namespace nineball::window {
namespace {

constexpr double kLiveFrame = 1.0 / 60.0;
constexpr int kMaxFrames = 60 * 60 * 30;  // half an hour of play: a rack ends long before

struct Features {
  int fouls = 0;
  int scratches = 0;   // the cue ball pocketed
  int cue_placed = 0;  // ball in hand used (not the break)
  int push_outs = 0;
  int decisions = 0;
  int spotted = 0;
  int calls = 0;
};

struct LiveRack {
  MatchSetup setup;
  std::vector<TurnInput> turns;
  std::vector<std::uint64_t> hashes;  // after each turn
  std::vector<BallState> end;
  bool won = false;
  int winner_seat = -1;
  Features seen;
};

void tally(Features& f, const TurnRecord& r, const TurnInput& t, bool was_break,
           const Match& match) {
  if (!r.verdict.legal()) ++f.fouls;
  for (const Event& e : match.world().events()) {
    if (e.type == EventType::Pocket && e.a == kCueBall && t.kind != TurnInput::Kind::Decision) {
      ++f.scratches;
      break;
    }
  }
  if (t.cue && !was_break) ++f.cue_placed;
  if (t.kind == TurnInput::Kind::PushOut) ++f.push_outs;
  if (t.kind == TurnInput::Kind::Decision) ++f.decisions;
  if (t.call) ++f.calls;
  f.spotted += static_cast<int>(r.verdict.to_spot.size());
}

// Plays one rack in the session as the window does: the computer (ComputerPlayer) on seat 2,
// and on seat 1 a planner of `seat1` (or the computer's level) answering through the same
// calls the mouse and keys make; the physics advanced a fixed frame at a time.
LiveRack playLive(const MatchSetup& setup, ai::Level seat1, ai::Level seat2, std::uint64_t seed) {
  LiveRack rack;
  GameSession s(setup);
  rack.setup = s.rackSetup();
  ComputerPlayer computer(seed);
  computer.setWaitForPlans(true);
  computer.setOpponent(s, ComputerSeat{seat2});
  ai::Planner player(seat1, seed + 17, 1);
  bool was_break = true;
  s.setTurnObserver([&](int, const TurnRecord& r, bool) {
    const TurnInput& t = s.rackTurns().back();
    tally(rack.seen, r, t, was_break, s.match());
    was_break = s.match().rack().isBreak();
    rack.hashes.push_back(stateHash(s.match().balls()));
  });
  for (int frame = 0; frame < kMaxFrames && s.phase() != Phase::GameOver; ++frame) {
    if (s.phase() != Phase::Rolling && s.seatToMove() == 0) {
      const TurnInput turn = player.turnFor(s.match());
      if (turn.kind == TurnInput::Kind::Decision) {
        s.decide(turn.shoot);
      } else {
        if (turn.call) s.setCall(*turn.call);
        EXPECT_TRUE(s.shoot(turn)) << s.message();
      }
    } else {
      computer.update(s, kLiveFrame);
    }
    s.advance(kLiveFrame);
  }
  rack.turns = s.rackTurns();
  rack.end = s.match().balls();
  rack.won = s.phase() == Phase::GameOver;
  if (const auto w = s.match().rack().winner()) rack.winner_seat = s.seatOf(*w);
  return rack;
}

std::vector<std::uint64_t> playHeadless(const MatchSetup& setup,
                                        const std::vector<TurnInput>& turns) {
  Match match(setup);
  std::vector<std::uint64_t> hashes;
  for (const TurnInput& t : turns) {
    match.play(t);
    hashes.push_back(stateHash(match.balls()));
  }
  return hashes;
}

// The replay the window offers once the rack is over (V) rebuilds the rack from its turns and
// plays the last shot to where the rack ended.
void expectReplayEndsWhereTheRackEnded(const LiveRack& live) {
  ShotReplay replay(live.setup, live.turns, 1.0);
  for (int frame = 0; frame < kMaxFrames && !replay.finished(); ++frame) replay.advance(kLiveFrame);
  ASSERT_TRUE(replay.finished());
  EXPECT_EQ(stateHash(replay.balls()), stateHash(live.end));
}

void expectSameRack(const LiveRack& live) {
  ASSERT_TRUE(live.won) << "the rack did not end";
  expectReplayEndsWhereTheRackEnded(live);
  ASSERT_EQ(live.hashes.size(), live.turns.size());
  const auto headless = playHeadless(live.setup, live.turns);
  ASSERT_EQ(headless.size(), live.hashes.size());
  for (std::size_t i = 0; i < headless.size(); ++i) {
    ASSERT_EQ(headless[i], live.hashes[i])
        << "the paths part after turn " << i << " of " << headless.size();
  }
}

MatchSetup gameSetup(rules::Game game, std::uint64_t seed) {
  MatchSetup setup;
  setup.game = game;
  setup.seed = seed;
  return setup;
}

struct Case {
  rules::Game game;
  ai::Level seat1;
  ai::Level seat2;
  std::uint64_t seed;
};

struct Seen {
  Features features;
  std::vector<int> winner_seats;
};

Seen playCases(const std::vector<Case>& cases) {
  Seen seen;
  Features& all = seen.features;
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(rules::gameName(c.game)) + " seed " + std::to_string(c.seed));
    const LiveRack live = playLive(gameSetup(c.game, c.seed), c.seat1, c.seat2, c.seed);
    expectSameRack(live);
    all.fouls += live.seen.fouls;
    all.scratches += live.seen.scratches;
    all.cue_placed += live.seen.cue_placed;
    all.push_outs += live.seen.push_outs;
    all.decisions += live.seen.decisions;
    all.spotted += live.seen.spotted;
    all.calls += live.seen.calls;
    seen.winner_seats.push_back(live.winner_seat);
  }
  return seen;
}

using ai::Level;

// The seeds are chosen so that the racks hold what the paths could part on; the counts are
// checked, so a change to the planner that loses one fails here rather than passing silently
// (chosen again when issue 28 moved the physics in its last bits, and when the ladder of
// levels gave club and casual their stroke model).
TEST(LiveAndHeadless, NineBallRacksWithFoulsPushOutsAndBallInHandAreTheSameEitherWay) {
  const Seen seen = playCases({{rules::Game::NineBall, Level::Casual, Level::Club, 9},
                               {rules::Game::NineBall, Level::Casual, Level::Club, 35},
                               {rules::Game::NineBall, Level::Club, Level::Club, 12}});
  const Features& f = seen.features;
  EXPECT_GE(f.fouls, 3);
  EXPECT_GE(f.scratches, 2);
  EXPECT_GE(f.cue_placed, 3);
  EXPECT_GE(f.push_outs, 2);
  EXPECT_GE(f.decisions, 2);
}

// The crash the replay had: club against club (medium, then), a scratch and ball in hand, the
// computer (Player 2) winning, then V. (Seed 7 since the pockets' fall model of issue 34: seed
// 5's rack went another way once a ball could bounce out of a pocket.)
TEST(LiveAndHeadless, AClubRackTheComputerWinsAfterAScratchReplaysToItsEnd) {
  const Seen seen = playCases({{rules::Game::NineBall, Level::Club, Level::Club, 7}});
  EXPECT_GE(seen.features.scratches, 1);
  EXPECT_GE(seen.features.cue_placed, 1);
  EXPECT_EQ(seen.winner_seats, std::vector<int>{ComputerPlayer::kSeat});
}

TEST(LiveAndHeadless, EightBallRacksWithScratchesAndCallsAreTheSameEitherWay) {
  const Seen seen = playCases({{rules::Game::EightBall, Level::Casual, Level::Club, 12},
                               {rules::Game::EightBall, Level::Club, Level::Club, 8}});
  EXPECT_GE(seen.features.calls, 2);  // the 8 is called
  EXPECT_GE(seen.features.scratches, 2);
  EXPECT_GE(seen.features.cue_placed, 2);
}

TEST(LiveAndHeadless, TenBallRacksWithCallsSpotsAndPushOutsAreTheSameEitherWay) {
  const Seen seen = playCases({{rules::Game::TenBall, Level::Casual, Level::Club, 2},
                               {rules::Game::TenBall, Level::Club, Level::Club, 5}});
  const Features& f = seen.features;
  EXPECT_GE(f.calls, 40);
  EXPECT_GE(f.spotted, 1);
  EXPECT_GE(f.push_outs, 1);
  EXPECT_GE(f.decisions, 4);
  EXPECT_GE(f.scratches, 2);
}

// Three-cushion: each player's own ball, the scoreboard and equal innings, frame by frame in the
// window as headless.
TEST(LiveAndHeadless, AThreeCushionGameIsTheSameEitherWay) {
  MatchSetup setup;
  setup.setGame(rules::Game::ThreeCushion);
  setup.seed = 2;
  setup.points = 3;
  const LiveRack live = playLive(setup, Level::Advanced, Level::Pro, 2);
  expectSameRack(live);
  EXPECT_GE(live.turns.size(), 4u);
}

// Rolls the session's shot to its end a fixed frame at a time.
void rollFrames(GameSession& s) {
  for (int frame = 0; frame < kMaxFrames && s.phase() == Phase::Rolling; ++frame) {
    s.advance(kLiveFrame);
  }
}

// The turns of a session played frame by frame, then headless, compared after every turn.
void expectSameAsHeadless(GameSession& s, const std::vector<std::uint64_t>& live) {
  ASSERT_EQ(live.size(), s.rackTurns().size());
  const auto headless = playHeadless(s.rackSetup(), s.rackTurns());
  for (std::size_t i = 0; i < live.size(); ++i) {
    EXPECT_EQ(headless[i], live[i]) << "the paths part after turn " << i;
  }
}

// The break, a push-out, the opponent passes it back, and the pusher shoots again.
TEST(LiveAndHeadless, APushOutAndThePassAreTheSameEitherWay) {
  GameSession s{MatchSetup{}};
  std::vector<std::uint64_t> live;
  s.setTurnObserver(
      [&](int, const TurnRecord&, bool) { live.push_back(stateHash(s.match().balls())); });
  ASSERT_TRUE(s.shoot());
  rollFrames(s);
  ASSERT_TRUE(s.pushOutAvailable());
  s.togglePushOut();
  s.setSpeed(1.0);
  ASSERT_TRUE(s.shoot());
  rollFrames(s);
  ASSERT_EQ(s.phase(), Phase::PushOutChoice);
  s.decide(false);
  ASSERT_EQ(s.phase(), Phase::Aiming);
  s.setSpeed(2.5);
  ASSERT_TRUE(s.shoot());
  rollFrames(s);
  EXPECT_EQ(s.rackTurns()[1].kind, TurnInput::Kind::PushOut);
  EXPECT_EQ(s.rackTurns()[2].kind, TurnInput::Kind::Decision);
  expectSameAsHeadless(s, live);
}

// The 9 potted on a foul (hit before the 1) is spotted; the opponent takes ball in hand.
TEST(LiveAndHeadless, ASpottedNineAndBallInHandAreTheSameEitherWay) {
  MatchSetup setup;
  const Vec2 nine{1.0, 0.35};
  const Vec2 to_corner = normalized(Vec2{1.27, 0.635} - nine);
  setup.balls = {BallState::at(0, nine - to_corner * 0.2), BallState::at(1, {-0.5, 0.0}),
                 BallState::at(9, nine)};
  GameSession s(setup);
  std::vector<std::uint64_t> live;
  std::vector<int> spotted;
  s.setTurnObserver([&](int, const TurnRecord& r, bool) {
    live.push_back(stateHash(s.match().balls()));
    spotted.insert(spotted.end(), r.verdict.to_spot.begin(), r.verdict.to_spot.end());
  });
  s.setHeading(std::atan2(to_corner.y, to_corner.x));
  s.setSpeed(1.5);
  ASSERT_TRUE(s.shoot());
  rollFrames(s);
  ASSERT_EQ(spotted, std::vector<int>{9});
  ASSERT_TRUE(s.cueInHand());
  ASSERT_TRUE(s.placeCue({-0.9, 0.1}));
  s.setHeading(0.05);
  s.setSpeed(2.0);
  ASSERT_TRUE(s.shoot());
  rollFrames(s);
  expectSameAsHeadless(s, live);
}

// `nineball match` itself: the same turns written as a script (degrees, as the contract has
// them), played by the CLI and, parsed the same way, frame by frame in the session, end with
// every ball in the same place bit for bit. A heading written in degrees and read back may
// differ from the planner's in its last bit, and a rack is chaotic enough to part on it: the
// seed is one whose rack the round trip leaves as it was (3; chosen again with issue 28 and
// with the ladder of levels).
TEST(LiveAndHeadless, NineballMatchEndsWhereTheWindowEnds) {
  const LiveRack played =
      playLive(gameSetup(rules::Game::NineBall, 3), Level::Casual, Level::Club, 3);
  ASSERT_TRUE(played.won);
  nlohmann::json script = {{"game", "nine-ball"}, {"seed", 3}, {"turns", nlohmann::json::array()}};
  for (const TurnInput& t : played.turns) {
    if (t.kind == TurnInput::Kind::Decision) {
      script["turns"].push_back({{"decision", t.shoot ? "shoot" : "pass"}});
      continue;
    }
    nlohmann::json turn = {{"heading_deg", radToDeg(t.shot.heading_rad)},
                           {"speed", t.shot.speed},
                           {"tip", {t.shot.tip.x, t.shot.tip.y}},
                           {"elevation_deg", radToDeg(t.shot.elevation_rad)}};
    if (t.cue) turn["cue"] = {t.cue->x, t.cue->y};
    if (t.kind == TurnInput::Kind::PushOut) turn["push_out"] = true;
    script["turns"].push_back(turn);
  }
  const std::string text = script.dump();
  const auto parsed = io::parseMatchScript(text);
  ASSERT_TRUE(std::holds_alternative<io::MatchScript>(parsed));
  const io::MatchScript& ms = std::get<io::MatchScript>(parsed);

  GameSession s(ms.setup);
  for (const TurnInput& t : ms.turns) {
    if (t.kind == TurnInput::Kind::Decision) {
      s.decide(t.shoot);
      continue;
    }
    ASSERT_TRUE(s.shoot(t)) << s.message();
    for (int frame = 0; frame < kMaxFrames && s.phase() == Phase::Rolling; ++frame) {
      s.advance(kLiveFrame);
    }
  }
  testing::TempFile file(text);
  const testing::CliOutcome run = testing::runNineball("match " + file.path());
  ASSERT_EQ(run.status, 0) << run.err;
  const auto doc = nlohmann::json::parse(run.out);
  const auto balls = s.match().balls();
  ASSERT_EQ(doc["balls"].size(), balls.size());
  for (std::size_t i = 0; i < balls.size(); ++i) {
    EXPECT_EQ(doc["balls"][i]["id"].get<int>(), balls[i].id);
    EXPECT_EQ(doc["balls"][i]["x"].get<double>(), balls[i].pos.x) << balls[i].id;
    EXPECT_EQ(doc["balls"][i]["y"].get<double>(), balls[i].pos.y) << balls[i].id;
  }
}

}  // namespace
}  // namespace nineball::window
