#include "window/game_session.hpp"

// The session's practice calls, answered by its practice part (practice_mode.hpp).
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
  return practice_ && practice_->moveBall(*this, id, pos);
}

void GameSession::toggleBall(int id, Vec2 near) {
  if (practice_) practice_->toggleBall(*this, id, near);
}

void GameSession::undoShot() {
  if (practice_) practice_->undo(*this);
}

void GameSession::retryShot() {
  if (practice_) practice_->retry(*this);
}

void GameSession::takeCue(const PracticeShot& shot) {
  cue_.take(shot.heading, shot.speed, shot.tip, shot.elevation);
}

}  // namespace nineball::window
