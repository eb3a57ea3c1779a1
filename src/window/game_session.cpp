#include "window/game_session.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <exception>
#include <utility>

#include "common/log.hpp"
#include "nineball/games.hpp"
#include "nineball/table_markings.hpp"
#include "play/jump_flight.hpp"
#include "play/shot_summary.hpp"
#include "rules/three_cushion.hpp"
#include "window/shot_call.hpp"
#include "window/snooker_turn_message.hpp"
#include "window/turn_message.hpp"

namespace nineball::window {
namespace {

// Search step (m) for a free spot for the cue ball in hand.
constexpr double kSpotSearchStep = 0.01;

std::string formatSpeed(double mps) {
  char s[32];
  std::snprintf(s, sizeof s, "%g", mps);
  return s;
}

}  // namespace

GameSession::GameSession(const MatchSetup& setup, bool practice)
    : setup_(setup), playback_(FixedStepClock::forPlay(setup.step.dt(), setup.step.hz)) {
  if (practice) {
    practice_ = std::make_unique<PracticeMode>(Match(setup));
    names_[0] = "Practice";
    names_[1] = "";
    rebuildPractice();
    aimAtBallOn();
    return;
  }
  startRack();
}

void GameSession::rebuildPractice() {
  // A fresh world of the position: no rules are judged, so none carry over.
  MatchSetup s = setup_;
  s.balls = practice_->table().layout();
  match_ = std::make_unique<Match>(s);
  playback_.settle(*match_);
  pocketed_ = practice_->offTable();
  phase_ = Phase::Aiming;
}

GameSession::~GameSession() = default;
GameSession::GameSession(GameSession&&) noexcept = default;
GameSession& GameSession::operator=(GameSession&&) noexcept = default;

double GameSession::maxTip() const {
  return std::min(kMaxTip, match_->world().physics().miscue_limit);
}

bool GameSession::pushOutAvailable() const {
  return !practice_ && phase_ == Phase::Aiming && match_->rack().pushOutAvailable();
}

void GameSession::togglePushOut() {
  if (!pushOutAvailable()) {
    if (practice_) {
      say("Practice has no rules, so no push-out: just shoot.", render::Tone::Warning);
    } else if (phase_ == Phase::Aiming) {
      say("No push-out now: it may be played only on the shot just after the break.",
          render::Tone::Warning);
    }
    return;
  }
  push_out_ = !push_out_;
  say(push_out_ ? "Push-out declared: no foul for the wrong ball or no cushion; the opponent "
                  "then chooses who shoots."
                : "Push-out withdrawn.");
}

bool GameSession::cueInHand() const {
  return !practice_ && phase_ == Phase::Aiming && match_->cueInHand();
}

std::optional<std::string> GameSession::caromCount() const {
  if (practice_ || playback_.replaying() ||
      gameDef(match_->rack().game()).family != GameFamily::Carom) {
    return std::nullopt;
  }
  if (phase_ != Phase::Rolling && !last_count_.empty()) return last_count_;
  if (phase_ != Phase::Rolling) return std::nullopt;
  // The events the picture has reached: the world may be a step ahead of what is drawn.
  const double now = drawTime();
  std::vector<Event> seen;
  for (const Event& e : match_->world().events()) {
    if (e.t <= now) seen.push_back(e);
  }
  const rules::ShotSummary summary = play::summarize(seen, playback_.shotBall());
  bool both = false;
  const int cushions =
      rules::ThreeCushionRules::cushionsBeforeSecond(summary, playback_.shotBall(), both);
  std::string text = "Cushions: " + std::to_string(cushions);
  if (both) text += cushions >= 3 ? "   POINT" : "   no point";
  return text;
}

int GameSession::shooterBall() const {
  return practice_ ? kCueBall : match_->rack().cueBall();
}

Vec2 GameSession::cuePosition() const {
  if (cueInHand() && cue_.spot()) return *cue_.spot();
  const int cue = shooterBall();
  for (const BallState& b : playback_.balls()) {
    if (b.id == cue) return b.pos;
  }
  return {};
}

std::optional<std::string> GameSession::placementProblem(Vec2 pos) const {
  if (!cueInHand()) return std::string("the cue ball is not in hand");
  const auto problem = match_->cuePlacementProblem(pos);
  // The rules give the head string as a coordinate; a player knows it as a line on the cloth.
  if (problem && problem->find("head string") != std::string::npos) {
    return std::string(
        "on the break it goes behind the head string, the line through the second diamonds");
  }
  return problem;
}

bool GameSession::placeCue(Vec2 pos) {
  if (auto problem = placementProblem(pos)) {
    message_.refusePlacement("The cue ball cannot go there: " + *problem + ".");
    return false;
  }
  cue_.setSpot(pos);
  message_.placementTaken();
  return true;
}

AimGuide GameSession::aimGuide() const {
  const Engine& w = match_->world();
  Shot shot;
  shot.heading_rad = cue_.heading();
  shot.speed = cue_.speed();
  shot.tip = cue_.tip();
  shot.elevation_rad = cue_.elevation();
  // A raised cue may jump the ball: the guide then passes over what it clears and marks where
  // it comes down.
  return play::jumpAimGuide(w.table(), w.physics(), playback_.balls(), cuePosition(), shot,
                            shooterBall());
}

void GameSession::startRack() {
  last_count_.clear();
  breaker_seat_ = breakerOfRack();
  // The breaker is the rack's Player A (seatOf): the rules see A break every rack.
  const MatchSetup s = nineball::rackSetup(setup_, rack_, rules::Player::A);
  match_ = std::make_unique<Match>(s);
  rack_setup_ = s;
  rack_turns_.clear();
  playback_.stopReplay();
  pocketed_.clear();
  // Carom's opening is an ordinary stroke, not a break.
  const bool pool_break =
      match_->rack().isBreak() && gameDef(match_->rack().game()).family == GameFamily::Pool;
  const bool snooker = gameDef(match_->rack().game()).snookers;
  if (pool_break) cue_.setSpeed(snooker ? kBreakOffSpeed : kBreakSpeed);
  message_.clearPlain();
  startTurn();
  logger("game")->info(
      "rack {}: {} breaks, rules {}, seed {} (--seed {} plays the game's racks again)",
      rackNumber(), seatName(seatToMove()), rules::ruleSetName(s.rules), s.seed, setup_.seed);
}

void GameSession::startTurn() {
  playback_.settle(*match_);
  phase_ = match_->rack().awaitingDecision() ? Phase::PushOutChoice : Phase::Aiming;
  push_out_ = false;
  cue_.newTurn();
  call_ball_.reset();
  call_pocket_.reset();
  if (match_->cueInHand()) {
    std::optional<Vec2> on_table;
    for (const BallState& b : playback_.balls()) {
      if (b.id == kCueBall && !b.pocket) on_table = b.pos;
    }
    cue_.setSpot(on_table && !match_->cuePlacementProblem(*on_table) ? *on_table : freeCueSpot());
  }
  aimAtBallOn();
}

Vec2 GameSession::freeCueSpot() const {
  const TableGeometry& t = match_->world().table();
  Vec2 head{t.headStringX(), 0.0};
  // Snooker breaks off from between the brown and the yellow, as players usually do.
  if (match_->cueArea() == CueArea::TheD) {
    const SnookerLayout l = SnookerLayout::of(t.def);
    head = (l.brown + l.yellow) * 0.5;
  }
  if (!match_->cuePlacementProblem(head)) return head;
  // Rings of growing radius round the head spot, then anywhere it fits.
  for (double radius = kSpotSearchStep; radius < t.def.length; radius += kSpotSearchStep) {
    const int n = std::max(8, static_cast<int>(2.0 * kPi * radius / kSpotSearchStep));
    for (int i = 0; i < n; ++i) {
      const Vec2 p = head + fromAngle(kPi + 2.0 * kPi * i / n) * radius;
      if (!match_->cuePlacementProblem(p)) return p;
    }
  }
  return head;
}

void GameSession::aimAtBallOn() {
  const int on = match_->rack().ballOn();
  const Vec2 cue = cuePosition();
  // Snooker has many balls on, and the lowest-numbered red often stands behind the pink.
  if (gameDef(match_->rack().game()).snookers) {
    if (const auto heading = clearHeadingToBallOn(cue)) {
      cue_.setHeading(*heading);
      return;
    }
  }
  for (const BallState& b : playback_.balls()) {
    if (b.id == on && !b.pocket && length(b.pos - cue) > 0.0) {
      cue_.setHeading(std::atan2(b.pos.y - cue.y, b.pos.x - cue.x));
    }
  }
}

std::optional<double> GameSession::clearHeadingToBallOn(Vec2 cue) const {
  const double r = match_->world().physics().ball_radius;
  const Engine& w = match_->world();
  // The cue ball sent at `aim` (a ghost ball's place) meets `on` before anything else: the aim
  // guide's own trace.
  auto reaches = [&](int on, Vec2 aim) {
    if (length(aim - cue) <= 0.0) return false;
    const AimGuide guide = computeAimGuide(w.table(), r, playback_.balls(), cue,
                                           std::atan2(aim.y - cue.y, aim.x - cue.x));
    return guide.target == AimTarget::Ball && guide.ball == on;
  };
  // The nearest ball on straight at its centre, else the nearest a thin contact reaches (snooker's
  // break-off clips the end red of the triangle).
  for (double offset : {0.0, 1.9, -1.9}) {
    std::optional<double> best;
    double best_distance = 0.0;
    for (int on : match_->rack().legalFirstBalls()) {
      for (const BallState& b : playback_.balls()) {
        if (b.id != on || b.pocket) continue;
        const double d = length(b.pos - cue);
        if (d <= 0.0 || (best && d >= best_distance)) continue;
        const Vec2 aim = b.pos + perp((b.pos - cue) / d) * (offset * r);
        if (!reaches(on, aim)) continue;
        best = std::atan2(aim.y - cue.y, aim.x - cue.x);
        best_distance = d;
      }
    }
    if (best) return best;
  }
  return std::nullopt;
}

bool GameSession::shoot() {
  if (phase_ != Phase::Aiming) return false;
  TurnInput turn;
  turn.kind = push_out_ ? TurnInput::Kind::PushOut : TurnInput::Kind::Shot;
  turn.shot.heading_rad = cue_.heading();
  turn.shot.speed = cue_.speed();
  turn.shot.tip = cue_.tip();
  turn.shot.elevation_rad = cue_.elevation();
  if (turn.kind == TurnInput::Kind::Shot) turn.call = call();
  return shoot(turn);
}

bool GameSession::shoot(const TurnInput& given) {
  if (phase_ != Phase::Aiming || given.kind == TurnInput::Kind::Decision) return false;
  TurnInput turn = given;
  if (practice_) {
    turn.kind = TurnInput::Kind::Shot;
    turn.cue.reset();
    practice_->recordShot(turn.shot);
    rebuildPractice();
    // The replay starts from this position: each practice shot is a rack of its own.
    rack_setup_ = setup_;
    rack_setup_.balls = practice_->table().layout();
  }
  if (!practice_ && turn.kind == TurnInput::Kind::Shot && match_->rack().callRequired() &&
      !turn.call) {
    say(std::string("Call the shot first: click the pocket for the ") + std::to_string(callBall()) +
            (gameDef(match_->rack().game()).call_any_ball ? " (click a ball first to call another)"
                                                          : "") +
            ", or press K to call the obvious shot.",
        render::Tone::Warning);
    return false;
  }
  if (match_->cueInHand()) {
    if (!turn.cue) turn.cue = cue_.spot();
  } else {
    turn.cue.reset();
  }
  if (relay_.prepare && !practice_) {
    const std::optional<TurnInput> relayed = relay_.prepare(turn);
    if (!relayed) return false;
    turn = *relayed;
  }
  ball_on_at_shot_ = match_->rack().ballOn();
  groups_at_shot_ = match_->rack().groups();
  breaking_ = match_->rack().isBreak();
  try {
    match_->beginShot(turn);
  } catch (const IllegalAction& e) {
    say(std::string("Not allowed: ") + e.what() + ".", render::Tone::Warning);
    return false;
  }
  if (relay_.begun && !practice_) relay_.begun(turn);
  if (practice_) rack_turns_.clear();  // each practice shot is a rack of its own
  rack_turns_.push_back(turn);
  if (!practice_) match_turns_.push_back(turn);
  cue_.take(turn.shot.heading_rad, turn.shot.speed, turn.shot.tip, turn.shot.elevation_rad);
  push_out_ = turn.kind == TurnInput::Kind::PushOut;
  if (turn.cue) cue_.setSpot(turn.cue);
  logger("game")->info(
      "{} shoots: heading {:.2f} deg, {:.2f} m/s, tip [{:.2f}, {:.2f}], elevation {:.0f} deg{}",
      seatName(seatToMove()), radToDeg(turn.shot.heading_rad), turn.shot.speed, turn.shot.tip.x,
      turn.shot.tip.y, radToDeg(turn.shot.elevation_rad), push_out_ ? ", push-out" : "");
  phase_ = Phase::Rolling;
  playback_.begin(*match_, shooterBall(), turn.shot.speed);
  playback_.strikeFrom(cuePosition());
  message_.clear();
  return true;
}

bool GameSession::replayAvailable() const {
  return phase_ != Phase::Rolling && ShotReplay::available(rack_turns_);
}

void GameSession::startReplay(bool slow) {
  if (!replayAvailable()) {
    say("No shot to replay yet in this rack.", render::Tone::Warning);
    return;
  }
  try {
    playback_.startReplay(
        std::make_unique<ShotReplay>(rack_setup_, rack_turns_, slow ? kSlowReplay : 1.0));
  } catch (const std::exception& e) {
    // The rack played again should always rebuild; if it ever does not, the game goes on.
    playback_.stopReplay();
    logger("game")->warn("the replay could not be rebuilt: {}", e.what());
    say(std::string("The replay could not be rebuilt: ") + e.what() + ".", render::Tone::Warning);
  }
}

void GameSession::stopReplay() {
  playback_.stopReplay();
}

std::vector<audio::Impact> GameSession::advance(double frame_seconds) {
  std::vector<audio::Impact> impacts;
  if (playback_.advance(frame_seconds, phase_ == Phase::Rolling, *match_, impacts)) finishShot();
  return impacts;
}

double GameSession::shotTime() const {
  return match_->world().time() - playback_.start();
}

void GameSession::finishShot() {
  if (practice_) {
    practice_->finishShot(*this, match_->balls());
    return;
  }
  const TurnRecord record = match_->finishShot();
  afterTurn(record, ball_on_at_shot_);
}

void GameSession::afterTurn(const TurnRecord& record, int ball_on_before) {
  if (observer_) observer_(seatOf(record.shooter), record, breaking_);
  if (breaking_) cue_.setSpeed(kShotSpeed);
  breaking_ = false;
  for (int b : record.verdict.pocketed) {
    const auto& spot = record.verdict.to_spot;
    if (std::find(spot.begin(), spot.end(), b) == spot.end()) pocketed_.push_back(b);
  }
  const auto& events = match_->world().events();
  const rules::ShotSummary summary = play::summarize(events, playback_.shotBall());
  if (record.kind != TurnInput::Kind::Decision) {
    const bool point = record.verdict.points[0] + record.verdict.points[1] > 0;
    last_count_ = "Cushions: " + std::to_string(record.verdict.cushions) +
                  (point ? "   POINT" : "   no point");
  }
  const std::string shooter = seatName(seatOf(record.shooter));
  const std::string opponent = seatName(seatOf(rules::other(record.shooter)));
  const GameDef& game = gameDef(match_->rack().game());
  TurnMessage m = game.family == GameFamily::Carom
                      ? describeCaromTurn(record, match_->rack(), shooter, opponent)
                  : game.snookers ? describeSnookerTurn(record, match_->rack(), shooter, opponent)
                                  : describeTurn(record, summary, ball_on_before, shooter, opponent,
                                                 groups_at_shot_);
  const bool miscue = record.kind != TurnInput::Kind::Decision &&
                      std::any_of(events.begin(), events.end(),
                                  [](const Event& e) { return e.type == EventType::Miscue; });
  if (miscue) m.text = "Miscue! " + m.text;
  say(m.text, m.tone);
  logger("game")->info("turn: {}", m.text);
  if (match_->rack().over()) {
    if (const auto winner = match_->rack().winner()) {
      ++racks_won_[seatOf(*winner)];
      last_winner_seat_ = seatOf(*winner);
    }
    playback_.settle(*match_);
    phase_ = Phase::GameOver;
    return;
  }
  startTurn();
}

void GameSession::decide(bool shoot_now, bool replace) {
  if (phase_ != Phase::PushOutChoice) return;
  if (replace && match_->rack().pendingDecision() != rules::Decision::PlayPutBackOrReplace) return;
  TurnInput turn;
  turn.kind = TurnInput::Kind::Decision;
  turn.shoot = shoot_now && !replace;
  turn.replace = replace;
  if (relay_.prepare) {
    const std::optional<TurnInput> relayed = relay_.prepare(turn);
    if (!relayed) return;
    turn = *relayed;
  }
  groups_at_shot_ = match_->rack().groups();
  const TurnRecord record = match_->play(turn);
  rack_turns_.push_back(turn);
  match_turns_.push_back(turn);
  if (relay_.begun) relay_.begun(turn);
  // A re-rack puts every ball back: the tray of balls down empties with it.
  if (match_->rack().isBreak()) pocketed_.clear();
  afterTurn(record, match_->rack().ballOn());
}

void GameSession::playTurn(const TurnInput& turn) {
  if (practice_) throw IllegalAction("practice has no turns to play from a script");
  if (turn.kind != TurnInput::Kind::Decision &&
      (turn.shot.speed < kMinSpeed || turn.shot.speed > kMaxSpeed)) {
    throw IllegalAction("the cue gives " + formatSpeed(kMinSpeed) + " to " +
                        formatSpeed(kMaxSpeed) + " m/s in the game, not " +
                        formatSpeed(turn.shot.speed));
  }
  nextRackForScript();
  const int ball_on = match_->rack().ballOn();
  groups_at_shot_ = match_->rack().groups();
  breaking_ = match_->rack().isBreak() && turn.kind != TurnInput::Kind::Decision;
  const TurnRecord record = match_->play(turn);
  rack_turns_.push_back(turn);
  match_turns_.push_back(turn);
  afterTurn(record, ball_on);
}

void GameSession::restoreMatch(const MatchSnapshot& snapshot) {
  if (phase_ == Phase::Rolling) return;
  match_->restore(snapshot);
  if (match_->rack().over()) {
    playback_.settle(*match_);
    phase_ = Phase::GameOver;
    return;
  }
  startTurn();
}

std::vector<BallState> GameSession::ballsToDraw() const {
  if (playback_.replaying() || phase_ == Phase::Rolling) {
    return playback_.ballsToDraw(phase_ == Phase::Rolling);
  }
  std::vector<BallState> out = playback_.balls();
  if (cueInHand() && cue_.spot()) {
    for (BallState& b : out) {
      if (b.id == kCueBall) {
        b.pos = *cue_.spot();
        b.backOnTable();
      }
    }
  }
  return out;
}

double GameSession::drawTime() const {
  return playback_.drawTime(phase_ == Phase::Rolling);
}

std::optional<GameSession::Strike> GameSession::strike() const {
  if (phase_ != Phase::Rolling || playback_.replaying()) return std::nullopt;
  return Strike{playback_.struckFrom(), cue_.heading(), power(), drawTime() - playback_.start()};
}

std::string GameSession::status() const {
  const std::string name = seatName(seatToMove());
  if (const ShotReplay* replay = playback_.replay()) {
    return std::string(replay->rate() < 1.0 ? "Slow replay" : "Replay") +
           " of the last shot: any key returns";
  }
  if (practice_) {
    return phase_ == Phase::Rolling
               ? "Practice shot..."
               // The top band names U, Y and 1-9: the status line does not say them twice.
               : "Practice: shoot as ever; Shift+drag moves any ball";
  }
  switch (phase_) {
    case Phase::Rolling:
      return name + " shoots...";
    case Phase::PushOutChoice:
      if (match_->rack().pendingDecision() == rules::Decision::RerackOrPlayOn) {
        return name + ": play on as it lies (S) or re-rack and break (P)?";
      }
      if (match_->rack().pendingDecision() == rules::Decision::PlayOrPutBack) {
        return name + ": play from here (S) or put " + seatName(1 - seatToMove()) + " back in (P)?";
      }
      if (match_->rack().pendingDecision() == rules::Decision::PlayPutBackOrReplace) {
        return name + ": play from here (S), put " + seatName(1 - seatToMove()) +
               " back in (P), or replace the balls (R)?";
      }
      return name + ": play from here (S) or pass it back (P)?";
    case Phase::GameOver: {
      const auto winner = match_->rack().winner();
      if (!winner) return "A draw in game " + std::to_string(rackNumber()) + ". R: rematch";
      if (const auto seat = matchWinner()) {
        const std::string length = gameDef(match_->rack().game()).snookers
                                       ? "best of " + std::to_string(best_of_)
                                       : "race to " + std::to_string(framesToWinMatch(best_of_));
        return seatName(*seat) + " wins the match " + std::to_string(racks_won_[*seat]) + "-" +
               std::to_string(racks_won_[1 - *seat]) + " (" + length + "). R: new match";
      }
      const std::string winner_name = seatName(seatOf(*winner));
      if (best_of_ > 0 && !gameDef(match_->rack().game()).snookers) {
        return winner_name + " wins rack " + std::to_string(rackNumber()) + " (racks " +
               std::to_string(racks_won_[0]) + "-" + std::to_string(racks_won_[1]) + ", race to " +
               std::to_string(framesToWinMatch(best_of_)) + "). R: next rack";
      }
      if (best_of_ > 0) {
        // Frames are never drawn (a tie re-spots the black): those won are those played.
        const int frame = racks_won_[0] + racks_won_[1];
        return winner_name + " wins frame " + std::to_string(frame) + " (frames " +
               std::to_string(racks_won_[0]) + "-" + std::to_string(racks_won_[1]) + ", best of " +
               std::to_string(best_of_) + "). R: next frame";
      }
      const bool carom = gameDef(match_->rack().game()).family == GameFamily::Carom;
      return winner_name + (carom ? " wins game " : " wins rack ") + std::to_string(rackNumber()) +
             ". R: rematch";
    }
    case Phase::Aiming:
      break;
  }
  std::string s = name + " to ";
  if (gameDef(match_->rack().game()).family == GameFamily::Carom) {
    const char* ball = caromBallName(shooterBall());
    s += std::string("play the ") + (ball ? ball : "cue ball");
    if (match_->rack().isBreak()) s += ": the opening shot, straight onto the red";
    return s;
  }
  const GameDef& game = gameDef(match_->rack().game());
  if (match_->rack().isBreak()) {
    s += game.break_area == CueArea::TheD ? "break off (cue ball in hand in the D)"
                                          : "break (cue ball behind the head string)";
  } else if (cueInHand()) {
    s += game.in_hand_area == CueArea::TheD ? "shoot: cue ball in hand in the D, drag it"
                                            : "shoot: ball in hand, drag the cue ball";
  } else {
    s += "shoot";
  }
  if (callRequired()) {
    const auto c = call();
    s += c ? " - called: " + std::to_string(c->ball) + " in " + pocketName(c->pocket)
           : " - call the " + std::to_string(callBall()) + "'s pocket (click it, or K)";
  }
  if (pushOutAvailable()) s += push_out_ ? " - PUSH-OUT" : " - may push out (P)";
  return s;
}

void GameSession::say(const std::string& text, render::Tone tone) {
  message_.say(text, tone);
}

}  // namespace nineball::window
