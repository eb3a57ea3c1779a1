#include "window/frame_builder.hpp"

#include <algorithm>
#include <cstdio>

#include "app/opponent.hpp"
#include "nineball/games.hpp"
#include "nineball/rules.hpp"
#include "nineball/seat.hpp"
#include "nineball/snooker_rack.hpp"
#include "render/cue_stick_shape.hpp"
#include "rules/snooker_balls.hpp"
#include "window/game_help.hpp"
#include "window/screens/dialog_contents.hpp"

namespace nineball::window {
namespace {

// Nine-ball's "foul: the 3 is not the ball on", or nothing when the guide's first ball may be hit.
std::string guideFoul(const GameSession& session, const AimGuide& guide) {
  if (session.practice() || session.pushOutDeclared() || guide.target != AimTarget::Ball) return "";
  const std::vector<int> legal = session.match().rack().legalFirstBalls();
  if (legal.empty() || std::find(legal.begin(), legal.end(), guide.ball) != legal.end()) return "";
  const std::string ball = "foul: " + gameDef(session.match().rack().game()).theBall(guide.ball);
  return legal.size() == 1 ? ball + " is not the ball on" : ball + " may not be hit first";
}

// The stick's stroke: the tip meets the ball at the strike (a real stroke covers the draw-back
// in about the frame before it) and follows through past the ball's place, slowing.
constexpr double kStroke = 0.08;         // s of the physics' clock
constexpr double kFollowThrough = 0.06;  // m past the ball's place

render::CuePose cuePose(double heading_rad, double pull, const GameSession& session) {
  render::CuePose pose;
  pose.heading_rad = heading_rad;
  pose.pull = pull;
  pose.side = session.tip().x;
  pose.elevation_rad = session.elevation();
  return pose;
}

double addressPull(double power) {
  return std::clamp(power, 0.0, 1.0) * render::CueStickShape::kMaxPull;
}

render::CuePose stroke(const GameSession::Strike& s, const GameSession& session) {
  const double p = std::clamp(s.since / kStroke, 0.0, 1.0);
  const double e = 1.0 - (1.0 - p) * (1.0 - p);  // fast through the ball, slowing after
  render::CuePose pose = cuePose(s.heading_rad, -kFollowThrough * e, session);
  pose.at = s.from;
  return pose;
}

}  // namespace

std::vector<Vec2> dialogKeepClear(const GameSession& session) {
  std::vector<Vec2> keep;
  for (const BallState& b : session.ballsToDraw()) {
    if (!b.pocket) keep.push_back(b.pos);
  }
  return keep;
}

bool leavingLosesNothing(const GameSession& session, const UiState& ui) {
  if (!ui.leave_to_menu || session.practice()) return false;
  return ui.rack_kept || session.rackTurns().empty() || session.phase() == Phase::GameOver;
}

std::string opponentModeLabel(const Seat& opponent) {
  return app::opponentLabel(opponent) + "   O: opponent";
}

namespace {

// Carom's HUD: each player's points, innings, average and high run (a scoreboard's line), no
// ball tray, and during a shot the cushions the shooter's ball has met before the second ball.
void fillCaromHud(render::HudState& hud, const GameSession& session) {
  const rules::Rack& rack = session.match().rack();
  const Score score = scoreOf(rack);
  for (rules::Player p : {rules::Player::A, rules::Player::B}) {
    const PlayerScore& ps = p == rules::Player::A ? score.a : score.b;
    char average[16];
    std::snprintf(average, sizeof average, "%.3f",
                  ps.innings > 0 ? static_cast<double>(ps.points) / ps.innings : 0.0);
    hud.players[session.seatOf(p)].detail = std::to_string(ps.points) + " pts   inn " +
                                            std::to_string(ps.innings) + "   avg " + average +
                                            "   high " + std::to_string(ps.high_run);
  }
  hud.on_table.clear();
  hud.pocketed.clear();
  hud.ball_on = 0;
  hud.rules = std::string(gameDef(rack.game()).name) + " to " +
              std::to_string(rack.targetPoints()) + ", UMB rules";
  if (const auto count = session.caromCount()) hud.carom_count = *count;
}

// Snooker's HUD: each player's points in the frame, frames won and highest break; the ball on
// (a red, a named colour, or "any colour" after a red); the current break, the points remaining
// and the referee's calls in the tray's place.
void fillSnookerHud(render::HudState& hud, const GameSession& session) {
  const rules::Rack& rack = session.match().rack();
  const Score score = scoreOf(rack);
  for (rules::Player p : {rules::Player::A, rules::Player::B}) {
    const PlayerScore& ps = p == rules::Player::A ? score.a : score.b;
    render::PlayerPanel& panel = hud.players[session.seatOf(p)];
    panel.detail = std::to_string(ps.points) + " pts   frames " + std::to_string(panel.racks) +
                   "   high " + std::to_string(ps.high_run);
  }
  const std::vector<int> on = rack.legalFirstBalls();
  const bool reds_on = !on.empty() && std::all_of(on.begin(), on.end(), rules::snooker::isRed);
  hud.ball_on = rack.over() || on.empty() ? 0 : reds_on ? on.front() : on.size() == 1 ? on[0] : 0;
  std::string line;
  if (!rack.over() && !on.empty() && hud.ball_on == 0) line = "on: any colour   ";
  line += "break " + std::to_string(rack.over() ? 0 : rack.currentRun()) + "   remaining " +
          std::to_string(rack.pointsRemaining());
  hud.score_call = false;
  if (!rack.over() && rules::freeBall(rack)) {
    line += "   FREE BALL";
    hud.score_call = true;
  }
  for (rules::Player p : {rules::Player::A, rules::Player::B}) {
    if (rack.over() || !rules::snookersRequired(rack, p)) continue;
    line += "   " + session.seatName(session.seatOf(p)) + ": snookers required";
    hud.score_call = true;
  }
  hud.score_line = line;
  hud.on_table.clear();
  hud.pocketed.clear();
}

}  // namespace

render::Frame buildFrame(const GameSession& session, const UiState& ui, const Seats& seats) {
  render::Frame f;
  f.table = &session.match().world().table();
  f.balls = session.ballsToDraw();
  f.time = session.drawTime();
  f.ball_radius = session.match().world().physics().ball_radius;
  f.looks = gameDef(session.match().rack().game()).looks;
  const bool aiming = session.phase() == Phase::Aiming && !session.replaying();
  const bool computer_turn = seats.controls(session);
  if (computer_turn) {
    if (aiming && seats.showsCue(session)) {
      f.guide = session.aimGuide();
      f.cue = cuePose(session.heading(), seats.pull(session), session);
    }
    if (const auto carried = seats.carriedCue()) {
      for (BallState& b : f.balls) {
        if (b.id == kCueBall) b.pos = *carried;
      }
    }
  } else if (aiming && ui.drag != Drag::Cue && ui.drag != Drag::Ball) {
    f.guide = session.aimGuide();
    f.guide_foul = guideFoul(session, *f.guide);
    // Drawn back as far as the power set asks (a drag sets both at once).
    f.cue = cuePose(session.heading(), std::max(ui.pull, addressPull(session.power())), session);
  }
  if (const auto s = session.strike(); s && s->since < kStroke) f.cue = stroke(*s, session);
  // Carom: the stick addresses the shooter's own ball, which need not be ball 0.
  if (f.cue && !f.cue->at && !session.practice()) f.cue->at = session.cuePosition();
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
  hud.rules = rack.rules() == rules::RuleSet::Wpa     ? "WPA rules"
              : rack.rules() == rules::RuleSet::Wpbsa ? "WPBSA rules"
                                                      : "Paper rules";
  const GameDef& game = gameDef(rack.game());
  if (&game != &defaultGame()) hud.rules = std::string(game.name) + ", " + hud.rules;
  if (!game.snookers && session.bestOf() > 0) {
    hud.rules += ", race to " + std::to_string(framesToWinMatch(session.bestOf()));
  }
  if (game.groups) {
    hud.split_groups = true;
    for (rules::Player p : {rules::Player::A, rules::Player::B}) {
      render::PlayerPanel& panel = hud.players[session.seatOf(p)];
      panel.detail = "racks " + std::to_string(panel.racks) + "   " + groupLabel(rack.groups(), p);
    }
  }
  if (game.family == GameFamily::Carom) fillCaromHud(hud, session);
  if (game.snookers) fillSnookerHud(hud, session);
  hud.mode = opponentModeLabel(seats.opponent());
  if (session.practice()) {
    const std::size_t steps = session.practiceSteps();
    hud.players[0].detail = std::to_string(steps) + (steps == 1 ? " step" : " steps") + " to undo";
    hud.ball_on = 0;
    hud.rules = "Practice: no rules";
    hud.mode = "U undo   Y retry   1-9 add/remove";
  }
  hud.status = computer_turn && !session.replaying() ? seats.status(session) : session.status();
  hud.message = session.message();
  hud.tone = session.tone();
  hud.power = session.power();
  hud.speed = session.speed();
  hud.tip = session.tip();
  hud.elevation_deg = radToDeg(session.elevation());
  hud.max_elevation_deg = GameSession::kMaxElevationDeg;
  hud.max_tip = session.maxTip();
  hud.push_out_declared = session.pushOutDeclared();
  hud.keys = ui.leave_to_menu ? "H help   Esc menu" : "H help   Esc quit";
  fillDialog(hud, session, ui, seats);
  hud.keep_clear = dialogKeepClear(session);
  return f;
}

}  // namespace nineball::window
