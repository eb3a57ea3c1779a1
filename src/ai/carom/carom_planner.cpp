#include "ai/carom/carom_planner.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "ai/carom/carom_judge.hpp"
#include "common/parallel_map.hpp"

namespace nineball::ai {
namespace {

constexpr double kPi = 3.14159265358979323846;

// One way of striking the ball: everything but the heading.
struct Stroke {
  double speed;
  Vec2 tip;
  double elevation_deg;
};

// A heading tried with one stroke, and what it gave.
struct Trial {
  double heading_deg;
  std::size_t stroke;
  CaromOutcome outcome;
};

// A run of neighbouring headings of one stroke that all score: a candidate shot at its middle.
struct Window {
  double heading_deg;
  double width_deg;
  std::size_t stroke;
  double value = 0.0;  // the share of cueing errors it survives, then the position it leaves
};

Shot shotOf(double heading_deg, const Stroke& k) {
  Shot s = Shot::withSpeed(heading_deg, k.speed);
  s.tip = k.tip;
  s.elevation_rad = k.elevation_deg * kPi / 180.0;
  return s;
}

const BallState* ballWithId(const std::vector<BallState>& balls, int id) {
  for (const BallState& b : balls) {
    if (b.id == id && !b.pocket) return &b;
  }
  return nullptr;
}

double wrapDegrees(double d) {
  d = std::fmod(d, 360.0);
  return d < 0.0 ? d + 360.0 : d;
}

// The headings of the search: every `step` degrees round the table, and every `fine` degrees
// across each object ball (a ball-first shot's window is a few degrees wide).
std::vector<double> headingsFor(const PlanInput& in, int cue, const CaromSearch& s) {
  std::vector<double> out;
  const int coarse = static_cast<int>(std::lround(360.0 / s.heading_step_deg));
  for (int k = 0; k < coarse; ++k) out.push_back(k * 360.0 / coarse);
  const BallState* c = ballWithId(in.balls, cue);
  if (c && s.fine_step_deg > 0.0) {
    const double reach = 2.0 * in.physics.ball_radius;
    for (const BallState& b : in.balls) {
      if (b.id == cue || b.pocket) continue;
      const Vec2 d = b.pos - c->pos;
      const double dist = length(d);
      if (dist <= reach) continue;
      const double centre = std::atan2(d.y, d.x) * 180.0 / kPi;
      const double half = std::asin(std::min(1.0, reach / dist)) * 180.0 / kPi;
      for (double a = -half; a <= half; a += s.fine_step_deg)
        out.push_back(wrapDegrees(centre + a));
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<Stroke> strokesFor(const CaromSearch& s) {
  std::vector<Stroke> out;
  for (double v : s.speeds) {
    for (Vec2 tip : s.tips) {
      for (double e : s.elevations_deg) out.push_back({v, tip, e});
    }
  }
  return out;
}

// The raised-cue strokes: running side either way with a little follow, at the two slowest
// speeds, for each raised elevation.
std::vector<Stroke> raisedStrokesFor(const CaromSearch& s) {
  std::vector<Stroke> out;
  const std::size_t speeds = std::min<std::size_t>(2, s.speeds.size());
  for (double e : s.raised_elevations_deg) {
    for (std::size_t k = 0; k < speeds; ++k) {
      for (Vec2 tip : {Vec2{0.35, 0.2}, Vec2{-0.35, 0.2}}) out.push_back({s.speeds[k], tip, e});
    }
  }
  return out;
}

// Every heading of `headings` with every stroke, played until the point is decided; trial
// i * headings + j is stroke i at heading j.
std::vector<Trial> playGrid(const CaromJudge& judge, const std::vector<double>& headings,
                            const std::vector<Stroke>& strokes, std::size_t first_stroke,
                            int threads, long& sims) {
  std::vector<Trial> trials(headings.size() * strokes.size());
  parallelFor(trials.size(), threads, [&](std::size_t i) {
    const std::size_t k = i / headings.size();
    const double h = headings[i % headings.size()];
    trials[i] = {h, first_stroke + k, judge.run(shotOf(h, strokes[k]), false)};
  });
  sims += static_cast<long>(trials.size());
  return trials;
}

// Every run of neighbouring scoring headings of each stroke (the headings sorted, round the
// circle), widest first.
std::vector<Window> windowsOf(const std::vector<double>& headings, std::size_t strokes,
                              const std::vector<Trial>& trials) {
  std::vector<Window> out;
  const std::size_t n = headings.size();
  if (n == 0) return out;
  for (std::size_t k = 0; k < strokes; ++k) {
    const Trial* row = &trials[k * n];
    std::size_t i = 0;
    while (i < n) {
      if (!row[i].outcome.point) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j + 1 < n && row[j + 1].outcome.point) ++j;
      const double lo = i > 0 ? 0.5 * (headings[i - 1] + headings[i]) : headings[i];
      const double hi = j + 1 < n ? 0.5 * (headings[j] + headings[j + 1]) : headings[j];
      // Its middle heading that was played and scored: a path of three cushions is chaotic
      // enough that a heading between two scoring ones need not score.
      out.push_back({headings[(i + j) / 2], hi - lo, row[0].stroke});
      i = j + 1;
    }
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const Window& a, const Window& b) { return a.width_deg > b.width_deg; });
  return out;
}

// The share of the level's cueing errors a shot still scores under: headings at
// -1.5 .. +1.5 deviations, each at the speed's -1, 0, +1 deviations.
double survival(const CaromJudge& judge, const Shot& shot, const LevelSettings& s, long& sims) {
  static const double kAim[] = {-1.5, -1.0, -0.5, 0.5, 1.0, 1.5};
  static const double kSpeed[] = {-1.0, 0.0, 1.0};
  const double aim = std::max(s.robust_aim_deg, s.aim_noise_deg);
  const double speed = std::max(s.robust_speed, s.speed_noise);
  int scored = 0;
  int tried = 0;
  for (double a : kAim) {
    for (double v : kSpeed) {
      Shot p = shot;
      p.heading_rad += a * aim * kPi / 180.0;
      p.speed *= 1.0 + v * speed;
      scored += judge.run(p, false).point ? 1 : 0;
      ++tried;
    }
  }
  sims += tried;
  return static_cast<double>(scored) / tried;
}

// How promising the position after a point is for the next one: the share of a quick sweep of
// headings that scores from it.
double nextPointChance(const PlanInput& in, const CaromOutcome& after, const CaromSearch& s,
                       long& sims) {
  PlanInput next = in;
  next.balls = after.balls;
  next.rack = after.rack;
  if (next.rack.over()) return 1.0;
  const CaromJudge judge(next);
  int scored = 0;
  for (int k = 0; k < s.position_headings; ++k) {
    const double h = k * 360.0 / s.position_headings;
    for (const Stroke& st : {Stroke{3.0, {0.0, 0.0}, 0.0}, Stroke{3.5, {0.3, 0.2}, 0.0},
                             Stroke{3.5, {-0.3, 0.2}, 0.0}}) {
      scored += judge.run(shotOf(h, st), false).point ? 1 : 0;
      ++sims;
    }
  }
  return static_cast<double>(scored) / (3.0 * s.position_headings);
}

// The shot that came closest when nothing scored: both balls touched, then the most cushions
// before the second, then the most cushions.
std::size_t closest(const std::vector<Trial>& trials) {
  std::size_t best = 0;
  auto rank = [](const CaromOutcome& o) {
    return (o.touched_both ? 100 : 0) + std::min(o.cushions, 3) * 10;
  };
  for (std::size_t i = 1; i < trials.size(); ++i) {
    if (rank(trials[i].outcome) > rank(trials[best].outcome)) best = i;
  }
  return best;
}

// The stroke model's difficulty of a shot: the cut on the first object ball when it is hit
// first, and the distance to it.
void describeStroke(const PlanInput& in, int cue, double heading_deg, Plan& plan) {
  plan.first = -1;  // a cushion first, unless a ball lies on the line
  const BallState* c = ballWithId(in.balls, cue);
  if (!c) return;
  const Vec2 dir = fromAngle(heading_deg * kPi / 180.0);
  const double two_r = 2.0 * in.physics.ball_radius;
  double nearest = 1e9;
  for (const BallState& b : in.balls) {
    if (b.id == cue || b.pocket) continue;
    const Vec2 d = b.pos - c->pos;
    const double along = dot(d, dir);
    const double off = std::abs(cross(dir, d));
    if (along <= 0.0 || off >= two_r || along >= nearest) continue;
    nearest = along;
    plan.first = b.id;
    plan.cut_deg = std::asin(off / two_r) * 180.0 / kPi;
    plan.reach_m = std::max(0.0, along - std::sqrt(two_r * two_r - off * off));
  }
}

}  // namespace

Plan planCarom(const PlanInput& in, const LevelSettings& settings, int threads, long& sims) {
  const CaromSearch& s = settings.carom;
  const CaromJudge judge(in);
  const std::vector<double> headings = headingsFor(in, judge.cue(), s);
  std::vector<Stroke> strokes = strokesFor(s);
  const std::size_t level_strokes = strokes.size();
  std::vector<Trial> trials = playGrid(judge, headings, strokes, 0, threads, sims);
  std::vector<Window> windows = windowsOf(headings, level_strokes, trials);
  // The raised cue on a coarser grid of its own.
  const std::vector<Stroke> raised = raisedStrokesFor(s);
  if (!raised.empty()) {
    std::vector<double> coarse;
    const int n = static_cast<int>(std::lround(360.0 / s.raised_step_deg));
    for (int k = 0; k < n; ++k) coarse.push_back(k * 360.0 / n);
    const std::vector<Trial> more = playGrid(judge, coarse, raised, level_strokes, threads, sims);
    std::vector<Window> found = windowsOf(coarse, raised.size(), more);
    // Measured without the coarser grid's half steps, so that a lone scoring heading there
    // does not outrank two neighbours on the finer one.
    for (Window& w : found) w.width_deg = std::max(0.0, w.width_deg - s.raised_step_deg);
    windows.insert(windows.end(), found.begin(), found.end());
    std::stable_sort(windows.begin(), windows.end(),
                     [](const Window& a, const Window& b) { return a.width_deg > b.width_deg; });
    trials.insert(trials.end(), more.begin(), more.end());
    strokes.insert(strokes.end(), raised.begin(), raised.end());
  }

  Plan plan;
  plan.kind = ShotKind::Point;
  if (windows.empty()) {
    const Trial& t = trials[closest(trials)];
    plan.turn.shot = shotOf(t.heading_deg, strokes[t.stroke]);
    describeStroke(in, judge.cue(), t.heading_deg, plan);
    plan.value = 0.0;
    plan.simulations = static_cast<int>(sims);
    return plan;
  }
  windows.resize(std::min<std::size_t>(windows.size(), std::max(1, s.robust_top)));
  std::vector<long> counts(windows.size(), 0);
  parallelFor(windows.size(), threads, [&](std::size_t i) {
    Window& w = windows[i];
    const Shot shot = shotOf(w.heading_deg, strokes[w.stroke]);
    w.value = s.robust_top > 0 ? survival(judge, shot, settings, counts[i]) : 1.0;
    // A tie between robust shots goes to the wider window.
    w.value += 1e-4 * std::min(w.width_deg, 10.0);
  });
  for (long c : counts) sims += c;
  std::stable_sort(windows.begin(), windows.end(),
                   [](const Window& a, const Window& b) { return a.value > b.value; });
  if (s.position_top > 0) {
    const std::size_t top = std::min<std::size_t>(windows.size(), s.position_top);
    std::vector<long> more(top, 0);
    parallelFor(top, threads, [&](std::size_t i) {
      Window& w = windows[i];
      const CaromOutcome after = judge.run(shotOf(w.heading_deg, strokes[w.stroke]), true);
      ++more[i];
      if (after.point) w.value *= 1.0 + s.position_weight * nextPointChance(in, after, s, more[i]);
    });
    for (long c : more) sims += c;
    std::stable_sort(windows.begin(), windows.begin() + static_cast<std::ptrdiff_t>(top),
                     [](const Window& a, const Window& b) { return a.value > b.value; });
  }
  const Window& best = windows.front();
  plan.turn.shot = shotOf(best.heading_deg, strokes[best.stroke]);
  describeStroke(in, judge.cue(), best.heading_deg, plan);
  plan.value = std::min(1.0, best.value);
  plan.simulations = static_cast<int>(sims);
  return plan;
}

}  // namespace nineball::ai
