#include "nineball/games.hpp"
#include "window/game_session.hpp"
#include "window/shot_call.hpp"

// The calls and nominations of the coming shot: clicks on pockets and balls, K's obvious call,
// the computer's call shown as a person's (GameSession's calling half).
namespace nineball::window {

bool GameSession::callRequired() const {
  return !practice_ && phase_ == Phase::Aiming && !push_out_ && match_->rack().callRequired();
}

int GameSession::callBall() const {
  if (!callRequired()) return 0;
  return call_ball_.value_or(match_->rack().ballOn());
}

std::optional<rules::Call> GameSession::call() const {
  if (!callRequired() || !call_pocket_) return std::nullopt;
  return rules::Call{callBall(), *call_pocket_};
}

std::optional<PocketId> GameSession::callPocketAt(Vec2 pos) const {
  if (!callRequired()) return std::nullopt;
  const Engine& w = match_->world();
  return pocketNear(w.table(), pos, 3.0 * w.physics().ball_radius);
}

bool GameSession::clickCall(Vec2 pos) {
  if (!callRequired()) return false;
  if (const auto pocket = callPocketAt(pos)) {
    call_pocket_ = pocket;
    say("Called: the " + std::to_string(callBall()) + " in the " + pocketName(*pocket) +
        " pocket.");
    return true;
  }
  if (!gameDef(match_->rack().game()).call_any_ball) return false;
  const auto ball = ballAt(pos);
  if (!ball || *ball == kCueBall) return false;
  call_ball_ = *ball;
  say("Calling the " + std::to_string(*ball) + ": now click its pocket.");
  return true;
}

void GameSession::callObvious() {
  if (!callRequired()) {
    say(practice_ ? "Practice has no rules, so no calls." : "No call is needed for this shot.",
        render::Tone::Warning);
    return;
  }
  const rules::Rack& rack = match_->rack();
  // The aimed ball is the obvious call only when it may be hit first: aimed at another, the call
  // is the ball on's (ten-ball calls any ball, but a pot of one hit first illegally is a foul).
  const std::vector<int> callable = rack.legalFirstBalls();
  const auto c =
      obviousCall(match_->world().table(), playback_.balls(), aimGuide(), callBall(), callable);
  if (!c) return;
  call_ball_ = c->ball;
  call_pocket_ = c->pocket;
  say("Called: the " + std::to_string(c->ball) + " in the " + pocketName(c->pocket) + " pocket.");
}

bool GameSession::setCall(const rules::Call& c) {
  if (!callRequired()) return false;
  call_ball_ = c.ball;
  call_pocket_ = c.pocket;
  say("Called: the " + std::to_string(c.ball) + " in the " + pocketName(c.pocket) + " pocket.");
  return true;
}

}  // namespace nineball::window
