#include "render/table_finish.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "render/palette.hpp"

namespace nineball::render {
namespace {

// A repeatable value in 0-1 for each pixel: the cloth's nap, the wood's pores.
double hash(unsigned x, unsigned y) {
  std::uint32_t h = x * 374761393u + y * 668265263u;
  h = (h ^ (h >> 13)) * 1274126177u;
  return static_cast<double>(h ^ (h >> 16)) / 4294967295.0;
}

bool is(const sf::Color& c, Rgb r) {
  return c.r == r.r && c.g == r.g && c.b == r.b;
}

sf::Color scaled(Rgb c, double k) {
  auto channel = [&](int v) {
    return static_cast<sf::Uint8>(std::clamp(static_cast<int>(std::lround(v * k)), 0, 255));
  };
  return {channel(c.r), channel(c.g), channel(c.b)};
}

// The light over the bed: brightest over the middle, falling off towards the rails.
double poolOfLight(Vec2 m, const TableDef& def) {
  const double u = m.x / (0.5 * def.length + 0.2), v = m.y / (0.5 * def.width + 0.2);
  return 1.07 - 0.16 * (u * u + v * v);
}

// Wood: grain along the rail (u along, v across, metres), wavy, with fine pores.
double grain(double u, double v, double pore) {
  const double wave = 0.004 * std::sin(u * 9.0 + v * 40.0) + 0.002 * std::sin(u * 23.0);
  const double ring = std::sin((v + wave) * 900.0);
  return 0.9 + 0.07 * ring + 0.08 * (pore - 0.5);
}

}  // namespace

void finishTable(sf::Image& picture, const ViewTransform& view, const TableGeometry& table) {
  const sf::Vector2u size = picture.getSize();
  const TableDef& def = table.def;
  const double hx = def.length / 2.0, hy = def.width / 2.0;
  for (unsigned y = 0; y < size.y; ++y) {
    for (unsigned x = 0; x < size.x; ++x) {
      const sf::Color c = picture.getPixel(x, y);
      const Vec2 m = view.toWorld({x + 0.5, y + 0.5});
      const double nap = hash(x, y), coarse = hash(x / 3, y / 3);
      if (is(c, kCloth)) {
        const double k = poolOfLight(m, def) * (1.0 + 0.05 * (nap - 0.5) + 0.03 * (coarse - 0.5));
        picture.setPixel(x, y, scaled(kCloth, k));
      } else if (is(c, kCushion)) {
        const double k = 0.95 * poolOfLight(m, def) * (1.0 + 0.05 * (nap - 0.5));
        picture.setPixel(x, y, scaled(kCushion, k));
      } else if (is(c, kWood)) {
        // The long rails' grain runs along x, the short rails' along y; the wood is lit from
        // the same lamp, its outer edge falling off.
        const bool long_rail = std::abs(m.y) - hy > std::abs(m.x) - hx;
        const double u = long_rail ? m.x : m.y, v = long_rail ? m.y : m.x;
        const double k = grain(u, v, nap) * (0.8 + 0.25 * poolOfLight(m, def));
        picture.setPixel(x, y, scaled(kWood, k));
      } else if (is(c, kDiamond)) {
        picture.setPixel(x, y, scaled(kDiamond, 0.92 + 0.12 * nap));
      }
    }
  }
}

}  // namespace nineball::render
