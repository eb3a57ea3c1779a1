// The real game window under Xvfb: its screenshots checked pixel by pixel against the physics.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <SFML/Graphics/Image.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "io/match_json.hpp"
#include "nineball/match.hpp"
#include "render/ball_spin.hpp"
#include "render/cue_stick_shape.hpp"
#include "render/palette.hpp"
#include "render/view_transform.hpp"
#include "support/file_text.hpp"
#include "support/xvfb_run.hpp"
#include "window/game_session.hpp"

using nineball::BallState;
using nineball::kCueBall;
using nineball::Match;
using nineball::MatchSetup;
using nineball::TurnInput;
using nineball::Vec2;
using nineball::render::Rgb;
using nineball::render::ViewTransform;

namespace {

using nineball::testing::shellWord;

using nineball::testing::fileText;

using nineball::testing::kHeight;
using nineball::testing::kWidth;
// Each colour channel may differ this much from the palette (there is no antialiasing).
constexpr int kTolerance = 24;

using nineball::testing::haveXvfbRun;
using nineball::testing::XvfbRun;

// Runs the game binary under a fresh virtual display with the given arguments.
XvfbRun runUnderXvfb(const std::string& args, const std::string& env = "") {
  return nineball::testing::runGameUnderXvfb(args, kWidth, kHeight, env);
}

// A leak report (sanitizer builds only) may name the GL driver, never nineball's own code.
void expectNoLeakOfOurs(const XvfbRun& r) {
  if (r.err.find("LeakSanitizer") == std::string::npos) return;
  EXPECT_EQ(r.err.find("nineball::"), std::string::npos) << r.err;
}

bool near(sf::Color c, Rgb want) {
  return std::abs(c.r - want.r) <= kTolerance && std::abs(c.g - want.g) <= kTolerance &&
         std::abs(c.b - want.b) <= kTolerance;
}

std::string show(sf::Color c) {
  return "(" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) + ")";
}

// Inside a convex quad (pixel coordinates), grown by `margin` pixels.
bool insideQuad(const std::array<Vec2, 4>& q, Vec2 p, double margin) {
  for (int i = 0; i < 4; ++i) {
    const Vec2 a = q[i], b = q[(i + 1) % 4];
    const Vec2 edge = normalized(b - a);
    // The quad's corners run one way round; accept either.
    if (nineball::cross(edge, p - a) > margin) {
      for (int k = 0; k < 4; ++k) {
        const Vec2 c = q[k], d = q[(k + 1) % 4];
        if (nineball::cross(normalized(d - c), p - c) < -margin) return false;
      }
      return true;
    }
  }
  for (int i = 0; i < 4; ++i) {
    const Vec2 a = q[i], b = q[(i + 1) % 4];
    if (nineball::cross(normalized(b - a), p - a) > margin) return false;
  }
  return true;
}

// What the picture must show: the balls where the physics puts them and the stick's place.
struct Scene {
  std::vector<BallState> balls;
  double radius = 0.028575;
  std::optional<std::array<Vec2, 4>> stick;  // pixels
};

class Picture {
 public:
  Picture(const std::string& path, const Scene& scene)
      : scene_(scene), view_(nineball::TableDef{}, kWidth, kHeight) {
    loaded_ = image_.loadFromFile(path);
  }

  bool loaded() const { return loaded_; }
  sf::Vector2u size() const { return image_.getSize(); }

  bool underStick(Vec2 px) const {
    // The stick's shadow falls a few pixels down and right of it.
    return scene_.stick &&
           (insideQuad(*scene_.stick, px, 4.0) ||
            insideQuad(*scene_.stick, px - Vec2{view_.px(0.006), view_.px(0.009)}, 4.0));
  }

  sf::Color at(Vec2 px) const {
    return image_.getPixel(static_cast<unsigned>(std::lround(px.x)),
                           static_cast<unsigned>(std::lround(px.y)));
  }

  // The cloth round the table's centre, away from balls and the stick (the aim line may
  // cross it: most, not all, of the patch must be cloth).
  void expectClothAtCentre() const {
    const Vec2 c = view_.toPixels({0.0, 0.0});
    int looked = 0, cloth = 0;
    for (int dy = -6; dy <= 6; ++dy) {
      for (int dx = -6; dx <= 6; ++dx) {
        const Vec2 p = c + Vec2{static_cast<double>(dx), static_cast<double>(dy)};
        bool clear = !underStick(p);
        for (const BallState& b : scene_.balls) {
          if (!b.pocket && length(view_.toPixels(b.pos) - p) < view_.px(scene_.radius) * 1.4) {
            clear = false;
          }
        }
        if (!clear) continue;
        ++looked;
        if (near(at(p), nineball::render::kCloth)) ++cloth;
      }
    }
    ASSERT_GT(looked, 40);
    EXPECT_GE(cloth, looked * 3 / 4) << "cloth at the centre: " << cloth << " of " << looked
                                     << " pixels, centre " << show(at(c));
  }

  // Each ball's colour at points round its centre, lit where they are. A ball that has rolled
  // may show its number disc or a stripe's white there instead: no point may show anything but
  // a colour of that ball, and a solid its own at two points at least (the samples lie in two
  // groups on either side, 90 degrees apart over the top; the number disc, 30 degrees wide,
  // covers one group at most, and the other disc is then under the ball).
  void expectBallColours() const {
    static const Vec2 kSamples[] = {
        {0.7, 0.0}, {-0.7, 0.0}, {0.68, -0.25}, {-0.68, -0.25}, {0.68, 0.25}};
    int balls_checked = 0;
    for (const BallState& b : scene_.balls) {
      if (b.pocket) continue;
      const Rgb colour = nineball::render::ballColour(b.id);
      int seen = 0, own = 0;
      for (Vec2 s : kSamples) {
        const Vec2 p = view_.toPixels(b.pos + s * scene_.radius);
        if (underStick(p)) continue;
        ++seen;
        // Lit at the centre of the pixel read: the light changes fast towards the rim.
        const Vec2 c = view_.toPixels(b.pos);
        const double r_px = view_.px(scene_.radius);
        const double sx = (std::lround(p.x) + 0.5 - c.x) / r_px;
        const double sy = -(std::lround(p.y) + 0.5 - c.y) / r_px;
        const Rgb want = nineball::render::litColour(colour, sx, sy);
        const sf::Color got = at(p);
        const bool mine = near(got, want);
        own += mine ? 1 : 0;
        // Else the number disc: white, the ink, or a grey of the glyph's soft edge; or the cue
        // ball's spot.
        const bool grey = std::abs(got.r - got.g) < 16 && std::abs(got.g - got.b) < 16;
        const bool spot =
            b.id == nineball::kCueBall &&
            near(got, nineball::render::litColour(nineball::render::kCueSpot, sx, sy));
        EXPECT_TRUE(mine || grey || spot)
            << "ball " << b.id << " at (" << b.pos.x << ", " << b.pos.y << ") m, pixel (" << p.x
            << ", " << p.y << "): " << show(at(p)) << ", expected "
            << show(sf::Color(want.r, want.g, want.b));
      }
      if (seen >= 2) ++balls_checked;
      if (seen == 5 && !nineball::isStripe(b.id) && b.id != nineball::kCueBall) {
        EXPECT_GE(own, 2) << "ball " << b.id << ": its colour at " << own << " of " << seen;
      }
    }
    EXPECT_GE(balls_checked, 5);
  }

  // The stick's shaft, 0.4 m behind its tip, in maple.
  void expectStick(Vec2 cue, double heading) const {
    const Vec2 dir = nineball::fromAngle(heading);
    const Vec2 shaft =
        nineball::render::CueStickShape::tip(cue, dir, scene_.radius, 0.0) - dir * 0.4;
    const Vec2 p = view_.toPixels(shaft);
    if (p.x < 0 || p.y < 0 || p.x >= kWidth || p.y >= kHeight) return;
    EXPECT_TRUE(near(at(p), Rgb{226, 196, 142})) << "cue stick shaft: " << show(at(p));
  }

  const ViewTransform& view() const { return view_; }

 private:
  Scene scene_;
  ViewTransform view_;
  sf::Image image_;
  bool loaded_ = false;
};

std::string tempPath(const std::string& tag) {
  return "/tmp/nineball-test-" + tag + "-" + std::to_string(getpid()) + ".png";
}

Scene sceneOf(const nineball::window::GameSession& session) {
  Scene s;
  s.balls = session.ballsToDraw();
  s.radius = session.match().world().physics().ball_radius;
  if (session.phase() == nineball::window::Phase::Aiming) {
    const Vec2 dir = nineball::fromAngle(session.heading());
    const auto outline =
        nineball::render::CueStickShape::outline(session.cuePosition(), dir, s.radius, 0.0);
    const ViewTransform view(nineball::TableDef{}, kWidth, kHeight);
    std::array<Vec2, 4> px;
    for (int i = 0; i < 4; ++i) px[i] = view.toPixels(outline[i]);
    s.stick = px;
  }
  return s;
}

// The same balls from the physics alone: a Match played through the same turns.
std::vector<BallState> physicsBalls(const MatchSetup& setup, const std::vector<TurnInput>& turns) {
  Match m(setup);
  for (const TurnInput& t : turns) m.play(t);
  return m.balls();
}

void expectSameObjectBalls(const std::vector<BallState>& drawn,
                           const std::vector<BallState>& physics) {
  for (const BallState& p : physics) {
    if (p.id == kCueBall) continue;
    for (const BallState& d : drawn) {
      if (d.id != p.id) continue;
      EXPECT_EQ(d.pocket.has_value(), p.pocket.has_value()) << p.id;
      if (!p.pocket) {
        EXPECT_EQ(d.pos, p.pos) << p.id;
      }
    }
  }
}

}  // namespace

TEST(GameWindow, ScreenshotsUnderXvfbShowThePhysics) {
  ASSERT_TRUE(haveXvfbRun()) << "xvfb-run not found: the game window test needs a virtual "
                                "display; install xvfb and xauth (bash scripts/setup.sh)";

  {
    SCOPED_TRACE("the rack before the break");
    const std::string png = tempPath("rack");
    const XvfbRun r = runUnderXvfb("--screenshot " + shellWord(png));
    ASSERT_EQ(r.status, 0) << r.err;
    expectNoLeakOfOurs(r);
    MatchSetup setup;
    const nineball::window::GameSession session(setup);
    expectSameObjectBalls(session.ballsToDraw(), physicsBalls(setup, {}));
    const Picture pic(png, sceneOf(session));
    ASSERT_TRUE(pic.loaded());
    ASSERT_EQ(pic.size(), sf::Vector2u(kWidth, kHeight));
    pic.expectClothAtCentre();
    pic.expectBallColours();
    pic.expectStick(session.cuePosition(), session.heading());
    std::remove(png.c_str());
  }
  {
    SCOPED_TRACE("the position after a match script");
    const std::string script_path = "/tmp/nineball-test-script-" + std::to_string(getpid());
    const std::string script =
        R"({"rules": "wpa", "seed": 3, "turns": [{"heading_deg": 0.4, "speed": 9}]})";
    std::ofstream(script_path) << script;
    const std::string png = tempPath("script");
    const XvfbRun r =
        runUnderXvfb("--script " + shellWord(script_path) + " --screenshot " + shellWord(png));
    std::remove(script_path.c_str());
    ASSERT_EQ(r.status, 0) << r.err;
    expectNoLeakOfOurs(r);
    const auto parsed = nineball::io::parseMatchScript(script);
    const auto& ms = std::get<nineball::io::MatchScript>(parsed);
    nineball::window::GameSession session(ms.setup);
    for (const TurnInput& t : ms.turns) session.playTurn(t);
    expectSameObjectBalls(session.ballsToDraw(), physicsBalls(ms.setup, ms.turns));
    const Picture pic(png, sceneOf(session));
    ASSERT_TRUE(pic.loaded());
    pic.expectClothAtCentre();
    pic.expectBallColours();
    std::remove(png.c_str());
  }
  {
    SCOPED_TRACE("the break in motion, 30 frames of 1/60 s in");
    const std::string png = tempPath("moving");
    const XvfbRun r = runUnderXvfb("--frames 30 --screenshot " + shellWord(png));
    ASSERT_EQ(r.status, 0) << r.err;
    expectNoLeakOfOurs(r);
    nineball::window::GameSession session{MatchSetup{}};
    ASSERT_TRUE(session.shoot());
    for (int frame = 0; frame < 30; ++frame) session.advance(1.0 / 60.0);
    ASSERT_EQ(session.phase(), nineball::window::Phase::Rolling);
    // The same steps straight on the physics.
    Match m{MatchSetup{}};
    TurnInput brk;
    brk.shot.speed = nineball::window::GameSession::kBreakSpeed;
    brk.cue = Vec2{m.world().table().headStringX(), 0.0};
    m.beginShot(brk);
    // Drawing interpolates between the last two steps; a whole 1/60 s frame has no step
    // left over, so the picture shows the step before the last one.
    const long steps = session.match().world().steps();
    ASSERT_EQ(steps, 30);
    while (m.world().steps() < steps - 1) m.world().step();
    const auto drawn = session.ballsToDraw();
    for (const BallState& p : m.balls()) {
      for (const BallState& d : drawn) {
        if (d.id == p.id && !d.pocket && !p.pocket) {
          EXPECT_EQ(d.pos, p.pos) << p.id;
        }
      }
    }
    const Picture pic(png, sceneOf(session));
    ASSERT_TRUE(pic.loaded());
    pic.expectBallColours();
    std::remove(png.c_str());
  }
}

// The HUD's own record of what it drew (NINEBALL_HUD_TEXTS): each tray ball's box by name.
std::map<std::string, std::array<double, 4>> trayBoxes(const std::string& path) {
  std::map<std::string, std::array<double, 4>> boxes;
  std::istringstream in(fileText(path));
  for (std::string line; std::getline(in, line);) {
    const auto colon = line.find(" : ");
    if (line.rfind("text ", 0) != 0 || colon == std::string::npos) continue;
    const std::string name = line.substr(colon + 3);
    if (name.rfind("on table ", 0) != 0 && name.rfind("pocketed ", 0) != 0) continue;
    std::array<double, 4> b{};
    std::istringstream(line.substr(5)) >> b[0] >> b[1] >> b[2] >> b[3];
    boxes[name] = b;
  }
  return boxes;
}

TEST(GameWindow, TheReplayAndTheTrayOnScreen) {
  ASSERT_TRUE(haveXvfbRun());
  // A break that drops balls, then 20 frames of its replay.
  const std::string script_path = "/tmp/nineball-test-replay-" + std::to_string(getpid());
  const std::string script =
      R"({"rules": "wpa", "seed": 3, "turns": [{"heading_deg": 0.4, "speed": 9}]})";
  std::ofstream(script_path) << script;
  const std::string png = tempPath("replay");
  const std::string texts = png + ".txt";
  const XvfbRun r = runUnderXvfb(
      "--script " + shellWord(script_path) + " --replay --frames 20 --screenshot " + shellWord(png),
      "NINEBALL_HUD_TEXTS=" + shellWord(texts));
  std::remove(script_path.c_str());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto parsed = nineball::io::parseMatchScript(script);
  const auto& ms = std::get<nineball::io::MatchScript>(parsed);
  nineball::window::GameSession session(ms.setup);
  for (const TurnInput& t : ms.turns) session.playTurn(t);
  const std::vector<int> pocketed = session.pocketedThisRack();
  ASSERT_FALSE(pocketed.empty()) << "the script's break should drop a ball";
  session.startReplay(false);
  for (int frame = 0; frame < 20; ++frame) session.advance(1.0 / 60.0);
  ASSERT_TRUE(session.replaying());
  // The balls stand where the replay has them 20 frames in, not where the break ended.
  Scene scene = sceneOf(session);
  scene.stick.reset();
  const Picture pic(png, scene);
  ASSERT_TRUE(pic.loaded());
  pic.expectBallColours();
  bool moved = false;
  const auto rest = physicsBalls(ms.setup, ms.turns);
  for (const BallState& b : scene.balls) {
    for (const BallState& e : rest) moved = moved || (b.id == e.id && b.pos != e.pos);
  }
  EXPECT_TRUE(moved);
  // The tray: every pocketed ball drawn in it, in its colour, and every ball on the table.
  const auto boxes = trayBoxes(texts);
  for (const BallState& b : rest) {
    if (b.id == nineball::kCueBall) continue;
    const std::string name = (b.pocket ? "pocketed " : "on table ") + std::to_string(b.id);
    const auto it = boxes.find(name);
    ASSERT_NE(it, boxes.end()) << name;
    const auto& box = it->second;
    const Vec2 centre{box[0] + box[2] * 0.5, box[1] + box[3] * 0.5};
    const Vec2 side = centre + Vec2{box[2] * 0.35, 0.0};
    // An icon is a ball number up, lit: its colour as the light shows it at the pixel read.
    const double r_px = box[2] * 0.5;
    const Rgb want = nineball::render::litColour(nineball::render::ballColour(b.id),
                                                 (std::lround(side.x) + 0.5 - centre.x) / r_px,
                                                 -(std::lround(side.y) + 0.5 - centre.y) / r_px);
    EXPECT_TRUE(near(pic.at(side), want)) << name << ": " << show(pic.at(side));
  }
  EXPECT_EQ(boxes.size(), 9u);
  std::remove(png.c_str());
  std::remove(texts.c_str());
}

TEST(GameWindow, WithoutADisplaySaysSoInOneLine) {
  const std::string err_path = "/tmp/nineball-nodisplay-" + std::to_string(getpid());
  const std::string cmd = "env -u DISPLAY " + shellWord(NINEBALL_BINARY) + " --mute >/dev/null 2>" +
                          shellWord(err_path);
  const int raw = std::system(cmd.c_str());
  const std::string err = fileText(err_path);
  std::remove(err_path.c_str());
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 1);
  EXPECT_NE(err.find("no display"), std::string::npos) << err;
  EXPECT_NE(err.find("xvfb-run"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
}
