#pragma once

#include <cstdint>

/// The colours of the table and the balls, shared by the game's painters and the headless
/// pictures (`nineball sim --svg`). No drawing library here.
namespace nineball {

struct Rgb {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
};

/// The cloth (a classic green, far enough from the 6 ball's to tell them apart).
constexpr Rgb kCloth{46, 139, 87};
constexpr Rgb kCushion{28, 104, 62};
constexpr Rgb kWood{96, 56, 30};
constexpr Rgb kPocket{12, 12, 12};
constexpr Rgb kDiamond{236, 228, 206};
constexpr Rgb kBackground{22, 26, 30};
constexpr Rgb kCueBallColour{246, 244, 232};
constexpr Rgb kNumberDisc{250, 250, 245};

/// The standard colour of a ball: 0 the cue ball; 1 yellow, 2 blue, 3 red, 4 purple, 5 orange,
/// 6 green, 7 maroon, 8 black; 9-15 the stripes of 1-7 (drawn on white).
inline Rgb ballColour(int id) {
  constexpr Rgb kSolids[8] = {
      {250, 196, 16},  // 1 yellow
      {24, 64, 196},   // 2 blue
      {214, 30, 36},   // 3 red
      {104, 44, 150},  // 4 purple
      {246, 118, 20},  // 5 orange
      {0, 96, 44},     // 6 green
      {128, 24, 36},   // 7 maroon
      {18, 18, 18},    // 8 black
  };
  if (id <= 0) return kCueBallColour;
  if (id <= 8) return kSolids[id - 1];
  return kSolids[(id - 9) % 7];
}

/// Balls 9-15 are stripes: a coloured band on a white ball.
inline bool isStripe(int id) {
  return id >= 9;
}

/// How a ball of a game's set looks from above.
struct BallLook {
  Rgb colour;
  bool stripe = false;    ///< a band of `colour` on a white ball
  bool numbered = false;  ///< a white disc with the ball's number
  bool spots = false;     ///< red spots that show it turning (pool's cue ball, carom's two)
};
/// The looks of one set of balls, by ball id (a game's GameDef::looks).
using BallLooks = BallLook (*)(int id);

/// Pool balls: the cue ball white and plain, 1-8 solids and 9-15 stripes, each numbered.
inline BallLook poolBallLook(int id) {
  return {ballColour(id), isStripe(id), id != 0, id == 0};
}

/// Carom balls: 0 white, 1 yellow, 2 red, no numbers or stripes; the two cue balls carry red
/// spots that show their spin (as tournament sets' spotted balls do).
inline BallLook caromBallLook(int id) {
  constexpr Rgb kYellow{246, 200, 40};
  constexpr Rgb kRed{206, 26, 32};
  if (id == 1) return {kYellow, false, false, true};
  if (id == 2) return {kRed, false, false, false};
  return {kCueBallColour, false, false, true};
}

/// A carom ball's name as players say it ("white", "yellow", "red"); null for another id.
inline const char* caromBallName(int id) {
  constexpr const char* kNames[] = {"white", "yellow", "red"};
  return id >= 0 && id <= 2 ? kNames[id] : nullptr;
}

/// Snooker balls (ids of the issue 34 contract): the cue ball white and plain, reds 1-15,
/// then yellow, green, brown, blue, pink and black (16-21); no numbers or stripes.
inline BallLook snookerBallLook(int id) {
  constexpr Rgb kColours[7] = {
      {200, 22, 30},    // red
      {246, 210, 30},   // yellow
      {0, 120, 56},     // green (darker than the cloth's, lighter than pool's 6)
      {120, 70, 30},    // brown
      {30, 80, 200},    // blue
      {240, 130, 170},  // pink
      {18, 18, 18},     // black
  };
  if (id >= 1 && id <= 15) return {kColours[0], false, false, false};
  if (id >= 16 && id <= 21) return {kColours[id - 15], false, false, false};
  return {kCueBallColour, false, false, false};
}

/// A snooker ball's name as players say it ("red", "yellow" ... "black"); null for another id.
inline const char* snookerBallName(int id) {
  constexpr const char* kColours[] = {"yellow", "green", "brown", "blue", "pink", "black"};
  if (id >= 1 && id <= 15) return "red";
  return id >= 16 && id <= 21 ? kColours[id - 16] : nullptr;
}

/// A game's ball names (GameDef::ball_name): null for a ball known by its number.
using BallNames = const char* (*)(int id);

/// The stripe's half height as a fraction of the radius.
constexpr double kStripeHalfHeight = 0.55;
/// The white disc that carries the number, as a fraction of the radius.
constexpr double kNumberDiscRadius = 0.5;

}  // namespace nineball
