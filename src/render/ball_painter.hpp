#pragma once

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/colours.hpp"
#include "nineball/table.hpp"
#include "render/ball_shader.hpp"
#include "render/ball_spin.hpp"
#include "render/triangle_batch.hpp"
#include "render/view_transform.hpp"

namespace nineball::render {

/// Balls seen from above: each a lit sphere turned as its spin has turned it (its number,
/// stripe and spots where the turning put them), its shadow cast away from the light, and a
/// ball that has just dropped sinking and darkening into its pocket.
class BallPainter {
 public:
  explicit BallPainter(const sf::Font& numbers) : spheres_(numbers) {}
  /// The set of balls drawn (a game's looks; pool balls until told).
  void setLooks(BallLooks looks) { looks_ = looks; }

  /// Draws every ball still on the table at its given position, radius r metres, turned to
  /// where its spin has brought it by `time` (s, the physics' clock); a ball pocketed less
  /// than kSinkTime ago sinks into its pocket of `table`.
  void draw(sf::RenderTarget& target, const ViewTransform& view,
            const std::vector<BallState>& balls, double r, double time, const TableGeometry& table);
  /// One ball at a pixel position and pixel radius, its number up (the HUD's icons, the ball
  /// in hand); `alpha` fades it.
  void drawOne(sf::RenderTarget& target, int id, Vec2 centre_px, double radius_px,
               std::uint8_t alpha = 255);

  /// How long a pocketed ball is seen sinking (s of the physics' clock).
  static constexpr double kSinkTime = 0.35;

  const BallSpins& spins() const { return spins_; }
  SphereBallRenderer& spheres() { return spheres_; }

 private:
  void shadow(Vec2 c, double r, std::uint8_t alpha, double lift_px = 0.0);
  void sinking(sf::RenderTarget& target, const ViewTransform& view, const BallState& b, double r,
               double time, const TableGeometry& table);

  SphereBallRenderer spheres_;
  BallSpins spins_;
  BallLooks looks_ = poolBallLook;
  TriangleBatch shadows_;
};

}  // namespace nineball::render
