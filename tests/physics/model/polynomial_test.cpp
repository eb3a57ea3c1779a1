// The contact root finder against the exhaustive search it replaced (every root of every
// derivative isolated, then bisection to neighbouring doubles): on random contact quartics of
// the sizes real scenes give (balls up to 3 m apart, speeds up to 14 m/s, accelerations of the
// cloth and of spin, horizons up to a whole arc's 10 s), both must find a crossing or neither,
// and each answer must be a boundary of f's sign between neighbouring doubles, as close to the
// old one as the rounding of f allows.
#include "physics/model/polynomial.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "nineball/random.hpp"
#include "nineball/vec2.hpp"
#include "physics/model/motion.hpp"

namespace nineball::physics {
namespace {

// --- the root finder as it was, kept here as the reference ---
int oldDegree(const Quartic& f) {
  int d = 4;
  while (d > 0 && f.c[d] == 0.0) --d;
  return d;
}

Quartic oldDerivative(const Quartic& f) {
  Quartic d;
  for (int i = 1; i <= 4; ++i) d.c[i - 1] = i * f.c[i];
  return d;
}

double oldBisect(const Quartic& f, double a, double b, double sign = 1.0) {
  for (int i = 0; i < 200; ++i) {
    const double m = a + (b - a) / 2.0;
    if (m <= a || m >= b) break;
    if (sign * f(m) > 0.0) {
      a = m;
    } else {
      b = m;
    }
  }
  return b;
}

void oldSignChanges(const Quartic& f, double lo, double hi, std::vector<double>& out) {
  const int d = oldDegree(f);
  if (d == 0) return;
  std::vector<double> points{lo};
  if (d >= 2) oldSignChanges(oldDerivative(f), lo, hi, points);
  points.push_back(hi);
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double a = points[i], b = points[i + 1];
    const double fa = f(a), fb = f(b);
    if ((fa > 0.0) == (fb > 0.0)) continue;
    const double root = oldBisect(f, a, b, fa > 0.0 ? 1.0 : -1.0);
    if (root > lo && root < hi) out.push_back(root);
  }
}

std::optional<double> oldFirstCrossing(const Quartic& f, double lo, double hi) {
  if (!(hi > lo) || !(f(lo) > 0.0)) return std::nullopt;
  std::vector<double> points{lo};
  if (oldDegree(f) >= 2) oldSignChanges(oldDerivative(f), lo, hi, points);
  points.push_back(hi);
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    if (f(points[i + 1]) <= 0.0) return oldBisect(f, points[i], points[i + 1]);
  }
  return std::nullopt;
}

bool sameBits(std::optional<double> a, std::optional<double> b) {
  if (a.has_value() != b.has_value()) return false;
  return !a || std::memcmp(&*a, &*b, sizeof(double)) == 0;
}

// |d + e s + g s^2 / 2|^2 - D^2: the separation of two balls on their paths.
Quartic contactQuartic(Vec2 d, Vec2 e, Vec2 g, double distance) {
  return {{dot(d, d) - distance * distance, 2.0 * dot(d, e), dot(e, e) + dot(d, g), dot(e, g),
           0.25 * dot(g, g)}};
}

// The size of f's terms at x: what its rounding is measured against.
double termSize(const Quartic& q, double x) {
  double size = 0.0, power = 1.0;
  for (double c : q.c) {
    size += std::abs(c) * power;
    power *= std::abs(x);
  }
  return size;
}

struct Agreement {
  long met = 0, never = 0, same_bits = 0, grazes = 0;
  double worst = 0.0;  // largest |new - old| / (1 + |old|)
};

// Compares one answer with the old search's. A crossing the two disagree on may only be a
// graze, where f's dip below zero is within rounding of its terms (1e-12 of them).
void compare(const Quartic& q, double lo, double hi, Agreement& out) {
  const auto want = oldFirstCrossing(q, lo, hi);
  const auto got = firstCrossing(q, lo, hi);
  if (sameBits(got, want)) ++out.same_bits;
  if (got.has_value() != want.has_value()) {
    const double x = got ? *got : *want;
    ASSERT_LT(std::abs(q(x)), 1e-12 * termSize(q, x)) << "a crossing only one search finds";
    ++out.grazes;
    return;
  }
  if (!got) {
    ++out.never;
    return;
  }
  ++out.met;
  // A boundary of the sign: not positive here, positive at the double before.
  ASSERT_LE(q(*got), 0.0);
  ASSERT_GT(q(std::nextafter(*got, lo)), 0.0);
  const double gap = std::abs(*got - *want) / (1.0 + std::abs(*want));
  if (gap > 1e-12) {
    // Apart by more than rounding: only where f is flat at the root, its value noise.
    ASSERT_LT(std::abs(q(*want)), 1e-12 * termSize(q, *want));
  }
  out.worst = std::max(out.worst, gap);
}

TEST(Polynomial, FirstCrossingAgreesWithTheExhaustiveSearch) {
  std::uint64_t rng = 2026;
  const double D = 2.0 * 0.028575;
  Agreement a;
  for (int k = 0; k < 300000; ++k) {
    // Near pairs more often than far ones, as the event search meets them.
    const double spread = k % 3 == 0 ? 3.0 : k % 3 == 1 ? 0.3 : 0.07;
    const Vec2 d{uniform(rng, -spread, spread), uniform(rng, -spread, spread)};
    const Vec2 e{uniform(rng, -14.0, 14.0), uniform(rng, -14.0, 14.0)};
    const Vec2 g = k % 4 == 0 ? Vec2{} : Vec2{uniform(rng, -30.0, 30.0), uniform(rng, -30.0, 30.0)};
    const double horizon = k % 5 == 0   ? uniform(rng, 0.0, 1e-3)
                           : k % 5 == 1 ? uniform(rng, 0.0, 10.0)
                                        : uniform(rng, 0.0, 2.0);
    const Quartic q = contactQuartic(d, e, g, D);
    compare(q, 0.0, horizon, a);
    // The same quartic from a later start (the search past a turning point).
    compare(q, 0.5 * horizon, horizon, a);
    if (HasFatalFailure()) return;
  }
  std::printf(
      "[ measured ] 600000 searches: %ld met, %ld never, %ld grazes only one saw; %ld the same "
      "bits; worst gap %.3g relative\n",
      a.met, a.never, a.grazes, a.same_bits, a.worst);
  EXPECT_GT(a.met, 10000);
  EXPECT_GT(a.never, 10000);
  EXPECT_LT(a.grazes, 10);
}

TEST(Polynomial, LowDegreesAndEdges) {
  // Straight lines and parabolas (cushion heights), a double root, no room, not positive at lo.
  const Quartic line{{1.0, -2.0, 0.0, 0.0, 0.0}};
  EXPECT_TRUE(sameBits(firstCrossing(line, 0.0, 1.0), oldFirstCrossing(line, 0.0, 1.0)));
  EXPECT_NEAR(*firstCrossing(line, 0.0, 1.0), 0.5, 1e-15);
  const Quartic touch{{1.0, -2.0, 1.0, 0.0, 0.0}};  // (1 - x)^2: touches 0 at 1
  EXPECT_TRUE(sameBits(firstCrossing(touch, 0.0, 2.0), oldFirstCrossing(touch, 0.0, 2.0)));
  EXPECT_FALSE(firstCrossing(line, 1.0, 1.0));
  EXPECT_FALSE(firstCrossing(line, 0.6, 1.0));
  const Quartic far{{5.0, -1.0, 0.0, 0.0, 0.0}};
  EXPECT_FALSE(firstCrossing(far, 0.0, 4.9));
  EXPECT_NEAR(*firstCrossing(far, 0.0, 5.1), 5.0, 1e-14);
  // No horizon (a ball on frictionless cloth): the crossing is found wherever it lies.
  EXPECT_NEAR(*firstCrossing(far, 0.0, kNever), 5.0, 1e-14);
  const Quartic away{{1.0, 2.0, 1.0, 0.0, 0.0}};  // (1 + x)^2: never zero past 0
  EXPECT_FALSE(firstCrossing(away, 0.0, kNever));
}

}  // namespace
}  // namespace nineball::physics
