#include "games/three_cushion/three_cushion.hpp"

#include "games/triangle.hpp"
#include "rules/three_cushion.hpp"

namespace nineball {
namespace {

// UMB art. 13: the starting spots lie 182 mm either side of the bottom spot on a 1.42 m wide
// match table.
constexpr double kStartingSpotOffset = 0.182;
constexpr double kMatchTableWidth = 1.42;

}  // namespace

std::vector<BallState> rackThreeCushion(const TableDef& table, double, std::uint64_t seed, double) {
  using rules::ThreeCushionRules;
  const double side =
      (seed % 2 == 1 ? 1.0 : -1.0) * kStartingSpotOffset * table.width / kMatchTableWidth;
  std::vector<BallState> balls;
  games::put(balls, ThreeCushionRules::kWhite, {-table.length / 4.0, side});
  games::put(balls, ThreeCushionRules::kYellow, {-table.length / 4.0, 0.0});
  games::put(balls, ThreeCushionRules::kRed, {table.length / 4.0, 0.0});
  return balls;
}

namespace games {

GameEntry threeCushion() {
  GameDef g;
  GameTexts t;
  g.id = rules::Game::ThreeCushion;
  g.family = GameFamily::Carom;
  g.name = "three-cushion";
  g.balls = {rules::ThreeCushionRules::kYellow, rules::ThreeCushionRules::kRed};
  g.required_balls = g.balls;
  g.required_why = "three-cushion is played with the white (0), the yellow (1) and the red (2)";
  g.highest_ball = rules::ThreeCushionRules::kRed;
  g.rule_sets = {rules::RuleSet::Umb};
  g.rack = rackThreeCushion;
  g.looks = caromBallLook;
  g.ball_name = caromBallName;
  g.tables = {"carom", "carom-small"};
  t.help = {"Three-cushion: your ball (white opens, yellow for the other) must touch both",
            "  other balls and meet three cushions before the second; a point plays on.",
            "The opening shot goes straight onto the red. Games to 15, 25 or 40 points."};
  t.made = "scored a point";
  g.physics = "carom";
  g.cue_in_hand = false;
  g.decisions = false;
  g.decision.about = "three-cushion has no choice between turns: every turn is a shot";
  g.default_points = 25;
  t.points_choices = {15, 25, 40};
  return {g, t};
}

}  // namespace games
}  // namespace nineball
