#include <algorithm>
#include <stdexcept>

#include "nineball/rules.hpp"

namespace nineball::rules {
namespace {

bool contains(const std::vector<int>& v, int x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

// The ball that wins the rack: the 9, or in a custom layout without it the highest number.
int gameBall(const std::vector<int>& balls) {
  if (contains(balls, 9) || balls.empty()) return 9;
  return *std::max_element(balls.begin(), balls.end());
}

// The fewest object balls a legal WPA break drives to a cushion when none is pocketed.
constexpr int kBreakBallsToRail = 4;
constexpr int kFoulsToLose = 3;

}  // namespace

const char* ruleSetName(RuleSet r) {
  return r == RuleSet::Wpa ? "wpa" : "paper";
}

std::optional<RuleSet> ruleSetFromName(const std::string& name) {
  if (name == "wpa") return RuleSet::Wpa;
  if (name == "paper") return RuleSet::Paper;
  return std::nullopt;
}

const char* foulName(Foul f) {
  switch (f) {
    case Foul::None:
      return "none";
    case Foul::Scratch:
      return "scratch";
    case Foul::WrongBallFirst:
      return "wrong-ball-first";
    case Foul::NoContact:
      return "no-contact";
    case Foul::NoRail:
      return "no-rail";
    case Foul::BadBreak:
      return "bad-break";
    case Foul::ThreeFouls:
      return "three-fouls";
  }
  return "?";
}

Rack::Rack(RuleSet rules, std::vector<int> object_balls, bool opening_break)
    : rules_(rules), on_table_(std::move(object_balls)), break_next_(opening_break) {
  std::sort(on_table_.begin(), on_table_.end());
}

int Rack::ballOn() const {
  return on_table_.empty() ? 0 : on_table_.front();
}

void Rack::removePocketed(const std::vector<int>& balls) {
  for (int b : balls)
    on_table_.erase(std::remove(on_table_.begin(), on_table_.end(), b), on_table_.end());
}

void Rack::respot(int ball) {
  if (!contains(on_table_, ball)) {
    on_table_.push_back(ball);
    std::sort(on_table_.begin(), on_table_.end());
  }
}

Verdict Rack::shoot(const ShotSummary& shot, bool push_out) {
  if (over()) throw std::logic_error("the game is over");
  if (awaiting_decision_) throw std::logic_error("a push-out is waiting for shoot or pass");
  if (push_out && (rules_ != RuleSet::Wpa || !push_out_available_)) {
    throw std::logic_error("no push-out is allowed on this shot");
  }
  Verdict v = rules_ == RuleSet::Wpa ? judgeWpa(shot, push_out) : judgePaper(shot);
  shooter_ = v.next;
  ball_in_hand_ = v.ball_in_hand;
  push_out_available_ = v.push_out_available;
  awaiting_decision_ = v.awaiting_decision;
  winner_ = v.winner;
  break_next_ = false;
  return v;
}

void Rack::decide(bool shoot_now) {
  if (!awaiting_decision_) throw std::logic_error("no push-out is waiting for a decision");
  awaiting_decision_ = false;
  if (!shoot_now) shooter_ = other(shooter_);
}

Verdict Rack::judgeWpa(const ShotSummary& shot, bool push_out) {
  Verdict v;
  v.shooter = shooter_;
  for (int b : shot.pocketed) {
    if (contains(on_table_, b)) v.pocketed.push_back(b);
  }
  const int on = ballOn();
  const int game_ball = gameBall(on_table_);
  const bool game_ball_down = contains(v.pocketed, game_ball);
  const bool was_break = break_next_;

  if (shot.cue_pocketed) {
    v.foul = Foul::Scratch;
  } else if (was_break) {
    if (shot.first_contact != on) {
      v.foul = Foul::BadBreak;
    } else if (v.pocketed.empty() && shot.object_balls_to_rail < kBreakBallsToRail) {
      v.foul = Foul::BadBreak;
    }
  } else if (!push_out) {
    if (!shot.first_contact) {
      v.foul = Foul::NoContact;
    } else if (*shot.first_contact != on) {
      v.foul = Foul::WrongBallFirst;
    } else if (v.pocketed.empty() && !shot.rail_after_contact) {
      v.foul = Foul::NoRail;
    }
  }

  if (!v.legal()) {
    if (++foulCount(shooter_) >= kFoulsToLose) v.foul = Foul::ThreeFouls;
  } else {
    foulCount(shooter_) = 0;
  }

  // The game ball goes back on the spot after a foul or a push-out; the rest stay down.
  std::vector<int> stay_down = v.pocketed;
  if (game_ball_down && (!v.legal() || push_out)) {
    v.to_spot.push_back(game_ball);
    stay_down.erase(std::remove(stay_down.begin(), stay_down.end(), game_ball), stay_down.end());
  }
  removePocketed(stay_down);

  if (v.foul == Foul::ThreeFouls) {
    v.winner = other(shooter_);
    v.next = other(shooter_);
  } else if (!v.legal()) {
    v.next = other(shooter_);
    v.ball_in_hand = true;
  } else if (push_out) {
    v.next = other(shooter_);
    v.awaiting_decision = true;
  } else if (game_ball_down) {
    v.winner = shooter_;
    v.next = shooter_;
  } else {
    v.next = v.pocketed.empty() ? other(shooter_) : shooter_;
  }
  v.push_out_available = was_break && !v.winner;
  return v;
}

Verdict Rack::judgePaper(const ShotSummary& shot) {
  Verdict v;
  v.shooter = shooter_;
  for (int b : shot.pocketed) {
    if (contains(on_table_, b)) v.pocketed.push_back(b);
  }
  const int on = ballOn();
  const bool nine_down = contains(v.pocketed, gameBall(on_table_));
  if (shot.cue_pocketed) {
    v.foul = Foul::Scratch;
  } else if (!shot.first_contact) {
    v.foul = Foul::NoContact;
  } else if (*shot.first_contact != on) {
    v.foul = Foul::WrongBallFirst;
  }
  removePocketed(v.pocketed);
  if (!v.legal()) {
    v.next = other(shooter_);
    v.cue_to_head_spot = shot.cue_pocketed;
    if (nine_down) v.winner = other(shooter_);
  } else if (nine_down || on_table_.empty()) {
    v.winner = shooter_;
    v.next = shooter_;
  } else {
    v.next = v.pocketed.empty() ? other(shooter_) : shooter_;
  }
  return v;
}

}  // namespace nineball::rules
