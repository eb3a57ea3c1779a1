#include "nineball/match.hpp"
#include "nineball/state_hash.hpp"

namespace nineball {
namespace {

void addInts(BitHash& h, const std::vector<int>& v) {
  h.add(static_cast<std::int64_t>(v.size()));
  for (int x : v) h.add(static_cast<std::int64_t>(x));
}

void addGroup(BitHash& h, const std::optional<rules::Group>& g) {
  h.add(g ? static_cast<std::int64_t>(*g) + 1 : 0);
}

void addRack(BitHash& h, const rules::RackState& s) {
  addInts(h, s.racked);
  addInts(h, s.on_table);
  const auto flag = [&h](bool b) { h.add(static_cast<std::int64_t>(b)); };
  h.add(static_cast<std::int64_t>(s.shooter));
  flag(s.break_next);
  flag(s.ball_in_hand);
  flag(s.push_out_available);
  h.add(static_cast<std::int64_t>(s.decision));
  h.add(s.winner ? static_cast<std::int64_t>(*s.winner) + 1 : 0);
  for (int i = 0; i < 2; ++i) {
    h.add(static_cast<std::int64_t>(s.fouls[i]));
    h.add(static_cast<std::int64_t>(s.score[i]));
    h.add(static_cast<std::int64_t>(s.innings[i]));
    h.add(static_cast<std::int64_t>(s.high_run[i]));
    h.add(static_cast<std::int64_t>(s.snooker.misses[i]));
  }
  addGroup(h, s.groups.a);
  addGroup(h, s.groups.b);
  h.add(static_cast<std::int64_t>(s.target));
  flag(s.inning_open);
  h.add(static_cast<std::int64_t>(s.run));
  flag(s.equalising);
  flag(s.draw);
  flag(s.snooker.colour_on);
  flag(s.snooker.free_ball);
  flag(s.snooker.respotted_black);
  flag(s.snooker.colour_on_before);
  flag(s.snooker.free_ball_before);
  addInts(h, s.snooker.on_table_before);
}

}  // namespace

std::uint64_t snapshotHash(const MatchSnapshot& snapshot) {
  BitHash h;
  h.add(static_cast<std::int64_t>(stateHash(snapshot.balls)));
  addRack(h, snapshot.rack);
  h.add(static_cast<std::int64_t>(snapshot.cue_pocketed));
  h.add(static_cast<std::int64_t>(stateHash(snapshot.balls_before)));
  return h.value();
}

MatchSnapshot Match::snapshot() const {
  if (in_progress_) throw IllegalAction("a shot is still rolling");
  MatchSnapshot s;
  s.balls = world_->balls();
  s.rack = rack_.state();
  s.cue_pocketed = cue_pocketed_;
  s.balls_before = before_shot_;
  return s;
}

void Match::restore(const MatchSnapshot& snapshot) {
  if (in_progress_) throw IllegalAction("a shot is still rolling");
  world_->reset();
  for (const BallState& b : snapshot.balls) world_->addBall(b);
  rack_.setState(snapshot.rack);
  cue_pocketed_ = snapshot.cue_pocketed;
  before_shot_ = snapshot.balls_before;
}

}  // namespace nineball
