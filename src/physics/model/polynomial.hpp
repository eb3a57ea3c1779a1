#pragma once

#include <array>
#include <optional>

namespace nineball::physics {

/// A polynomial of degree at most 4: c[0] + c[1] x + ... + c[4] x^4.
struct Quartic {
  std::array<double, 5> c{};

  double operator()(double x) const {
    return (((c[4] * x + c[3]) * x + c[2]) * x + c[1]) * x + c[0];
  }
};

/// The first x in (lo, hi] at which f, positive at lo, reaches zero or below, to full double
/// precision (the last x at which f is still positive is the double just before it).
/// The roots of the derivatives split [lo, hi] into stretches on which f is monotonic; the
/// first stretch that ends at or below zero holds the crossing, found by bisection.
std::optional<double> firstCrossing(const Quartic& f, double lo, double hi);

}  // namespace nineball::physics
