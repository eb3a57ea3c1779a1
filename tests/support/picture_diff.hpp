#pragma once

// How far two pictures of the game differ, for the tests that compare screenshots.
#include <SFML/Graphics/Image.hpp>
#include <cstdlib>

namespace nineball::testing {

/// The share of pixels (0-1) that differ clearly (by more than 30 over the three channels)
/// between two pictures; 1 for pictures of different sizes or none.
inline double differingShare(const sf::Image& a, const sf::Image& b) {
  if (a.getSize() != b.getSize() || a.getSize().x == 0) return 1.0;
  long n = 0;
  for (unsigned y = 0; y < a.getSize().y; ++y) {
    for (unsigned x = 0; x < a.getSize().x; ++x) {
      const sf::Color p = a.getPixel(x, y), q = b.getPixel(x, y);
      if (std::abs(p.r - q.r) + std::abs(p.g - q.g) + std::abs(p.b - q.b) > 30) ++n;
    }
  }
  return static_cast<double>(n) / (static_cast<double>(a.getSize().x) * a.getSize().y);
}

}  // namespace nineball::testing
