// The spin parts of the sim contract: "w" on scene balls, "tip" on the shot, "w" in the
// result, a miscue event.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "io/result_json.hpp"
#include "io/scene_json.hpp"

namespace nineball::io {
namespace {

Scene parsed(const std::string& text) {
  SceneResult r = parseScene(text);
  if (const auto* e = std::get_if<ParseError>(&r)) {
    ADD_FAILURE() << "refused: " << e->message;
    return {};
  }
  return std::get<Scene>(r);
}

std::string refusal(const std::string& text) {
  SceneResult r = parseScene(text);
  const auto* e = std::get_if<ParseError>(&r);
  return e ? e->message : "";
}

}  // namespace

TEST(SpinJson, BallsTakeAnAngularVelocity) {
  const Scene s = parsed(R"({"balls": [{"id": 0, "x": 0, "y": 0, "vx": 1, "w": [0, 35, 2]}]})");
  EXPECT_EQ(s.balls[0].w, Vec3(0.0, 35.0, 2.0));
  EXPECT_EQ(refusal(R"({"balls": [{"id": 0, "x": 0, "y": 0, "w": [0, 35]}]})")
                .rfind("balls[0].w: expected [wx, wy, wz]", 0),
            0u);
  EXPECT_EQ(refusal(R"({"balls": [{"id": 0, "x": 0, "y": 0, "w": [0, "a", 0]}]})")
                .rfind("balls[0].w[1]: ", 0),
            0u);
}

TEST(SpinJson, ARollingBallKeepsRollingAndTheResultGivesItsSpin) {
  // Rolling along +x at 1 m/s: w = (0, v/R, 0); with no rolling resistance it keeps going.
  const Scene s = parsed(R"({"physics": {"rolling_friction": 0},
      "balls": [{"id": 0, "x": -0.5, "y": 0, "vx": 1, "w": [0, 34.99562554680665, 0]}],
      "until": 0.2})");
  const auto j = resultToJson(simulate(s));
  const auto& ball = j["balls"][0];
  EXPECT_NEAR(ball["vx"].get<double>(), 1.0, 1e-9);
  ASSERT_EQ(ball["w"].size(), 3u);
  EXPECT_NEAR(ball["w"][1].get<double>(), 1.0 / 0.028575, 1e-6);
}

TEST(SpinJson, AVelocityAloneSlides) {
  // No "w": the ball starts with no spin, slides, and ends rolling at 5/7 of its speed.
  const Scene s = parsed(R"({"physics": {"rolling_friction": 0},
      "balls": [{"id": 0, "x": -1.0, "y": 0, "vx": 1}], "until": 0.5})");
  const SimResult r = simulate(s);
  EXPECT_NEAR(r.balls[0].vel.x, 5.0 / 7.0, 0.005);
}

TEST(SpinJson, AMiscueIsAnEventAndTheBallStaysPut) {
  const Scene s = parsed(R"({"balls": [{"id": 0, "x": 0, "y": 0}],
      "shot": {"heading_deg": 0, "speed": 2, "tip": [0.5, 0.3]}})");
  const auto j = resultToJson(simulate(s));
  ASSERT_GE(j["events"].size(), 1u);
  EXPECT_EQ(j["events"][0]["type"], "miscue");
  EXPECT_EQ(j["events"][0]["ball"], 0);
  EXPECT_EQ(j["balls"][0]["x"].get<double>(), 0.0);
}

}  // namespace nineball::io
