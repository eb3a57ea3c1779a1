#include "physics/model/polynomial.hpp"

#include <cmath>
#include <vector>

namespace nineball::physics {
namespace {

int degree(const Quartic& f) {
  int d = 4;
  while (d > 0 && f.c[d] == 0.0) --d;
  return d;
}

Quartic derivative(const Quartic& f) {
  Quartic d;
  for (int i = 1; i <= 4; ++i) d.c[i - 1] = i * f.c[i];
  return d;
}

// The boundary between a, where sign f > 0, and b, where it is <= 0, bisected down to adjacent
// doubles.
double bisect(const Quartic& f, double a, double b, double sign = 1.0) {
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

// Every root of f in (lo, hi), in order, where f changes sign: the stretches between the
// roots of f' are monotonic.
void signChanges(const Quartic& f, double lo, double hi, std::vector<double>& out) {
  const int d = degree(f);
  if (d == 0) return;
  std::vector<double> points{lo};
  if (d >= 2) signChanges(derivative(f), lo, hi, points);
  points.push_back(hi);
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double a = points[i], b = points[i + 1];
    const double fa = f(a), fb = f(b);
    if ((fa > 0.0) == (fb > 0.0)) continue;
    const double root = bisect(f, a, b, fa > 0.0 ? 1.0 : -1.0);
    if (root > lo && root < hi) out.push_back(root);
  }
}

}  // namespace

std::optional<double> firstCrossing(const Quartic& f, double lo, double hi) {
  if (!(hi > lo) || !(f(lo) > 0.0)) return std::nullopt;
  std::vector<double> points{lo};
  if (degree(f) >= 2) signChanges(derivative(f), lo, hi, points);
  points.push_back(hi);
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    if (f(points[i + 1]) <= 0.0) return bisect(f, points[i], points[i + 1]);
  }
  return std::nullopt;
}

}  // namespace nineball::physics
