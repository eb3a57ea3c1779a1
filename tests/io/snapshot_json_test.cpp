// A match's state as JSON (what a host sends whole to heal a peer out of step): it reads back
// to the same bits, and a state that does not fit the match, or carries a number out of
// range, is refused by field.
#include "io/snapshot_json.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "net/racks_in_progress.hpp"
#include "nineball/match.hpp"
#include "nineball/table.hpp"

namespace nineball::io {
namespace {

using net_test::everyGame;
using net_test::playTurns;
using net_test::setupOf;
using nlohmann::json;

double boundOf(const Match& m) {
  const TableDef& t = m.world().table().def;
  return 0.5 * std::max(t.length, t.width) + 1.0;
}

// The snapshot through its JSON text and back.
MatchSnapshot throughText(const MatchSnapshot& s, const Match& m) {
  return parseSnapshot(json::parse(snapshotToJson(s).dump()), m.balls(), boundOf(m));
}

std::string refusal(const json& state, const Match& m) {
  try {
    parseSnapshot(state, m.balls(), boundOf(m));
  } catch (const ParseError& e) {
    return e.message;
  }
  ADD_FAILURE() << "read " << state.dump();
  return "";
}

TEST(SnapshotJson, ARackInProgressOfEveryGameReadsBackToTheSameHash) {
  for (rules::Game game : everyGame()) {
    Match m(setupOf(game));
    playTurns(m, 3);
    const MatchSnapshot s = m.snapshot();
    const MatchSnapshot back = throughText(s, m);
    EXPECT_EQ(snapshotHash(back), snapshotHash(s)) << rules::gameName(game);
    EXPECT_EQ(snapshotToJson(back), snapshotToJson(s)) << rules::gameName(game);
    // And a match restored from what was read plays on with it.
    Match restored(setupOf(game));
    restored.restore(back);
    EXPECT_EQ(snapshotHash(restored.snapshot()), snapshotHash(s)) << rules::gameName(game);
  }
}

TEST(SnapshotJson, EveryDoubleKeepsItsBits) {
  Match m(setupOf(rules::Game::NineBall));
  MatchSnapshot s = m.snapshot();
  s.balls[0].pos = {std::nextafter(0.1, 1.0), -1.0 / 3.0};
  s.balls[0].vel = {std::numeric_limits<double>::denorm_min(), -0.0};
  s.balls[0].w = {1e-300, -123.456789012345678, std::nextafter(0.0, -1.0)};
  s.balls[1].mass = 0.1700000000000001;
  s.balls[2].pocket = PocketId::BottomLeft;
  s.balls_before = {s.balls[0]};
  s.rack.winner = rules::Player::B;
  s.rack.groups.a = rules::Group::Stripes;
  s.rack.decision = rules::Decision::PlayOrPass;
  s.rack.snooker.on_table_before = {1, 2};
  s.rack.snooker.misses[1] = 2;
  s.cue_pocketed = true;
  const MatchSnapshot back = throughText(s, m);
  EXPECT_EQ(snapshotHash(back), snapshotHash(s));
  EXPECT_TRUE(std::signbit(back.balls[0].vel.y));
  EXPECT_EQ(back.balls[0].vel.x, std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(back.rack.winner, rules::Player::B);
  EXPECT_EQ(back.rack.groups.a, rules::Group::Stripes);
  EXPECT_FALSE(back.rack.groups.b.has_value());
  EXPECT_EQ(back.balls[2].pocket, PocketId::BottomLeft);
}

TEST(SnapshotJson, AStateOfAnotherMatchIsRefused) {
  Match nine(setupOf(rules::Game::NineBall));
  Match snooker(setupOf(rules::Game::Snooker));
  const json of_snooker = snapshotToJson(snooker.snapshot());
  EXPECT_NE(refusal(of_snooker, nine).find("state.balls"), std::string::npos);
  json swapped = snapshotToJson(nine.snapshot());
  std::swap(swapped["balls"][1], swapped["balls"][2]);
  EXPECT_NE(refusal(swapped, nine).find("state.balls[1].id: expected ball"), std::string::npos);
}

TEST(SnapshotJson, AFieldOutOfRangeOrOfTheWrongTypeIsRefusedByName) {
  Match m(setupOf(rules::Game::EightBall));
  playTurns(m, 1);
  const json good = snapshotToJson(m.snapshot());
  ASSERT_NO_THROW(parseSnapshot(good, m.balls(), boundOf(m)));
  struct Bad {
    json::json_pointer at;
    json value;
    const char* named;
  };
  const std::vector<Bad> bad = {
      {json::json_pointer("/balls/0/x"), 3.0, "state.balls[0].x"},
      {json::json_pointer("/balls/0/y"), "0", "state.balls[0].y"},
      {json::json_pointer("/balls/0/y"), nullptr, "state.balls[0].y"},
      {json::json_pointer("/balls/1/vx"), 101.0, "state.balls[1].vx"},
      {json::json_pointer("/balls/1/w"), {0, 0}, "state.balls[1].w"},
      {json::json_pointer("/balls/1/w/2"), -1e5, "state.balls[1].w[2]"},
      {json::json_pointer("/balls/2/mass"), 0.0, "state.balls[2].mass"},
      {json::json_pointer("/balls/2/mass"), 11.0, "state.balls[2].mass"},
      {json::json_pointer("/balls/3/pocket"), 6, "state.balls[3].pocket"},
      {json::json_pointer("/balls/3/pocket"), -1, "state.balls[3].pocket"},
      {json::json_pointer("/balls/3/spin"), 0, "state.balls[3].spin"},
      {json::json_pointer("/rack/racked"), {3, 2}, "state.rack.racked[1]"},
      {json::json_pointer("/rack/on_table"), {1, 1}, "state.rack.on_table[1]"},
      {json::json_pointer("/rack/on_table"), {16}, "state.rack.on_table[0]"},
      {json::json_pointer("/rack/shooter"), "C", "state.rack.shooter"},
      {json::json_pointer("/rack/winner"), 1, "state.rack.winner"},
      {json::json_pointer("/rack/break_next"), 0, "state.rack.break_next"},
      {json::json_pointer("/rack/decision"), 5, "state.rack.decision"},
      {json::json_pointer("/rack/fouls"), {0}, "state.rack.fouls"},
      {json::json_pointer("/rack/score"), {0, -1}, "state.rack.score[1]"},
      {json::json_pointer("/rack/groups"), {2, nullptr}, "state.rack.groups[0]"},
      {json::json_pointer("/rack/run"), 1.5, "state.rack.run"},
      {json::json_pointer("/rack/target"), 2000000, "state.rack.target"},
      {json::json_pointer("/rack/snooker/misses"), {0, 0, 0}, "state.rack.snooker.misses"},
      {json::json_pointer("/rack/snooker/on_table_before"),
       {0, 99},
       "state.rack.snooker.on_table_before[1]"},
      {json::json_pointer("/rack/snooker/extra"), true, "state.rack.snooker.extra"},
      {json::json_pointer("/rack/extra"), true, "state.rack.extra"},
      {json::json_pointer("/cue_pocketed"), "no", "state.cue_pocketed"},
      {json::json_pointer("/extra"), 1, "state.extra"},
  };
  for (const Bad& b : bad) {
    json j = good;
    j[b.at] = b.value;
    const std::string why = refusal(j, m);
    EXPECT_EQ(why.rfind(b.named, 0), 0u) << b.at.to_string() << ": " << why;
  }
  for (const char* key : {"balls", "rack", "cue_pocketed", "balls_before"}) {
    json j = good;
    j.erase(key);
    EXPECT_NE(refusal(j, m).find(key), std::string::npos) << key;
  }
  json more_before = good;
  more_before["balls_before"] = good["balls"];
  more_before["balls_before"].push_back(good["balls"][0]);
  EXPECT_NE(refusal(more_before, m).find("state.balls_before"), std::string::npos);
  json fewer = good;
  fewer["balls"].erase(fewer["balls"].size() - 1);
  EXPECT_NE(refusal(fewer, m).find("state.balls"), std::string::npos);
  EXPECT_NE(refusal(json::array(), m).find("state"), std::string::npos);
}

}  // namespace
}  // namespace nineball::io
