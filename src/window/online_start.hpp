#pragma once

#include <optional>

#include "app/game_options.hpp"
#include "window/game_window.hpp"
#include "window/menu.hpp"
#include "window/online_play.hpp"
#include "window/settings.hpp"

// How an online game is asked for: --host / --join on the command line, or the start menu's
// "Play online". The table begins it (TableScreen::beginOnline) in its lobby.
namespace nineball::window {

/// --host / --join: this side of the link, its name, code and script (the options were checked).
OnlineConfig onlineConfigFromOptions(const app::GameOptions& options, const GameStart& start);

/// The start menu's "Play online": host on the default port, or join the address typed there,
/// with the name typed on the menu's main screen; nothing for any other outcome.
std::optional<OnlineConfig> onlineConfigFromMenu(MenuModel::Outcome outcome,
                                                 const Settings& settings, const MatchSetup& setup);

}  // namespace nineball::window
