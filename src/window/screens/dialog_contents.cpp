#include "window/screens/dialog_contents.hpp"

#include <optional>
#include <string>
#include <vector>

#include "app/opponent.hpp"
#include "nineball/games.hpp"
#include "nineball/rules.hpp"
#include "nineball/seat.hpp"
#include "window/game_help.hpp"
#include "window/menu_choice.hpp"

namespace nineball::window {
namespace {

// The leave dialog's line: what becomes of the rack in play (or the practice table).
std::string whatLeavingKeeps(const GameSession& session, const UiState& ui) {
  if (session.practice()) return "The practice table is not kept.";
  if (session.rackTurns().empty() || session.phase() == Phase::GameOver) {
    return "No rack in play to lose.";
  }
  if (ui.rack_kept) return "The rack is saved: \"Resume rack\" in the menu plays on.";
  return "The rack in play will be lost.";
}

}  // namespace

bool replaceOffered(const GameSession& session, const UiState& ui) {
  return dialogCalledFor(session, ui) == DialogKind::PushOutChoice &&
         session.match().rack().pendingDecision() == rules::Decision::PlayPutBackOrReplace;
}

DialogKind dialogCalledFor(const GameSession& session, const UiState& ui) {
  if (ui.confirm_quit) return DialogKind::ConfirmQuit;
  if (session.replaying()) return DialogKind::None;  // the replay is watched whole
  if (ui.help) return DialogKind::Help;
  if (session.phase() == Phase::PushOutChoice) return DialogKind::PushOutChoice;
  if (session.phase() == Phase::GameOver) return DialogKind::GameOver;
  return DialogKind::None;
}

std::optional<render::DialogLook> lookOf(DialogKind kind) {
  switch (kind) {
    case DialogKind::Help:
      return render::DialogLook::wide();
    case DialogKind::ConfirmQuit:
      return render::DialogLook::box();
    case DialogKind::PushOutChoice:
      return render::DialogLook::across(0.36);
    case DialogKind::GameOver: {
      render::DialogLook look = render::DialogLook::across(0.5);
      look.win = true;
      return look;
    }
    case DialogKind::None:
      break;
  }
  return std::nullopt;
}

void fillDialog(render::HudState& hud, const GameSession& session, const UiState& ui,
                const Seats& seats) {
  const DialogKind kind = dialogCalledFor(session, ui);
  const bool computer_decides = seats.controls(session);
  hud.dialog = lookOf(kind);
  switch (kind) {
    case DialogKind::Help: {
      hud.overlay_title = "How to play";
      hud.overlay_lines = controlHelpLines();
      if (session.practice()) {
        hud.overlay_lines.push_back(
            "Practice: Shift+drag moves a ball; 1-9 add / remove; U undo (shots and moves), Y "
            "retry");
      }
      const std::optional<ai::Level> level = computerLevel(seats.opponent());
      hud.overlay_lines.insert(hud.overlay_lines.end(),
                               "O: 2 players, or the computer at a level, " +
                                   std::string(ai::levelName(ai::allLevels().front())) + " to " +
                                   ai::levelName(ai::allLevels().back()) + " (now: " +
                                   (level ? std::string("computer ") + ai::levelName(*level)
                                          : std::string("2 players")) +
                                   ")");
      for (const std::string& line : gameHelpLines(session.match().rack().game())) {
        hud.overlay_lines.push_back(line);
      }
      hud.button_right = "Close (H)";
      break;
    }
    case DialogKind::ConfirmQuit:
      hud.overlay_title = ui.leave_to_menu ? "Back to the menu?" : "Quit nineball?";
      hud.overlay_lines = {whatLeavingKeeps(session, ui)};
      hud.button_left = ui.leave_to_menu ? "Menu (Y)" : "Quit (Y)";
      hud.button_right = "Keep playing (N)";
      break;
    case DialogKind::PushOutChoice: {
      const std::string name = session.seatName(session.seatToMove());
      hud.overlay_title = "Push-out: " + name + " chooses";
      const rules::Rack& rack = session.match().rack();
      if (rack.pendingDecision() == rules::Decision::RerackOrPlayOn) {
        hud.overlay_title = "Illegal break: " + name + " chooses";
        if (computer_decides) {
          hud.overlay_lines = {"Thinking: play on as it lies, or re-rack and break?"};
          break;
        }
        hud.overlay_lines = {"Play the table as it lies, or re-rack and break."};
        hud.button_left = "Play on (S)";
        hud.button_right = "Re-rack (P)";
        break;
      }
      if (rack.pendingDecision() == rules::Decision::PlayOrPutBack ||
          rack.pendingDecision() == rules::Decision::PlayPutBackOrReplace) {
        const bool miss = rack.pendingDecision() == rules::Decision::PlayPutBackOrReplace;
        const std::string offender = session.seatName(1 - session.seatToMove());
        hud.overlay_title = (miss ? "Foul and a miss: " : "Foul: ") + name + " chooses";
        if (computer_decides) {
          hud.overlay_lines = {"Thinking: play from here, or put " + offender + " back in?"};
          break;
        }
        hud.overlay_lines = {"Play from here, or put " + offender + " back in to play again."};
        if (miss) {
          hud.overlay_lines.push_back("Or replace the balls where they were, and " + offender +
                                      " plays again.");
          hud.button_middle = "Replace (R)";
        }
        hud.button_left = "Play (S)";
        hud.button_right = "Put back (P)";
        break;
      }
      // Ten-ball: a pot not as called gives the same choice as a push-out.
      if (!session.rackTurns().empty() &&
          session.rackTurns().back().kind == TurnInput::Kind::Shot) {
        hud.overlay_title = "Not as called: " + name + " chooses";
      }
      if (computer_decides) {
        hud.overlay_lines = {"Thinking: play from here, or pass the shot back?"};
        break;
      }
      hud.overlay_lines = {"Play from here, or pass the shot back."};
      hud.button_left = "Play (S)";
      hud.button_right = "Pass (P)";
      break;
    }
    case DialogKind::GameOver: {
      const auto winner = session.match().rack().winner();
      const std::string name = winner ? session.seatName(session.seatOf(*winner)) : "";
      // A match of bestOf() frames (snooker) or a race to so many racks (pool); without one the
      // racks simply add up.
      const bool frames = gameDef(session.match().rack().game()).snookers;
      const std::string unit = frames ? "frame" : "rack";
      const std::string tally = session.seatName(0) + " " + std::to_string(session.racksWon(0)) +
                                " - " + std::to_string(session.racksWon(1)) + " " +
                                session.seatName(1);
      hud.overlay_title = name + " wins " + unit + " " + std::to_string(session.rackNumber()) + "!";
      // How the rack ended is the message line below the table: the dialog does not say it
      // twice, and keeps to the score and the players' figures.
      hud.overlay_lines = {(frames ? "Frames: " : "Racks: ") + tally};
      hud.button_left = frames ? "Next frame (R)" : "Rematch (R)";
      if (session.bestOf() > 0) {
        const int race = framesToWinMatch(session.bestOf());
        hud.overlay_lines.back() += frames ? " (best of " + std::to_string(session.bestOf()) + ")"
                                           : " (race to " + std::to_string(race) + ")";
        if (!frames) hud.button_left = "Next rack (R)";
        if (const auto champion = session.matchWinner()) {
          hud.overlay_title = session.seatName(*champion) + " wins the match!";
          hud.button_left = "New match (R)";
        }
      }
      hud.button_right = "Quit";
      break;
    }
    case DialogKind::None:
      break;
  }
}

}  // namespace nineball::window
