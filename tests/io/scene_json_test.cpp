#include "io/scene_json.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "io/scene_checks.hpp"

namespace nineball::io {
namespace {

/// Two balls well apart on a 9 ft table, with `extra` spliced in as further top-level keys.
std::string twoBallScene(const std::string& extra = "") {
  return R"({"balls": [{"id": 0, "x": -0.635, "y": 0.0}, {"id": 1, "x": 0.635, "y": 0.1}])" +
         (extra.empty() ? "" : ", " + extra) + "}";
}

using testing::accepted;
using testing::refusedAt;

TEST(SceneJson, RefusesUnreadableJson) {
  EXPECT_TRUE(refusedAt(R"({"balls": [)", "invalid JSON", "parse error"));
  EXPECT_TRUE(refusedAt(twoBallScene() + " trailing", "invalid JSON", "parse error"));
  EXPECT_TRUE(refusedAt("", "invalid JSON", "empty input"));
  EXPECT_TRUE(refusedAt(" \n", "invalid JSON", "empty input"));
}

TEST(SceneJson, RefusesARootThatIsNotAnObject) {
  EXPECT_TRUE(refusedAt("[]", "scene", "expected an object"));
  EXPECT_TRUE(refusedAt("3", "scene", "expected an object"));
}

TEST(SceneJson, RefusesMissingBalls) {
  EXPECT_TRUE(refusedAt("{}", "balls", "required"));
  EXPECT_TRUE(refusedAt(R"({"balls": {}})", "balls", "expected an array"));
  EXPECT_TRUE(refusedAt(R"({"balls": [{"id": 0, "x": 0}]})", "balls[0].y", "required"));
}

TEST(SceneJson, RefusesMistypedFields) {
  EXPECT_TRUE(refusedAt(
      R"({"balls": [{"id": 0, "x": 0, "y": 0}, {"id": 1, "x": 0.5, "y": 0},
                    {"id": 2, "x": "far", "y": 0}]})",
      "balls[2].x", "expected a number"));
  EXPECT_TRUE(
      refusedAt(R"({"balls": [{"id": 0, "x": 0, "y": null}]})", "balls[0].y", "expected a number"));
  EXPECT_TRUE(
      refusedAt(R"({"balls": [{"id": 0, "x": true, "y": 0}]})", "balls[0].x", "expected a number"));
  EXPECT_TRUE(refusedAt(R"({"balls": ["cue"]})", "balls[0]", "expected an object"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"ball_mass": "heavy"})"), "physics.ball_mass",
                        "expected a number"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": [])"), "physics", "expected an object"));
  EXPECT_TRUE(
      refusedAt(twoBallScene(R"("table": 9)"), "table", "expected a table name or an object"));
}

TEST(SceneJson, RefusesIdsThatAreNotNonNegativeIntegers) {
  EXPECT_TRUE(refusedAt(R"({"balls": [{"id": 1.5, "x": 0, "y": 0}]})", "balls[0].id",
                        "expected an integer"));
  EXPECT_TRUE(refusedAt(R"({"balls": [{"id": 3.0, "x": 0, "y": 0}]})", "balls[0].id",
                        "expected an integer"));
  EXPECT_TRUE(refusedAt(R"({"balls": [{"id": -1, "x": 0, "y": 0}]})", "balls[0].id", ">= 0"));
  EXPECT_TRUE(refusedAt(R"({"balls": [{"id": 18446744073709551615, "x": 0, "y": 0}]})",
                        "balls[0].id", "<= 2147483647"));
}

TEST(SceneJson, RefusesNumbersNoDoubleCanHold) {
  EXPECT_TRUE(
      refusedAt(R"({"balls": [{"id": 0, "x": 0, "y": 0}, {"id": 1, "x": 0.5, "y": 1e999}]})",
                "balls[1].y", "out of range"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"gravity": -1e999})"), "physics.gravity",
                        "out of range"));
  EXPECT_TRUE(
      refusedAt(twoBallScene(R"("shot": {"heading_deg": 0, "speed": 1, "tip": [0, 1e999]})"),
                "shot.tip[1]", "out of range"));
}

TEST(SceneJson, RefusesAKeyGivenTwice) {
  EXPECT_TRUE(refusedAt(R"({"balls": [{"id": 0, "x": 0, "x": 1, "y": 0}]})", "balls[0].x",
                        "duplicate key"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("until": 1, "until": 2)"), "until", "duplicate key"));
}

TEST(SceneJson, RefusesUnknownFields) {
  EXPECT_TRUE(refusedAt(twoBallScene(R"("colour": "green")"), "colour", "unknown field"));
  EXPECT_TRUE(refusedAt(R"({"balls": [{"id": 0, "x": 0, "y": 0, "spin": 1}]})", "balls[0].spin",
                        "unknown field"));
  EXPECT_TRUE(
      refusedAt(twoBallScene(R"("step": {"substeps": 4})"), "step.substeps", "unknown field"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("shot": {"heading_deg": 0, "speed": 1, "english": 1})"),
                        "shot.english", "unknown field"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("table": {"length": 2, "width": 1, "rails": 6})"),
                        "table.rails", "unknown field"));
}

TEST(SceneJson, RefusesUnknownPhysicsParameters) {
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"air_drag": 0.1})"), "physics.air_drag",
                        "unknown parameter"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"preset": "moon"})"), "physics.preset",
                        "unknown preset \"moon\""));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"cloth": "felt"})"), "physics.cloth",
                        "unknown cloth model \"felt\""));
}

TEST(SceneJson, RefusesPhysicsOutOfRange) {
  EXPECT_TRUE(
      refusedAt(twoBallScene(R"("physics": {"ball_mass": 0})"), "physics.ball_mass", ">= 0.01"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"ball_radius": -0.01})"), "physics.ball_radius",
                        ">= 0.01 and <= 0.1"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"ball_restitution": 1.5})"),
                        "physics.ball_restitution", ">= 0 and <= 1"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"rolling_friction": -0.1})"),
                        "physics.rolling_friction", ">= 0"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"gravity": 0})"), "physics.gravity", "> 0"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"linear_damping": 1e300})"),
                        "physics.linear_damping", "<= 1000"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"ball_mass": 1e300})"), "physics.ball_mass",
                        ">= 0.01 and <= 1"));
}

TEST(SceneJson, RefusesWhatThePhysicsCannotHold) {
  // Each bound of nineball/limits.hpp, and the message that names it.
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"ball_radius": 1e-160})"),
                        "physics.ball_radius", ">= 0.01"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("step": {"hz": 1e5})"), "step.hz", "<= 2000"));
  EXPECT_TRUE(refusedAt(R"({"balls": [{"id": 0, "x": 0, "y": 0, "mass": 1e-40}]})", "balls[0].mass",
                        ">= 0.01"));
  EXPECT_TRUE(
      refusedAt(R"({"balls": [{"id": 0, "x": 0, "y": 0, "vx": 100}]})", "balls[0]", "<= 14 m/s"));
  EXPECT_TRUE(refusedAt(R"({"balls": [{"id": 0, "x": 0, "y": 0, "w": [0, 0, 1e4]}]})",
                        "balls[0].w[2]", "<= 1224.85"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("table": {"length": 0.27, "width": 0.27})"), "table",
                        "less than a ball's diameter"));
  EXPECT_TRUE(
      refusedAt(twoBallScene(R"("table": {"length": 2.54, "width": 1.27, "side_pocket": 0.06,
                                           "side_jaw_deg": 179.9})"),
                "table", "cross each other"));
  std::string many = R"({"balls": [)";
  for (int i = 0; i < 201; ++i)
    many += (i ? "," : "") + std::string(R"({"id": )") + std::to_string(i) + R"(, "x": 0, "y": 0})";
  EXPECT_TRUE(refusedAt(many + "]}", "balls", "more than the 200"));
}

TEST(SceneJson, CutsLongKeysAndRefusesNulBytes) {
  const auto long_key = parseScene("{\"" + std::string(100000, 'k') + "\": 1}");
  ASSERT_TRUE(std::holds_alternative<ParseError>(long_key));
  EXPECT_LT(std::get<ParseError>(long_key).message.size(), 300u);
  const std::string with_nul = std::string(R"({"balls": []})") + '\0' + "garbage";
  const auto nul = parseScene(with_nul);
  ASSERT_TRUE(std::holds_alternative<ParseError>(nul));
  EXPECT_NE(std::get<ParseError>(nul).message.find("NUL byte at offset 13"), std::string::npos);
}

TEST(SceneJson, RefusesUnknownOrImpossibleTables) {
  EXPECT_TRUE(refusedAt(twoBallScene(R"("table": "10ft")"), "table", "unknown table \"10ft\""));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("table": {"width": 1.27})"), "table.length", "required"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("table": {"length": 1.0, "width": 2.0})"), "table.width",
                        "<= table.length"));
  EXPECT_TRUE(
      refusedAt(twoBallScene(R"("table": {"length": 0, "width": 0})"), "table.length", "> 0"));
  EXPECT_TRUE(
      refusedAt(twoBallScene(R"("table": {"length": 2.54, "width": 1.27, "side_pocket": 0.7})"),
                "table.side_pocket", "< table.width / 2"));
}

TEST(SceneJson, RefusesDuplicateIds) {
  EXPECT_TRUE(refusedAt(R"({"balls": [{"id": 3, "x": 0, "y": 0}, {"id": 3, "x": 0.5, "y": 0}]})",
                        "balls[1].id", "duplicate id 3"));
}

TEST(SceneJson, RefusesANegativeMass) {
  EXPECT_TRUE(refusedAt(R"({"balls": [{"id": 0, "x": 0, "y": 0, "mass": -0.17}]})", "balls[0].mass",
                        ">= 0.01"));
}

TEST(SceneJson, RefusesABadUntil) {
  EXPECT_TRUE(refusedAt(twoBallScene(R"("until": "forever")"), "until", "expected \"rest\""));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("until": 0)"), "until", "> 0"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("until": 7200)"), "until", "<= 3600"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("until": [])"), "until", "expected \"rest\""));
}

TEST(SceneJson, RefusesABadStep) {
  EXPECT_TRUE(refusedAt(twoBallScene(R"("step": {"hz": 0})"), "step.hz", ">= 1 and <= 2000"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("step": {"velocity_iterations": 0})"),
                        "step.velocity_iterations", ">= 1"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("step": {"position_iterations": 2.5})"),
                        "step.position_iterations", "expected an integer"));
  EXPECT_TRUE(
      refusedAt(twoBallScene(R"("step": {"scale": 0.1})"), "step.scale", ">= 10 and <= 1000"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("step": {"contacts": "exact"})"), "step.contacts",
                        "unknown contact model"));
}

TEST(SceneJson, RefusesSpeedTogetherWithForce) {
  EXPECT_TRUE(refusedAt(
      twoBallScene(R"("shot": {"heading_deg": 0, "speed": 3, "force": 10, "contact_time": 0.01})"),
      "shot", "not both"));
}

TEST(SceneJson, RefusesIncompleteOrExcessiveShots) {
  EXPECT_TRUE(refusedAt(twoBallScene(R"("shot": {"speed": 3})"), "shot.heading_deg", "required"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("shot": {"heading_deg": 0})"), "shot", "needs \"speed\""));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("shot": {"heading_deg": 0, "force": 10})"),
                        "shot.contact_time", "required"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("shot": {"heading_deg": 0, "speed": 14.5})"), "shot.speed",
                        "<= 14"));
  EXPECT_TRUE(
      refusedAt(twoBallScene(R"("shot": {"heading_deg": 0, "force": 1000, "contact_time": 1})"),
                "shot", "more than 14"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("shot": {"heading_deg": 0, "speed": 1, "tip": [0.1]})"),
                        "shot.tip", "two numbers"));
  EXPECT_TRUE(
      refusedAt(twoBallScene(R"("shot": {"heading_deg": 0, "speed": 1, "tip": [0.9, 0.9]})"),
                "shot.tip", "must lie on the ball"));
}

TEST(SceneJson, RefusesAShotWithoutCueBall) {
  EXPECT_TRUE(refusedAt(R"({"balls": [{"id": 1, "x": 0, "y": 0}],
                            "shot": {"heading_deg": 0, "speed": 3}})",
                        "shot", "cue ball"));
}

// The last two rely on validateScene, whose message names the ball.
TEST(SceneJson, RefusesOverlappingBalls) {
  EXPECT_TRUE(refusedAt(R"({"balls": [{"id": 0, "x": 0, "y": 0}, {"id": 5, "x": 0.03, "y": 0}]})",
                        "balls[1]", "overlap"));
}

TEST(SceneJson, RefusesABallOffTheTable) {
  EXPECT_TRUE(refusedAt(R"({"balls": [{"id": 0, "x": 0, "y": 0}, {"id": 1, "x": 3.0, "y": 0}]})",
                        "balls[1]", "off the table"));
}

TEST(SceneJson, AppliesDefaults) {
  const Scene s = accepted(R"({"balls": [{"id": 0, "x": -0.5, "y": 0.25}]})");
  const TableDef nine = TableDef::nineFoot();
  EXPECT_EQ(s.table.length, nine.length);
  EXPECT_EQ(s.table.width, nine.width);
  EXPECT_EQ(s.table.corner_pocket, nine.corner_pocket);
  const PhysicsParams real = PhysicsParams::real();
  EXPECT_EQ(s.physics.ball_mass, real.ball_mass);
  EXPECT_EQ(s.physics.ball_restitution, real.ball_restitution);
  EXPECT_EQ(s.physics.cloth, real.cloth);
  const StepParams step;
  EXPECT_EQ(s.step.hz, step.hz);
  EXPECT_EQ(s.step.box2d.contacts, step.box2d.contacts);
  EXPECT_FALSE(s.shot.has_value());
  EXPECT_FALSE(s.until.has_value());
  ASSERT_EQ(s.balls.size(), 1u);
  EXPECT_EQ(s.balls[0].id, 0);
  EXPECT_EQ(s.balls[0].pos, Vec2(-0.5, 0.25));
  EXPECT_EQ(s.balls[0].vel, Vec2());
  EXPECT_FALSE(s.balls[0].mass.has_value());
  EXPECT_FALSE(s.balls[0].pocket.has_value());
}

TEST(SceneJson, ReadsBallFields) {
  const Scene s = accepted(R"({"balls": [{"id": 7, "x": 0.1, "y": -0.2, "vx": 1.5, "vy": -2,
                                          "mass": 0.16}]})");
  ASSERT_EQ(s.balls.size(), 1u);
  EXPECT_EQ(s.balls[0].id, 7);
  EXPECT_EQ(s.balls[0].vel, Vec2(1.5, -2.0));
  EXPECT_EQ(s.balls[0].mass, 0.16);
}

TEST(SceneJson, AppliesThePresetBeforeOverridesWhateverTheKeyOrder) {
  const Scene s = accepted(
      twoBallScene(R"("physics": {"ball_mass": 0.2, "preset": "paper", "cloth": "damping"})"));
  const PhysicsParams paper = PhysicsParams::paper();
  EXPECT_EQ(s.physics.ball_mass, 0.2);
  EXPECT_EQ(s.physics.ball_restitution, paper.ball_restitution);
  EXPECT_EQ(s.physics.cushion_restitution, paper.cushion_restitution);
  EXPECT_EQ(s.physics.cloth, ClothModel::Damping);
}

TEST(SceneJson, ReadsEveryPhysicsParameter) {
  const Scene s = accepted(twoBallScene(R"("physics": {
      "ball_mass": 0.16, "ball_radius": 0.028, "ball_restitution": 0.9,
      "cushion_restitution": 0.7, "rolling_friction": 0.02, "sliding_friction": 0.3,
      "cushion_friction": 0.1, "spin_decay": 8, "gravity": 9.8, "miscue_limit": 0.6})"));
  EXPECT_EQ(s.physics.ball_mass, 0.16);
  EXPECT_EQ(s.physics.ball_radius, 0.028);
  EXPECT_EQ(s.physics.ball_restitution, 0.9);
  EXPECT_EQ(s.physics.cushion_restitution, 0.7);
  EXPECT_EQ(s.physics.rolling_friction, 0.02);
  EXPECT_EQ(s.physics.sliding_friction, 0.3);
  EXPECT_EQ(s.physics.cushion_friction, 0.1);
  EXPECT_EQ(s.physics.spin_decay, 8.0);
  EXPECT_EQ(s.physics.gravity, 9.8);
  EXPECT_EQ(s.physics.miscue_limit, 0.6);
  const Scene d = accepted(twoBallScene(
      R"("physics": {"cloth": "damping", "linear_damping": 0.5, "rest_speed": 0.002})"));
  EXPECT_EQ(d.physics.linear_damping, 0.5);
  EXPECT_EQ(d.physics.rest_speed, 0.002);
}

TEST(SceneJson, ReadsTheBallBallModelAndItsFriction) {
  Scene s = accepted(twoBallScene(R"("physics": {"ball_friction": 0.05})"));
  EXPECT_EQ(s.physics.ball_ball, BallBallModel::named("frictional"));
  EXPECT_DOUBLE_EQ(s.physics.ball_friction.at(3.0), 0.05);
  s = accepted(twoBallScene(R"("physics": {"ball_friction": {"a": 0.01, "b": 0.1, "c": 1.0}})"));
  EXPECT_DOUBLE_EQ(s.physics.ball_friction.at(0.0), 0.11);
  s = accepted(twoBallScene(R"("physics": {"preset": "paper"})"));
  EXPECT_EQ(s.physics.ball_ball, BallBallModel::named("frictionless"));
  s = accepted(twoBallScene(R"("physics": {"ball_ball": "frictionless"})"));
  EXPECT_EQ(s.physics.ball_ball, BallBallModel::named("frictionless"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"ball_ball": "sticky"})"), "physics.ball_ball",
                        "unknown ball-ball model"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"ball_friction": 1.5})"),
                        "physics.ball_friction", "<= 1"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"ball_friction": {"a": 0.01, "b": 0.1}})"),
                        "physics.ball_friction.c", "required"));
  EXPECT_TRUE(
      refusedAt(twoBallScene(R"("physics": {"ball_friction": {"a": 0.6, "b": 0.6, "c": 1}})"),
                "physics.ball_friction", "a + b"));
}

TEST(SceneJson, ReadsTheCushionModelTheCueAndElevation) {
  Scene s = accepted(twoBallScene(R"("physics": {"cushion": "simple"})"));
  EXPECT_EQ(s.physics.cushion, CushionModel::named("simple"));
  s = accepted(twoBallScene(R"("physics": {"cushion_height": 0.037})"));
  EXPECT_EQ(s.physics.cushion, CushionModel::named("mathavan"));
  EXPECT_DOUBLE_EQ(s.physics.cushion_height, 0.037);
  // The nose follows a ball whose radius is set alone: 63.5 % of its diameter.
  s = accepted(twoBallScene(R"("physics": {"ball_radius": 0.03})"));
  EXPECT_DOUBLE_EQ(s.physics.cushion_height, 1.27 * 0.03);
  EXPECT_EQ(accepted(twoBallScene(R"("physics": {"preset": "paper"})")).physics.cushion,
            CushionModel::named("simple"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"cushion": "rubber"})"), "physics.cushion",
                        "unknown cushion model"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"cushion_height": 0.02})"),
                        "physics.cushion_height", "no lower than the ball's centre"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"cushion_height": 0.06})"),
                        "physics.cushion_height", "below its top"));
  EXPECT_TRUE(
      refusedAt(twoBallScene(R"("physics": {"cushion": "simple", "cushion_height": 0.036})"),
                "physics.cushion_height", "not used by the \"simple\" cushion"));
  s = accepted(twoBallScene(R"("shot": {"heading_deg": 0, "speed": 3, "elevation_deg": 30})"));
  ASSERT_TRUE(s.shot.has_value());
  EXPECT_NEAR(s.shot->elevation_rad, 30.0 * 3.14159265358979323846 / 180.0, 1e-12);
  EXPECT_TRUE(
      refusedAt(twoBallScene(R"("shot": {"heading_deg": 0, "speed": 3, "elevation_deg": 90})"),
                "shot.elevation_deg", ""));
  EXPECT_TRUE(
      refusedAt(twoBallScene(R"("shot": {"heading_deg": 0, "speed": 3, "elevation_deg": -1})"),
                "shot.elevation_deg", ""));
  s = accepted(twoBallScene(R"("physics": {"cue_end_mass": 0})"));
  EXPECT_EQ(s.physics.cue_end_mass, 0.0);
  EXPECT_TRUE(
      refusedAt(twoBallScene(R"("physics": {"cue_end_mass": -1})"), "physics.cue_end_mass", ""));
}

TEST(SceneJson, RefusesAParameterNoModelReads) {
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"ball_friction": 0.05, "preset": "paper"})"),
                        "physics.ball_friction", "not used by the \"frictionless\" ball-ball"));
  // The cloth may come after the parameter: the check waits for it.
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"spin_decay": 5, "preset": "paper"})"),
                        "physics.spin_decay", "not used by the \"friction\" cloth"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"linear_damping": 0.5})"),
                        "physics.linear_damping", "only by the \"damping\" cloth"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"cloth": "damping", "gravity": 9.8})"),
                        "physics.gravity", "\"spin\" or \"friction\""));
  EXPECT_TRUE(refusedAt(R"({"physics": {"preset": "paper"},
                           "balls": [{"id": 0, "x": 0, "y": 0, "w": [0, 10, 0]}]})",
                        "balls[0].w", "carries no spin"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("step": {"engine": "reference", "hz": 120})"), "step.hz",
                        "not used by the reference engine"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("step": {"scale": 50, "engine": "reference"})"),
                        "step.scale", "no time step"));
  const Scene r = accepted(twoBallScene(R"("step": {"engine": "reference", "max_time": 5})"));
  EXPECT_EQ(r.step.engine, EngineKind::named("reference"));
}

TEST(SceneJson, ReadsANamedTable) {
  const Scene s = accepted(R"({"table": "7ft", "balls": [{"id": 0, "x": -0.4, "y": 0}]})");
  EXPECT_EQ(s.table.length, 1.98);
  EXPECT_EQ(s.table.width, 0.99);
}

TEST(SceneJson, ReadsACustomTable) {
  const Scene s =
      accepted(twoBallScene(R"("table": {"length": 2.2, "width": 1.1, "corner_pocket": 0.12,
                                             "corner_jaw_deg": 140})"));
  EXPECT_EQ(s.table.length, 2.2);
  EXPECT_EQ(s.table.width, 1.1);
  EXPECT_EQ(s.table.corner_pocket, 0.12);
  EXPECT_EQ(s.table.corner_jaw_deg, 140.0);
  EXPECT_EQ(s.table.side_pocket, TableDef().side_pocket);
  EXPECT_EQ(s.table.side_jaw_deg, TableDef().side_jaw_deg);
}

TEST(SceneJson, ReadsTheCaromTablesWithoutPockets) {
  Scene s = accepted(R"({"table": "carom", "balls": [{"id": 0, "x": -0.4, "y": 0}]})");
  EXPECT_EQ(s.table.length, 2.84);
  EXPECT_EQ(s.table.width, 1.42);
  EXPECT_FALSE(s.table.pockets);
  s = accepted(R"({"table": "carom-small", "balls": [{"id": 0, "x": -0.4, "y": 0}]})");
  EXPECT_EQ(s.table.length, 2.10);
  EXPECT_EQ(s.table.width, 1.05);
  EXPECT_FALSE(s.table.pockets);
  s = accepted(twoBallScene(R"("table": {"length": 2.0, "width": 1.0, "pockets": false})"));
  EXPECT_FALSE(s.table.pockets);
  EXPECT_TRUE(accepted(twoBallScene(R"("table": {"length": 2.0, "width": 1.0, "pockets": true})"))
                  .table.pockets);
  // A ball in what would be a pool table's corner pocket is on the cloth of a carom table.
  EXPECT_EQ(
      accepted(R"({"table": "carom", "balls": [{"id": 0, "x": 1.38, "y": 0.67}]})").balls.size(),
      1u);
}

TEST(SceneJson, RefusesPocketFieldsOnATableWithoutPockets) {
  for (const char* key : {"corner_pocket", "side_pocket", "corner_jaw_deg", "side_jaw_deg",
                          "corner_jaw_radius", "side_jaw_radius"}) {
    const std::string table =
        std::string(R"("table": {"length": 2.0, "width": 1.0, "pockets": false, ")") + key +
        R"(": 0.1})";
    EXPECT_TRUE(refusedAt(twoBallScene(table), std::string("table.") + key,
                          "a table without pockets has no pocket mouths or jaws"))
        << key;
  }
  EXPECT_TRUE(refusedAt(twoBallScene(R"("table": {"length": 2.0, "width": 1.0, "pockets": 0})"),
                        "table.pockets", "expected true or false"));
  EXPECT_TRUE(refusedAt(twoBallScene(R"("table": "bar-box")"), "table",
                        R"(expected "9ft", "8ft", "7ft", "carom", "carom-small", "snooker", )"
                        R"("snooker-10ft" or an object)"));
}

TEST(SceneJson, ReadsTheCaromPreset) {
  const Scene s = accepted(twoBallScene(R"("physics": {"preset": "carom"})"));
  EXPECT_EQ(s.physics.ball_radius, 0.03075);
  EXPECT_EQ(s.physics.ball_mass, 0.210);
  EXPECT_EQ(s.physics.cushion_height, 0.037);
  EXPECT_EQ(s.physics.rolling_friction, 0.005);
  EXPECT_EQ(s.physics.cushion, PhysicsParams::real().cushion);
  EXPECT_EQ(s.physics.ball_ball, PhysicsParams::real().ball_ball);
  EXPECT_TRUE(refusedAt(twoBallScene(R"("physics": {"preset": "moon"})"), "physics.preset",
                        R"(expected "real", "paper", "carom" or "snooker")"));
}

TEST(SceneJson, ReadsTheSnookerPresetAndTables) {
  const Scene s = accepted(twoBallScene(R"("physics": {"preset": "snooker"}, "table": "snooker")"));
  EXPECT_EQ(s.physics.ball_radius, 0.02625);
  EXPECT_EQ(s.physics.ball_mass, 0.142);
  EXPECT_EQ(s.physics.sliding_friction, 0.212);
  EXPECT_EQ(s.physics.cushion, PhysicsParams::real().cushion);
  EXPECT_EQ(s.table.length, 3.569);
  EXPECT_EQ(s.table.corner_jaw_radius, TableDef::snooker().corner_jaw_radius);
  // A custom table may round its jaws too; a radius below 0 is refused by name.
  const Scene custom = accepted(twoBallScene(
      R"("table": {"length": 2.54, "width": 1.27, "corner_jaw_radius": 0.01, "side_jaw_radius": 0})"));
  EXPECT_EQ(custom.table.corner_jaw_radius, 0.01);
  EXPECT_TRUE(refusedAt(
      twoBallScene(R"("table": {"length": 2.54, "width": 1.27, "corner_jaw_radius": -0.01})"),
      "table.corner_jaw_radius", ""));
}

TEST(SceneJson, ReadsASpeedShotWithTip) {
  const Scene s =
      accepted(twoBallScene(R"("shot": {"heading_deg": 90, "speed": 3, "tip": [0.25, -0.5]})"));
  ASSERT_TRUE(s.shot.has_value());
  const Shot expected = Shot::withSpeed(90.0, 3.0);
  EXPECT_EQ(s.shot->heading_rad, expected.heading_rad);
  EXPECT_EQ(s.shot->speed, 3.0);
  EXPECT_EQ(s.shot->tip, Vec2(0.25, -0.5));
}

TEST(SceneJson, ReadsAnImpulseShotWithTheCueBallMass) {
  const Scene s =
      accepted(twoBallScene(R"("shot": {"heading_deg": 0, "force": 10, "contact_time": 0.01})"));
  ASSERT_TRUE(s.shot.has_value());
  EXPECT_EQ(s.shot->speed, Shot::withImpulse(0.0, 10.0, 0.01, PhysicsParams().ball_mass).speed);

  const Scene heavy = accepted(R"({"balls": [{"id": 0, "x": 0, "y": 0, "mass": 0.2}],
                                   "physics": {"ball_mass": 0.1},
                                   "shot": {"heading_deg": 0, "force": 10, "contact_time": 0.01}})");
  ASSERT_TRUE(heavy.shot.has_value());
  EXPECT_EQ(heavy.shot->speed, Shot::withImpulse(0.0, 10.0, 0.01, 0.2).speed);
}

TEST(SceneJson, ReadsUntilAndStep) {
  const Scene timed = accepted(twoBallScene(R"("until": 2.5, "step": {"hz": 2000,
      "velocity_iterations": 10, "position_iterations": 0, "scale": 50, "contacts": "box2d",
      "max_time": 30})"));
  EXPECT_EQ(timed.until, 2.5);
  EXPECT_EQ(timed.step.hz, 2000.0);
  EXPECT_EQ(timed.step.box2d.velocity_iterations, 10);
  EXPECT_EQ(timed.step.box2d.position_iterations, 0);
  EXPECT_EQ(timed.step.box2d.scale, 50.0);
  EXPECT_EQ(timed.step.box2d.contacts, ContactModel::Box2D);
  EXPECT_EQ(timed.step.max_time, 30.0);
  EXPECT_FALSE(accepted(twoBallScene(R"("until": "rest")")).until.has_value());
}

TEST(SceneJson, ReadsAParsedDocument) {
  const auto doc = nlohmann::json::parse(twoBallScene(R"("until": 1)"));
  const SceneResult r = sceneFromJson(doc);
  ASSERT_TRUE(std::holds_alternative<Scene>(r));
  EXPECT_EQ(std::get<Scene>(r).balls.size(), 2u);
  const SceneResult bad = sceneFromJson(nlohmann::json::array());
  ASSERT_TRUE(std::holds_alternative<ParseError>(bad));
}

}  // namespace
}  // namespace nineball::io
