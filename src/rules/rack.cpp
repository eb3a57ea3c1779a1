#include <algorithm>
#include <stdexcept>

#include "nineball/ball.hpp"
#include "nineball/rules.hpp"

namespace nineball::rules {

Rack::Rack(RuleSet rules, std::vector<int> object_balls, bool opening_break)
    : Rack(Game::NineBall, rules, std::move(object_balls), opening_break) {}

Rack::Rack(Game game, RuleSet rules, std::vector<int> object_balls, bool opening_break)
    : Rack(ruleBook(game, rules), std::move(object_balls), opening_break) {}

Rack::Rack(const RuleBook& book, std::vector<int> object_balls, bool opening_break) : book_(&book) {
  std::sort(object_balls.begin(), object_balls.end());
  s_.racked = object_balls;
  s_.on_table = std::move(object_balls);
  s_.break_next = opening_break;
}

void Rack::setOpener(Player p) {
  s_.shooter = p;
}

int RuleBook::ballOn(const RackState& s) const {
  const std::vector<int> balls = legalFirstBalls(s);
  return balls.empty() ? 0 : *std::min_element(balls.begin(), balls.end());
}

int RuleBook::cueBall(const RackState&) const {
  return kCueBall;
}

void Rack::respot(int ball) {
  if (!s_.has(ball)) {
    s_.on_table.push_back(ball);
    std::sort(s_.on_table.begin(), s_.on_table.end());
  }
}

Verdict Rack::shoot(const ShotSummary& shot, bool push_out) {
  if (over()) throw std::logic_error("the game is over");
  if (awaitingDecision()) {
    throw std::logic_error(s_.decision == Decision::RerackOrPlayOn
                               ? "the illegal break waits for re-rack or play on"
                           : s_.decision == Decision::PlayOrPass
                               ? "a push-out is waiting for shoot or pass"
                               : "the foul waits for the opponent's choice (play or put back)");
  }
  if (push_out && !s_.push_out_available) {
    throw std::logic_error("no push-out is allowed on this shot");
  }
  Verdict v = book_->judge(s_, shot, push_out);
  v.awaiting_decision = v.decision != Decision::None;
  v.groups = s_.groups;
  s_.shooter = v.next;
  s_.ball_in_hand = v.ball_in_hand;
  s_.push_out_available = v.push_out_available;
  s_.decision = v.decision;
  s_.winner = v.winner;
  s_.draw = v.draw;
  s_.break_next = false;
  s_.score[0] += v.points[0];
  s_.score[1] += v.points[1];
  return v;
}

void Rack::decide(bool shoot_now) {
  if (!awaitingDecision()) throw std::logic_error("no push-out is waiting for a decision");
  const Decision d = s_.decision;
  s_.decision = Decision::None;
  if (d == Decision::PlayOrPutBack || d == Decision::PlayPutBackOrReplace) {
    // Snooker's misses count in a row only while the balls are replaced (WPBSA 3.14(h)).
    s_.snooker.misses[s_.shooter == Player::A ? 1 : 0] = 0;
  }
  if (shoot_now) return;
  if (d != Decision::RerackOrPlayOn) {
    // Passed back (or the offender put back in): a free ball stated for the other is void
    // (WPBSA 3.12(f)).
    s_.shooter = other(s_.shooter);
    s_.snooker.free_ball = false;
    return;
  }
  // A re-rack starts the rack over; the player who chose it breaks.
  s_.on_table = s_.racked;
  s_.break_next = true;
  s_.ball_in_hand = false;
  s_.push_out_available = false;
  s_.groups = Groups{};
  s_.fouls[0] = s_.fouls[1] = 0;
}

}  // namespace nineball::rules
