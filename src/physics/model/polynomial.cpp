#include "physics/model/polynomial.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>

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

// The margins (1e-9 of the size of f's, or f''s, terms over [0, b]) are far above the rounding of
// the shift and of evaluating f, so these answer only where the exact search would agree.
// What f's Taylor coefficients at a, g_k, prove over [a, b]: f(a + x) >= g_0 + the g_k w^k with
// g_k < 0, and f'(a + x) <= g_1 + the k g_k w^(k-1) with g_k > 0, for x in [0, w].
struct Stretch {
  bool positive;  ///< f stays clearly above zero
  bool falling;   ///< f' stays clearly below zero
};

Stretch look(const Quartic& f, double a, double b) {
  std::array<double, 5> g = f.c;
  for (int k = 0; k < 4; ++k) {
    for (int j = 3; j >= k; --j) g[j] += a * g[j + 1];
  }
  const double w = b - a, reach = std::abs(a) + w;
  double low = g[0], size = std::abs(f.c[0]);
  double high = g[1], slope_size = std::abs(f.c[1]);
  double power = 1.0, reach_power = 1.0;
  for (int k = 1; k <= 4; ++k) {
    if (k >= 2) {
      if (g[k] > 0.0) high += k * g[k] * power;  // power is w^(k-1) here
      slope_size += k * std::abs(f.c[k]) * reach_power;
    }
    power *= w;
    reach_power *= reach;
    if (g[k] < 0.0) low += g[k] * power;
    size += std::abs(f.c[k]) * reach_power;
  }
  return {low > 1e-9 * size, high < -1e-9 * slope_size};
}

// The sign boundary of a falling f in (a, b], f(a) > 0 >= f(b): Illinois false position down to
// neighbouring doubles, the first where f <= 0 returned, as bisection would, in a dozen steps
// rather than fifty.
double fallingRoot(const Quartic& f, double lo, double hi) {
  double f_lo = f(lo), f_hi = f(hi);
  int side = 0;
  for (int i = 0; i < 300; ++i) {
    if (!(std::nextafter(lo, hi) < hi)) break;
    double x = lo + (hi - lo) * (f_lo / (f_lo - f_hi));
    if (!(x > lo && x < hi)) x = lo + (hi - lo) / 2.0;
    if (!(x > lo && x < hi)) break;
    const double fx = f(x);
    if (fx > 0.0) {
      lo = x;
      f_lo = fx;
      if (side > 0) f_hi *= 0.5;
      side = 1;
    } else {
      hi = x;
      f_hi = fx;
      if (side < 0) f_lo *= 0.5;
      side = -1;
    }
  }
  return hi;
}

// The exact search on [lo, hi], f(lo) > 0: every sign change of f' (and of its derivatives in
// turn) isolated, then the first stretch that ends at or below zero bisected.
std::optional<double> exactFirstCrossing(const Quartic& f, double lo, double hi) {
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

// Halvings before the exact search takes over: most of a long horizon is cleared by the bound
// in a few, and the exact search then isolates roots over a 1/256th of it alone.
constexpr int kMaxDepth = 8;

// The first crossing in [a, b], f(a) > 0: stretches the bound clears are skipped, the rest
// halved, left first, down to kMaxDepth, where the exact search answers.
std::optional<double> scan(const Quartic& f, double a, double b, int depth) {
  const Stretch st = look(f, a, b);
  if (st.positive) return std::nullopt;
  if (st.falling) {
    // One crossing at most: there, if f has reached zero by b.
    if (f(b) > 0.0) return std::nullopt;
    return fallingRoot(f, a, b);
  }
  if (depth == kMaxDepth) return exactFirstCrossing(f, a, b);
  const double m = a + (b - a) / 2.0;
  if (!(m > a && m < b)) return exactFirstCrossing(f, a, b);
  if (auto root = scan(f, a, m, depth + 1)) return root;
  // Nothing in [a, m]: f(m) > 0, cleared by the bound or checked by the exact search.
  return scan(f, m, b, depth + 1);
}

// The boundary bisection would find near `root`, stepped to over neighbouring doubles: the last
// double where f > 0 before the first where f <= 0. Nothing when the steps run long (f's sign
// is noise over a wide stretch there) or leave (lo, hi].
std::optional<double> stepToBoundary(const Quartic& f, double root, double lo, double hi) {
  if (!(root > lo) || !(root <= hi)) return std::nullopt;
  double x = root;
  for (int step = 0; step < 64; ++step) {
    if (f(x) > 0.0) {
      if (x >= hi) return std::nullopt;
      x = std::nextafter(x, hi);
    } else {
      const double down = std::nextafter(x, lo);
      if (down <= lo) return std::nullopt;
      if (f(down) > 0.0) return x;
      x = down;
    }
  }
  return std::nullopt;
}

// A line's or a parabola's first crossing from its roots in closed form (f(lo) > 0), without
// isolating anything: the roots are computed without cancellation, and the answer stepped to
// the sign boundary. `decided` is false where the closed form cannot be trusted (a double root,
// a root at the horizon, a sign that is noise), and the exact search answers.
std::optional<double> closedFormCrossing(const Quartic& f, int d, double lo, double hi,
                                         bool& decided) {
  decided = false;
  const double c0 = f.c[0], c1 = f.c[1], c2 = d == 2 ? f.c[2] : 0.0;
  double roots[2];
  int n = 0;
  if (d == 1) {
    roots[n++] = -c0 / c1;
  } else {
    const double disc = c1 * c1 - 4.0 * c2 * c0;
    if (!(disc > 1e-12 * (c1 * c1 + std::abs(4.0 * c2 * c0)))) return std::nullopt;
    const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
    roots[0] = q / c2;
    roots[1] = c0 / q;
    if (roots[0] > roots[1]) std::swap(roots[0], roots[1]);
    n = 2;
  }
  // The first root past lo where f goes from above zero to below it.
  for (int k = 0; k < n; ++k) {
    if (!(roots[k] > lo)) continue;
    const double slope = c1 + 2.0 * c2 * roots[k];
    if (!(slope < 0.0)) return std::nullopt;  // f(lo) > 0 puts a falling root first
    if (roots[k] > hi) {
      decided = f(hi) > 0.0;
      return std::nullopt;
    }
    auto x = stepToBoundary(f, roots[k], lo, hi);
    decided = x.has_value();
    return x;
  }
  decided = f(hi) > 0.0;
  return std::nullopt;
}

}  // namespace

std::optional<double> firstCrossing(const Quartic& f, double lo, double hi) {
  if (!(hi > lo) || !(f(lo) > 0.0)) return std::nullopt;
  const int d = degree(f);
  if (!std::isfinite(hi)) {
    // No horizon (a ball that never slows): every root lies within Cauchy's bound,
    // 1 + max |c_k / c_d|, so the search ends there (doubled, clear of its rounding).
    if (d == 0) return std::nullopt;
    double bound = 0.0;
    for (int k = 0; k < d; ++k) bound = std::max(bound, std::abs(f.c[k] / f.c[d]));
    hi = 2.0 * (1.0 + bound);
    if (!(hi > lo) || !std::isfinite(hi)) return std::nullopt;
  }
  if (d == 1 || d == 2) {
    bool decided = false;
    const auto x = closedFormCrossing(f, d, lo, hi, decided);
    if (decided) return x;
  }
  return scan(f, lo, hi, 0);
}

}  // namespace nineball::physics
