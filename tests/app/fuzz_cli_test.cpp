// Property-based fuzzing of `nineball sim` as a hostile user drives it: a seeded generator
// writes scenes anywhere in the allowed ranges and just outside them, with wrong types, NUL
// bytes, long keys and cut documents. Whatever comes in, the process must end with 0 (a
// complete result), 3 (a partial one, flagged) or 2 (a refusal: one line on stderr, nothing on
// stdout); a result must be finite, keep every ball on the table or in a pocket, and never
// hold more energy than the scene started with.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "app/cli_runner.hpp"
#include "common/limits.hpp"
#include "nineball/params.hpp"
#include "nineball/random.hpp"
#include "nineball/table.hpp"

namespace nineball::testing {
namespace {

using nlohmann::json;

#ifdef NINEBALL_SANITIZED
constexpr int kScenes = 400;  // ten times slower under the sanitizers
#else
constexpr int kScenes = 2500;
#endif

// Energy may rise by the rounding of Box2D's single-precision velocities only (the stress
// test's own bound).
constexpr double kEnergyRounding = 1e-6;

double logUniform(std::uint64_t& rng, double lo, double hi) {
  return lo * std::pow(hi / lo, uniform(rng, 0.0, 1.0));
}

// A value at, inside or just past one end of [lo, hi].
double edgy(std::uint64_t& rng, double lo, double hi) {
  switch (splitmix64(rng) % 40) {
    case 0:
      return lo;
    case 1:
      return hi;
    case 2:
      return hi * 1.0001;
    case 3:
      return lo * 0.9999;
    default:
      return lo > 0.0 ? logUniform(rng, lo, hi) : uniform(rng, lo, hi);
  }
}

json generate(std::uint64_t& rng) {
  json s;
  // One scene in four on a carom table with the carom preset, decided from a copy so that the
  // other draws stay as they were.
  std::uint64_t carom_draw = rng ^ 0x6361726f6dULL;
  const bool carom = splitmix64(carom_draw) % 4 == 0;
  // One in four of the others on a snooker table (its rounded jaws) with the snooker preset,
  // decided the same way.
  std::uint64_t snooker_draw = rng ^ 0x736e6f6f6b6572ULL;
  const bool snooker = !carom && splitmix64(snooker_draw) % 4 == 0;
  const double r = carom     ? PhysicsParams::carom().ball_radius
                   : snooker ? PhysicsParams::snooker().ball_radius
                   : splitmix64(rng) % 2
                       ? 0.028575
                       : edgy(rng, limits::kMinBallRadius, limits::kMaxBallRadius);
  const char* cloths[] = {"spin", "friction", "damping"};
  const char* cloth = cloths[splitmix64(rng) % 3];
  json physics = {{"cloth", cloth}, {"ball_radius", r}};
  physics["ball_restitution"] = splitmix64(rng) % 3 == 0 ? 0.0
                                : splitmix64(rng) % 2    ? 1.0
                                                         : uniform(rng, 0, 1);
  physics["cushion_restitution"] = splitmix64(rng) % 3 == 0 ? 0.0
                                   : splitmix64(rng) % 2    ? 1.0
                                                            : uniform(rng, 0, 1);
  physics["ball_mass"] = edgy(rng, limits::kMinBallMass, limits::kMaxBallMass);
  const bool frictionless = splitmix64(rng) % 3 == 0;
  if (std::string(cloth) == "damping") {
    physics["linear_damping"] = frictionless ? 0.0 : uniform(rng, 0.0, 2.0);
  } else {
    physics["rolling_friction"] = frictionless ? 0.0 : uniform(rng, 0.0, 0.05);
  }
  s["physics"] = physics;
  const double corner = uniform(rng, 1.5 * r, 6.0 * r), side = uniform(rng, 1.5 * r, 6.0 * r);
  const double width =
      std::max(2.05 * std::max(corner, side),
               (splitmix64(rng) % 2 ? 1.0 : logUniform(rng, 0.5, 4.0)) *
                   (std::sqrt(2.0) * corner + 2.0 * r) * (splitmix64(rng) % 4 ? 1.2 : 1.0));
  const double table_length =
      std::min(limits::kMaxTableLength,
               std::max(width, 2.0 * (corner / std::sqrt(2.0) + side / 2.0 + 2.0 * r)) *
                   logUniform(rng, 1.0, 3.0));
  TableDef table;
  if (carom) {
    const bool small = splitmix64(carom_draw) % 2 == 0;
    table = small ? TableDef::caromSmall() : TableDef::carom();
    s["table"] = small ? "carom-small" : "carom";
    s["physics"]["preset"] = "carom";
  } else if (snooker) {
    const bool small = splitmix64(snooker_draw) % 2 == 0;
    table = small ? TableDef::snookerTenFoot() : TableDef::snooker();
    s["table"] = small ? "snooker-10ft" : "snooker";
    s["physics"]["preset"] = "snooker";
  } else if (splitmix64(rng) % 3 == 0) {
    s["table"] = "9ft";
  } else {
    table.length = table_length;
    table.width = std::min(width, table_length);
    table.corner_pocket = corner;
    table.side_pocket = side;
    s["table"] = {{"length", table.length},
                  {"width", table.width},
                  {"corner_pocket", corner},
                  {"side_pocket", side}};
  }
  const double hx = table.length / 2.0 - r, hy = table.width / 2.0 - r;
  const int n = 1 + static_cast<int>(splitmix64(rng) % 16);
  json balls = json::array();
  std::vector<Vec2> at;
  for (int tries = 0; static_cast<int>(at.size()) < n && tries < 2000; ++tries) {
    const Vec2 p{uniform(rng, -hx, hx), uniform(rng, -hy, hy)};
    bool clear = true;
    for (Vec2 q : at) clear &= length(p - q) >= 2.0 * r + 1e-6;
    if (!clear) continue;
    at.push_back(p);
    json b = {{"id", static_cast<int>(at.size()) - 1}, {"x", p.x}, {"y", p.y}};
    const Vec2 v = fromAngle(uniform(rng, -kPi, kPi)) * edgy(rng, 0.0, limits::kMaxSpeed);
    b["vx"] = v.x;
    b["vy"] = v.y;
    balls.push_back(b);
  }
  s["balls"] = balls;
  if (splitmix64(rng) % 2)
    s["shot"] = {{"heading_deg", uniform(rng, -1e6, 1e6)},
                 {"speed", edgy(rng, 0.0, limits::kMaxSpeed)}};
  s["until"] = splitmix64(rng) % 2 ? json("rest") : json(uniform(rng, 0.01, 2.0));
  json step = json::object();
  if (splitmix64(rng) % 2) step["scale"] = edgy(rng, limits::kMinScale, limits::kMaxScale);
  if (splitmix64(rng) % 2) step["hz"] = edgy(rng, limits::kMinHz, limits::kMaxHz);
  step["max_time"] = 20.0;
  s["step"] = step;
  // One hostile change in three.
  switch (splitmix64(rng) % 24) {
    case 0:
      s["physics"]["ball_mass"] = "heavy";
      break;
    case 1:
      s["balls"].push_back({{"id", 99}, {"x", 1e308}, {"y", 0}});
      break;
    case 2:
      s[std::string(200000, 'k')] = 1;
      break;
    case 3:
      s["step"]["hz"] = 1e5;
      break;
    case 4:
      s["physics"]["ball_radius"] = 1e-160;
      break;
    case 5:
      s["balls"][0]["mass"] = 1e-40;
      break;
    case 6:
      s["shot"] = {{"heading_deg", 1e308}, {"speed", 100}};
      break;
    case 7:
      s["table"] = {{"length", 0.27}, {"width", 0.27}};
      break;
    default:
      break;
  }
  return s;
}

double energy(const json& balls, double mass) {
  double e = 0.0;
  for (const json& b : balls) {
    if (!b.contains("pocket") || b["pocket"].is_null()) {
      const double m = b.value("mass", mass);
      e += 0.5 * m * (std::pow(b.value("vx", 0.0), 2) + std::pow(b.value("vy", 0.0), 2));
    }
  }
  return e;
}

TEST(FuzzCli, EveryInputEndsWellOrIsRefusedCleanly) {
  std::uint64_t rng = 20261123;
  int ok = 0, partial = 0, refused = 0, off_table = 0;
  for (int i = 0; i < kScenes; ++i) {
    json scene = generate(rng);
    // A trace on one scene in three (its own numbers, so that the scenes stay the same): a
    // rate, the events alone, or a bad one.
    std::uint64_t trace_rng = 0x7ace + static_cast<std::uint64_t>(i);
    switch (i % 3 == 1 ? splitmix64(trace_rng) % 8 : 8) {
      case 0:
        scene["trace"] = {{"events_only", true}};
        break;
      case 1:
        scene["trace"] = {{"hz", 1e9}};
        break;
      case 8:
        break;
      default:
        // Up to a tenth of the top rate: 20 s of many balls at 10 kHz prints hundreds of MB.
        scene["trace"] = {{"hz", edgy(trace_rng, limits::kMinTraceHz, limits::kMaxTraceHz / 10)}};
        break;
    }
    std::string text = scene.dump();
    if (i % 50 == 7) text = text.substr(0, text.size() / 2);          // cut short
    if (i % 50 == 19) text += std::string(1, '\0') + "{\"junk\":1}";  // data after a NUL
    TempFile in(text);
    const CliOutcome r = runNineball("sim -", in.path());
    const std::string where = "scene " + std::to_string(i) + ": " + text.substr(0, 300);
    ASSERT_TRUE(r.status == 0 || r.status == 2 || r.status == 3)
        << "exit " << r.status << " " << r.err.substr(0, 300) << "\n"
        << where;
    if (r.status == 2) {
      ++refused;
      if (std::getenv("NINEBALL_FUZZ_SHOW")) std::printf("%s", r.err.substr(0, 200).c_str());
      EXPECT_TRUE(r.out.empty()) << where;
      EXPECT_EQ(r.err.rfind("nineball sim: ", 0), 0u) << r.err.substr(0, 200);
      EXPECT_LT(r.err.size(), 2000u) << "a refusal must not echo its input whole";
      continue;
    }
    EXPECT_FALSE(i % 50 == 7 || i % 50 == 19)
        << "a cut document or one with a NUL was run: " << where;
    (r.status == 0 ? ok : partial)++;
    const json out = json::parse(r.out);  // throws (fails) on non-finite numbers printed as null
    EXPECT_EQ(out["partial"].get<bool>(), r.status == 3) << where;
    const double r_ball = scene["physics"]["ball_radius"].get<double>();
    TableDef def;
    if (scene["table"].is_string()) def = *TableDef::named(scene["table"].get<std::string>());
    if (scene["table"].is_object()) {
      def.length = scene["table"]["length"];
      def.width = scene["table"]["width"];
      def.corner_pocket = scene["table"]["corner_pocket"];
      def.side_pocket = scene["table"]["side_pocket"];
    }
    const TableGeometry table = buildTable(def, r_ball);
    if (scene.contains("trace")) {
      ASSERT_TRUE(out.contains("trace")) << where;
      for (const auto& [id, t] : out["trace"].items()) {
        for (const char* key : {"t", "x", "y", "vx", "vy"}) {
          ASSERT_EQ(t[key].size(), t["t"].size()) << where;
          for (const json& v : t[key]) ASSERT_TRUE(v.is_number()) << id << " " << key << where;
        }
      }
    }
    for (const json& b : out["balls"]) {
      ASSERT_TRUE(b["x"].is_number() && b["y"].is_number()) << where;
      if (!b["pocket"].is_null()) continue;
      if (table.insideLoop({b["x"].get<double>(), b["y"].get<double>()})) continue;
      ++off_table;
      ADD_FAILURE() << where << ": ball " << b["id"] << " off the table, not pocketed";
      if (const char* dump = std::getenv("NINEBALL_FUZZ_DUMP")) std::ofstream(dump) << text;
    }
    if (!scene.contains("shot") && scene["physics"]["cloth"] != "spin") {
      const double mass = scene["physics"]["ball_mass"].get<double>();
      const double e0 = energy(scene["balls"], mass), e1 = energy(out["balls"], mass);
      EXPECT_LE(e1, e0 * (1.0 + kEnergyRounding) + 1e-12) << where;
    }
  }
  std::printf(
      "[ measured ] fuzz: %d scenes, %d complete, %d partial, %d refused; %d balls off the table\n",
      kScenes, ok, partial, refused, off_table);
  EXPECT_GT(ok, kScenes / 4) << "the generator must reach valid scenes, not only refusals";
  EXPECT_GT(refused, kScenes / 20) << "and hostile ones";
}

}  // namespace
}  // namespace nineball::testing
