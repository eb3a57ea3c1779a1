#pragma once

#include <optional>

#include "render/scene_painter.hpp"
#include "window/computer_player.hpp"
#include "window/game_session.hpp"
#include "window/ui_state.hpp"

namespace nineball::window {

/// The picture of the game now: the balls where they are, the cue and the guide while
/// aiming (the computer's as it aims), the HUD with its dialog.
render::Frame buildFrame(const GameSession& session, const UiState& ui,
                         const ComputerPlayer& computer);

/// The point on the table a dialog must leave in sight: the cue ball, which the push-out choice
/// is about and the next rack's break starts near.
std::optional<Vec2> dialogKeepClear(const GameSession& session);

/// The dialog on screen, if any (the same rule the input uses to route keys and clicks).
render::Overlay activeOverlay(const GameSession& session, const UiState& ui);

}  // namespace nineball::window
