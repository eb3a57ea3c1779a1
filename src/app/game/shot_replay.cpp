#include "app/game/shot_replay.hpp"

#include <algorithm>
#include <cmath>

namespace nineball::app {
namespace {

// As the live game: a shot still rolling after this long (s, simulated) is over.
constexpr double kMaxShotTime = 120.0;
// Frames longer than this (s of play) are not caught up in one go.
constexpr double kMaxCatchUp = 0.25;

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
      clock_(rack_setup.step.dt(),
             std::max(1, static_cast<int>(std::ceil(kMaxCatchUp * rack_setup.step.hz)))) {
  const auto last = std::find_if(turns.rbegin(), turns.rend(), isShot);
  if (last == turns.rend()) {
    finished_ = true;
    current_ = previous_ = match_->balls();
    return;
  }
  const auto shot = last.base() - 1;
  for (auto it = turns.begin(); it != shot; ++it) match_->play(*it);
  match_->beginShot(*shot);
  start_ = match_->world().time();
  current_ = previous_ = match_->balls();
}

ShotReplay::~ShotReplay() = default;

std::vector<audio::Impact> ShotReplay::advance(double seconds) {
  std::vector<audio::Impact> impacts;
  if (finished_) return impacts;
  World& world = match_->world();
  const int steps = clock_.advance(seconds * rate_);
  for (int i = 0; i < steps; ++i) {
    previous_ = current_;
    world.step();
    current_ = match_->balls();
    const auto& events = world.events();
    if (events.size() > events_seen_) {
      const std::vector<Event> fresh(events.begin() + static_cast<long>(events_seen_),
                                     events.end());
      const auto more = audio::impactsFromEvents(fresh, previous_);
      impacts.insert(impacts.end(), more.begin(), more.end());
      events_seen_ = events.size();
    }
    if (world.atRest() || world.time() - start_ > kMaxShotTime) {
      finished_ = true;
      previous_ = current_;
      break;
    }
  }
  return impacts;
}

std::vector<BallState> ShotReplay::balls() const {
  std::vector<BallState> out = current_;
  const double a = clock_.alpha();
  for (std::size_t i = 0; i < out.size() && i < previous_.size(); ++i) {
    if (!out[i].pocket) out[i].pos = previous_[i].pos + (out[i].pos - previous_[i].pos) * a;
  }
  return out;
}

}  // namespace nineball::app
