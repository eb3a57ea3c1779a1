#include <array>
#include <cmath>

#include "nineball/random.hpp"
#include "nineball/scenes.hpp"

namespace nineball {
namespace {

// The spots of a triangle with `rows` rows, apex on the foot spot, rows growing away from the
// head: row r holds r + 1 balls. Spot i of row r is number r(r+1)/2 + i.
std::vector<Vec2> triangleSpots(const TableDef& table, double ball_radius, double gap, int rows) {
  const double d = 2.0 * ball_radius + gap;  // centre to centre of neighbours
  const double row_step = d * std::sqrt(3.0) / 2.0;
  const Vec2 foot{table.length / 4.0, 0.0};
  std::vector<Vec2> spots;
  for (int row = 0; row < rows; ++row) {
    for (int i = 0; i <= row; ++i) spots.push_back({foot.x + row * row_step, (i - row / 2.0) * d});
  }
  return spots;
}

template <std::size_t N>
void shuffle(std::array<int, N>& v, std::uint64_t& state) {
  for (std::size_t i = N - 1; i > 0; --i) {
    const std::size_t j = splitmix64(state) % (i + 1);
    std::swap(v[i], v[j]);
  }
}

void put(std::vector<BallState>& balls, int id, Vec2 p) {
  balls.push_back(BallState::at(id, p));
}

}  // namespace

std::vector<BallState> rackEightBall(const TableDef& table, double ball_radius, std::uint64_t seed,
                                     double gap) {
  const std::vector<Vec2> spots = triangleSpots(table, ball_radius, gap, 5);
  constexpr int kCentre = 4;                          // the middle of the third row
  constexpr std::array<int, 2> kBackCorners{10, 14};  // the ends of the fifth row
  std::uint64_t state = seed;
  std::array<int, 7> solids{1, 2, 3, 4, 5, 6, 7};
  std::array<int, 7> stripes{9, 10, 11, 12, 13, 14, 15};
  shuffle(solids, state);
  shuffle(stripes, state);
  const bool solid_left = (splitmix64(state) & 1) == 0;
  std::vector<BallState> balls;
  put(balls, 8, spots[kCentre]);
  put(balls, solids[0], spots[kBackCorners[solid_left ? 0 : 1]]);
  put(balls, stripes[0], spots[kBackCorners[solid_left ? 1 : 0]]);
  // The other six of each group fill the twelve spots left, in an order from the seed.
  std::array<int, 12> rest{};
  for (std::size_t i = 0; i < 6; ++i) {
    rest[i] = solids[i + 1];
    rest[i + 6] = stripes[i + 1];
  }
  shuffle(rest, state);
  std::size_t next = 0;
  for (int i = 0; i < static_cast<int>(spots.size()); ++i) {
    if (i == kCentre || i == kBackCorners[0] || i == kBackCorners[1]) continue;
    put(balls, rest[next++], spots[i]);
  }
  return balls;
}

std::vector<BallState> rackTenBall(const TableDef& table, double ball_radius, std::uint64_t seed,
                                   double gap) {
  const std::vector<Vec2> spots = triangleSpots(table, ball_radius, gap, 4);
  constexpr int kApex = 0;
  constexpr int kCentre = 4;  // the middle of the third row
  std::uint64_t state = seed;
  std::array<int, 8> others{2, 3, 4, 5, 6, 7, 8, 9};
  shuffle(others, state);
  std::vector<BallState> balls;
  put(balls, 1, spots[kApex]);
  put(balls, 10, spots[kCentre]);
  std::size_t next = 0;
  for (int i = 0; i < static_cast<int>(spots.size()); ++i) {
    if (i == kApex || i == kCentre) continue;
    put(balls, others[next++], spots[i]);
  }
  return balls;
}

std::vector<BallState> rackFor(rules::Game game, const TableDef& table, double ball_radius,
                               std::uint64_t seed, double gap) {
  switch (game) {
    case rules::Game::EightBall:
      return rackEightBall(table, ball_radius, seed, gap);
    case rules::Game::TenBall:
      return rackTenBall(table, ball_radius, seed, gap);
    case rules::Game::NineBall:
      break;
  }
  return rackNineBall(table, ball_radius, seed, gap);
}

}  // namespace nineball
