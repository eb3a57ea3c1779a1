#include "nineball/match.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "nineball/carom_rack.hpp"
#include "nineball/games.hpp"
#include "nineball/scenes.hpp"
#include "nineball/sim.hpp"
#include "nineball/snooker_rack.hpp"
#include "play/jump_shot.hpp"
#include "play/shot_summary.hpp"
#include "play/snookered.hpp"
#include "rules/snooker_balls.hpp"

namespace nineball {

void MatchSetup::setGame(rules::Game g) {
  const GameDef& def = gameDef(g);
  game = g;
  rules = def.rule_sets.front();
  // Every game's table and preset are built in (tests/games/registry_test.cpp holds it).
  table = TableDef::named(def.tables.front()).value();
  physics = PhysicsParams::preset(def.physics).value();
  points = def.default_points;
}

namespace {

// Spotting walks the long axis in steps this small (m) looking for room.
constexpr double kSpotStep = 0.0005;
// A cue ball exactly on the head string counts as behind it.
constexpr double kLineTolerance = 1e-9;

std::vector<int> objectBalls(const std::vector<BallState>& balls) {
  std::vector<int> ids;
  for (const BallState& b : balls) {
    if (b.id != kCueBall && !b.pocket) ids.push_back(b.id);
  }
  return ids;
}

bool holdsCueBall(const std::vector<BallState>& balls) {
  return std::any_of(balls.begin(), balls.end(),
                     [](const BallState& b) { return b.id == kCueBall; });
}

// A carom ball rests touching the shooter's (UMB art. 27: the balls are set up again).
bool frozenTo(const Engine& world, int cue) {
  const double touching = 2.0 * world.physics().ball_radius + 1e-6;
  const std::vector<BallState> balls = world.balls();
  for (const BallState& b : balls) {
    if (b.id != cue) continue;
    for (const BallState& o : balls) {
      if (o.id != cue && !o.pocket && length(o.pos - b.pos) <= touching) return true;
    }
  }
  return false;
}

}  // namespace

Score scoreOf(const rules::Rack& rack) {
  Score s;
  for (rules::Player p : {rules::Player::A, rules::Player::B}) {
    PlayerScore& one = p == rules::Player::A ? s.a : s.b;
    one.points = rack.score(p);
    one.innings = rules::innings(rack, p);
    one.high_run = rules::highRun(rack, p);
    one.run = !rack.over() && rack.shooter() == p ? rack.currentRun() : 0;
  }
  return s;
}

std::vector<BallState> MatchSetup::openingBalls() const {
  std::vector<BallState> opening = rackFor(game, table, physics.ball_radius, seed);
  if (!holdsCueBall(opening)) {
    opening.insert(
        opening.begin(),
        BallState::at(kCueBall, {buildTable(table, physics.ball_radius).headStringX(), 0.0}));
  }
  return opening;
}

Match::Match(const MatchSetup& setup)
    : setup_(setup),
      world_(makeEngine(setup.table, setup.physics, setup.step)),
      rack_(setup.game, setup.rules, {}, !setup.balls) {
  const std::string table_problem = tableProblem(gameDef(setup.game), setup.table);
  if (!table_problem.empty()) throw IllegalAction(table_problem);
  if (setup.opener != rules::Player::A && gameDef(setup.game).family == GameFamily::Carom) {
    throw IllegalAction(std::string(gameDef(setup.game).name) +
                        " is opened by A, who plays the white");
  }
  std::vector<BallState> balls;
  if (setup.balls) {
    balls = *setup.balls;
  } else {
    balls = setup.openingBalls();
  }
  cue_pocketed_ = true;
  for (const BallState& b : balls) {
    world_->addBall(b);
    if (b.id == kCueBall && !b.pocket) cue_pocketed_ = false;
  }
  if (cue_pocketed_ && std::none_of(balls.begin(), balls.end(),
                                    [](const BallState& b) { return b.id == kCueBall; })) {
    BallState cue;
    cue.id = kCueBall;
    cue.pos = {world_->table().headStringX(), 0.0};
    cue.pocket = PocketId::TopLeft;  // off the table until placed
    world_->addBall(cue);
  }
  rack_ = rules::Rack(setup.game, setup.rules, objectBalls(balls), !setup.balls);
  rack_.setTargetPoints(setup.points);
  rack_.setOpener(setup.opener);
  if (setup.standing) joinStanding(*setup.standing);
}

// The rack's state as `standing` says, checked against what the game can be in.
void Match::joinStanding(const RackStanding& standing) {
  const GameDef& def = gameDef(rack_.game());
  if (!setup_.balls) throw IllegalAction("a rack's standing needs its balls");
  if (standing.ball_in_hand && !def.cue_in_hand) {
    throw IllegalAction(std::string(def.name) + " has no ball in hand");
  }
  if ((standing.groups.a || standing.groups.b) && !def.groups) {
    throw IllegalAction(std::string(def.name) + " has no groups");
  }
  if (standing.groups.a.has_value() != standing.groups.b.has_value() ||
      (standing.groups.a && *standing.groups.a == *standing.groups.b)) {
    throw IllegalAction("groups: each player takes the group the other does not");
  }
  for (const int f : standing.fouls) {
    if (f < 0 || f > 2) throw IllegalAction("fouls: a count of 0, 1 or 2 (three lose the rack)");
  }
  const bool scored = standing.score[0] != 0 || standing.score[1] != 0;
  if (scored && !def.keepsScore()) {
    throw IllegalAction(std::string(def.name) + " keeps no score");
  }
  for (const int points : standing.score) {
    if (points < 0 || (rack_.targetPoints() > 0 && points >= rack_.targetPoints())) {
      throw IllegalAction("score: from 0 to less than the distance played to");
    }
  }
  rules::RackState s = rack_.state();
  s.shooter = standing.shooter;
  s.ball_in_hand = standing.ball_in_hand;
  s.fouls[0] = standing.fouls[0];
  s.fouls[1] = standing.fouls[1];
  s.groups = standing.groups;
  s.score[0] = standing.score[0];
  s.score[1] = standing.score[1];
  rack_.setState(s);
}

Match::~Match() = default;

bool Match::cueInHand() const {
  if (!gameDef(rack_.game()).cue_in_hand) return false;
  return rack_.isBreak() || rack_.ballInHand() || cue_pocketed_;
}

bool Match::cueBehindHeadString() const {
  return rack_.isBreak() && gameDef(rack_.game()).break_area == CueArea::BehindHeadString;
}

CueArea Match::cueArea() const {
  const GameDef& def = gameDef(rack_.game());
  return rack_.isBreak() ? def.break_area : def.in_hand_area;
}

bool Match::cueMustBePlaced() const {
  return cue_pocketed_ || (cueInHand() && cueArea() == CueArea::TheD);
}

bool Match::cueSnookered() const {
  const std::vector<BallState> balls = world_->balls();
  const auto cue =
      std::find_if(balls.begin(), balls.end(), [](const BallState& b) { return b.id == kCueBall; });
  if (cue == balls.end() || cue->pocket) return false;
  return play::snookered(cue->pos, rack_.legalFirstBalls(), balls, world_->physics().ball_radius);
}

std::optional<std::string> Match::cuePlacementProblem(Vec2 pos) const {
  if (!std::isfinite(pos.x) || !std::isfinite(pos.y)) return "the cue position is not a number";
  const double r = world_->physics().ball_radius;
  if (!world_->table().ballFits(pos, r)) return "the cue ball would be off the table";
  if (cueBehindHeadString() && pos.x > world_->table().headStringX() + kLineTolerance) {
    return "on the break the cue ball goes behind the head string (x <= " +
           std::to_string(world_->table().headStringX()) + ")";
  }
  if (cueArea() == CueArea::TheD && !inCueArea(CueArea::TheD, world_->table().def, pos)) {
    return "the cue ball in hand goes " + cueAreaText(CueArea::TheD, world_->table().def);
  }
  for (const BallState& b : world_->balls()) {
    if (b.id == kCueBall || b.pocket) continue;
    if (length(b.pos - pos) < 2.0 * r - 1e-7) {
      return "the cue ball would be on ball " + std::to_string(b.id);
    }
  }
  return std::nullopt;
}

void Match::placeCue(Vec2 pos) {
  world_->placeBall(kCueBall, pos);
  cue_pocketed_ = false;
}

Vec2 Match::freeSpotOnLine(Vec2 from, Vec2 step_dir) const {
  const double r = world_->physics().ball_radius;
  const auto balls = world_->balls();
  for (int dir : {1, -1}) {
    for (Vec2 p = from; world_->table().insideLoop(p); p += step_dir * (dir * kSpotStep)) {
      bool ok = world_->table().ballFits(p, r);
      for (const BallState& b : balls) {
        if (b.pocket) continue;
        ok = ok && length(b.pos - p) >= 2.0 * r;
      }
      if (ok) return p;
    }
  }
  return from;
}

void Match::spot(int ball) {
  if (const SpotFinder finder = gameDef(rack_.game()).spot) {
    world_->placeBall(
        ball, finder(ball, world_->table(), world_->physics().ball_radius, world_->balls()));
    rack_.respot(ball);
    return;
  }
  // WPA: on the foot spot, or as close behind it on the long axis as it fits.
  const Vec2 p = freeSpotOnLine(world_->table().footSpot(), {1.0, 0.0});
  world_->placeBall(ball, p);
  rack_.respot(ball);
}

void Match::rerack() {
  // The same rack as at the start (same seed), the cue ball back in hand on the head string.
  for (const BallState& b :
       rackFor(setup_.game, setup_.table, setup_.physics.ball_radius, setup_.seed)) {
    world_->placeBall(b.id, b.pos);
  }
  placeCue({world_->table().headStringX(), 0.0});
}

void Match::returnCueToHeadSpot() {
  const Vec2 head{world_->table().headStringX(), 0.0};
  placeCue(freeSpotOnLine(head, {-1.0, 0.0}));
}

void Match::beginShot(const TurnInput& turn) {
  if (in_progress_) throw IllegalAction("a shot is still rolling");
  if (rack_.over()) throw IllegalAction("the game is over");
  if (turn.kind == TurnInput::Kind::Decision) {
    throw IllegalAction("a decision is not a shot");
  }
  if (rack_.pendingDecision() == rules::Decision::RerackOrPlayOn) {
    throw IllegalAction("the illegal break waits for the opponent's decision (play on or rerack)");
  }
  if (rack_.pendingDecision() == rules::Decision::PlayOrPutBack ||
      rack_.pendingDecision() == rules::Decision::PlayPutBackOrReplace) {
    throw IllegalAction(
        "the foul waits for the opponent's decision (play or put-back, after a miss also "
        "replace)");
  }
  if (rack_.awaitingDecision()) {
    throw IllegalAction(gameDef(rack_.game()).pot_not_as_called_passes
                            ? "the turn waits for the opponent's decision (shoot or pass)"
                            : "the push-out waits for the opponent's decision (shoot or pass)");
  }
  const bool push_out = turn.kind == TurnInput::Kind::PushOut;
  const GameDef& game = gameDef(rack_.game());
  if (push_out && !game.push_outs) {
    throw IllegalAction(std::string(game.name) + " has no push-out");
  }
  if (push_out && !rack_.pushOutAvailable()) {
    throw IllegalAction("no push-out is allowed now: only on the shot just after the break");
  }
  if (turn.call && !game.takes_calls) {
    throw IllegalAction(std::string(game.name) + " takes no call: \"call\" is for " +
                        gamesTakingCalls());
  }
  if (turn.call && game.snookers && !rack_.isBreak()) {
    if (const auto problem = rules::snooker::nominationProblem(rack_.state(), turn.call->ball)) {
      throw IllegalAction(*problem);
    }
  }
  if (!push_out && rack_.callRequired() && !turn.call) {
    throw IllegalAction(std::string("every ") + gameDef(rack_.game()).called_shots + " in " +
                        gameDef(rack_.game()).name +
                        " is called: the turn needs \"call\": {\"ball\", \"pocket\"}");
  }
  if (turn.call && !rack_.isBreak()) {
    const auto& on = rack_.ballsOnTable();
    if (std::find(on.begin(), on.end(), turn.call->ball) == on.end()) {
      throw IllegalAction("the called ball " + std::to_string(turn.call->ball) +
                          " is not on the table");
    }
  }
  if (turn.cue) {
    if (!cueInHand()) throw IllegalAction("the cue ball is not in hand");
    if (auto problem = cuePlacementProblem(*turn.cue)) throw IllegalAction(*problem);
    placeCue(*turn.cue);
  } else if (cue_pocketed_ && cueArea() != CueArea::TheD) {
    throw IllegalAction("ball in hand after a scratch: the turn must place the cue ball (\"cue\")");
  } else if (cueMustBePlaced()) {
    throw IllegalAction("the cue ball is in hand " + cueAreaText(cueArea(), world_->table().def) +
                        ": the turn must place it (\"cue\")");
  }
  // Snooker's miss, touching ball and jump shot are judged on the balls as they lie before the
  // stroke, and a miss may have them put back there.
  if (game.snookers || game.jump_shot_foul) before_shot_ = world_->balls();
  if (game.snookers) {
    snookered_before_ = cueSnookered();
    for (const BallState& b : before_shot_) {
      if (b.id == kCueBall) {
        touching_before_ = play::touchingBalls(b.pos, before_shot_, world_->physics().ball_radius);
      }
    }
  }
  ball_on_at_start_ = rack_.ballOn();
  push_out_ = push_out;
  call_ = turn.call;
  world_->clearEvents();
  cue_ = rack_.cueBall();
  world_->strike(cue_, turn.shot);
  shot_deadline_ = world_->time() + setup_.step.max_time;
  in_progress_ = true;
}

bool Match::stepShot() {
  if (!in_progress_) throw IllegalAction("no shot is rolling");
  return world_->stepTowardRest(shot_deadline_);
}

TurnRecord Match::finishShot() {
  if (!in_progress_) throw IllegalAction("no shot is rolling");
  while (!stepShot()) {
  }
  in_progress_ = false;
  rules::ShotSummary summary = play::summarize(world_->events(), cue_);
  summary.call = call_;
  summary.snookered_before = snookered_before_;
  summary.touching_before = touching_before_;
  if (gameDef(rack_.game()).jump_shot_foul) {
    summary.jumped_over =
        play::ballsJumpedOver(world_->events(), before_shot_, world_->physics().ball_radius, cue_);
  }
  TurnRecord rec;
  rec.call = call_;
  rec.shooter = rack_.shooter();
  rec.kind = push_out_ ? TurnInput::Kind::PushOut : TurnInput::Kind::Shot;
  rec.verdict = rack_.shoot(summary, push_out_);
  // WPBSA 3.7(b): when several colours are spotted the highest value takes precedence.
  std::vector<int> to_spot = rec.verdict.to_spot;
  std::sort(to_spot.rbegin(), to_spot.rend());
  for (int b : to_spot) spot(b);
  const bool cue_spotted = std::find(to_spot.begin(), to_spot.end(), cue_) != to_spot.end();
  if (summary.cue_pocketed && !cue_spotted) {
    if (rec.verdict.cue_to_head_spot) {
      returnCueToHeadSpot();
    } else {
      cue_pocketed_ = true;
    }
  }
  if (!rack_.over() && !gameDef(rack_.game()).cue_in_hand && frozenTo(*world_, rack_.cueBall())) {
    setUpFrozenBalls();
  }
  if (gameDef(rack_.game()).snookers && rack_.awaitingDecision()) {
    // WPBSA 3.12: after a foul the incoming striker snookered on every ball on gets a free
    // ball. With the cue ball in hand (in the D) nineball never states one.
    rules::stateFreeBall(rack_, !cue_pocketed_ && cueSnookered());
  }
  rec.ball_on = rack_.ballOn();
  rec.score = scoreOf(rack_);
  rec.points_remaining = rack_.pointsRemaining();
  rec.free_ball_next = rules::freeBall(rack_);
  return rec;
}

void Match::replaceBalls() {
  for (const BallState& b : before_shot_) {
    if (!b.pocket) world_->placeBall(b.id, b.pos);
  }
  cue_pocketed_ = false;
}

void Match::setUpFrozenBalls() {
  // UMB art. 27: the balls go back to the opening position, the shooter's ball on the
  // starting spot and the other's on the bottom spot, and the shot is played as the opening
  // one (straight onto the red).
  const std::vector<BallState> opening =
      rackFor(setup_.game, setup_.table, setup_.physics.ball_radius, setup_.seed);
  const int shooter = rack_.cueBall();
  for (const BallState& b : opening) {
    // The opener's spot takes the shooter's ball, and the shooter's spot the opener's.
    const int id = b.id == kCueBall ? shooter : b.id == shooter ? kCueBall : b.id;
    world_->placeBall(id, b.pos);
  }
  rules::replayOpening(rack_);
}

TurnRecord Match::play(const TurnInput& turn) {
  if (turn.kind == TurnInput::Kind::Decision) {
    if (rack_.over()) throw IllegalAction("the game is over");
    const GameDef& game = gameDef(rack_.game());
    if (!game.decisions) throw IllegalAction(game.decision.about);
    if (!rack_.awaitingDecision()) {
      throw IllegalAction(std::string("no decision is due now (") + game.decision.about + ")");
    }
    TurnRecord rec;
    rec.kind = TurnInput::Kind::Decision;
    rec.shooter = rack_.shooter();
    rec.answered = rack_.pendingDecision();
    rec.shoot = turn.shoot && !turn.replace;
    rec.replace = turn.replace;
    if (turn.replace) {
      if (rack_.pendingDecision() != rules::Decision::PlayPutBackOrReplace) {
        throw IllegalAction("only a miss lets the balls be replaced");
      }
      replaceBalls();
      rules::replaceAfterMiss(rack_);
    } else {
      rack_.decide(turn.shoot);
    }
    if (rack_.isBreak()) rerack();
    rec.verdict.shooter = rec.shooter;
    rec.verdict.next = rack_.shooter();
    rec.ball_on = rack_.ballOn();
    rec.score = scoreOf(rack_);
    rec.points_remaining = rack_.pointsRemaining();
    rec.free_ball_next = rules::freeBall(rack_);
    return rec;
  }
  beginShot(turn);
  return finishShot();
}

}  // namespace nineball
