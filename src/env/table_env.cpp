#include "env/table_env.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "nineball/games.hpp"
#include "nineball/random.hpp"
#include "nineball/table.hpp"

namespace nineball::env {

const char* const kStateNames[kStateSize] = {
    "shooter",       "agent_to_shoot", "ball_in_hand", "behind_head_string", "break",
    "ball_on",       "call_required",  "decision",     "fouls_shooter",      "fouls_other",
    "group_shooter", "score_shooter",  "score_other"};

namespace {

// The pot task's object ball: nine-ball's 1, the ball on.
constexpr int kPotBall = 1;
// The pot task's balls are placed at least this far apart (m), clear of each other.
constexpr double kPotClearance = 0.005;
// A stroke with the cue raised past this (rad, some 6 degrees: a jump or a swerve, never a
// level stroke's rest on the rail) errs in elevation as a level's jump does.
constexpr double kJumpElevationRad = 0.1;

int side(rules::Player p) {
  return p == rules::Player::A ? 0 : 1;
}

// Balls the turn took off the table (the object balls gone from the rack).
int ballsGone(const std::vector<int>& before, const std::vector<int>& after) {
  return static_cast<int>(std::count_if(before.begin(), before.end(), [&](int b) {
    return std::find(after.begin(), after.end(), b) == after.end();
  }));
}

// The pot task's opening: the cue ball and the 1 anywhere on the bed they fit, apart.
std::vector<BallState> randomPot(const TableGeometry& table, double r, std::uint64_t& rng) {
  const TableDef& def = table.def;
  auto place = [&] {
    for (;;) {
      const Vec2 p{uniform(rng, -def.length / 2 + r, def.length / 2 - r),
                   uniform(rng, -def.width / 2 + r, def.width / 2 - r)};
      if (table.ballFits(p, r)) return p;
    }
  };
  BallState cue;
  cue.id = kCueBall;
  cue.pos = place();
  BallState object;
  object.id = kPotBall;
  do {
    object.pos = place();
  } while (length(object.pos - cue.pos) < 2.0 * r + kPotClearance);
  return {cue, object};
}

}  // namespace

EnvSpec EnvSpec::named(const std::string& name, const std::optional<std::string>& opponent,
                       const std::string& noise, const std::string& engine) {
  EnvSpec spec;
  spec.name = name;
  MatchSetup setup;
  if (name != "pot") {
    spec.game = rules::gameFromName(name);
    if (!spec.game) {
      throw std::invalid_argument("name: unknown environment \"" + name +
                                  "\" (expected \"pot\" or a game)");
    }
    setup.setGame(*spec.game);
  } else {
    setup.setGame(rules::Game::NineBall);
  }
  spec.table = setup.table;
  spec.physics = setup.physics;
  spec.step = setup.step;
  const std::optional<EngineKind> kind = EngineKind::fromName(engine);
  if (!kind) {
    std::string names;
    for (const std::string& n : EngineKind::names()) names += (names.empty() ? "" : ", ") + n;
    throw std::invalid_argument("engine: unknown engine \"" + engine + "\" (expected " + names +
                                ")");
  }
  spec.step.engine = *kind;
  if (opponent) {
    spec.opponent = ai::levelFromName(*opponent);
    if (!spec.opponent) {
      throw std::invalid_argument("opponent: unknown level \"" + *opponent + "\" (expected " +
                                  ai::levelNamesText() + ")");
    }
    if (!spec.game) throw std::invalid_argument("opponent: the pot task has no opponent");
  }
  const std::optional<ai::LevelSettings> cueing = ai::cueingNamed(noise);
  if (!cueing) {
    std::string names;
    for (const std::string& n : ai::cueingNames()) names += (names.empty() ? "" : ", ") + n;
    throw std::invalid_argument("noise: unknown model \"" + noise + "\" (expected " + names + ")");
  }
  spec.noise = noise;
  spec.cueing = *cueing;
  return spec;
}

TableEnv::TableEnv(EnvSpec spec) : spec_(std::move(spec)) {
  // The observation's rows: every ball of the game's rack, however many a position has left.
  if (spec_.game) {
    MatchSetup setup;
    setup.setGame(*spec_.game);
    setup.table = spec_.table;
    for (const BallState& b : setup.openingBalls()) ids_.push_back(b.id);
    if (std::find(ids_.begin(), ids_.end(), kCueBall) == ids_.end()) ids_.push_back(kCueBall);
  } else {
    ids_ = {kCueBall, kPotBall};
  }
  std::sort(ids_.begin(), ids_.end());
  geometry_ = std::make_unique<TableGeometry>(buildTable(spec_.table, spec_.physics.ball_radius));
  reset(1);
}

TableEnv::~TableEnv() = default;
TableEnv::TableEnv(TableEnv&&) noexcept = default;
TableEnv& TableEnv::operator=(TableEnv&&) noexcept = default;

rules::Player TableEnv::agentSide() const {
  return spec_.opponent ? rules::Player::A : match_->rack().shooter();
}

void TableEnv::reset(std::uint64_t seed, const std::optional<MatchSetup>& start) {
  rng_ = seed * 0x9E3779B97F4A7C15ull + 0x6a09e667f3bcc909ull;
  turns_ = 0;
  over_ = false;
  MatchSetup setup;
  if (start) {
    if (!spec_.game || start->game != *spec_.game) {
      throw std::invalid_argument("start: a position of " + spec_.name + " only");
    }
    for (const BallState& b : start->balls.value_or(std::vector<BallState>{})) {
      if (std::find(ids_.begin(), ids_.end(), b.id) == ids_.end()) {
        throw std::invalid_argument("balls: " + std::to_string(b.id) + " is not a ball of " +
                                    spec_.name);
      }
    }
    setup = *start;
    setup.table = spec_.table;
    setup.physics = spec_.physics;
    setup.step = spec_.step;
  } else {
    setup.setGame(spec_.game.value_or(rules::Game::NineBall));
    setup.table = spec_.table;
    setup.physics = spec_.physics;
    setup.step = spec_.step;
    setup.seed = splitmix64(rng_) % 1000000007ull;
    if (!spec_.game) setup.balls = randomPot(*geometry_, setup.physics.ball_radius, rng_);
  }
  match_ = std::make_unique<Match>(setup);
  if (spec_.opponent) {
    opponent_ = std::make_unique<ai::Planner>(*spec_.opponent, splitmix64(rng_), 1);
  }
  // The agent is A: when B is to shoot first, the computer plays until A's turn comes.
  if (opponent_) {
    while (!match_->rack().over() && match_->rack().shooter() != rules::Player::A) {
      match_->play(opponent_->turnFor(*match_));
    }
    over_ = match_->rack().over();
  }
}

ai::StrokeDifficulty TableEnv::difficultyOf(const Shot& shot) const {
  ai::StrokeDifficulty d;
  const std::vector<BallState> balls = match_->balls();
  const int cue_id = match_->rack().cueBall();
  const auto cue =
      std::find_if(balls.begin(), balls.end(), [&](const BallState& b) { return b.id == cue_id; });
  if (cue == balls.end() || cue->pocket) return d;
  const double r2 = 2.0 * spec_.physics.ball_radius;
  const Vec2 dir = fromAngle(shot.heading_rad);
  double nearest = INFINITY;
  for (const BallState& b : balls) {
    if (b.id == cue_id || b.pocket) continue;
    // Where the cue ball's straight path first touches b, if it does.
    const Vec2 to = b.pos - cue->pos;
    const double along = dot(to, dir);
    const double off2 = dot(to, to) - along * along;
    if (along <= 0.0 || off2 >= r2 * r2) continue;
    const double travel = along - std::sqrt(r2 * r2 - off2);
    if (travel < nearest) {
      nearest = travel;
      d.reach_m = std::max(0.0, travel);
      d.cut_deg = radToDeg(std::asin(std::sqrt(off2) / r2));
    }
  }
  return d;
}

std::optional<std::string> TableEnv::actionProblem(const Action& action) const {
  if (over_) return "the episode is over: reset the environment";
  const rules::Rack& rack = match_->rack();
  if (rack.awaitingDecision() && action.kind != TurnInput::Kind::Decision) {
    return "a decision is due (\"decision\")";
  }
  if (!rack.awaitingDecision() && action.kind == TurnInput::Kind::Decision) {
    return "no decision is due: play a stroke";
  }
  if (action.kind == TurnInput::Kind::Decision) return std::nullopt;
  if (action.cue) {
    if (!match_->cueInHand()) return "the cue ball is not in hand: no \"cue\"";
    if (auto problem = match_->cuePlacementProblem(*action.cue)) return "cue: " + *problem;
  } else if (match_->cueMustBePlaced()) {
    return "the cue ball is in hand: place it (\"cue\")";
  }
  if (rack.callRequired() && !action.call) return "the shot must be called (\"call\")";
  return std::nullopt;
}

StepOutcome TableEnv::step(const Action& action) {
  if (auto problem = actionProblem(action)) throw IllegalAction(*problem);
  StepOutcome out;
  const rules::Player shooter = match_->rack().shooter();
  const rules::Game game = match_->rack().game();
  const std::vector<int> before = match_->rack().ballsOnTable();
  const int score_before = match_->rack().score(shooter);
  out.executed = action;
  if (action.kind != TurnInput::Kind::Decision) {
    ai::StrokeDifficulty d = difficultyOf(action.shot);
    d.is_break = match_->rack().isBreak();
    d.is_jump = action.shot.elevation_rad > kJumpElevationRad;
    out.executed.shot = ai::executeStroke(action.shot, spec_.cueing, d, spec_.physics, rng_);
  }
  const TurnRecord record = match_->play(out.executed);
  ++turns_;
  out.legal = record.verdict.legal();
  if (action.kind != TurnInput::Kind::Decision) {
    out.potted = ballsGone(before, match_->rack().ballsOnTable());
    if (gameDef(game).keepsScore()) {
      out.reward += spec_.rewards.point * (match_->rack().score(shooter) - score_before);
    } else if (out.legal) {
      out.reward += spec_.rewards.pot * out.potted;
    }
    if (!out.legal) out.reward += spec_.rewards.foul;
  }
  if (!spec_.game) {
    over_ = true;
  } else if (opponent_) {
    while (!match_->rack().over() && match_->rack().shooter() != rules::Player::A) {
      match_->play(opponent_->turnFor(*match_));
      ++out.opponent_turns;
    }
  }
  if (spec_.game && match_->rack().over()) {
    over_ = true;
    out.winner = match_->rack().winner();
    if (out.winner) out.reward += *out.winner == shooter ? spec_.rewards.win : spec_.rewards.loss;
  }
  out.terminated = over_;
  out.truncated = !over_ && turns_ >= spec_.max_turns;
  return out;
}

Action TableEnv::completed(Action action) const {
  const rules::Rack& rack = match_->rack();
  if (rack.awaitingDecision()) {
    Action decision;
    decision.kind = TurnInput::Kind::Decision;
    decision.shoot = true;  // take the table (play on)
    return decision;
  }
  if (!action.cue && match_->cueMustBePlaced()) action.cue = teacher(ai::Level::Beginner).cue;
  if (!action.call && rack.callRequired()) action.call = teacher(ai::Level::Beginner).call;
  return action;
}

Action TableEnv::teacher(ai::Level level) const {
  ai::Planner planner(level, rng_, 1);
  return planner.plan(ai::planInputFrom(*match_)).turn;
}

void TableEnv::observe(double* places, std::uint8_t* on_table, double* state) const {
  const std::vector<BallState> balls = match_->balls();
  for (std::size_t i = 0; i < ids_.size(); ++i) {
    const auto b = std::find_if(balls.begin(), balls.end(),
                                [&](const BallState& s) { return s.id == ids_[i]; });
    const bool on = b != balls.end() && !b->pocket;
    on_table[i] = on ? 1 : 0;
    places[2 * i] = on ? b->pos.x : 0.0;
    places[2 * i + 1] = on ? b->pos.y : 0.0;
  }
  const rules::Rack& rack = match_->rack();
  const rules::Player s = rack.shooter();
  const std::optional<rules::Group> group = rack.groups().of(s);
  const double values[kStateSize] = {static_cast<double>(side(s)),
                                     s == agentSide() ? 1.0 : 0.0,
                                     match_->cueInHand() ? 1.0 : 0.0,
                                     match_->cueBehindHeadString() ? 1.0 : 0.0,
                                     rack.isBreak() ? 1.0 : 0.0,
                                     static_cast<double>(rack.ballOn()),
                                     rack.callRequired() ? 1.0 : 0.0,
                                     static_cast<double>(static_cast<int>(rack.pendingDecision())),
                                     static_cast<double>(rack.consecutiveFouls(s)),
                                     static_cast<double>(rack.consecutiveFouls(rules::other(s))),
                                     group ? (*group == rules::Group::Solids ? 1.0 : 2.0) : 0.0,
                                     static_cast<double>(rack.score(s)),
                                     static_cast<double>(rack.score(rules::other(s)))};
  std::copy(values, values + kStateSize, state);
}

}  // namespace nineball::env
