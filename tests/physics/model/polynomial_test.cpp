// The contact root finder against the one it replaced (the same search with a list allocated
// per call and no early answer): on random contact quartics of the sizes real scenes give
// (balls up to 3 m apart, speeds up to 14 m/s, accelerations of the cloth and of spin), every
// answer must be the same double, bit for bit, or the same "never".
#include "physics/model/polynomial.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <vector>

#include "nineball/random.hpp"
#include "nineball/vec2.hpp"

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

TEST(Polynomial, FirstCrossingIsTheSameDoubleAsTheSearchItReplaced) {
  std::uint64_t rng = 2026;
  const double D = 2.0 * 0.028575;
  long met = 0, never = 0;
  for (int k = 0; k < 300000; ++k) {
    // Near pairs more often than far ones, as the event search meets them.
    const double spread = k % 3 == 0 ? 3.0 : k % 3 == 1 ? 0.3 : 0.07;
    const Vec2 d{uniform(rng, -spread, spread), uniform(rng, -spread, spread)};
    const Vec2 e{uniform(rng, -14.0, 14.0), uniform(rng, -14.0, 14.0)};
    const Vec2 g = k % 4 == 0 ? Vec2{} : Vec2{uniform(rng, -30.0, 30.0), uniform(rng, -30.0, 30.0)};
    const double horizon = k % 5 == 0 ? uniform(rng, 0.0, 1e-3) : uniform(rng, 0.0, 2.0);
    const Quartic q = contactQuartic(d, e, g, D);
    const auto want = oldFirstCrossing(q, 0.0, horizon);
    const auto got = firstCrossing(q, 0.0, horizon);
    ASSERT_TRUE(sameBits(got, want)) << "case " << k;
    want ? ++met : ++never;
    // The same quartic from a later start (the search past a turning point).
    const double lo = 0.5 * horizon;
    ASSERT_TRUE(sameBits(firstCrossing(q, lo, horizon), oldFirstCrossing(q, lo, horizon)));
  }
  std::printf("[ measured ] 300000 contact quartics: %ld met, %ld never, every one the same bits\n",
              met, never);
  EXPECT_GT(met, 10000);
  EXPECT_GT(never, 10000);
}

TEST(Polynomial, LowDegreesAndEdgesAsBefore) {
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
}

}  // namespace
}  // namespace nineball::physics
