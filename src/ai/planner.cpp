// The search: generate candidates, simulate each, re-simulate the best with small errors in
// aim and speed, and keep the shot whose outcomes are worth most on average.
#include "nineball/planner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "ai/carom/carom_planner.hpp"
#include "ai/planner_candidates.hpp"
#include "ai/planner_evaluate.hpp"
#include "ai/planner_geometry.hpp"
#include "ai/planner_lookahead.hpp"
#include "ai/planner_robust.hpp"
#include "common/log.hpp"
#include "common/parallel_map.hpp"
#include "nineball/random.hpp"

namespace nineball::ai {
namespace {

// A shot worth this much to the shooter is as good as what the opponent would get from the
// same position: the line between shooting and passing after a push-out.
constexpr double kEven = 0.5;
// Below this best worth the aimed shots leave the opponent an easy shot or foul: sweep every
// direction too.
constexpr double kSweepBelow = 0.3;
// The break is chaotic: averaging a few candidates over cueing errors is all that helps, and
// each break costs as much as many ordinary shots.
constexpr int kBreakRobustTop = 4;
// A level judges what a position leaves by its own cueing: this multiple of its aim error,
// and never finer than the floor (degrees).
constexpr double kJudgingAimOfNoise = 1.5;
constexpr double kMinJudgingAimDeg = 0.15;
// The break aims at a whole rack: a player errs far less there than on a pot.
constexpr double kBreakNoiseScale = 1.0 / 3.0;
// Executed speeds stay within what a cue can give (m/s).
constexpr double kMinExecutedSpeed = 0.05;
constexpr double kMaxExecutedSpeed = 13.0;
// A controlled break's speed (m/s), offered to a planner breaking under the whole noise.
constexpr double kControlledBreakSpeed = 6.5;
// The cue's tilt a noisy stroke can reach (the window allows 60 degrees).
constexpr double kMaxExecutedElevationDeg = 60.0;

std::vector<Candidate> candidatesFor(const SearchContext& ctx, const Evaluator& eval) {
  const BallState* cue = findOnTable(ctx.in.balls, kCueBall);
  if (ctx.in.cue_in_hand || !cue) {
    return ctx.in.rack.isBreak() ? breakShots(ctx, eval) : inHandShots(ctx, eval);
  }
  return shotsFrom(ctx, ctx.in.balls, cue->pos, std::nullopt);
}

// Candidates best first by their simulated worth, then by how promising they looked.
std::vector<std::size_t> ranking(const std::vector<Candidate>& cands,
                                 const std::vector<double>& values) {
  std::vector<std::size_t> order(cands.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (values[a] != values[b]) return values[a] > values[b];
    return cands[a].prior > cands[b].prior;
  });
  return order;
}

// Simulates the next shot after the best candidates that keep the table (position play by
// simulation rather than geometry); their worth and gains are updated. Returns the shots taken.
long lookFurther(const SearchContext& ctx, const Evaluator& eval,
                 const std::vector<Candidate>& cands, std::vector<double>& values,
                 std::vector<double>& gains, int threads) {
  std::vector<std::size_t> picked;
  for (std::size_t i : ranking(cands, values)) {
    if (static_cast<int>(picked.size()) >= ctx.level.lookahead_top) break;
    if (values[i] >= kContinueBase && values[i] < 1.0) picked.push_back(i);
  }
  std::vector<LookAhead> found(picked.size());
  parallelFor(picked.size(), threads,
              [&](std::size_t k) { found[k] = lookAhead(ctx, eval, cands[picked[k]]); });
  long sims = 0;
  for (std::size_t k = 0; k < picked.size(); ++k) {
    gains[picked[k]] = found[k].value - values[picked[k]];
    values[picked[k]] = found[k].value;
    sims += found[k].simulations;
  }
  return sims;
}

// The stroke's cut and reach (Plan::cut_deg, reach_m): from where the cue ball is struck, along
// the heading, to the first ball when it is aimed at directly.
void measureStroke(const PlanInput& in, double ball_radius, Plan& plan) {
  if (plan.kind == ShotKind::Break || plan.kind == ShotKind::Kick || plan.first == 0) return;
  const BallState* cue = findOnTable(in.balls, kCueBall);
  const BallState* first = findOnTable(in.balls, plan.first);
  if (!first || (!plan.turn.cue && !cue)) return;
  const Vec2 from = plan.turn.cue ? *plan.turn.cue : cue->pos;
  const Vec2 to_first = first->pos - from;
  const Vec2 heading{std::cos(plan.turn.shot.heading_rad), std::sin(plan.turn.shot.heading_rad)};
  const double along = dot(to_first, heading);
  const double offset = std::abs(cross(heading, to_first));
  if (along <= 0.0 || offset >= 2.0 * ball_radius) return;
  plan.cut_deg = radToDeg(std::asin(offset / (2.0 * ball_radius)));
  plan.reach_m = std::max(0.0, length(to_first) - 2.0 * ball_radius);
}

// How much larger than on an easy stroke the heading's error is on this one.
double aimGrowth(const LevelSettings& s, const StrokeDifficulty& d, double speed) {
  const double sin_cut = std::sin(degToRad(d.cut_deg));
  const double pace = std::max(0.0, speed / kPaceReference - 1.0);
  return (1.0 + s.cut_growth * sin_cut * sin_cut) * (1.0 + s.reach_growth * d.reach_m) *
         (1.0 + s.pace_growth * pace);
}

StrokeDifficulty difficultyOf(const Plan& plan) {
  StrokeDifficulty d;
  d.cut_deg = plan.cut_deg;
  d.reach_m = plan.reach_m;
  d.is_break = plan.kind == ShotKind::Break;
  d.is_jump = plan.kind == ShotKind::Jump;
  return d;
}

// A break under the whole noise (the tournaments') is judged by striking each candidate that
// many times with that very noise, from a fixed seed, and averaging the outcomes: the
// robustness check's grid of aim and speed errors misses what the tip's and the elevation's
// errors do to a rack, and favoured the hardest breaks, which pocket a ball least often under
// them. (Judging every shot so instead of by the grid cleared fewer racks: 21 of 100, not 26.)
constexpr int kNoisySamples = 24;
constexpr std::uint64_t kNoisySeed = 0x6e6f697379627265;  // fixed: plans stay repeatable
constexpr StrokeDifficulty kBreakStroke{0.0, 0.0, true, false};

// `ranked`: every break candidate, best first (ties go to the better ranked).
RobustChoice chooseBreakUnderNoise(const std::vector<Candidate>& cands,
                                   const std::vector<std::size_t>& ranked, const Evaluator& eval,
                                   const LevelSettings& s, const PhysicsParams& physics,
                                   int threads) {
  const std::size_t n = ranked.size() * kNoisySamples;
  std::vector<double> worth(n, 0.0);
  parallelFor(n, threads, [&](std::size_t j) {
    const Candidate& c = cands[ranked[j / kNoisySamples]];
    std::uint64_t rng = kNoisySeed + j % kNoisySamples;
    worth[j] = eval.value(c, executeStroke(c.shot, s, kBreakStroke, physics, rng));
  });
  RobustChoice best;
  best.simulations = static_cast<long>(n);
  best.value = -1.0;
  for (std::size_t r = 0; r < ranked.size(); ++r) {
    double sum = 0.0;
    for (int k = 0; k < kNoisySamples; ++k) {
      sum += worth[r * kNoisySamples + static_cast<std::size_t>(k)];
    }
    const double expected = sum / kNoisySamples;
    if (expected > best.value) {
      best.value = expected;
      best.index = ranked[r];
    }
  }
  return best;
}

}  // namespace

// FastFiz's cue weighs 600 g (Table::CUE_MASS in fastfiz/include/FastFiz.h, used by its
// CueStrikeEvent): the tournaments' speed noise is on that cue's speed.
constexpr double kTournamentCueMass = 0.600;  // kg

// The cue ball's speed (Shot::speed: the impulse over the ball's mass) per m/s of the cue
// stick's, as FastFiz strikes (Leckie and Greenspan's eq. 1): v = 2 V / (1 + m/M + 5/(2R^2)
// (a^2 + b^2 cos^2 t + c^2 sin^2 t - 2 b c cos t sin t)), a and b the tip's offsets across and
// up in the table's frame, c = sqrt(R^2 - a^2 - b^2), t the elevation. The bracket is the
// square of the impulse's lever arm, b cos t - c sin t being the tip's height seen along the
// cue; nineball's tip is seen along the cue, so the bracket is R^2 (side^2 + height^2) at any
// elevation. (FastFiz's 0.999425 on the bracket, to match its predecessor, is left out.)
double ballSpeedPerStickSpeed(Vec2 tip, double ball_mass) {
  return 2.0 / (1.0 + ball_mass / kTournamentCueMass + 2.5 * dot(tip, tip));
}

PlanInput planInputFrom(const Match& match) {
  PlanInput in;
  in.table = match.world().table().def;
  in.physics = match.world().physics();
  in.step = match.world().stepParams();
  in.balls = match.balls();
  in.rack = match.rack();
  in.cue_in_hand = match.cueInHand();
  in.behind_head_string = match.cueBehindHeadString();
  in.cue_area = match.cueArea();
  return in;
}

Planner::Planner(Level level, std::uint64_t seed, int threads)
    : level_(level),
      settings_(LevelSettings::of(level)),
      rng_state_(seed),
      threads_(std::max(threads, 1)) {}

Planner::Planner(Level level, const ExecutionNoise& noise, std::uint64_t seed, int threads)
    : Planner(level, seed, threads) {
  noise.applyTo(settings_);
}

ExecutionNoise ExecutionNoise::olympiad(double magnitude) {
  ExecutionNoise n;
  n.aim_deg = 0.125 * magnitude;
  n.elevation_deg = 0.1 * magnitude;
  n.speed_ms = 0.075 * magnitude;
  n.tip_m = 0.0005 * magnitude;
  return n;
}

std::optional<ExecutionNoise> ExecutionNoise::named(const std::string& name) {
  if (name == "none") return ExecutionNoise{};
  if (name == "olympiad") return olympiad();
  if (name == "olympiad-5x") return olympiad(5.0);
  return std::nullopt;
}

std::vector<std::string> ExecutionNoise::names() {
  return {"none", "olympiad", "olympiad-5x"};
}

void ExecutionNoise::applyTo(LevelSettings& s) const {
  s.aim_noise_deg = aim_deg;
  s.cut_growth = 0.0;
  s.reach_growth = 0.0;
  s.pace_growth = 0.0;
  s.speed_noise = 0.0;
  s.speed_noise_ms = speed_ms;
  s.elevation_noise_deg = elevation_deg;
  s.jump_elevation_noise_deg = elevation_deg;
  s.tip_noise_m = tip_m;
  s.noise_on_break = true;
  // Struck with the whole noise, a controlled break may pocket more than a power break: the
  // planner gets the choice (and judges it by the noise, chooseBreakUnderNoise).
  if (std::find(s.break_speeds.begin(), s.break_speeds.end(), kControlledBreakSpeed) ==
      s.break_speeds.end()) {
    s.break_speeds.insert(s.break_speeds.begin(), kControlledBreakSpeed);
  }
}

std::optional<LevelSettings> cueingNamed(const std::string& name) {
  for (Level level : allLevels()) {
    if (name == levelName(level)) return LevelSettings::of(level);
  }
  const auto noise = ExecutionNoise::named(name);
  if (!noise) return std::nullopt;
  LevelSettings s;  // the search's fields a default's: only the cueing errors are meant
  noise->applyTo(s);
  return s;
}

std::vector<std::string> cueingNames() {
  std::vector<std::string> names;
  for (Level level : allLevels()) names.emplace_back(levelName(level));
  for (const std::string& name : ExecutionNoise::names()) names.push_back(name);
  return names;
}

// The draws come from `rng` in a fixed order; the tournaments' terms (the stick's speed, the
// elevation on a stroke that is not a jump) are drawn only where set, so that a level's own draws,
// and with them every match it plays, stay as they were.
Shot executeStroke(const Shot& intended, const LevelSettings& s, const StrokeDifficulty& d,
                   const PhysicsParams& physics, std::uint64_t& rng) {
  const double scale = d.is_break && !s.noise_on_break ? kBreakNoiseScale : 1.0;
  const double growth = d.is_break ? 1.0 : aimGrowth(s, d, intended.speed);
  const double elevation_sd_deg = d.is_jump ? s.jump_elevation_noise_deg : s.elevation_noise_deg;
  Shot shot = intended;
  const double aim_error = gaussian(rng);
  const double speed_error = gaussian(rng);
  shot.heading_rad += scale * growth * degToRad(s.aim_noise_deg) * aim_error;
  double speed = shot.speed * (1.0 + scale * s.speed_noise * speed_error);
  const double stick_error = s.speed_noise_ms > 0.0 ? gaussian(rng) : 0.0;
  if (elevation_sd_deg > 0.0) {
    const double e = shot.elevation_rad + scale * degToRad(elevation_sd_deg) * gaussian(rng);
    shot.elevation_rad = std::clamp(e, 0.0, degToRad(kMaxExecutedElevationDeg));
  }
  if (s.tip_noise_m > 0.0) {
    const double k = scale * s.tip_noise_m / physics.ball_radius;
    shot.tip.x += k * gaussian(rng);
    shot.tip.y += k * gaussian(rng);
  }
  if (s.speed_noise_ms > 0.0) {
    // The error is on the stick: back from the ball's speed to the stick's with the tip meant,
    // the error added, and on to the ball's with the tip struck.
    const double stick = speed / ballSpeedPerStickSpeed(intended.tip, physics.ball_mass) +
                         scale * s.speed_noise_ms * stick_error;
    speed = stick * ballSpeedPerStickSpeed(shot.tip, physics.ball_mass);
  }
  shot.speed = std::clamp(speed, kMinExecutedSpeed, kMaxExecutedSpeed);
  return shot;
}

Plan Planner::plan(const PlanInput& in) {
  if (gameDef(in.rack.game()).family == GameFamily::Carom) return planCaromShot(in);
  const auto started = std::chrono::steady_clock::now();
  physics_ = in.physics;
  const TableGeometry table = buildTable(in.table, in.physics.ball_radius);
  const Evaluator eval(in, table,
                       std::max(kMinJudgingAimDeg, kJudgingAimOfNoise * settings_.aim_noise_deg),
                       settings_.group_sense);
  const SearchContext ctx{in, table, settings_, in.physics.ball_radius, in.rack.legalFirstBalls()};
  const BallState* cue = findOnTable(in.balls, kCueBall);
  const bool placing = in.cue_in_hand || !cue;
  const bool breaking = placing && in.rack.isBreak();
  const int robust_top =
      breaking ? std::min(settings_.robust_top, kBreakRobustTop) : settings_.robust_top;

  std::vector<Candidate> cands = candidatesFor(ctx, eval);
  if (in.rack.pushOutAvailable() && !placing && settings_.push_out_headings > 0) {
    const auto push_outs = pushOutShots(ctx, settings_.push_out_headings);
    cands.insert(cands.end(), push_outs.begin(), push_outs.end());
  }
  assignCalls(ctx, cands);
  std::vector<double> values;
  std::vector<double> gains;  // what the look ahead added to a candidate's worth
  long sims = 0;
  auto simulateFrom = [&](std::size_t first) {
    values.resize(cands.size(), 0.0);
    gains.resize(cands.size(), 0.0);
    parallelFor(cands.size() - first, threads_,
                [&](std::size_t i) { values[first + i] = eval.value(cands[first + i]); });
    sims += static_cast<long>(cands.size() - first);
  };
  auto choose = [&] {
    const std::vector<std::size_t> order = ranking(cands, values);
    RobustChoice choice;
    if (order.empty()) return choice;
    choice.index = order.front();
    choice.value = values[choice.index];
    if (breaking && settings_.noise_on_break) {
      choice = chooseBreakUnderNoise(cands, order, eval, settings_, in.physics, threads_);
      sims += choice.simulations;
      return choice;
    }
    const std::size_t top = std::min<std::size_t>(order.size(), std::max(robust_top, 0));
    if (settings_.robust_steps > 0 && top > 0) {
      const std::vector<std::size_t> ranked(order.begin(), order.begin() + top);
      choice = chooseRobustly(cands, ranked, eval, settings_, in.physics.ball_mass, threads_,
                              breaking ? kBreakNoiseScale : 1.0, !breaking, gains);
      sims += choice.simulations;
    }
    return choice;
  };

  simulateFrom(0);
  if (!breaking && settings_.lookahead_top > 0) {
    sims += lookFurther(ctx, eval, cands, values, gains, threads_);
  }
  RobustChoice choice = choose();
  if (choice.value < kSweepBelow && !placing && settings_.sweep_headings > 0) {
    const std::size_t first = cands.size();
    std::vector<Candidate> sweep = sweepShots(ctx, settings_.sweep_headings);
    assignCalls(ctx, sweep);
    cands.insert(cands.end(), sweep.begin(), sweep.end());
    simulateFrom(first);
    choice = choose();
  }

  Plan plan;
  plan.simulations = static_cast<int>(sims);
  plan.value = choice.value;
  if (!cands.empty()) {
    const Candidate& c = cands[choice.index];
    plan.turn.kind = c.kind == ShotKind::PushOut ? TurnInput::Kind::PushOut : TurnInput::Kind::Shot;
    plan.turn.shot = c.shot;
    plan.turn.shot.heading_rad += choice.aim_shift;
    plan.turn.cue = c.cue;
    plan.turn.call = c.call;
    plan.kind = c.kind;
    plan.target = c.target;
    plan.pocket = c.pocket;
    plan.first = c.first;
    measureStroke(in, in.physics.ball_radius, plan);
  }
  last_think_seconds_ =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  think_seconds_ += last_think_seconds_;
  simulations_ += sims;
  logger("ai")->info("{}: {} of {} value {:.3f} ({} candidates, {} simulated, {:.0f} ms)",
                     levelName(level_), shotKindName(plan.kind), plan.target, plan.value,
                     cands.size(), sims, 1000.0 * last_think_seconds_);
  return plan;
}

bool Planner::shootAfterPushOut(const PlanInput& in) {
  PlanInput after = in;
  if (after.rack.awaitingDecision()) after.rack.decide(true);
  const bool shoot = plan(after).value >= kEven;
  logger("ai")->info("{}: after the push-out: {}", levelName(level_), shoot ? "shoot" : "pass");
  return shoot;
}

Plan Planner::planCaromShot(const PlanInput& in) {
  const auto started = std::chrono::steady_clock::now();
  physics_ = in.physics;
  long sims = 0;
  Plan plan = planCarom(in, settings_, threads_, sims);
  simulations_ += sims;
  last_think_seconds_ =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  think_seconds_ += last_think_seconds_;
  return plan;
}

TurnInput Planner::execute(const Plan& plan) {
  TurnInput turn = plan.turn;
  turn.shot = executeStroke(turn.shot, settings_, difficultyOf(plan), physics_, rng_state_);
  return turn;
}

TurnInput Planner::turnFor(const Match& match) {
  const PlanInput in = planInputFrom(match);
  const rules::Decision pending = match.rack().pendingDecision();
  if (pending == rules::Decision::PlayOrPutBack ||
      pending == rules::Decision::PlayPutBackOrReplace) {
    return decideAfterFoul(match);
  }
  if (match.rack().awaitingDecision()) {
    TurnInput turn;
    turn.kind = TurnInput::Kind::Decision;
    turn.shoot = shootAfterPushOut(in);
    return turn;
  }
  return execute(plan(in));
}

}  // namespace nineball::ai
