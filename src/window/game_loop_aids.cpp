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
// s the end of a rack stays on screen before a watched race racks the next.
constexpr double kRackOverPause = 2.5;

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
  if (phase == Phase::GameOver && session_.bestOf() > 0 && !session_.matchWinner()) {
    // A race's script goes on into the next rack once the last one's end has been seen.
    rested_ += dt;
    if (rested_ < kRackOverPause) return;
    rested_ = 0.0;
    session_.rematch();
    return;
  }
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

// F5: the match (or the rack) as a match script in the current directory, to play again
// headless or here.
void GameLoop::saveRackScript() {
  const bool match = savesMatch(session_);
  const auto script = gameScript(session_, script_setup_);
  const bool played = match ? !session_.matchTurns().empty() : !session_.rackTurns().empty();
  if (!script || !played) {
    session_.say("No rack to save yet: F5 saves a rack once it has a turn.", render::Tone::Warning);
    return;
  }
  const std::string name = gameScriptName(match);
  const std::string what = match ? "Match" : "Rack";
  std::string why;
  if (writeFileAtomically(name, script->dump(2) + "\n", why)) {
    session_.say(what + " saved: " + name + " (nineball match " + name + " plays it again).");
    logger("game")->info("{} saved as a match script: {}", match ? "match" : "rack", name);
  } else {
    session_.say(what + " not saved: " + why, render::Tone::Warning);
  }
}

}  // namespace nineball::window
