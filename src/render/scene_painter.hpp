#pragma once

#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/RenderTexture.hpp>
#include <optional>
#include <string>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/table.hpp"
#include "play/aim_guide.hpp"
#include "render/ball_painter.hpp"
#include "render/call_painter.hpp"
#include "render/cue_painter.hpp"
#include "render/fonts.hpp"
#include "render/hud_painter.hpp"
#include "render/hud_state.hpp"
#include "render/table_painter.hpp"
#include "render/view_transform.hpp"

namespace nineball::render {

/// The cue stick's pose.
struct CuePose {
  double heading_rad = 0.0;
  double pull = 0.0;  ///< m pulled back from the ball
  double side = 0.0;  ///< the tip's side offset, fraction of R (right of the aim is positive)
  double elevation_rad = 0.0;  ///< the cue's tilt above the table
  /// Where the cue ball stood (the stroke's follow-through); the cue ball's place if empty.
  std::optional<Vec2> at;
};

/// A ball being moved by hand (the cue ball in hand), wherever the pointer is.
struct CueGhost {
  Vec2 pos;
  bool legal = true;
  std::string problem;  ///< why not, shown beside it
  int id = kCueBall;    ///< the ball moved (practice moves any ball)
};

/// One picture of the game: what the window shows at one instant.
struct Frame {
  std::vector<BallState> balls;  ///< where to draw each ball (pocketed ones are skipped)
  /// The physics' clock at this picture (s): how far each ball has turned with its spin, and
  /// how far a pocketed one has sunk.
  double time = 0.0;
  double ball_radius = 0.028575;
  std::optional<AimGuide> guide;
  /// The guide's lines after the contact, times normal; 0 draws the cue ball's line alone.
  double guide_scale = 1.0;
  std::optional<AimGuide> bank;  ///< the path on from the first cushion (a setting)
  /// The guide's first ball would be a foul: why, in a few words ("foul: the 3 is not the ball
  /// on"); the guide is then drawn red with this beside its ghost ball. Empty: no foul.
  std::string guide_foul;
  std::optional<CuePose> cue;
  std::optional<CueGhost> ghost;
  std::optional<CallMark> call;    ///< the shot being called (games with calls)
  BallLooks looks = poolBallLook;  ///< the game's set of balls
  HudState hud;
  /// The table the balls are on, when the picture knows it: the painter then draws that table
  /// (a menu's pick, a host's match or a resumed rack change it under the painter). Owned by
  /// whoever built the frame, and read only while the frame is drawn.
  const TableGeometry* table = nullptr;
};

/// True when two built tables are drawn alike: the same sizes, marks and cushion loop.
bool sameTable(const TableGeometry& a, const TableGeometry& b);

/// Draws frames of one table at one window size.
class ScenePainter {
 public:
  ScenePainter(const TableGeometry& table, const Fonts& fonts);

  /// Call when the window's size changes.
  void resize(double width_px, double height_px);
  /// Draws `table` from now on (its picture made again when it differs from the one drawn);
  /// draw() does this for every frame that names its table.
  void showTable(const TableGeometry& table);
  const TableGeometry& table() const { return table_; }
  /// Draws the table `zoom` times closer (1 to 4) round `focus` (m), the HUD as ever.
  void setZoom(double zoom, Vec2 focus);
  /// The view the table, the balls and the pointer are seen through (zoomed).
  const ViewTransform& view() const { return zoomed_; }

  void draw(sf::RenderTarget& target, const Frame& frame);
  /// The dialog of `hud` (its `dialog`), over the picture draw() drew last: a dialog screen
  /// draws itself so over the table. Its texts join hudTexts().
  void drawDialog(sf::RenderTarget& target, const HudState& hud) {
    hud_painter_.drawDialog(target, view_, hud);
  }
  /// Every line of text the last frame's HUD drew.
  const std::vector<DrawnText>& hudTexts() const { return hud_painter_.drawnTexts(); }

 private:
  void coverBands(sf::RenderTarget& target);
  void drawTable(sf::RenderTarget& target);

  TableGeometry table_;
  const Fonts& fonts_;
  ViewTransform view_;    // unzoomed: the table's picture and the HUD
  ViewTransform zoomed_;  // the table as seen now
  double zoom_ = 1.0;
  Vec2 focus_;
  TablePainter table_painter_;
  // The background and the table drawn once per size: the software renderer is bound by
  // filled pixels, so each frame starts from one opaque copy instead of layers of shapes.
  sf::RenderTexture table_picture_;
  bool have_picture_ = false;
  BallPainter ball_painter_;
  CuePainter cue_painter_;
  HudPainter hud_painter_;
};

}  // namespace nineball::render
