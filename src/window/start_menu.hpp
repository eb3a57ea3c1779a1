#pragma once

#include <SFML/Graphics/RenderWindow.hpp>
#include <functional>
#include <vector>

#include "app/game_options.hpp"
#include "render/menu_painter.hpp"
#include "render/scene_painter.hpp"
#include "window/game_session.hpp"
#include "window/menu.hpp"
#include "window/rack_save.hpp"
#include "window/seats/seats.hpp"
#include "window/settings.hpp"

namespace nineball::window {

/// What the window needs to show the start menu over the table.
struct StartMenuContext {
  sf::RenderWindow& window;
  render::ScenePainter& painter;
  render::MenuPainter& menu_painter;
  std::function<render::Frame()> frame;  ///< the table behind the menu
  bool muted_by_option = false;          ///< --mute: no sound this run, whatever the settings
  /// A game started from the menu racks from a new seed (drawsFreshSeeds); else from the
  /// session's own (--seed, or a test's picture that must come out the same).
  bool fresh_seeds = false;
  /// Keys given to the menu before it shows (the tests' way to pick a game from it).
  std::vector<MenuKey> typed;
};

/// The menu's choices as the command line asks: an option given there (--game, --rules,
/// --opponent, a default value too) wins over the choice the settings remember.
void presetFromCommandLine(Settings& settings, const app::GameOptions& options,
                           const MatchSetup& setup);

/// The table behind the menu, its top band saying who plays as the menu now chooses.
render::Frame menuBackdrop(render::Frame behind, const MenuModel& model);

/// "Ann vs Computer: rack 4, racks 2-1": the saved rack's entry in the menu.
std::string describeSavedRack(const SavedRack& rack);

/// Draws the start menu once into the window's back buffer (for --menu --screenshot).
void drawStartMenu(StartMenuContext& ctx, const Settings& settings);

/// The start menu as it opens: the settings' choices, and "Resume rack" when a rack is saved.
MenuModel openStartMenu(const StartMenuContext& ctx, const Settings& settings,
                        const std::optional<SavedRack>& saved);

/// The menu's end: `settings` become the menu's (saved), and on Play, Resume or "Play online"
/// `session` becomes the game chosen (the saved rack replayed for Resume, which it then forgets
/// if it does not replay), the computer takes Player 2's seat if chosen, the names are set. The
/// new session tells `observer` of its turns, the replayed ones included. False when no game
/// starts (Quit, or the window closed). "Play online: host / join" start the game chosen as
/// Play does (a joiner's is replaced by the host's once welcomed).
bool startChosenGame(const StartMenuContext& ctx, const MenuModel& model,
                     const std::optional<SavedRack>& saved, GameSession& session, Seats& seats,
                     Settings& settings, const GameSession::TurnObserver& observer);

/// The start menu settled by the keys typed into it before it shows (ctx.typed, a picture
/// run's choice): as startChosenGame, false too when the keys settle nothing (nobody is there
/// to finish the choice). `outcome`, when given, says what was chosen.
bool chooseByTypedKeys(StartMenuContext& ctx, GameSession& session, Seats& seats,
                       Settings& settings, const GameSession::TurnObserver& observer,
                       MenuModel::Outcome* outcome = nullptr);

/// Draws the menu over the table behind it (its top band saying who plays as the menu now
/// chooses) into `target`.
void drawStartMenuOver(const StartMenuContext& ctx, sf::RenderTarget& target,
                       const MenuModel& model);

}  // namespace nineball::window
