#include "games/snooker/snooker.hpp"

#include "games/snooker/respot.hpp"
#include "games/snooker/spots.hpp"
#include "games/triangle.hpp"
#include "rules/snooker_balls.hpp"

namespace nineball {
namespace {

// The apex red sits this far (m) beyond touching the pink: "as near as possible without
// touching" (WPBSA 3.2), kept measurable for the engines' contact tests.
constexpr double kApexClearance = 0.0002;
constexpr int kRows = 5;
namespace balls = rules::snooker;

}  // namespace

std::vector<BallState> rackSnooker(const TableDef& table, double ball_radius, std::uint64_t,
                                   double gap) {
  std::vector<BallState> placed;
  const double shift = 2.0 * ball_radius + kApexClearance;
  const std::vector<Vec2> reds = games::triangleSpots(table, ball_radius, gap, kRows);
  const Vec2 pink = snooker::colourSpot(table, balls::kPink);
  for (int i = 0; i <= balls::kLastRed - balls::kFirstRed; ++i) {
    // triangleSpots puts the apex on the foot spot, which is the pink's spot.
    const Vec2 p =
        reds[static_cast<std::size_t>(i)] + Vec2{pink.x - table.length / 4.0 + shift, 0.0};
    games::put(placed, balls::kFirstRed + i, p);
  }
  for (int colour = balls::kYellow; colour <= balls::kBlack; ++colour) {
    games::put(placed, colour, snooker::colourSpot(table, colour));
  }
  return placed;
}

namespace games {

GameEntry snooker() {
  GameDef g;
  GameTexts t;
  g.id = rules::Game::Snooker;
  g.name = "snooker";
  for (int b = balls::kFirstRed; b <= balls::kBlack; ++b) g.balls.push_back(b);
  g.highest_ball = balls::kBlack;
  g.rule_sets = {rules::RuleSet::Wpbsa};
  g.rack = rackSnooker;
  g.looks = snookerBallLook;
  g.ball_name = snookerBallName;
  g.tables = {"snooker", "snooker-10ft"};
  t.help = {"Snooker: pot a red (1), then a colour (its value: yellow 2 ... black 7), while reds",
            "  remain; colours are re-spotted. Then the colours from yellow to black.",
            "A foul gives the opponent 4-7 points; they play on or put you back in.",
            "Snookered after a foul: a free ball. The cue ball is in hand in the D."};
  t.made = "potted the ball on";
  g.physics = "snooker";
  g.takes_calls = true;
  g.decision = {"play", "put-back", "the choice after a foul (\"replace\" too after a miss)",
                "replace"};
  g.break_area = CueArea::TheD;
  g.in_hand_area = CueArea::TheD;
  g.spot = snooker::respotPlace;
  g.snookers = true;
  g.jump_shot_foul = true;
  // A snooker match is the best of an agreed odd number of frames, odd so that it cannot be tied
  // (professional ones from best of 9 to the world final's 35: sportsdefinitions.com/snooker/
  // frame, liquisearch.com/rules_of_snooker); up to 11 here, a single frame the quick game.
  t.best_of_choices = {1, 3, 5, 7, 9, 11};
  return {g, t};
}

}  // namespace games
}  // namespace nineball
