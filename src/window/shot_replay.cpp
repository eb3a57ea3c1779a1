#include "window/shot_replay.hpp"

#include <algorithm>
#include <cmath>

namespace nineball::window {
namespace {

bool isShot(const TurnInput& t) {
  return t.kind != TurnInput::Kind::Decision;
}

}  // namespace

bool ShotReplay::available(const std::vector<TurnInput>& turns) {
  return std::any_of(turns.begin(), turns.end(), isShot);
}

ShotReplay::ShotReplay(const MatchSetup& rack_setup, const std::vector<TurnInput>& turns,
                       double rate)
    : match_(std::make_unique<Match>(rack_setup)),
      rate_(rate),
      clock_(FixedStepClock::forPlay(rack_setup.step.dt(), rack_setup.step.hz)) {
  const auto last = std::find_if(turns.rbegin(), turns.rend(), isShot);
  if (last == turns.rend()) {
    finished_ = true;
    steps_.begin(*match_);
    return;
  }
  const auto shot = last.base() - 1;
  for (auto it = turns.begin(); it != shot; ++it) match_->play(*it);
  match_->beginShot(*shot);
  steps_.begin(*match_);
}

ShotReplay::~ShotReplay() = default;

std::vector<audio::Impact> ShotReplay::advance(double seconds) {
  std::vector<audio::Impact> impacts;
  if (finished_) return impacts;
  if (steps_.take(*match_, clock_.advance(seconds * rate_), impacts)) {
    // A shot cut short for the eye still ends where it ended: run it out, as the game did.
    match_->finishShot();
    finished_ = true;
    steps_.current = steps_.previous = match_->balls();
  }
  return impacts;
}

std::vector<BallState> ShotReplay::balls() const {
  return steps_.between(clock_.alpha());
}

double ShotReplay::time() const {
  return steps_.timeBetween(clock_.alpha());
}

}  // namespace nineball::window
