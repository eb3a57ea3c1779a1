#pragma once

#include <map>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/colours.hpp"
#include "nineball/vec3.hpp"

// No SFML here: the orientation of each ball and the colour of each point of it are plain
// arithmetic, shared by the shader's CPU fallback and the tests.
namespace nineball::render {

/// A rotation as a unit quaternion: body coordinates (the number disc at +z, the stripe band
/// around the body's y axis) to table coordinates (x right, y towards the top rail, z up).
struct Orientation {
  double w = 1.0, x = 0.0, y = 0.0, z = 0.0;

  /// The same orientation turned by the rotation vector `turn` (axis times angle, rad) about
  /// the table's axes.
  Orientation turned(Vec3 turn) const;
  /// Where a body vector points on the table.
  Vec3 toTable(Vec3 body) const;
  /// Which body vector points along a table vector.
  Vec3 toBody(Vec3 table) const;
};

/// Every ball's orientation, turned frame after frame by its angular velocity. The physics'
/// spin is piecewise linear in time within a phase (sliding, rolling and spinning all change w
/// at a steady rate), so the turn between two frames, the trapezoid of their spins times the
/// simulated time between them, is the physics' own while the axis holds, whatever the frame
/// rate.
class BallSpins {
 public:
  /// Turns each ball by the spin between the last call's state and this one's, `sim_time` s
  /// of the physics' clock after the start (a step back, a new rack or a replay restarting,
  /// turns nothing). A ball seen for the first time faces its number up.
  void advance(const std::vector<BallState>& balls, double sim_time);
  Orientation of(int id) const;
  /// When (the physics' clock) and where a ball was last seen dropping into a pocket: from
  /// the first state that has it pocketed after one that had it on the table.
  struct Drop {
    double time = 0.0;
    Vec2 at;
  };
  const Drop* dropOf(int id) const;
  /// Forget every ball: the next rack starts with every number up.
  void reset();

 private:
  struct Kept {
    Orientation q;
    Vec3 w;
    bool on_table = true;
    bool dropped = false;
    Drop drop;
  };
  std::map<int, Kept> balls_;
  double time_ = 0.0;
  bool started_ = false;
};

/// The cue ball's spots, one at each pole.
constexpr Rgb kCueSpot{200, 30, 40};

/// A colour with alpha, 0-1.
struct Shade {
  double r = 0.0, g = 0.0, b = 0.0, a = 0.0;
};

/// The scale of a number's glyph, `width` x `height` as the font draws it, in a square cell of
/// `cell` px that stands for the number disc: tall enough to read, and narrow enough that two
/// digits stay inside the disc (within 0.78 of its width, where the disc is still flat enough
/// to read).
double glyphScale(double width, double height, double cell);

/// The light over the table: up and a little towards the top left, as the shadows fall.
Vec3 lightDirection();

/// What a ball's surface shows at a body direction `body` (unit), before lighting: the base
/// colour or the stripe band, the number discs at the two poles (the number itself read from
/// `ink` at disc coordinates -1..1, 1 where the glyph is), the cue ball's spots. `ink` may be
/// null (no glyphs).
using InkSampler = double (*)(const void* glyphs, int number, double u, double v);
Shade surfaceColour(const BallLook& look, int number, Vec3 body, InkSampler ink,
                    const void* glyphs);

/// A surface colour as the table's light shows it at (sx, sy) on a ball seen from above (-1..1,
/// y towards the top rail): the diffuse and specular terms litBall and the shader apply.
Shade lightAt(Shade surface, double sx, double sy);
/// The same for a palette colour, rounded to a pixel's (what a picture of a ball must show).
Rgb litColour(Rgb surface, double sx, double sy);

/// The lit colour of a ball at (sx, sy) within its disc as seen from above (-1..1, y towards
/// the top rail), or nothing outside (alpha 0); `edge` is the disc's radius in pixels, for the
/// soft rim. The same arithmetic as the shader (render/ball_shader.cpp).
Shade litBall(const BallLook& look, int number, const Orientation& q, double sx, double sy,
              double edge, InkSampler ink, const void* glyphs);

}  // namespace nineball::render
