#include "window/shot_playback.hpp"

#include <algorithm>
#include <utility>

namespace nineball::window {
namespace {

// The picture's clock runs on this long (s) after the balls stop: a ball that dropped as the
// shot ended finishes sinking into its pocket (the balls at rest turn no further).
constexpr double kPictureAfterRest = 1.0;

}  // namespace

void ShotPlayback::settle(const Match& match) {
  shot_.current = shot_.previous = match.balls();
  shot_.current_time = shot_.previous_time = match.world().time();
}

void ShotPlayback::begin(const Match& match, int ball, double speed) {
  clock_.reset();
  after_rest_ = 0.0;
  shot_ball_ = ball;
  shot_.begin(match);
  strike_ = audio::cueStrike(speed);
}

void ShotPlayback::strikeFrom(Vec2 fallback) {
  strike_from_ = fallback;
  for (const BallState& b : shot_.current) {
    if (b.id == shot_ball_) strike_from_ = b.pos;
  }
}

bool ShotPlayback::advance(double frame_seconds, bool rolling, Match& match,
                           std::vector<audio::Impact>& impacts) {
  const double seconds = frame_seconds * play_rate_;
  // The strike is heard with the first frame of the shot.
  if (strike_) impacts.push_back(*std::exchange(strike_, std::nullopt));
  if (replay_) {
    for (const audio::Impact& i : replay_->advance(seconds)) impacts.push_back(i);
    if (replay_->finished()) replay_.reset();
    return false;
  }
  if (!rolling) {
    after_rest_ = std::min(kPictureAfterRest, after_rest_ + seconds);
    return false;
  }
  return shot_.take(match, clock_.advance(seconds), impacts);
}

std::vector<BallState> ShotPlayback::ballsToDraw(bool rolling) const {
  if (replay_) return replay_->balls();
  if (rolling) return shot_.between(clock_.alpha());
  return shot_.current;
}

double ShotPlayback::drawTime(bool rolling) const {
  if (replay_) return replay_->time();
  if (rolling) return shot_.timeBetween(clock_.alpha());
  return shot_.current_time + after_rest_;
}

}  // namespace nineball::window
