#pragma once

#include <optional>
#include <string>
#include <vector>

#include "render/scene_painter.hpp"
#include "window/game_session.hpp"
#include "window/seats/seats.hpp"
#include "window/ui_state.hpp"

namespace nineball::window {

/// The picture of the game now: the balls where they are, the cue and the guide while
/// aiming (the cue of the seat whose player has the table: the computer's or a remote player's
/// as it aims), the HUD with its dialog.
render::Frame buildFrame(const GameSession& session, const UiState& ui, const Seats& seats);

/// The points on the table a dialog must leave in sight: every ball on it, since the push-out
/// choice is about the whole position (and the rack's end shows how it ended).
std::vector<Vec2> dialogKeepClear(const GameSession& session);

/// True when Esc may leave for the menu without asking: the rack in play is saved for
/// "Resume rack", or there is none to lose.
bool leavingLosesNothing(const GameSession& session, const UiState& ui);

/// "vs computer (medium)   O: opponent": who plays, as the HUD's top band says it.
std::string opponentModeLabel(const Seat& opponent);

}  // namespace nineball::window
