#include "play/shot_summary.hpp"
#include "window/game_session.hpp"
#include "window/turn_message.hpp"

// Practice: no rules and no turns; any ball placed anywhere, added or taken away; the last shot
// undone or retried (GameSession's practice half).
namespace nineball::window {

std::optional<int> GameSession::ballAt(Vec2 pos) const {
  const double r = match_->world().physics().ball_radius;
  std::optional<int> best;
  double best_d = 1.2 * r;
  for (const BallState& b : playback_.balls()) {
    if (b.pocket) continue;
    const double d = length(b.pos - pos);
    if (d <= best_d) {
      best = b.id;
      best_d = d;
    }
  }
  return best;
}

std::optional<std::string> GameSession::ballPlacementProblem(int id, Vec2 pos) const {
  if (!practice_) return std::string("balls move by hand only in practice");
  return practice_->placementProblem(id, pos);
}

bool GameSession::moveBall(int id, Vec2 pos) {
  if (!practice_ || phase_ != Phase::Aiming) return false;
  if (const auto problem = practice_->placementProblem(id, pos)) {
    say("The ball cannot go there: " + *problem + ".", render::Tone::Warning);
    return false;
  }
  practice_->place(id, pos);
  rebuildPractice();
  return true;
}

void GameSession::toggleBall(int id, Vec2 near) {
  if (!practice_ || phase_ != Phase::Aiming || id == kCueBall) return;
  if (practice_->has(id)) {
    practice_->remove(id);
    say("The " + std::to_string(id) + " is off the table (" + std::to_string(id) +
        " puts it back).");
  } else if (const auto spot = practice_->freeSpotNear(id, near)) {
    practice_->place(id, *spot);
    say("The " + std::to_string(id) + " is on the table: Shift+drag it where you want it.");
  } else {
    say("No room for the " + std::to_string(id) + ".", render::Tone::Warning);
    return;
  }
  rebuildPractice();
}

void GameSession::restorePracticeShot(const PracticeShot& shot) {
  rebuildPractice();
  cue_.take(shot.heading, shot.speed, shot.tip, shot.elevation);
}

void GameSession::undoShot() {
  if (!practice_ || phase_ != Phase::Aiming) return;
  const auto step = practice_->undo();
  if (!step) {
    say("Nothing to undo: no shot played or ball moved yet.", render::Tone::Warning);
    return;
  }
  const std::string more = " (" + std::to_string(practice_->stepsRemembered()) + " more to undo).";
  if (!step->shot) {
    rebuildPractice();
    say("The last ball moved is back where it was" + more);
    return;
  }
  restorePracticeShot(step->before);
  say("Back to before the last shot" + more);
}

void GameSession::retryShot() {
  if (!practice_ || phase_ != Phase::Aiming) return;
  const auto shot = practice_->retry();
  if (!shot) {
    say("Nothing to retry: no shot played yet.", render::Tone::Warning);
    return;
  }
  restorePracticeShot(*shot);
  say("The last shot set up again: same position, aim, power and spin.");
}

void GameSession::finishPracticeShot() {
  const std::vector<BallState> after = match_->balls();
  std::vector<int> down;
  for (const BallState& b : after) {
    if (b.pocket && b.id != kCueBall && practice_->has(b.id)) down.push_back(b.id);
  }
  const bool cue_back = practice_->settle(after);
  rebuildPractice();
  std::string text = down.empty() ? "Nothing down." : sentence(ballList(down)) + " down.";
  if (cue_back) text += " The cue ball dropped: it is back where it was struck from.";
  say(text + " U: undo, Y: retry.", cue_back ? render::Tone::Foul : render::Tone::Info);
}

}  // namespace nineball::window
