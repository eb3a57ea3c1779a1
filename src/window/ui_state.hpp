#pragma once

#include <optional>

#include "nineball/vec2.hpp"
#include "render/scene_painter.hpp"

namespace nineball::window {

/// What the mouse is dragging.
enum class Drag { None, Power, Cue, Ball, Spin, Tilt };

/// The window's own state beside the match: dialogs and drags. No SFML.
struct UiState {
  bool help = false;
  bool confirm_quit = false;
  Drag drag = Drag::None;
  Vec2 drag_anchor;   ///< where a power drag began (m)
  double pull = 0.0;  ///< how far the stick is drawn back (m)
  double speed_before_drag = 0.0;
  std::optional<render::CueGhost> ghost;  ///< the ball under the pointer while moved
  Vec2 pointer;  ///< where the pointer last was on the table (m): practice adds balls there
  /// The aim line locked (X): the pointer no longer moves it; Shift with the pointer, the
  /// arrows and the wheel still fine-tune it. A new turn unlocks it.
  bool aim_locked = false;
  /// The table seen this many times closer (1 to 4; Z, Shift+Z, Ctrl+wheel), round the cue
  /// ball as it rolls, or round `zoom_at` (m) when the wheel zoomed at the pointer.
  double zoom = 1.0;
  std::optional<Vec2> zoom_at;
  bool leave_to_menu = false;  ///< Esc leads to the start menu (else it quits the program)
  bool rack_kept = false;      ///< leaving saves the rack in play for "Resume rack"
};

}  // namespace nineball::window
