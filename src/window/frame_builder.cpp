#include "window/frame_builder.hpp"

#include <algorithm>

#include "app/opponent.hpp"
#include "nineball/games.hpp"
#include "nineball/rules.hpp"
#include "render/cue_stick_shape.hpp"
#include "window/game_help.hpp"

namespace nineball::window {
namespace {

using render::Overlay;

const std::vector<std::string> kHelpLines = {
    "Mouse: point where to aim; press, drag back and let go to strike",
    "  (the further you drag, the harder the shot; right click cancels)",
    "Left / Right: turn the aim (Shift: finer)    Up / Down: power",
    "Space: shoot    E / Q: raise / lower the cue",
    "T / B / L / R: top / back / left / right spin",
    "Click the cue-ball icon for side spin, the arc by it to tilt the cue (C: reset)",
    "The aim line is the ghost ball's: throw, squirt and swerve bend the real paths",
    "Ball in hand: drag the cue ball, or move it with W A S D",
    "P: declare a push-out when offered; then S: play or P: pass",
    "V: replay the last shot (Shift+V: slowed)    R: rematch after a rack",
    "M: mute    F1: full screen    F2: settings    F12: screenshot",
};

void fillDialog(render::HudState& hud, const GameSession& session, Overlay overlay,
                const ComputerPlayer& computer) {
  const bool computer_decides = computer.controls(session);
  hud.overlay = overlay;
  switch (overlay) {
    case Overlay::Help: {
      hud.overlay_title = "How to play";
      hud.overlay_lines = kHelpLines;
      const std::optional<ai::Level> level = computerLevel(computer.opponent());
      hud.overlay_lines.insert(hud.overlay_lines.end(),
                               "O: 2 players, or vs computer easy / medium / hard (now: " +
                                   (level ? std::string("computer ") + ai::levelName(*level)
                                          : std::string("2 players")) +
                                   ")");
      for (const std::string& line : gameHelpLines(session.match().rack().game())) {
        hud.overlay_lines.push_back(line);
      }
      hud.button_right = "Close (H)";
      break;
    }
    case Overlay::ConfirmQuit:
      hud.overlay_title = "Quit nineball?";
      hud.overlay_lines = {"The rack in play will be lost."};
      hud.button_left = "Quit (Y)";
      hud.button_right = "Keep playing (N)";
      break;
    case Overlay::PushOutChoice: {
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
    case Overlay::GameOver: {
      const auto winner = session.match().rack().winner();
      const std::string name = winner ? session.seatName(session.seatOf(*winner)) : "";
      hud.overlay_title = name + " wins rack " + std::to_string(session.rackNumber()) + "!";
      hud.overlay_lines = {session.message(), "Racks: " + session.seatName(0) + " " +
                                                  std::to_string(session.racksWon(0)) + " - " +
                                                  std::to_string(session.racksWon(1)) + " " +
                                                  session.seatName(1)};
      hud.button_left = "Rematch (R)";
      hud.button_right = "Quit";
      break;
    }
    case Overlay::None:
      break;
  }
}

// The stick's stroke: the tip meets the ball at the strike (a real stroke covers the draw-back
// in about the frame before it) and follows through past the ball's place, slowing.
constexpr double kStroke = 0.08;         // s of the physics' clock
constexpr double kFollowThrough = 0.06;  // m past the ball's place

render::CuePose cuePose(double heading_rad, double pull, double side) {
  render::CuePose pose;
  pose.heading_rad = heading_rad;
  pose.pull = pull;
  pose.side = side;
  return pose;
}

double addressPull(double power) {
  return std::clamp(power, 0.0, 1.0) * render::CueStickShape::kMaxPull;
}

render::CuePose stroke(const GameSession::Strike& s, const GameSession& session) {
  const double p = std::clamp(s.since / kStroke, 0.0, 1.0);
  const double e = 1.0 - (1.0 - p) * (1.0 - p);  // fast through the ball, slowing after
  render::CuePose pose = cuePose(s.heading_rad, -kFollowThrough * e, session.tip().x);
  pose.at = s.from;
  return pose;
}

}  // namespace

std::optional<Vec2> dialogKeepClear(const GameSession& session) {
  return session.cuePosition();
}

Overlay activeOverlay(const GameSession& session, const UiState& ui) {
  if (ui.confirm_quit) return Overlay::ConfirmQuit;
  if (session.replaying()) return Overlay::None;  // the replay is watched whole
  if (ui.help) return Overlay::Help;
  if (session.phase() == Phase::PushOutChoice) return Overlay::PushOutChoice;
  if (session.phase() == Phase::GameOver) return Overlay::GameOver;
  return Overlay::None;
}

render::Frame buildFrame(const GameSession& session, const UiState& ui,
                         const ComputerPlayer& computer) {
  render::Frame f;
  f.balls = session.ballsToDraw();
  f.time = session.drawTime();
  f.ball_radius = session.match().world().physics().ball_radius;
  f.looks = gameDef(session.match().rack().game()).looks;
  const bool aiming = session.phase() == Phase::Aiming && !session.replaying();
  const bool computer_turn = computer.controls(session);
  if (computer_turn) {
    if (aiming && computer.showsCue()) {
      f.guide = session.aimGuide();
      f.cue = cuePose(session.heading(), computer.pull(), session.tip().x);
    }
    if (const auto carried = computer.carriedCue()) {
      for (BallState& b : f.balls) {
        if (b.id == kCueBall) b.pos = *carried;
      }
    }
  } else if (aiming && ui.drag != Drag::Cue && ui.drag != Drag::Ball) {
    f.guide = session.aimGuide();
    // Drawn back as far as the power set asks (a drag sets both at once).
    f.cue = cuePose(session.heading(), std::max(ui.pull, addressPull(session.power())),
                    session.tip().x);
  }
  if (const auto s = session.strike(); s && s->since < kStroke) f.cue = stroke(*s, session);
  if ((ui.drag == Drag::Cue || ui.drag == Drag::Ball) && ui.ghost) {
    f.ghost = ui.ghost;
    for (BallState& b : f.balls) {
      if (b.id == ui.ghost->id) b.pocket = PocketId::TopLeft;  // drawn as the ghost instead
    }
  }

  // The computer's call shows once made, as a person's; not the prompt while it thinks.
  if (session.callRequired() && (!computer_turn || session.call())) {
    render::CallMark mark;
    for (const BallState& b : f.balls) {
      if (b.id == session.callBall() && !b.pocket) mark.ball = b.pos;
    }
    if (const auto c = session.call()) {
      for (const Pocket& p : session.match().world().table().pockets) {
        if (p.id == c->pocket) mark.pocket = p.drop_centre;
      }
    }
    f.call = mark;
  }

  render::HudState& hud = f.hud;
  for (int seat = 0; seat < 2; ++seat) {
    hud.players[seat].name = session.seatName(seat);
    hud.players[seat].racks = session.racksWon(seat);
    hud.players[seat].to_move = session.phase() != Phase::GameOver && session.seatToMove() == seat;
  }
  const rules::Rack& rack = session.match().rack();
  for (rules::Player p : {rules::Player::A, rules::Player::B}) {
    hud.players[session.seatOf(p)].fouls = rack.consecutiveFouls(p);
  }
  hud.ball_on = rack.over() ? 0 : rack.ballOn();
  // A ball on only when one ball may be hit first (a game of groups: its last ball); groups say the
  // rest.
  if (rack.legalFirstBalls().size() != 1) hud.ball_on = 0;
  for (const BallState& b : session.match().balls()) {
    if (b.id != kCueBall && !b.pocket) hud.on_table.push_back(b.id);
  }
  std::sort(hud.on_table.begin(), hud.on_table.end());
  hud.pocketed = session.pocketedThisRack();
  hud.rules = rack.rules() == rules::RuleSet::Wpa ? "WPA rules" : "Paper rules";
  const GameDef& game = gameDef(rack.game());
  if (&game != &defaultGame()) hud.rules = std::string(game.name) + ", " + hud.rules;
  if (game.groups) {
    hud.split_groups = true;
    for (rules::Player p : {rules::Player::A, rules::Player::B}) {
      render::PlayerPanel& panel = hud.players[session.seatOf(p)];
      panel.detail = "racks " + std::to_string(panel.racks) + "   " + groupLabel(rack.groups(), p);
    }
  }
  hud.mode = app::opponentLabel(computer.opponent()) + "   O: opponent";
  if (session.practice()) {
    const std::size_t shots = session.practiceShots();
    hud.players[0].detail = std::to_string(shots) + (shots == 1 ? " shot" : " shots") + " to undo";
    hud.ball_on = 0;
    hud.rules = "Practice: no rules";
    hud.mode = "U undo   Y retry   1-9 add/remove";
  }
  hud.status = computer_turn && !session.replaying() ? computer.status(session) : session.status();
  hud.message = session.message();
  hud.tone = session.tone();
  hud.power = session.power();
  hud.speed = session.speed();
  hud.tip = session.tip();
  hud.elevation_deg = radToDeg(session.elevation());
  hud.max_elevation_deg = GameSession::kMaxElevationDeg;
  hud.max_tip = session.maxTip();
  hud.push_out_declared = session.pushOutDeclared();
  fillDialog(hud, session, activeOverlay(session, ui), computer);
  hud.keep_clear = dialogKeepClear(session);
  return f;
}

}  // namespace nineball::window
