#include "window/start_menu.hpp"

#include "common/log.hpp"
#include "nineball/games.hpp"
#include "window/frame_builder.hpp"
#include "window/menu_screen.hpp"
#include "window/rack_save.hpp"
#include "window/rack_seed.hpp"
#include "window/state_file.hpp"

namespace nineball::window {
namespace {

std::optional<std::string> resumeLabel(const std::optional<SavedRack>& saved) {
  if (!saved) return std::nullopt;
  return describeSavedRack(*saved);
}

}  // namespace

void presetFromCommandLine(Settings& settings, const app::GameOptions& options,
                           const MatchSetup& setup) {
  if (options.opponent_given) {
    settings.last.opponent = seatFromName(options.opponent).value_or(HumanSeat{});
  }
  if (options.rules_given) settings.last.rules = setup.rules;
  if (options.game_given) settings.last.game = setup.game;
}

render::Frame menuBackdrop(render::Frame behind, const MenuModel& model) {
  behind.hud.mode = opponentModeLabel(model.choice().opponent);
  return behind;
}

std::string describeSavedRack(const SavedRack& rack) {
  const std::string p2 = isComputer(rack.opponent) ? std::string("Computer") : rack.names[1];
  const std::string game =
      rack.game == defaultGame().id ? "" : std::string(gameDef(rack.game).name) + ", ";
  return game + rack.names[0] + " vs " + p2 + ": rack " + std::to_string(rack.rack_index + 1) +
         ", racks " + std::to_string(rack.racks_won[0]) + "-" + std::to_string(rack.racks_won[1]);
}

MenuModel openStartMenu(const StartMenuContext& ctx, const Settings& settings,
                        const std::optional<SavedRack>& saved) {
  MenuModel model(settings, resumeLabel(saved));
  model.setMutedByOption(ctx.muted_by_option);
  return model;
}

void drawStartMenuOver(const StartMenuContext& ctx, sf::RenderTarget& target,
                       const MenuModel& model) {
  ctx.painter.draw(target, menuBackdrop(ctx.frame(), model));
  ctx.menu_painter.draw(target, ctx.window.getSize().x, ctx.window.getSize().y, menuPicture(model));
}

void drawStartMenu(StartMenuContext& ctx, const Settings& settings) {
  drawStartMenuOver(ctx, ctx.window, openStartMenu(ctx, settings, loadRack(rackSavePath())));
}

bool chooseByTypedKeys(StartMenuContext& ctx, GameSession& session, Seats& seats,
                       Settings& settings, const GameSession::TurnObserver& observer,
                       MenuModel::Outcome* outcome_out) {
  const std::optional<SavedRack> saved = loadRack(rackSavePath());
  MenuModel model = openStartMenu(ctx, settings, saved);
  for (const MenuKey k : ctx.typed) model.key(k);
  // Keys typed that settle nothing end the menu: nobody is there to finish the choice.
  if (model.outcome() == MenuModel::Outcome::None) return false;
  if (outcome_out) *outcome_out = model.outcome();
  return startChosenGame(ctx, model, saved, session, seats, settings, observer);
}

bool startChosenGame(const StartMenuContext& ctx, const MenuModel& model,
                     const std::optional<SavedRack>& saved, GameSession& session, Seats& seats,
                     Settings& settings, const GameSession::TurnObserver& observer) {
  const std::string rack_path = rackSavePath();
  const MenuModel::Outcome outcome = model.outcome();
  settings = model.settings();
  std::string why;
  if (!saveSettings(settings, settingsPath(), why)) {
    logger("game")->warn("settings not saved: {}", why);
  }
  const bool online = outcome == MenuModel::Outcome::Host || outcome == MenuModel::Outcome::Join;
  if (outcome != MenuModel::Outcome::Play && outcome != MenuModel::Outcome::Resume && !online) {
    return false;
  }

  MatchSetup setup = session.setup();
  if (outcome == MenuModel::Outcome::Resume && saved) {
    setup.setGame(saved->game);
    setup.rules = saved->rules;
    setup.seed = saved->seed;
    try {
      GameSession resumed(setup);
      resumed.setTurnObserver(observer);
      replayRack(resumed, *saved);
      session = std::move(resumed);
      seats.setOpponent(session, saved->opponent);
      session.setSeatName(0, saved->names[0]);
      if (!isComputer(saved->opponent)) session.setSeatName(1, saved->names[1]);
      session.say("Rack resumed: " + describeSavedRack(*saved) + ".");
      logger("game")->info("resumed the saved rack: {} turns replayed", saved->turns.size());
      return true;
    } catch (const std::exception& e) {
      // Whatever the file held, the game goes on: the rack is dropped, never the program.
      logger("game")->warn("saved rack {} does not replay ({}); starting afresh", rack_path,
                           printable(e.what()));
      forgetRack(rack_path);
    }
  }
  const MenuChoice choice = model.choice();
  if (ctx.fresh_seeds) setup.seed = freshSeed();
  setup.setGame(choice.game);
  setup.rules = choice.rules;
  if (choice.points > 0) setup.points = choice.points;
  if (choice.mode == GameMode::Practice) {
    session = GameSession(setup, true);
    seats.setOpponent(session, HumanSeat{});
    return true;
  }
  session = GameSession(setup);
  session.setBestOf(choice.best_of);
  session.setBreaks(choice.breaks);
  session.setTurnObserver(observer);
  seats.setOpponent(session, choice.opponent);
  session.setSeatName(0, choice.names[0]);
  if (!isComputer(choice.opponent)) session.setSeatName(1, choice.names[1]);
  return true;
}

}  // namespace nineball::window
