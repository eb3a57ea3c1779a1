#include "fit/recorded_shot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>

#include "common/limits.hpp"

namespace nineball {
namespace {

// Beyond this a tracked position is no tracking noise but another table (m).
constexpr double kOffTable = 0.1;

std::string shortNumber(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// No cue drives a ball faster than fit::kMaxSpeed: samples further apart than that in their
// time are a tracker's (or its clock's) mistake, and a first guess of the strike from them
// would be nonsense. A time recorded twice (a coarse clock) defines no speed.
std::string speedFault(const RecordedPath& b, const std::string& at, std::size_t i) {
  const double dt = b.t[i] - b.t[i - 1];
  if (!(dt > 0.0)) return {};
  const double speed = std::hypot(b.x[i] - b.x[i - 1], b.y[i] - b.y[i - 1]) / dt;
  if (speed <= fit::kMaxSpeed) return {};
  return at + ": samples " + std::to_string(i - 1) + "-" + std::to_string(i) + " imply " +
         shortNumber(speed) + " m/s";
}

std::string pathFault(const RecordedPath& b, const std::string& at) {
  if (b.t.size() != b.x.size() || b.t.size() != b.y.size()) {
    return at + ": t, x and y have different lengths (" + std::to_string(b.t.size()) + ", " +
           std::to_string(b.x.size()) + ", " + std::to_string(b.y.size()) + ")";
  }
  if (b.t.size() < 2) return at + ": needs at least 2 samples";
  for (std::size_t i = 0; i < b.t.size(); ++i) {
    if (!std::isfinite(b.t[i]) || !std::isfinite(b.x[i]) || !std::isfinite(b.y[i])) {
      return at + ": sample " + std::to_string(i) + " is not a finite number";
    }
    if (i == 0) continue;
    // A time may repeat (real trackers have coarse clocks), never go back.
    if (b.t[i] < b.t[i - 1]) return at + ".t: decreasing at sample " + std::to_string(i);
    if (std::string why = speedFault(b, at, i); !why.empty()) return why;
  }
  if (!(b.t.back() > b.t.front())) {
    return at + ".t: every sample at one time (needs two different times at least)";
  }
  return {};
}

// A fit simulates from the strike to the last sample: a recording longer than the longest run
// is no shot (and its runs would trace for ages).
std::string spanFault(const Recording& r) {
  double first = std::numeric_limits<double>::infinity();
  for (const RecordedPath& b : r.balls) first = std::min(first, b.t.front());
  for (const RecordedPath& b : r.balls) {
    const auto late = std::upper_bound(b.t.begin(), b.t.end(), first + limits::kMaxSimTime);
    if (late == b.t.end()) continue;
    return "balls." + b.name + ".t: sample " + std::to_string(late - b.t.begin()) + " lies " +
           shortNumber(*late - first) + " s after the recording's first, more than the " +
           shortNumber(limits::kMaxSimTime) + " s a run may last";
  }
  return {};
}

}  // namespace

std::optional<std::string> recordingFault(const Recording& r) {
  if (r.balls.empty()) return "balls: no ball recorded";
  std::set<std::string> names;
  for (const RecordedPath& b : r.balls) {
    const std::string at = "balls." + b.name;
    if (b.name.empty()) return std::string("balls: a ball has an empty name");
    if (!names.insert(b.name).second) return at + ": recorded twice";
    if (std::string why = pathFault(b, at); !why.empty()) return why;
    const double hx = r.table.length / 2.0 + kOffTable;
    const double hy = r.table.width / 2.0 + kOffTable;
    for (std::size_t i = 0; i < b.t.size(); ++i) {
      if (std::abs(b.x[i]) > hx || std::abs(b.y[i]) > hy) {
        return at + ": sample " + std::to_string(i) + " lies off the table";
      }
    }
  }
  if (std::string why = spanFault(r); !why.empty()) return why;
  if (!r.cue_ball.empty() && !names.count(r.cue_ball)) {
    return "cue_ball: no ball named \"" + r.cue_ball + "\" is recorded";
  }
  return std::nullopt;
}

namespace fit {
namespace {

// A ball has moved once it lies kMoved from where it stood at two samples running: twice over,
// so that noise alone almost never moves it.
// Samples this near where a ball stood are the ball at rest seen through the tracker's noise:
// with 5 mm on each coordinate, 1 % of them fall further out (m).
constexpr double kStill = 0.012;
// The cue ball's first samples in motion that give the first guess of its line (s).
constexpr double kEarlyWindow = 0.1;
// A turn this sharp between frames is a contact (rad).
constexpr double kTurn = 30.0 * kPi / 180.0;
// Off its early line by this much, the cue ball has met something (m).
constexpr double kTurned = 0.03;

Vec2 medianOf(const RecordedPath& b, std::size_t from, std::size_t to) {
  std::vector<double> xs(b.x.begin() + from, b.x.begin() + to);
  std::vector<double> ys(b.y.begin() + from, b.y.begin() + to);
  auto median = [](std::vector<double>& v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  };
  return {median(xs), median(ys)};
}

Vec2 at(const RecordedPath& b, std::size_t i) {
  return {b.x[i], b.y[i]};
}

// Least squares line p(t) = a + v (t - tm) through samples [from, to).
struct Line {
  Vec2 a, v;
  double tm = 0.0;
};

Line lineThrough(const RecordedPath& b, std::size_t from, std::size_t to) {
  Line l;
  const double n = static_cast<double>(to - from);
  for (std::size_t i = from; i < to; ++i) {
    l.tm += b.t[i] / n;
    l.a += at(b, i) * (1.0 / n);
  }
  double stt = 0.0;
  Vec2 stp;
  for (std::size_t i = from; i < to; ++i) {
    const double dt = b.t[i] - l.tm;
    stt += dt * dt;
    stp += (at(b, i) - l.a) * dt;
  }
  // Samples all but at one instant give no velocity (1 / stt overflows).
  const Vec2 v = stp * (1.0 / stt);
  if (stt > 0.0 && std::isfinite(v.x) && std::isfinite(v.y)) l.v = v;
  return l;
}

// The last sample that has a later one at a later time (times may repeat).
std::size_t lastStepFrom(const RecordedPath& b) {
  std::size_t i = b.t.size() - 2;
  while (i > 0 && !(b.t[i] < b.t.back())) --i;
  return i;
}

// The first sample after `i` whose time is later than its time.
std::size_t laterSample(const RecordedPath& b, std::size_t i) {
  std::size_t next = i + 1;
  while (next + 1 < b.t.size() && !(b.t[next] > b.t[i])) ++next;
  return next;
}

struct Onset {
  std::size_t index = 0;  // the first sample in motion; size() when it never moves
  bool from_start = false;
  double time = 0.0;  // when it began to move, as its first samples in motion tell
};

// Three samples running kMoved from `origin`: noise alone all but never does that.
std::size_t firstAway(const RecordedPath& b, Vec2 origin) {
  const std::size_t n = b.t.size();
  auto far = [&](std::size_t i) { return i >= n || length(at(b, i) - origin) > kMoved; };
  for (std::size_t i = 1; i < n; ++i) {
    if (far(i) && far(i + 1) && far(i + 2)) return i;
  }
  return n;
}

// Where a ball stood from its first sample, less the tracker's noise: the median of its
// first samples up to `limit` that follow each other without a gap (after a gap the tracker
// saw it move again), then of those the ones within kStill of that median. With `near_first`,
// only samples within kMoved of the first count (the ball may move from it at once).
Vec2 leadingRest(const RecordedPath& b, std::size_t limit, bool near_first) {
  const std::size_t end = std::min(limit, b.t.size());
  std::size_t k = 1;
  while (k < end && b.t[k] - b.t[k - 1] <= kEarlyWindow &&
         (!near_first || length(at(b, k) - at(b, 0)) <= kMoved)) {
    ++k;
  }
  const Vec2 around = medianOf(b, 0, k);
  RecordedPath still;
  for (std::size_t i = 0; i < k; ++i) {
    if (length(at(b, i) - around) > kStill) continue;
    still.x.push_back(b.x[i]);
    still.y.push_back(b.y[i]);
  }
  return still.x.empty() ? around : medianOf(still, 0, still.x.size());
}

// A ball struck slowly creeps before it lies kMoved away: its samples in the 0.1 s before its
// onset are left out when there are others.
Vec2 restOf(const RecordedPath& b, const Onset& o) {
  if (o.index == 0) return at(b, 0);
  std::size_t last = std::min(o.index, b.t.size());
  while (last > 1 && o.index < b.t.size() && b.t[last - 1] > b.t[o.index] - 0.1) --last;
  return leadingRest(b, last, false);
}

// The end of the samples from `from` that a line through the first motion takes: those up to
// kEarlyWindow after it, at least two, and at least one at a later time (clocks repeat).
std::size_t earlyEnd(const RecordedPath& b, std::size_t from) {
  const std::size_t n = b.t.size();
  std::size_t to = std::min(from + 2, n);
  while (to < n && (b.t[to] <= b.t[from] + kEarlyWindow || !(b.t[to - 1] > b.t[from]))) ++to;
  return to;
}

// A tracker samples a ball at rest only when it moves again, so its first sample in motion
// can follow its last at rest by seconds, and its first samples can all be moving: when it
// began to move is read off the line through its first moving samples, carried back to
// where it stood. At or before the first sample: it was moving when the recording began
// (the cue ball of a recording that starts at the strike).
Onset onsetOf(const RecordedPath& b) {
  const std::size_t n = b.t.size();
  Onset o;
  o.index = firstAway(b, leadingRest(b, b.t.size(), true));
  if (o.index >= n) {
    o.time = b.t.back();
    return o;
  }
  const Vec2 rest = restOf(b, o);
  const std::size_t end = earlyEnd(b, o.index);
  // Samples seconds apart (a ball nudged while the tracker looked away) carry no line back:
  // it moved by the first of them.
  if (b.t[end - 1] - b.t[o.index] > 2.0 * kEarlyWindow || !(b.t[end - 1] > b.t[o.index])) {
    o.time = b.t[o.index];
    return o;
  }
  const Line line = lineThrough(b, o.index, end);
  const double speed2 = dot(line.v, line.v);
  const double back = speed2 > 0.0 ? line.tm + dot(rest - line.a, line.v) / speed2 : b.t[0];
  const double frame = b.t[laterSample(b, 0)] - b.t[0];
  if (o.index == 1 && frame <= kEarlyWindow && back <= b.t[0] + 0.25 * frame) {
    o.index = 0;
    o.from_start = true;
    o.time = std::min(back, b.t[0]);
    return o;
  }
  o.time = std::clamp(back, b.t[o.index - 1], b.t[o.index]);
  return o;
}

bool nearCushion(Vec2 p, const TableDef& table, double radius) {
  const double margin = radius + 0.01;
  return std::abs(p.x) > table.length / 2.0 - margin || std::abs(p.y) > table.width / 2.0 - margin;
}

// Between samples i - 2, i - 1 and i the ball turns by more than kTurn: a cushion or a ball
// met between frames (steps too short to tell a turn from noise do not count).
bool turns(const RecordedPath& b, std::size_t i) {
  const Vec2 before = at(b, i - 1) - at(b, i - 2);
  const Vec2 step = at(b, i) - at(b, i - 1);
  if (length(before) < kMoved || length(step) < kMoved) return false;
  return dot(before, step) < std::cos(kTurn) * length(before) * length(step);
}

std::size_t cueIndex(const Recording& r, const std::vector<Onset>& onsets) {
  if (!r.cue_ball.empty()) {
    for (std::size_t i = 0; i < r.balls.size(); ++i) {
      if (r.balls[i].name == r.cue_ball) return i;
    }
  }
  std::size_t best = 0;
  double earliest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < r.balls.size(); ++i) {
    const RecordedPath& b = r.balls[i];
    if (onsets[i].index >= b.t.size()) continue;
    // Ties go to the one listed first.
    const double when = onsets[i].time;
    if (when < earliest) {
      best = i;
      earliest = when;
    }
  }
  return best;
}

}  // namespace

RecordedShot readRecording(const Recording& r) {
  RecordedShot s;
  s.recording = &r;
  std::vector<Onset> onsets;
  for (const RecordedPath& b : r.balls) {
    onsets.push_back(onsetOf(b));
    s.end = std::max(s.end, b.t.back());
  }
  const std::size_t cue = cueIndex(r, onsets);
  s.order.push_back(cue);
  for (std::size_t i = 0; i < r.balls.size(); ++i) {
    if (i != cue) s.order.push_back(i);
  }
  for (std::size_t k : s.order) s.rest.push_back(restOf(r.balls[k], onsets[k]));

  const RecordedPath& c = r.balls[cue];
  const Onset o = onsets[cue];
  const std::size_t n = c.t.size();
  const std::size_t start = std::min(o.index, lastStepFrom(c));
  s.cue_onset = c.t[start];
  // The early line ends before a cushion: a ball struck near one meets it within a frame or two.
  std::size_t stop = start + 2;
  while (stop < n && c.t[stop] <= s.cue_onset + kEarlyWindow &&
         !nearCushion(at(c, stop), r.table, r.physics.ball_radius) && !turns(c, stop)) {
    ++stop;
  }
  const Line line = lineThrough(c, start, stop);
  // Its first step in motion bounds the speed from below: a line through a turn is slower.
  // A coarse clock repeats times: the first step runs to the next sample at a later time.
  const std::size_t next = laterSample(c, start);
  const double sample = c.t[next] - c.t[start];
  const double first_step = length(at(c, next) - at(c, start)) / sample;
  const double speed = std::clamp(std::max(length(line.v), first_step), kMinSpeed, kMaxSpeed);
  const Vec2 dir = length(line.v) > 0.0 ? normalized(line.v) : Vec2{1.0, 0.0};
  if (o.from_start) {
    // Struck half a frame before the first sample, as far as the samples can tell.
    s.cue_moving_at_start = true;
    s.line_at = line.a;
    s.line_velocity = line.v;
    s.line_time = line.tm;
    s.rest[0] = s.cueAtStrike(c.t[0] - 0.5 * sample);
  }
  s.strike = line.tm + dot(s.rest[0] - line.a, dir) / speed;
  s.cue_first_move = length(at(c, start) - s.rest[0]);
  s.latest = s.cue_onset;
  s.earliest = s.latest - std::max(0.3, 3.0 * sample);
  s.strike = std::clamp(s.strike, s.earliest, s.latest);
  s.heading = std::atan2(dir.y, dir.x);
  const PhysicsParams& p = r.physics;
  const double mu = p.spin() ? p.sliding_friction : p.rolling_friction;
  s.speed = std::min(speed + mu * p.gravity * std::max(0.0, line.tm - s.strike), kMaxSpeed);

  s.first_event = s.end;
  for (std::size_t k = 1; k < s.order.size(); ++k) {
    const RecordedPath& b = r.balls[s.order[k]];
    const Onset& ob = onsets[s.order[k]];
    if (ob.index < b.t.size()) s.first_event = std::min(s.first_event, ob.time);
  }
  for (std::size_t i = start; i < n && c.t[i] < s.first_event; ++i) {
    const Vec2 off = at(c, i) - (line.a + line.v * (c.t[i] - line.tm));
    if (length(off) > kTurned || nearCushion(at(c, i), r.table, p.ball_radius)) {
      s.first_event = c.t[i];
      break;
    }
  }
  s.first_event = std::max(s.first_event, s.cue_onset + sample);
  return s;
}

void separate(std::vector<Vec2>& rest, const TableDef& table, double radius) {
  const double hx = table.length / 2.0 - radius - 1e-6;
  const double hy = table.width / 2.0 - radius - 1e-6;
  for (int sweep = 0; sweep < 50; ++sweep) {
    bool moved = false;
    for (Vec2& p : rest) {
      const Vec2 clamped{std::clamp(p.x, -hx, hx), std::clamp(p.y, -hy, hy)};
      moved = moved || clamped != p;
      p = clamped;
    }
    for (std::size_t i = 0; i < rest.size(); ++i) {
      for (std::size_t j = i + 1; j < rest.size(); ++j) {
        const Vec2 d = rest[j] - rest[i];
        const double gap = length(d) - 2.0 * radius;
        if (gap >= 1e-6) continue;
        const Vec2 u = length(d) > 0.0 ? normalized(d) : Vec2{1.0, 0.0};
        const Vec2 push = u * (0.5 * (1e-6 - gap) + 1e-7);
        rest[i] -= push;
        rest[j] += push;
        moved = true;
      }
    }
    if (!moved) return;
  }
}

}  // namespace fit
}  // namespace nineball
