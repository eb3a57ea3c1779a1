#include "fit/nelder_mead.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace nineball::fit {
namespace {

using Point = std::vector<double>;

Point along(const Point& from, const Point& to, double by) {
  Point out(from.size());
  for (std::size_t i = 0; i < from.size(); ++i) out[i] = from[i] + by * (to[i] - from[i]);
  return out;
}

class Simplex {
 public:
  Simplex(const std::function<double(const Point&)>& f, int budget, const std::atomic<bool>* cancel)
      : f_(f), budget_(budget), cancel_(cancel) {}

  bool spent() const {
    return evals_ >= budget_ || (cancel_ && cancel_->load(std::memory_order_relaxed));
  }
  double value(const Point& x) {
    ++evals_;
    const double v = f_(x);
    return std::isfinite(v) ? v : std::numeric_limits<double>::infinity();
  }
  int evals() const { return evals_; }

 private:
  const std::function<double(const Point&)>& f_;
  int budget_;
  const std::atomic<bool>* cancel_;
  int evals_ = 0;
};

bool converged(const std::vector<Point>& v, const Point& step, double tolerance) {
  for (std::size_t k = 1; k < v.size(); ++k) {
    for (std::size_t i = 0; i < step.size(); ++i) {
      if (std::abs(v[k][i] - v[0][i]) > tolerance * std::abs(step[i])) return false;
    }
  }
  return true;
}

// A simplex not yet whole (the budget ran out while it was built) spans at least the steps.
Point extentOf(const std::vector<Point>& v, const Point& step) {
  Point extent(step.size(), 0.0);
  for (std::size_t i = 0; i < step.size(); ++i) {
    if (v.size() < step.size() + 1) extent[i] = std::abs(step[i]);
    for (const Point& p : v) extent[i] = std::max(extent[i], std::abs(p[i] - v[0][i]));
  }
  return extent;
}

}  // namespace

Minimum nelderMead(const std::function<double(const Point&)>& f, const Point& x0, const Point& step,
                   int budget, double tolerance, const std::atomic<bool>* cancel) {
  const std::size_t n = x0.size();
  Simplex s(f, std::max(budget, 1), cancel);
  std::vector<Point> v{x0};
  std::vector<double> fv{s.value(x0)};
  for (std::size_t i = 0; i < n && !s.spent(); ++i) {
    Point x = x0;
    x[i] += step[i];
    v.push_back(x);
    fv.push_back(s.value(x));
  }
  std::vector<std::size_t> order(v.size());
  auto sort = [&] {
    std::iota(order.begin(), order.end(), 0);
    // Ties by index keep the order, and so the search, the same on every platform.
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return fv[a] < fv[b]; });
    std::vector<Point> sv;
    std::vector<double> sf;
    for (std::size_t k : order) {
      sv.push_back(v[k]);
      sf.push_back(fv[k]);
    }
    v = sv;
    fv = sf;
  };
  sort();
  while (v.size() == n + 1 && !s.spent() && !converged(v, step, tolerance)) {
    Point centroid(n, 0.0);
    for (std::size_t k = 0; k < n; ++k) {
      for (std::size_t i = 0; i < n; ++i) centroid[i] += v[k][i] / static_cast<double>(n);
    }
    const Point reflected = along(centroid, v[n], -1.0);
    const double fr = s.value(reflected);
    if (fr < fv[0]) {
      const Point expanded = along(centroid, v[n], -2.0);
      const double fe = s.spent() ? fr + 1.0 : s.value(expanded);
      v[n] = fe < fr ? expanded : reflected;
      fv[n] = std::min(fe, fr);
    } else if (fr < fv[n - 1]) {
      v[n] = reflected;
      fv[n] = fr;
    } else {
      const bool outside = fr < fv[n];
      const Point contracted = along(centroid, outside ? reflected : v[n], 0.5);
      const double fc = s.spent() ? fv[n] + 1.0 : s.value(contracted);
      if (fc < (outside ? fr : fv[n])) {
        v[n] = contracted;
        fv[n] = fc;
      } else {
        for (std::size_t k = 1; k <= n && !s.spent(); ++k) {
          v[k] = along(v[0], v[k], 0.5);
          fv[k] = s.value(v[k]);
        }
      }
    }
    sort();
  }
  return {v[0], fv[0], s.evals(), v.size() == n + 1 && converged(v, step, tolerance),
          extentOf(v, step)};
}

}  // namespace nineball::fit
