#include "window/practice_table.hpp"

#include <algorithm>
#include <cmath>

namespace nineball::window {
namespace {

// Search step (m) for a free spot.
constexpr double kSpotStep = 0.01;
// A practice position keeps this many steps for undo; older ones are forgotten.
constexpr std::size_t kMaxSteps = 200;

}  // namespace

PracticeTable::PracticeTable(const TableGeometry& table, double ball_radius,
                             std::vector<BallState> layout)
    : table_(table), r_(ball_radius) {
  for (BallState& b : layout) {
    if (b.pocket) continue;
    b.vel = {};
    b.w = {};
    layout_.push_back(b);
  }
  if (!has(kCueBall)) {
    const Vec2 head{table_.headStringX(), 0.0};
    layout_.insert(layout_.begin(),
                   BallState::at(kCueBall, freeSpotNear(kCueBall, head).value_or(head)));
  }
}

bool PracticeTable::has(int id) const {
  return std::any_of(layout_.begin(), layout_.end(),
                     [id](const BallState& b) { return b.id == id; });
}

std::optional<std::string> PracticeTable::placementProblem(int id, Vec2 pos) const {
  if (!std::isfinite(pos.x) || !std::isfinite(pos.y)) return std::string("not a position");
  if (!table_.ballFits(pos, r_)) return std::string("off the table");
  for (const BallState& b : layout_) {
    if (b.id != id && length(b.pos - pos) < 2.0 * r_) {
      return "on the " + (b.id == kCueBall ? std::string("cue ball") : std::to_string(b.id));
    }
  }
  return std::nullopt;
}

void PracticeTable::recordMove() {
  PracticeStep step;
  step.before.layout = layout_;
  steps_.push_back(std::move(step));
  if (steps_.size() > kMaxSteps) steps_.erase(steps_.begin());
}

void PracticeTable::recordShot(PracticeShot shot) {
  last_shot_ = shot;
  steps_.push_back({std::move(shot), true});
  if (steps_.size() > kMaxSteps) steps_.erase(steps_.begin());
}

bool PracticeTable::place(int id, Vec2 pos) {
  if (placementProblem(id, pos)) return false;
  recordMove();
  for (BallState& b : layout_) {
    if (b.id == id) {
      b.pos = pos;
      return true;
    }
  }
  layout_.push_back(BallState::at(id, pos));
  // Kept in id order, so that a rebuilt world adds them in the same order every time.
  std::sort(layout_.begin(), layout_.end(),
            [](const BallState& a, const BallState& b) { return a.id < b.id; });
  return true;
}

bool PracticeTable::remove(int id) {
  if (id == kCueBall || !has(id)) return false;
  recordMove();
  const auto before = layout_.size();
  layout_.erase(std::remove_if(layout_.begin(), layout_.end(),
                               [id](const BallState& b) { return b.id == id; }),
                layout_.end());
  return layout_.size() != before;
}

std::optional<Vec2> PracticeTable::freeSpotNear(int id, Vec2 near) const {
  if (!placementProblem(id, near)) return near;
  for (double radius = kSpotStep; radius < table_.def.length; radius += kSpotStep) {
    const int n = std::max(8, static_cast<int>(2.0 * kPi * radius / kSpotStep));
    for (int i = 0; i < n; ++i) {
      const Vec2 p = near + fromAngle(2.0 * kPi * i / n) * radius;
      if (!placementProblem(id, p)) return p;
    }
  }
  return std::nullopt;
}

bool PracticeTable::settle(const std::vector<BallState>& after) {
  Vec2 cue_from;
  for (const BallState& b : layout_) {
    if (b.id == kCueBall) cue_from = b.pos;
  }
  bool cue_back = false;
  layout_.clear();
  for (BallState b : after) {
    if (b.pocket && b.id != kCueBall) continue;
    b.vel = {};
    b.w = {};
    if (b.pocket) {
      b.backOnTable();
      b.pos = cue_from;
      cue_back = true;
    }
    layout_.push_back(b);
  }
  // The cue ball's old spot may be taken now: then the nearest free one.
  if (cue_back) {
    for (BallState& b : layout_) {
      if (b.id == kCueBall) b.pos = freeSpotNear(kCueBall, cue_from).value_or(cue_from);
    }
  }
  return cue_back;
}

std::optional<PracticeShot> PracticeTable::retry() {
  if (!last_shot_) return std::nullopt;
  layout_ = last_shot_->layout;
  return last_shot_;
}

std::optional<PracticeStep> PracticeTable::undo() {
  if (steps_.empty()) return std::nullopt;
  PracticeStep last = steps_.back();
  steps_.pop_back();
  layout_ = last.before.layout;
  return last;
}

}  // namespace nineball::window
