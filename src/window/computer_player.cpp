#include "window/computer_player.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <system_error>

#include "app/opponent.hpp"
#include "common/log.hpp"
#include "render/cue_stick_shape.hpp"
#include "window/shot_call.hpp"

namespace nineball::window {
namespace {

// How the computer's turn is paced on screen (s): a player takes a moment even over an easy
// shot, so "thinking" shows at least this long; then the cue ball is carried to its spot, the
// cue turned to the aim (longer for a bigger turn), drawn back, held, and sent through.
constexpr double kMinThink = 0.6;
constexpr double kPlaceTime = 0.6;
constexpr double kAimTime = 0.6;
constexpr double kAimTimePerHalfTurn = 0.4;
constexpr double kPullTime = 0.5;
constexpr double kHoldTime = 0.25;
constexpr double kStrikeTime = 0.08;
// The shot played when the planner fails: straight at the ball on, firm enough to reach a
// cushion after the hit from most places.
constexpr double kFallbackSpeed = 2.0;

// Smooth start and stop over t in [0, 1].
double ease(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// The planner's cueing errors: one stream per planner, fixed by the game's seed.
std::uint64_t plannerSeed(std::uint64_t seed, long made) {
  return seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(made) + 1;
}

ComputerMove fallbackMove(const GameSession& session) {
  ComputerMove m;
  const rules::Rack& rack = session.match().rack();
  if (rack.awaitingDecision()) {
    m.turn.kind = TurnInput::Kind::Decision;
    m.turn.shoot = true;  // shoot, or play on as it lies: never throws the table away
    return m;
  }
  const Vec2 cue = session.cuePosition();
  const int on = rack.ballOn();
  m.turn.shot.heading_rad = session.heading();
  for (const BallState& b : session.match().balls()) {
    if (b.id == on && !b.pocket && length(b.pos - cue) > 0.0) {
      m.turn.shot.heading_rad = std::atan2(b.pos.y - cue.y, b.pos.x - cue.x);
      // A called game refuses an uncalled shot: the ball on, where the hit sends it.
      if (rack.callRequired()) {
        m.turn.call = rules::Call{
            on, pocketAlong(session.match().world().table(), b.pos, normalized(b.pos - cue))};
      }
    }
  }
  m.turn.shot.speed = session.match().rack().isBreak() ? GameSession::kBreakSpeed : kFallbackSpeed;
  if (session.cueInHand()) m.turn.cue = cue;
  return m;
}

std::string planText(const ai::Plan& plan, int ball_on, const GameDef& game) {
  // Eight-ball has no single ball on: the plan names the ball it hits first.
  const std::string on = game.theBall(plan.first > 0 ? plan.first : ball_on);
  const std::string target = game.theBall(plan.target);
  const std::string pocket =
      plan.pocket ? std::string(" in the ") + pocketName(*plan.pocket) + " pocket" : "";
  switch (plan.kind) {
    case ai::ShotKind::Break:
      return "break";
    case ai::ShotKind::Pot:
      return "pot " + target + pocket;
    case ai::ShotKind::Combination:
      return "combination, " + on + " onto " + target + pocket;
    case ai::ShotKind::Bank:
      return "bank " + target + pocket;
    case ai::ShotKind::Kick:
      return "kick at " + on + " off the cushion";
    case ai::ShotKind::PushOut:
      return "push out";
    case ai::ShotKind::Jump:
      return plan.pocket ? "jump, pot " + target + pocket : "jump at " + on;
    case ai::ShotKind::Point: {
      const char* ball = caromBallName(plan.first);
      const std::string first =
          ball ? std::string("the ") + ball + " first" : std::string("a cushion first");
      return (plan.value > 0.0 ? "three cushions, " : "no point in sight, the closest try: ") +
             first;
    }
    case ai::ShotKind::Safety:
      break;
  }
  return "play safe on " + on;
}

}  // namespace

std::string describePlan(const ai::Plan& plan, int ball_on, const GameDef& game) {
  std::string text = planText(plan, ball_on, game);
  const auto& call = plan.turn.call;
  if (!call || plan.kind == ai::ShotKind::PushOut) return text;
  if (call->ball == plan.target && plan.pocket && call->pocket == *plan.pocket) {
    return text + " (called)";
  }
  if (game.snookers) return text + " (nominated: " + game.theBall(call->ball) + ")";
  return text + " (called: " + game.theBall(call->ball) + " in the " + pocketName(call->pocket) +
         " pocket)";
}

ComputerMove planMove(ai::Planner& planner, const ai::PlanInput& in, bool deciding) {
  ComputerMove move;
  if (deciding) {
    move.turn.kind = TurnInput::Kind::Decision;
    move.turn.shoot = planner.shootAfterPushOut(in);
  } else {
    move.plan = planner.plan(in);
    move.turn = planner.execute(*move.plan);
  }
  return move;
}

ComputerPlayer::ComputerPlayer(std::uint64_t seed) : seed_(seed) {}

ComputerPlayer::~ComputerPlayer() {
  abandon();
  reapAbandoned(true);
}

void ComputerPlayer::setOpponent(GameSession& session, const Seat& opponent) {
  abandon();
  if (opponent != opponent_) planner_.reset();
  opponent_ = opponent;
  stuck_ = false;
  session.setSeatName(kSeat, isComputer(opponent) ? "Computer" : "Player 2");
  logger("game")->info("opponent: {}", app::opponentLabel(opponent));
}

bool ComputerPlayer::computerTurn(const GameSession& session) const {
  const Phase phase = session.phase();
  return isComputer(opponent_) && session.seatToMove() == kSeat &&
         (phase == Phase::Aiming || phase == Phase::PushOutChoice);
}

bool ComputerPlayer::controls(const GameSession& session) const {
  return computerTurn(session) && !stuck_;
}

bool ComputerPlayer::showsCue() const {
  return stage_ == Stage::Aiming || stage_ == Stage::Cueing || stage_ == Stage::Striking;
}

std::optional<Vec2> ComputerPlayer::carriedCue() const {
  if (stage_ != Stage::Placing || !move_ || !move_->turn.cue) return std::nullopt;
  return cue_from_ + (*move_->turn.cue - cue_from_) * ease(elapsed_ / duration_);
}

std::string ComputerPlayer::status(const GameSession& session) const {
  const std::string name = session.seatName(kSeat);
  switch (stage_) {
    case Stage::Idle:
      break;
    case Stage::Thinking:
      if (!deciding_) return name + " thinking...";
      return rerack_choice_ ? name + " thinking: play on or re-rack?"
                            : name + " thinking: play from here or pass it back?";
    case Stage::Placing:
      return name + " places the cue ball";
    case Stage::Aiming:
    case Stage::Cueing:
    case Stage::Striking:
      if (move_ && move_->turn.kind == TurnInput::Kind::PushOut) return name + " pushes out";
      if (move_ && move_->plan) {
        return name + ": " +
               describePlan(*move_->plan, session.match().rack().ballOn(),
                            gameDef(session.match().rack().game()));
      }
      return name + " shoots at the " + std::to_string(session.match().rack().ballOn());
  }
  return controls(session) ? name + " thinking..." : session.status();
}

void ComputerPlayer::update(GameSession& session, double seconds) {
  reapAbandoned(false);
  if (!computerTurn(session)) {
    stuck_ = false;
    if (stage_ != Stage::Idle) abandon();
    return;
  }
  if (stuck_) return;
  elapsed_ += seconds;
  const double t = duration_ > 0.0 ? elapsed_ / duration_ : 1.0;
  switch (stage_) {
    case Stage::Idle:
      startThinking(session);
      return;
    case Stage::Thinking:
      if (elapsed_ >= kMinThink) {
        if (auto move = takeMove(session)) beginMove(session, *move);
      }
      return;
    case Stage::Placing:
      if (t < 1.0) return;
      if (!session.placeCue(*move_->turn.cue)) {
        logger("game")->warn("the computer's cue ball spot was refused; it plays a plain shot");
        move_ = fallbackMove(session);
      }
      startAiming(session);
      return;
    case Stage::Aiming:
      session.setHeading(heading_from_ + turn_by_ * ease(t));
      if (t < 1.0) return;
      session.setHeading(move_->turn.shot.heading_rad);
      callIfDue(session);
      stage_ = Stage::Cueing;
      elapsed_ = 0.0;
      duration_ = kPullTime + kHoldTime;
      return;
    case Stage::Cueing:
    case Stage::Striking: {
      const double speed = move_->turn.shot.speed;
      const double power = std::clamp(
          (speed - GameSession::kMinSpeed) / (GameSession::kMaxSpeed - GameSession::kMinSpeed), 0.0,
          1.0);
      const double full = power * render::CueStickShape::kMaxPull;
      if (stage_ == Stage::Cueing) {
        const double f = ease(elapsed_ / kPullTime);
        pull_ = f * full;
        session.setSpeed(GameSession::kMinSpeed + f * (speed - GameSession::kMinSpeed));
        if (t >= 1.0) {
          stage_ = Stage::Striking;
          elapsed_ = 0.0;
          duration_ = kStrikeTime;
        }
        return;
      }
      pull_ = full * (1.0 - std::min(1.0, t));
      if (t >= 1.0) strike(session);
      return;
    }
  }
}

void ComputerPlayer::startThinking(const GameSession& session) {
  stage_ = Stage::Thinking;
  elapsed_ = 0.0;
  pull_ = 0.0;
  move_.reset();
  deciding_ = session.match().rack().awaitingDecision();
  rerack_choice_ = session.match().rack().pendingDecision() == rules::Decision::RerackOrPlayOn;
  if (!planner_) {
    planner_ = std::make_shared<ai::Planner>(*computerLevel(opponent_),
                                             plannerSeed(seed_, planners_made_++));
  }
  // The worker plans from its own copy of the position: the match is never read off this
  // thread, whatever the window does meanwhile.
  const ai::PlanInput input = ai::planInputFrom(session.match());
  const bool deciding = deciding_;
  try {
    job_ = std::async(std::launch::async, [think = thinker_, planner = planner_, input, deciding] {
      return think(*planner, input, deciding);
    });
  } catch (const std::system_error& e) {
    logger("game")->error("the computer could not start thinking: {}", e.what());
  }
}

std::optional<ComputerMove> ComputerPlayer::takeMove(const GameSession& session) {
  if (!job_.valid()) return fallbackMove(session);
  if (!wait_ && job_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
    return std::nullopt;
  }
  try {
    return job_.get();
  } catch (const std::exception& e) {
    logger("game")->error("the computer's planner failed ({}); it plays a plain shot instead",
                          e.what());
  } catch (...) {
    logger("game")->error("the computer's planner failed; it plays a plain shot instead");
  }
  return fallbackMove(session);
}

void ComputerPlayer::beginMove(GameSession& session, const ComputerMove& move) {
  if (move.turn.kind == TurnInput::Kind::Decision) {
    stage_ = Stage::Idle;
    session.decide(move.turn.shoot);
    return;
  }
  move_ = move;
  // Declared and called before the cue moves, as a person does: the HUD and the table show it.
  if (move.turn.kind == TurnInput::Kind::PushOut) {
    if (!session.pushOutDeclared()) session.togglePushOut();
  } else if (move.turn.call) {
    session.setCall(*move.turn.call);
  }
  cue_from_ = session.cuePosition();
  if (session.cueInHand() && move.turn.cue && *move.turn.cue != cue_from_) {
    stage_ = Stage::Placing;
    elapsed_ = 0.0;
    duration_ = kPlaceTime;
    return;
  }
  startAiming(session);
}

void ComputerPlayer::startAiming(GameSession& session) {
  stage_ = Stage::Aiming;
  elapsed_ = 0.0;
  heading_from_ = session.heading();
  turn_by_ = std::remainder(move_->turn.shot.heading_rad - heading_from_, 2.0 * kPi);
  duration_ = kAimTime + kAimTimePerHalfTurn * std::abs(turn_by_) / kPi;
  session.setTip(move_->turn.shot.tip);
  session.setPower(0.0);
}

void ComputerPlayer::callIfDue(GameSession& session) {
  // A plan without the call the rules want (a fallback shot): the obvious one along the aim.
  if (move_->turn.kind != TurnInput::Kind::Shot || move_->turn.call || !session.callRequired()) {
    return;
  }
  session.callObvious();
  move_->turn.call = session.call();
}

void ComputerPlayer::strike(GameSession& session) {
  stage_ = Stage::Idle;
  pull_ = 0.0;
  const ComputerMove move = *move_;
  move_.reset();
  if (session.shoot(move.turn)) return;
  logger("game")->warn("the computer's shot was refused ({}); it plays a plain shot instead",
                       session.message());
  if (session.shoot(fallbackMove(session).turn)) return;
  logger("game")->error("the computer's plain shot was refused too ({})", session.message());
  stuck_ = true;
  session.say("The computer cannot play this shot: play it for the computer.",
              render::Tone::Warning);
}

void ComputerPlayer::abandon() {
  if (job_.valid()) {
    abandoned_.push_back(std::move(job_));
    planner_.reset();  // still planning on the worker: the next turn gets a fresh planner
  }
  stage_ = Stage::Idle;
  move_.reset();
  pull_ = 0.0;
}

void ComputerPlayer::reapAbandoned(bool wait) {
  auto done = [wait](std::future<ComputerMove>& f) {
    if (!wait && f.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return false;
    try {
      f.get();
    } catch (...) {
      // A dropped turn's failure matters to nobody.
    }
    return true;
  };
  abandoned_.erase(std::remove_if(abandoned_.begin(), abandoned_.end(), done), abandoned_.end());
}

}  // namespace nineball::window
