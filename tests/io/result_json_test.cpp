#include "io/result_json.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace nineball::io {
namespace {

std::vector<std::string> keysOf(const nlohmann::ordered_json& j) {
  std::vector<std::string> keys;
  for (const auto& item : j.items()) keys.push_back(item.key());
  return keys;
}

using Keys = std::vector<std::string>;

SimResult sampleResult() {
  SimResult r;
  r.time = 4.21;
  r.steps = 4210;
  r.wall_ms = 1.9;
  BallState cue;
  cue.id = 0;
  cue.pos = {0.1, -0.2};
  cue.vel = {0.0, 0.0};
  BallState one;
  one.id = 1;
  one.pos = {1.3, 0.65};
  one.pocket = PocketId::TopRight;
  r.balls = {cue, one};
  Event hit;
  hit.type = EventType::BallBall;
  hit.t = 0.113;
  hit.a = 0;
  hit.b = 1;
  hit.va = {0.1, 0.2};
  hit.vb = {2.9, -0.2};
  Event cushion;
  cushion.type = EventType::Cushion;
  cushion.t = 0.5;
  cushion.a = 1;
  cushion.va = {-1.0, 0.5};
  Event drop;
  drop.type = EventType::Pocket;
  drop.t = 0.9;
  drop.a = 1;
  drop.pocket = PocketId::TopRight;
  Event rest;
  rest.type = EventType::AllAtRest;
  rest.t = 4.21;
  r.events = {hit, cushion, drop, rest};
  return r;
}

TEST(ResultJson, HasTheDesignsKeysInOrder) {
  const auto j = resultToJson(sampleResult());
  EXPECT_EQ(keysOf(j), (Keys{"time", "steps", "wall_ms", "end", "partial", "balls", "events"}));
  EXPECT_EQ(j["time"], 4.21);
  EXPECT_EQ(j["steps"], 4210);
  EXPECT_EQ(j["wall_ms"], 1.9);
}

TEST(ResultJson, WritesBalls) {
  const auto j = resultToJson(sampleResult());
  ASSERT_EQ(j["balls"].size(), 2u);
  const auto& cue = j["balls"][0];
  EXPECT_EQ(keysOf(cue), (Keys{"id", "x", "y", "vx", "vy", "z", "vz", "w", "pocket", "off_table"}));
  EXPECT_EQ(cue["id"], 0);
  EXPECT_EQ(cue["x"], 0.1);
  EXPECT_EQ(cue["y"], -0.2);
  EXPECT_TRUE(cue["pocket"].is_null());
  EXPECT_EQ(j["balls"][1]["pocket"], "top-right");
}

TEST(ResultJson, WritesEachEventType) {
  const auto events = resultToJson(sampleResult())["events"];
  ASSERT_EQ(events.size(), 4u);
  EXPECT_EQ(keysOf(events[0]), (Keys{"t", "type", "a", "b", "va", "vb"}));
  EXPECT_EQ(events[0]["type"], "ball");
  EXPECT_EQ(events[0]["a"], 0);
  EXPECT_EQ(events[0]["b"], 1);
  EXPECT_EQ(events[0]["va"], nlohmann::ordered_json::array({0.1, 0.2}));
  EXPECT_EQ(events[0]["vb"], nlohmann::ordered_json::array({2.9, -0.2}));
  EXPECT_EQ(keysOf(events[1]), (Keys{"t", "type", "ball", "v"}));
  EXPECT_EQ(events[1]["type"], "cushion");
  EXPECT_EQ(events[1]["ball"], 1);
  EXPECT_EQ(events[1]["v"], nlohmann::ordered_json::array({-1.0, 0.5}));
  EXPECT_EQ(keysOf(events[2]), (Keys{"t", "type", "ball", "pocket"}));
  EXPECT_EQ(events[2]["type"], "pocket");
  EXPECT_EQ(events[2]["pocket"], "top-right");
  EXPECT_EQ(keysOf(events[3]), (Keys{"t", "type"}));
  EXPECT_EQ(events[3]["type"], "rest");
  EXPECT_EQ(events[3]["t"], 4.21);
}

TEST(ResultJson, KeepsFullPrecision) {
  SimResult r;
  r.time = 0.1 + 0.2;
  BallState b;
  b.pos = {1.0 / 3.0, -2.0 / 7.0};
  r.balls = {b};
  const auto back = nlohmann::json::parse(resultToJson(r).dump(2));
  EXPECT_EQ(back["time"].get<double>(), 0.1 + 0.2);
  EXPECT_EQ(back["balls"][0]["x"].get<double>(), 1.0 / 3.0);
  EXPECT_EQ(back["balls"][0]["y"].get<double>(), -2.0 / 7.0);
}

TEST(ResultJson, WritesEmptyListsAsArrays) {
  const auto j = resultToJson(SimResult{});
  EXPECT_TRUE(j["balls"].is_array());
  EXPECT_TRUE(j["events"].is_array());
}

}  // namespace
}  // namespace nineball::io
