#include "accuracy/whole_shots.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <tuple>
#include <utility>

#include "nineball/random.hpp"
#include "nineball/scenes.hpp"
#include "nineball/table.hpp"

namespace nineball {
namespace {

constexpr int kMaxCushions = 6;
constexpr double kMinSpeed = 0.3, kMaxSpeed = 8.0;  // m/s
constexpr std::uint64_t kSeed = 0x5A11D0E5ull;
// Balls on the table of successive candidates: more candidates with more balls, as fewer of
// them come out stable, so that every count from 1 to 4 is well represented.
constexpr std::array<int, 8> kBallCounts{2, 3, 4, 1, 3, 4, 2, 4};
// Candidates drawn per shot kept, at most, before a category gives up: the coverage test then
// names what is missing instead of the generation running on.
constexpr int kAttemptsPerShot = 400;

// What the suite holds: for every cushion count 0..kMaxCushions, `per_count` shots of each
// category. The paper preset knows no spin, so its shots are centre-ball hits.
struct Category {
  bool paper;
  SpinKind spin;
  int per_count;
};
constexpr std::array<Category, 5> kCategories{{{true, SpinKind::Stun, 2},
                                               {false, SpinKind::Stun, 1},
                                               {false, SpinKind::Follow, 1},
                                               {false, SpinKind::Draw, 1},
                                               {false, SpinKind::Side, 1}}};

Vec2 tipFor(SpinKind kind, std::uint64_t& rng) {
  switch (kind) {
    case SpinKind::Stun:
      return {};
    case SpinKind::Follow:
      return {0.0, uniform(rng, 0.15, 0.45)};
    case SpinKind::Draw:
      return {0.0, -uniform(rng, 0.15, 0.45)};
    case SpinKind::Side: {
      // |tip| <= sqrt(0.4^2 + 0.25^2) = 0.47, inside the 0.5 miscue limit.
      const double side = uniform(rng, 0.15, 0.4) * (uniform(rng, 0.0, 1.0) < 0.5 ? -1.0 : 1.0);
      return {side, uniform(rng, -0.25, 0.25)};
    }
  }
  return {};
}

// Speeds that tend to give `cushions` cushion events on the 9 ft table, with either preset
// (measured over the candidates): the search asks for the counts still missing.
std::pair<double, double> speedBand(int cushions) {
  return {kMinSpeed * std::pow(1.45, cushions), std::min(kMaxSpeed, 0.9 * std::pow(1.6, cushions))};
}

Vec2 randomSpot(const Scene& s, std::uint64_t& rng) {
  const double r = s.physics.ball_radius;
  const double hx = s.table.length / 2.0 - r, hy = s.table.width / 2.0 - r;
  return {uniform(rng, -hx, hx), uniform(rng, -hy, hy)};
}

// A random layout of `n_balls` (the cue ball and object balls 1, 2, ...), each placed by
// rejection until validateScene accepts it, and a shot in the speed band of `cushions`:
// mostly at ball 1 with a random cut, else in any direction. Ball 1 lies near the cue ball:
// a heading error grows by about the cue ball's travel over 2R at a contact, and far apart
// most shots come out chaotic.
Scene candidate(const Category& cat, int n_balls, int cushions, std::uint64_t& rng) {
  Scene s;
  s.physics = cat.paper ? PhysicsParams::paper() : PhysicsParams::real();
  const double r = s.physics.ball_radius;
  while (static_cast<int>(s.balls.size()) < n_balls) {
    const int id = static_cast<int>(s.balls.size());
    Vec2 at = randomSpot(s, rng);
    if (id == 1) {
      at = s.balls[0].pos + fromAngle(uniform(rng, -kPi, kPi)) * uniform(rng, 2.0 * r + 0.01, 0.5);
    }
    s.balls.push_back(BallState::at(id, at));
    if (validateScene(s)) s.balls.pop_back();
  }
  Shot shot;
  const Vec2 cue = s.balls[0].pos;
  if (n_balls > 1 && uniform(rng, 0.0, 1.0) < 0.75) {
    const Vec2 to = s.balls[1].pos - cue;
    // Offset of the object ball's centre from the cue ball's path: 0 full, 2R a miss.
    const double offset = uniform(rng, -0.9, 0.9) * 2.0 * r;
    shot.heading_rad = std::atan2(to.y, to.x) + std::asin(offset / length(to));
  } else {
    shot.heading_rad = uniform(rng, -kPi, kPi);
  }
  const auto [lo, hi] = speedBand(cushions);
  shot.speed = std::exp(uniform(rng, std::log(lo), std::log(hi)));
  shot.tip = cat.paper ? Vec2{} : tipFor(cat.spin, rng);
  s.shot = shot;
  return s;
}

SimResult runWith(Scene s, const StepParams& step) {
  s.step = step;
  return simulate(s);
}

StepParams referenceStep() {
  StepParams s;
  s.engine = EngineKind::named("reference");
  return s;
}

// The perturbed runs tell the same story as the run itself: see kStableHeadingRad.
bool stable(const Scene& s, const SimResult& base) {
  const std::array<std::pair<double, double>, 4> perturbations{{{kStableHeadingRad, 1.0},
                                                                {-kStableHeadingRad, 1.0},
                                                                {0.0, 1.0 + kStableSpeedRel},
                                                                {0.0, 1.0 - kStableSpeedRel}}};
  for (const auto& [dh, ds] : perturbations) {
    Scene p = s;
    p.shot->heading_rad += dh;
    p.shot->speed *= ds;
    const ShotComparison c = compareRuns(p, runWith(p, referenceStep()), base);
    if (!c.events_match || !c.pockets_match || c.position_error_mm > kStablePositionMm) {
      return false;
    }
  }
  return true;
}

std::vector<Scene> generateScenes() {
  struct Kept {
    std::size_t category;
    int cushions;
    Scene scene;
  };
  std::vector<Kept> kept;
  for (std::size_t ci = 0; ci < kCategories.size(); ++ci) {
    const Category& cat = kCategories[ci];
    std::array<int, kMaxCushions + 1> open{};
    open.fill(cat.per_count);
    int still_open = cat.per_count * (kMaxCushions + 1);
    std::uint64_t rng = kSeed + 0x1000 * ci;
    int filled = 0, target = 0;
    for (int attempt = 0; still_open > 0 && attempt < kAttemptsPerShot * (filled + 1); ++attempt) {
      const int n_balls = kBallCounts[static_cast<std::size_t>(attempt) % kBallCounts.size()];
      do {
        target = (target + 1) % (kMaxCushions + 1);
      } while (open[target] == 0);
      const Scene s = candidate(cat, n_balls, target, rng);
      const SimResult base = runWith(s, referenceStep());
      const int cushions = cushionEventCount(base.events);
      if (cushions > kMaxCushions || open[cushions] == 0 || !stable(s, base)) continue;
      --open[cushions];
      --still_open;
      ++filled;
      kept.push_back({ci, cushions, s});
    }
  }
  std::stable_sort(kept.begin(), kept.end(), [](const Kept& a, const Kept& b) {
    return std::tie(a.category, a.cushions) < std::tie(b.category, b.cushions);
  });
  std::vector<Scene> out;
  for (const Kept& k : kept) out.push_back(k.scene);
  return out;
}

// An event as the comparison sees it: a ball pair in either order is the same pair.
struct EventKey {
  EventType type;
  int a, b;
  int pocket;
  bool operator==(const EventKey& o) const {
    return type == o.type && a == o.a && b == o.b && pocket == o.pocket;
  }
};

EventKey keyOf(const Event& e) {
  EventKey k{e.type, e.a, e.b, -1};
  if (e.type == EventType::BallBall && k.a > k.b) std::swap(k.a, k.b);
  if (e.type != EventType::BallBall) k.b = -1;
  if (e.type == EventType::Pocket) k.pocket = static_cast<int>(e.pocket);
  return k;
}

bool inSequence(const Event& e) {
  return e.type != EventType::AllAtRest && e.type != EventType::Miscue;
}

std::vector<const Event*> sequenceOf(const std::vector<Event>& events) {
  std::vector<const Event*> out;
  for (const Event& e : events) {
    if (inSequence(e)) out.push_back(&e);
  }
  return out;
}

long countOf(const std::vector<Event>& events, EventType type) {
  return std::count_if(events.begin(), events.end(),
                       [type](const Event& e) { return e.type == type; });
}

std::string describe(const Event& e) {
  char buf[96];
  switch (e.type) {
    case EventType::BallBall:
      std::snprintf(buf, sizeof buf, "ball %d-%d at %.4f s", e.a, e.b, e.t);
      break;
    case EventType::Pocket:
      std::snprintf(buf, sizeof buf, "pocket %d %s at %.4f s", e.a, pocketName(e.pocket), e.t);
      break;
    default:
      std::snprintf(buf, sizeof buf, "%s %d at %.4f s", eventTypeName(e.type), e.a, e.t);
      break;
  }
  return buf;
}

// Walks the common prefix of two event sequences: how many match and their worst time error.
struct Prefix {
  std::size_t matched = 0;
  double time_error_ms = 0.0;
  std::string mismatch;
};

Prefix matchPrefix(const std::vector<const Event*>& got, const std::vector<const Event*>& want,
                   std::size_t limit) {
  Prefix p;
  const std::size_t n = std::min({got.size(), want.size(), limit});
  while (p.matched < n && keyOf(*got[p.matched]) == keyOf(*want[p.matched])) {
    p.time_error_ms =
        std::max(p.time_error_ms, std::abs(got[p.matched]->t - want[p.matched]->t) * 1000.0);
    ++p.matched;
  }
  const std::size_t i = p.matched;
  if (i < n) {
    p.mismatch = "event " + std::to_string(i) + ": " + describe(*got[i]) + ", reference " +
                 describe(*want[i]);
  } else if (i < limit && got.size() != want.size()) {
    p.mismatch = std::to_string(got.size()) + " events, reference " + std::to_string(want.size());
    p.mismatch += got.size() > i ? "; first extra " + describe(*got[i])
                                 : "; first missing " + describe(*want[i]);
  }
  return p;
}

const BallState* findBall(const std::vector<BallState>& balls, int id) {
  for (const BallState& b : balls) {
    if (b.id == id) return &b;
  }
  return nullptr;
}

}  // namespace

const char* spinKindName(SpinKind kind) {
  switch (kind) {
    case SpinKind::Stun:
      return "stun";
    case SpinKind::Follow:
      return "follow";
    case SpinKind::Draw:
      return "draw";
    case SpinKind::Side:
      return "side";
  }
  return "?";
}

SpinKind spinKindOf(const Shot& shot) {
  if (shot.tip.x != 0.0) return SpinKind::Side;
  if (shot.tip.y > 0.0) return SpinKind::Follow;
  if (shot.tip.y < 0.0) return SpinKind::Draw;
  return SpinKind::Stun;
}

const char* presetNameOf(const PhysicsParams& physics) {
  return physics.cloth == ClothModel::Friction ? "paper" : "real";
}

int cushionEventCount(const std::vector<Event>& events) {
  return static_cast<int>(countOf(events, EventType::Cushion));
}

bool isStableShot(const Scene& scene) {
  return stable(scene, runWith(scene, referenceStep()));
}

std::vector<Scene> wholeShotScenes() {
  static const std::vector<Scene> scenes = generateScenes();
  return scenes;
}

bool ShotComparison::withinTolerance() const {
  return events_match && pockets_match && position_error_mm <= kWholeShotPositionToleranceMm &&
         time_error_ms <= kWholeShotEventTimeToleranceMs;
}

ShotComparison compareRuns(const Scene& scene, const SimResult& got, const SimResult& want) {
  ShotComparison c;
  const std::vector<const Event*> g = sequenceOf(got.events), w = sequenceOf(want.events);
  const Prefix p = matchPrefix(g, w, g.size() + w.size());
  c.events_compared = static_cast<int>(p.matched);
  c.time_error_ms = p.time_error_ms;
  c.mismatch = p.mismatch;
  const long rest_g = countOf(got.events, EventType::AllAtRest);
  const long rest_w = countOf(want.events, EventType::AllAtRest);
  const long miscue_g = countOf(got.events, EventType::Miscue);
  const long miscue_w = countOf(want.events, EventType::Miscue);
  c.events_match = p.mismatch.empty() && rest_g == rest_w && miscue_g == miscue_w;
  if (p.mismatch.empty() && !c.events_match) {
    c.mismatch = "rest events " + std::to_string(rest_g) + " (reference " + std::to_string(rest_w) +
                 "), miscues " + std::to_string(miscue_g) + " (reference " +
                 std::to_string(miscue_w) + ")";
  }
  if (rest_g > 0 && rest_w > 0) {
    const auto rest = [](const std::vector<Event>& ev) {
      return std::find_if(ev.begin(), ev.end(),
                          [](const Event& e) { return e.type == EventType::AllAtRest; })
          ->t;
    };
    c.rest_time_error_ms = std::abs(rest(got.events) - rest(want.events)) * 1000.0;
  }

  const TableGeometry table = buildTable(scene.table, scene.physics.ball_radius);
  const auto dropCentre = [&](PocketId id) {
    return table.pockets[static_cast<std::size_t>(id)].drop_centre;
  };
  c.pockets_match = true;
  std::string pocket_mismatch;
  for (const BallState& wb : want.balls) {
    const BallState* gb = findBall(got.balls, wb.id);
    double error = 0.0;
    if (!gb) {
      c.pockets_match = false;
      pocket_mismatch = "ball " + std::to_string(wb.id) + " missing";
      continue;
    }
    if (gb->pocket && wb.pocket) {
      if (*gb->pocket != *wb.pocket) {
        error = length(dropCentre(*gb->pocket) - dropCentre(*wb.pocket));
      }
    } else if (gb->pocket) {
      error = length(dropCentre(*gb->pocket) - wb.pos);
    } else if (wb.pocket) {
      error = length(gb->pos - dropCentre(*wb.pocket));
    } else {
      error = length(gb->pos - wb.pos);
    }
    if (gb->pocket != wb.pocket && c.pockets_match) {
      c.pockets_match = false;
      pocket_mismatch = "ball " + std::to_string(wb.id) + " in " +
                        (gb->pocket ? pocketName(*gb->pocket) : "no pocket") + ", reference " +
                        (wb.pocket ? pocketName(*wb.pocket) : "no pocket");
    }
    c.position_error_mm = std::max(c.position_error_mm, error * 1000.0);
  }
  if (c.mismatch.empty()) c.mismatch = pocket_mismatch;
  return c;
}

bool BreakComparison::withinTolerance() const {
  return events_match && time_error_ms <= kBreakEventTimeToleranceMs;
}

BreakComparison compareBreakEvents(const SimResult& got, const SimResult& want) {
  BreakComparison c;
  const std::vector<const Event*> g = sequenceOf(got.events), w = sequenceOf(want.events);
  const Prefix p = matchPrefix(g, w, kBreakEventsCompared);
  c.events_compared = static_cast<int>(p.matched);
  c.time_error_ms = p.time_error_ms;
  c.mismatch = p.mismatch;
  c.events_match = p.matched == static_cast<std::size_t>(kBreakEventsCompared);
  if (c.events_match) return c;
  if (c.mismatch.empty()) {
    c.mismatch = std::to_string(g.size()) + " events, reference " + std::to_string(w.size()) +
                 ": fewer than " + std::to_string(kBreakEventsCompared);
  }
  return c;
}

bool WholeShotReport::withinTolerance() const {
  if (!break_shot.withinTolerance()) return false;
  return std::all_of(shots.begin(), shots.end(),
                     [](const WholeShotResult& s) { return s.comparison.withinTolerance(); });
}

WholeShotReport compareWholeShots(const StepParams& box2d_step) {
  StepParams box2d = box2d_step;
  box2d.engine = EngineKind::named("box2d");
  WholeShotReport report;
  const std::vector<Scene> scenes = wholeShotScenes();
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const Scene& s = scenes[i];
    const SimResult got = runWith(s, box2d);
    const SimResult want = runWith(s, referenceStep());
    WholeShotResult r;
    r.index = static_cast<int>(i);
    r.preset = presetNameOf(s.physics);
    r.spin = spinKindOf(*s.shot);
    r.balls = static_cast<int>(s.balls.size());
    r.cushions = cushionEventCount(want.events);
    r.speed = s.shot->speed;
    r.comparison = compareRuns(s, got, want);
    r.box2d_ms = got.wall_ms;
    r.reference_ms = want.wall_ms;
    if (!r.comparison.events_match || !r.comparison.pockets_match) ++report.mismatched_shots;
    report.worst_position_mm = std::max(report.worst_position_mm, r.comparison.position_error_mm);
    report.worst_time_ms = std::max(report.worst_time_ms, r.comparison.time_error_ms);
    report.box2d_ms += r.box2d_ms;
    report.reference_ms += r.reference_ms;
    report.shots.push_back(r);
  }
  report.break_shot = compareBreak(box2d);
  return report;
}

BreakComparison compareBreak(const StepParams& box2d_step) {
  StepParams box2d = box2d_step;
  box2d.engine = EngineKind::named("box2d");
  const Scene brk = breakScene();
  const SimResult got = runWith(brk, box2d);
  const SimResult want = runWith(brk, referenceStep());
  BreakComparison c = compareBreakEvents(got, want);
  c.box2d_ms = got.wall_ms;
  c.reference_ms = want.wall_ms;
  return c;
}

}  // namespace nineball
