#pragma once

#include <optional>

#include "render/hud_state.hpp"
#include "window/game_session.hpp"
#include "window/seats/seats.hpp"
#include "window/ui_state.hpp"

// The dialogs over the table: which one the table's state calls for, and what it says. A new
// dialog is a kind here, its words and look in dialog_contents.cpp and its screen in
// dialog_screen.hpp: this folder only.
namespace nineball::window {

enum class DialogKind { None, Help, ConfirmQuit, PushOutChoice, GameOver };

/// The dialog the table's state calls for, if any (the same rule the input uses to route keys
/// and clicks).
DialogKind dialogCalledFor(const GameSession& session, const UiState& ui);

/// The dialog on screen offers snooker's third answer after a miss, the balls replaced (its
/// middle button).
bool replaceOffered(const GameSession& session, const UiState& ui);

/// How a dialog of the kind is laid out (none for DialogKind::None).
std::optional<render::DialogLook> lookOf(DialogKind kind);

/// The dialog called for, in the HUD: its look, title, lines and buttons (nothing when none).
void fillDialog(render::HudState& hud, const GameSession& session, const UiState& ui,
                const Seats& seats);

}  // namespace nineball::window
