#include "physics/model/polynomial.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>

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

// Points of [lo, hi] in order: lo, the sign changes found, hi. A quartic has at most four roots,
// so six places hold any list: no allocation in the search (it runs for every pair of balls
// that may meet).
struct Points {
  std::array<double, 6> x{};
  std::size_t n = 0;

  void push(double v) { x[n++] = v; }
};

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

// bisect's answer for a line, without bisecting. A line evaluates as c1 x + c0 rounded twice,
// and rounding is monotonic, so its sign changes once over the doubles: the boundary bisection
// converges to is the only one, and stepping to it from the line's own root gives the same
// double. Nothing when the line is steep enough at a tiny root that bisection would stop before
// reaching neighbouring doubles (its 200 halvings), or the steps run long: then bisect.
std::optional<double> lineBoundary(const Quartic& f, double a, double b, double sign) {
  const double root = -f.c[0] / f.c[1];
  if (!(root > a && root < b) || !(std::abs(root) > (b - a) * 1e-30)) return std::nullopt;
  const auto positive = [&](double x) { return sign * f(x) > 0.0; };
  double x = root;
  for (int step = 0; step < 64; ++step) {
    if (positive(x)) {
      const double up = std::nextafter(x, b);
      if (!positive(up)) return up;
      x = up;
    } else {
      const double down = std::nextafter(x, a);
      if (down <= a || positive(down)) return x;
      x = down;
    }
  }
  return std::nullopt;
}

double boundary(const Quartic& f, int degree, double a, double b, double sign = 1.0) {
  if (degree == 1) {
    if (const auto x = lineBoundary(f, a, b, sign)) return *x;
  }
  return bisect(f, a, b, sign);
}

// Every root of f in (lo, hi), in order, where f changes sign: the stretches between the
// roots of f' are monotonic.
void signChanges(const Quartic& f, double lo, double hi, Points& out) {
  const int d = degree(f);
  if (d == 0) return;
  Points points;
  points.push(lo);
  if (d >= 2) signChanges(derivative(f), lo, hi, points);
  points.push(hi);
  for (std::size_t i = 0; i + 1 < points.n; ++i) {
    const double a = points.x[i], b = points.x[i + 1];
    const double fa = f(a), fb = f(b);
    if ((fa > 0.0) == (fb > 0.0)) continue;
    const double root = boundary(f, d, a, b, fa > 0.0 ? 1.0 : -1.0);
    if (root > lo && root < hi) out.push(root);
  }
}

// True when f stays clearly positive on [0, hi]: each term is at least c_k hi^k where c_k < 0
// and 0 where c_k >= 0. The margin (1e-9 of the terms' sizes) is far above the rounding of
// evaluating f, so this answers "no crossing" only where the exact search below would: the
// roots found stay bit for bit the same, and most pairs never reach the search.
bool clearlyPositive(const Quartic& f, double hi) {
  double low = f.c[0], size = std::abs(f.c[0]), power = 1.0;
  for (int k = 1; k <= 4; ++k) {
    power *= hi;
    const double term = f.c[k] * power;
    if (term < 0.0) low += term;
    size += std::abs(term);
  }
  return low > 1e-9 * size;
}

}  // namespace

std::optional<double> firstCrossing(const Quartic& f, double lo, double hi) {
  if (!(hi > lo) || !(f(lo) > 0.0)) return std::nullopt;
  if (lo == 0.0 && std::isfinite(hi) && clearlyPositive(f, hi)) return std::nullopt;
  const int d = degree(f);
  Points points;
  points.push(lo);
  if (d >= 2) signChanges(derivative(f), lo, hi, points);
  points.push(hi);
  for (std::size_t i = 0; i + 1 < points.n; ++i) {
    if (f(points.x[i + 1]) <= 0.0) return boundary(f, d, points.x[i], points.x[i + 1]);
  }
  return std::nullopt;
}

}  // namespace nineball::physics
