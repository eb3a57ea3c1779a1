#pragma once

#include <optional>

#include "app/game/computer_player.hpp"
#include "app/game/game_session.hpp"
#include "app/game/ui_state.hpp"
#include "render/scene_painter.hpp"

namespace nineball::app {

/// The picture of the game now: the balls where they are, the cue and the guide while
/// aiming (the computer's as it aims), the HUD with its dialog.
render::Frame buildFrame(const GameSession& session, const UiState& ui,
                         const ComputerPlayer& computer);

/// The point on the table a dialog must leave in sight: the cue ball, which the push-out choice
/// is about and the next rack's break starts near.
std::optional<Vec2> dialogKeepClear(const GameSession& session);

/// The dialog on screen, if any (the same rule the input uses to route keys and clicks).
render::Overlay activeOverlay(const GameSession& session, const UiState& ui);

}  // namespace nineball::app
