#include "common/atomic_file.hpp"
#include "common/log.hpp"
#include "window/game_loop.hpp"
#include "window/rack_script.hpp"

// GameLoop's aids to the player beside the frame's steps: the painter kept on the session's
// table, the zoomed view, a saved rack watched again (--watch) and F5's save of the rack.
namespace nineball::window {
namespace {

// --watch: the balls rest this long (s) before the next turn is played, as a player would.
constexpr double kWatchPause = 0.8;

}  // namespace

// The painter (and the view the pointer is read through) on the session's table.
void GameLoop::followTable() {
  painter_->showTable(session_.match().world().table());
}

// The table seen as close as the player asked, round the cue ball (following it as it rolls) or
// the point the wheel zoomed at; a dialog shows the whole table.
void GameLoop::zoomView(const render::Frame& picture) {
  const bool dialog = picture.hud.overlay != render::Overlay::None;
  Vec2 focus = session_.cuePosition();
  const int shooter = session_.practice() ? kCueBall : session_.shooterBall();
  for (const BallState& b : picture.balls) {
    if (b.id == shooter && !b.pocket) focus = b.pos;
  }
  painter_->setZoom(dialog ? 1.0 : ui_.zoom, ui_.zoom_at.value_or(focus));
}

// --watch: the next turn once the balls have rested a moment, as a player would take it; a turn
// the rack refuses ends the watching with its reason on screen.
void GameLoop::playWatchedTurn(double dt) {
  if (next_watched_ >= watched_.size() || session_.replaying()) return;
  const Phase phase = session_.phase();
  if (phase != Phase::Aiming && phase != Phase::PushOutChoice) {
    rested_ = 0.0;
    return;
  }
  rested_ += dt;
  if (rested_ < kWatchPause) return;
  rested_ = 0.0;
  const TurnInput& turn = watched_[next_watched_++];
  if (turn.kind == TurnInput::Kind::Decision) {
    session_.decide(turn.shoot, turn.replace);
    return;
  }
  if (!session_.shoot(turn)) {
    logger("game")->warn("--watch: turns[{}] refused: {}", next_watched_ - 1, session_.message());
    next_watched_ = watched_.size();
  }
}

// F5: the rack as a match script in the current directory, to play again headless or here.
void GameLoop::saveRackScript() {
  const auto script = rackScript(session_);
  if (!script || session_.rackTurns().empty()) {
    session_.say("No rack to save yet: F5 saves a rack once it has a turn.", render::Tone::Warning);
    return;
  }
  const std::string name = rackScriptName();
  std::string why;
  if (writeFileAtomically(name, script->dump(2) + "\n", why)) {
    session_.say("Rack saved: " + name + " (nineball match " + name + " plays it again).");
    logger("game")->info("rack saved as a match script: {}", name);
  } else {
    session_.say("Rack not saved: " + why, render::Tone::Warning);
  }
}

}  // namespace nineball::window
