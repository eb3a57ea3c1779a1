// The balls on screen turn with their physics: in the real game window under Xvfb, a rolling
// ball's number moves across it in the direction of travel by the angle it rolled, the cue
// ball's spot stays put while the stun break slides it, and a pocketed ball is seen sinking.
// Each picture is measured against the same frames played headless.
#include <gtest/gtest.h>

#include <SFML/Graphics/Image.hpp>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "nineball/match.hpp"
#include "render/ball_painter.hpp"
#include "render/ball_spin.hpp"
#include "render/view_transform.hpp"
#include "support/xvfb_run.hpp"
#include "window/game_session.hpp"

namespace nineball {
namespace {

using nineball::testing::kHeight;
using nineball::testing::kWidth;
constexpr double kFrame = 1.0 / 60.0;

// The break, frame by frame, as the window plays and draws it: what each frame shows and how
// far each ball has turned by then.
struct Played {
  std::vector<std::vector<BallState>> balls;
  std::vector<double> time;
  std::vector<std::vector<render::Orientation>> turned;  // by ball index
};

Played playTheBreak(int frames) {
  window::GameSession session{MatchSetup{}};
  EXPECT_TRUE(session.shoot());
  render::BallSpins spins;
  Played p;
  for (int f = 0; f <= frames; ++f) {
    if (f > 0) session.advance(kFrame);
    p.balls.push_back(session.ballsToDraw());
    p.time.push_back(session.drawTime());
    spins.advance(p.balls.back(), p.time.back());
    std::vector<render::Orientation> q;
    for (const BallState& b : p.balls.back()) q.push_back(spins.of(b.id));
    p.turned.push_back(q);
  }
  return p;
}

sf::Image screenshot(int frames, const std::string& env = "") {
  const std::string png =
      "/tmp/nineball-rolling-" + std::to_string(getpid()) + "-" + std::to_string(frames) + ".png";
  const testing::XvfbRun r = testing::runGameUnderXvfb(
      "--frames " + std::to_string(frames) + " --screenshot '" + png + "'", kWidth, kHeight, env);
  EXPECT_EQ(r.status, 0) << r.err;
  sf::Image image;
  EXPECT_TRUE(image.loadFromFile(png));
  std::remove(png.c_str());
  return image;
}

int difference(sf::Color a, render::Rgb b) {
  return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
}

// The centroid (ball radii, y up) of the pixels of a ball of colour `base` at `centre_px`
// that the test `keep` picks among those not showing the lit base colour.
template <typename Keep>
std::optional<Vec2> centroid(const sf::Image& image, Vec2 centre_px, double r_px, render::Rgb base,
                             const Keep& keep) {
  Vec2 sum;
  int n = 0;
  const int reach = static_cast<int>(std::ceil(r_px));
  for (int dy = -reach; dy <= reach; ++dy) {
    for (int dx = -reach; dx <= reach; ++dx) {
      const int x = static_cast<int>(std::floor(centre_px.x)) + dx;
      const int y = static_cast<int>(std::floor(centre_px.y)) + dy;
      const Vec2 s{(x + 0.5 - centre_px.x) / r_px, -(y + 0.5 - centre_px.y) / r_px};
      if (length(s) > 0.9) continue;  // the soft rim mixes in the cloth
      const sf::Color c = image.getPixel(static_cast<unsigned>(x), static_cast<unsigned>(y));
      if (!keep(c, render::litColour(base, s.x, s.y))) continue;
      sum += s;
      ++n;
    }
  }
  if (n < 4) return std::nullopt;
  return sum * (1.0 / n);
}

// The same centroid worked out from the orientation: where a ball of `look` numbered `id`
// shows the colour `keep` picks.
template <typename Keep>
Vec2 expectedCentroid(const render::Orientation& q, const BallLook& look, int id,
                      const Keep& keep) {
  Vec2 sum;
  int n = 0;
  for (double y = -0.9; y <= 0.9; y += 0.01) {
    for (double x = -0.9; x <= 0.9; x += 0.01) {
      if (x * x + y * y > 0.81) continue;
      const Vec3 body = q.toBody({x, y, std::sqrt(1.0 - x * x - y * y)});
      if (keep(render::surfaceColour(look, id, body, nullptr, nullptr))) {
        sum += Vec2{x, y};
        ++n;
      }
    }
  }
  return sum * (1.0 / std::max(1, n));
}

// Where the number disc of a solid is (a blue one: the disc is the only white).
Vec2 expectedDisc(const render::Orientation& q) {
  return expectedCentroid(q, BallLook{{0, 0, 200}, false, true}, 1,
                          [](const render::Shade& c) { return c.r > 0.9; });
}

Vec3 lifted(Vec2 s) {
  return {s.x, s.y, std::sqrt(std::max(0.0, 1.0 - dot(s, s)))};
}

double angleBetween(Vec3 a, Vec3 b) {
  return std::atan2(length(cross(a, b)), dot(a, b));
}

// The cloth contact point's velocity: zero when the ball rolls.
Vec2 slipOf(const BallState& b, double r) {
  return {b.vel.x - r * b.w.y, b.vel.y + r * b.w.x};
}

bool clearOfOthers(const std::vector<BallState>& balls, std::size_t i, double r) {
  for (std::size_t j = 0; j < balls.size(); ++j) {
    if (j != i && !balls[j].pocket && length(balls[j].pos - balls[i].pos) < 3.0 * r) return false;
  }
  return true;
}

TEST(RollingBallsOnScreen, ANumberMovesAcrossItsBallByTheAngleItRolled) {
  ASSERT_TRUE(testing::haveXvfbRun()) << "needs xvfb-run (bash scripts/setup.sh)";
  const Played p = playTheBreak(400);
  const double r = PhysicsParams::real().ball_radius;
  // A solid ball rolling at a pace a frame can follow, its number on the upper half at both
  // frames, away from the others.
  int frame = -1;
  std::size_t i = 0;
  for (int f = 30; f < 399 && frame < 0; ++f) {
    for (std::size_t k = 0; k < p.balls[f].size(); ++k) {
      const BallState& a = p.balls[f][k];
      const BallState& b = p.balls[f + 1][k];
      if (a.id < 1 || a.id > 7 || a.pocket || b.pocket) continue;
      const double v = length(a.vel);
      if (v < 0.3 || v > 0.9 || length(slipOf(a, r)) > 0.01) continue;
      if (p.turned[f][k].toTable({0, 0, 1}).z < 0.65 ||
          p.turned[f + 1][k].toTable({0, 0, 1}).z < 0.65)
        continue;
      if (!clearOfOthers(p.balls[f], k, r) || !clearOfOthers(p.balls[f + 1], k, r)) continue;
      frame = f;
      i = k;
      break;
    }
  }
  ASSERT_GE(frame, 0) << "no ball rolls slowly enough in this break";
  const render::ViewTransform view(TableDef{}, kWidth, kHeight);
  const double r_px = view.px(r);
  const int id = p.balls[frame][i].id;
  std::vector<Vec2> seen, want;
  for (int f : {frame, frame + 1}) {
    const sf::Image image = screenshot(f);
    const BallState& b = p.balls[f][i];
    const auto disc =
        centroid(image, view.toPixels(b.pos), r_px, ballColour(id),
                 [](sf::Color c, render::Rgb lit) { return difference(c, lit) > 90; });
    ASSERT_TRUE(disc) << "ball " << id << ": no number disc seen at frame " << f;
    seen.push_back(*disc);
    want.push_back(expectedDisc(p.turned[f][i]));
    // Where the orientation puts it, within a pixel and a half.
    EXPECT_LT(length(*disc - want.back()), 1.5 / r_px)
        << "ball " << id << " frame " << f << ": disc at (" << disc->x << ", " << disc->y
        << "), expected (" << want.back().x << ", " << want.back().y << ")";
  }
  // In the direction of travel, by the angle it rolled: the orientation turns by the distance
  // over the radius (the physics' own rolling) to a degree, and the number seen on screen turns
  // as the orientation's does, within 3 degrees (both measured the same way, from the centroid
  // of the disc's pixels, which foreshortening pulls a little towards the middle).
  const Vec2 travel = p.balls[frame + 1][i].pos - p.balls[frame][i].pos;
  const Vec2 moved = seen[1] - seen[0];
  EXPECT_GT(dot(normalized(moved), normalized(travel)), std::cos(degToRad(20.0)));
  const double rolled = length(travel) / r;
  const Vec3 up{0.0, 0.0, 1.0};
  const double turned =
      angleBetween(p.turned[frame][i].toTable(up), p.turned[frame + 1][i].toTable(up));
  EXPECT_NEAR(radToDeg(turned), radToDeg(rolled), 1.0);
  const double measured = angleBetween(lifted(seen[0]), lifted(seen[1]));
  const double expected = angleBetween(lifted(want[0]), lifted(want[1]));
  EXPECT_NEAR(radToDeg(measured), radToDeg(expected), 3.0)
      << "ball " << id << " at frames " << frame << "-" << frame + 1 << ", rolled "
      << radToDeg(rolled) << " deg";
}

TEST(RollingBallsOnScreen, TheStunBreaksCueBallSpotStaysPutWhileItSlides) {
  ASSERT_TRUE(testing::haveXvfbRun()) << "needs xvfb-run (bash scripts/setup.sh)";
  const Played p = playTheBreak(2);
  const render::ViewTransform view(TableDef{}, kWidth, kHeight);
  const double r = PhysicsParams::real().ball_radius, r_px = view.px(r);
  std::vector<Vec2> spots;
  for (int f : {1, 2}) {
    const sf::Image image = screenshot(f);
    const BallState& cue = p.balls[f][0];
    ASSERT_EQ(cue.id, kCueBall);
    const auto spot = centroid(image, view.toPixels(cue.pos), r_px, kCueBallColour,
                               [](sf::Color c, render::Rgb) { return c.r > 2 * c.g + 20; });
    ASSERT_TRUE(spot) << "no spot on the cue ball at frame " << f;
    spots.push_back(*spot);
    // Where the physics' spin has turned it, within a pixel and a half.
    const Vec2 want = expectedCentroid(p.turned[f][0], poolBallLook(kCueBall), kCueBall,
                                       [](const render::Shade& c) { return c.r > 2.0 * c.g; });
    EXPECT_LT(length(*spot - want), 1.5 / r_px)
        << "frame " << f << ": spot at (" << spot->x << ", " << spot->y << "), expected (" << want.x
        << ", " << want.y << ")";
  }
  // A stun ball slides: friction has only begun to roll it (the turn grows as t^2), so across
  // the frame it turns by under 2 % of what rolling the same way would turn it.
  const double rolled = length(p.balls[2][0].pos - p.balls[1][0].pos) / r;
  const Vec3 up{0.0, 0.0, 1.0};
  const double turned = angleBetween(p.turned[1][0].toTable(up), p.turned[2][0].toTable(up));
  ASSERT_GT(rolled, 2.0);
  EXPECT_LT(turned, 0.02 * rolled);
  EXPECT_LT(length(spots[1] - spots[0]), 0.1);
}

TEST(RollingBallsOnScreen, APocketedBallSinksAndDarkensIntoItsPocket) {
  ASSERT_TRUE(testing::haveXvfbRun()) << "needs xvfb-run (bash scripts/setup.sh)";
  const Played p = playTheBreak(400);
  int dropped = -1;
  std::size_t i = 0;
  for (int f = 1; f <= 400 && dropped < 0; ++f) {
    for (std::size_t k = 0; k < p.balls[f].size(); ++k) {
      const int id = p.balls[f][k].id;
      if (id >= 1 && id <= 7 && p.balls[f][k].pocket && !p.balls[f - 1][k].pocket) {
        dropped = f;
        i = k;
      }
    }
  }
  ASSERT_GE(dropped, 0) << "the break pockets no solid";
  const int f = dropped + 6;
  const BallState& b = p.balls[f][i];
  const double since = p.time[f] - p.time[dropped];
  ASSERT_LT(since, render::BallPainter::kSinkTime);
  // Where BallPainter puts it: on its way from where it dropped to the pocket's centre.
  const TableGeometry table = buildTable(TableDef{}, PhysicsParams::real().ball_radius);
  Vec2 centre;
  for (const Pocket& pk : table.pockets) {
    if (pk.id == *b.pocket) centre = pk.drop_centre;
  }
  const double e = 1.0 - std::pow(1.0 - since / render::BallPainter::kSinkTime, 2.0);
  const Vec2 at = b.pos + (centre - b.pos) * e;
  const render::ViewTransform view(TableDef{}, kWidth, kHeight);
  const double r_px = view.px(PhysicsParams::real().ball_radius) * (1.0 - 0.3 * e);
  const sf::Image image = screenshot(f);
  // Its colour, darkened, where the pocket is otherwise black.
  const render::Rgb base = ballColour(b.id);
  int coloured = 0, looked = 0;
  for (double dy = -0.5; dy <= 0.5; dy += 0.25) {
    for (double dx = -0.5; dx <= 0.5; dx += 0.25) {
      const Vec2 px = view.toPixels(at) + Vec2{dx, -dy} * r_px;
      const sf::Color c = image.getPixel(static_cast<unsigned>(px.x), static_cast<unsigned>(px.y));
      const render::Rgb lit = render::litColour(base, dx, dy);
      ++looked;
      const int sum = c.r + c.g + c.b, lit_sum = lit.r + lit.g + lit.b;
      // The ball's hue (its strongest channel), darker than it is lit on the cloth.
      const int strongest = base.r >= base.g && base.r >= base.b ? c.r
                            : base.g >= base.b                   ? c.g
                                                                 : c.b;
      if (sum > 30 && sum < lit_sum * 0.9 && 3 * strongest >= sum + 10) ++coloured;
    }
  }
  EXPECT_GE(coloured, looked / 3) << "ball " << b.id << " sinking at frame " << f << ", " << since
                                  << " s after it dropped";
}

TEST(RollingBallsOnScreen, TheCpuDrawsTheBallsAsTheShaderDoes) {
  ASSERT_TRUE(testing::haveXvfbRun()) << "needs xvfb-run (bash scripts/setup.sh)";
  // The break a moment in, balls turned every way: once by the shader, once as a driver
  // without shaders draws it.
  const Played p = playTheBreak(40);
  const sf::Image gpu = screenshot(40);
  const sf::Image cpu = screenshot(40, "NINEBALL_NO_SHADERS=1");
  const render::ViewTransform view(TableDef{}, kWidth, kHeight);
  const double r_px = view.px(PhysicsParams::real().ball_radius);
  long pixels = 0, total = 0, far_off = 0;
  for (const BallState& b : p.balls[40]) {
    if (b.pocket) continue;
    const Vec2 c = view.toPixels(b.pos);
    for (int dy = -static_cast<int>(r_px); dy <= static_cast<int>(r_px); ++dy) {
      for (int dx = -static_cast<int>(r_px); dx <= static_cast<int>(r_px); ++dx) {
        const Vec2 s{(std::floor(c.x) + dx + 0.5 - c.x) / r_px,
                     (std::floor(c.y) + dy + 0.5 - c.y) / r_px};
        if (length(s) > 0.85) continue;  // the rim, where the two blend with the cloth apart
        const auto x = static_cast<unsigned>(std::floor(c.x) + dx);
        const auto y = static_cast<unsigned>(std::floor(c.y) + dy);
        const sf::Color a = gpu.getPixel(x, y), k = cpu.getPixel(x, y);
        const int d = std::abs(a.r - k.r) + std::abs(a.g - k.g) + std::abs(a.b - k.b);
        total += d;
        ++pixels;
        // The glyphs' edges: the shader filters the glyph texture, the CPU takes its nearest
        // texel.
        if (d > 90) ++far_off;
      }
    }
  }
  ASSERT_GT(pixels, 1000);
  std::printf(
      "[ measured ] shader against CPU over %ld ball pixels: mean difference %.2f, %ld far "
      "apart\n",
      pixels, static_cast<double>(total) / pixels, far_off);
  EXPECT_LT(static_cast<double>(total) / pixels, 6.0) << "mean difference per pixel";
  EXPECT_LT(far_off, pixels / 50) << far_off << " of " << pixels << " pixels far apart";
}

}  // namespace
}  // namespace nineball
