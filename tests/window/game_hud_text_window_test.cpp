// The HUD's text under Xvfb at window sizes from 640x480 to 3840x2160, in the states whose
// lines are longest (a foul with balls down, the push-out choice, the rack won): every line
// stays inside its room and the window, and no two lines overlap.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli_runner.hpp"
#include "support/xvfb_run.hpp"

namespace nineball::testing {
namespace {

// Glyph boxes are whole pixels, rooms are not: a box may reach this far (px) past its room.
constexpr double kSlackPx = 1.0;

struct Box {
  double left = 0, top = 0, width = 0, height = 0;
  double right() const { return left + width; }
  double bottom() const { return top + height; }
};

struct Line {
  Box box;
  Box room;
  std::string text;
};

bool inside(const Box& a, const Box& room) {
  return a.left >= room.left - kSlackPx && a.top >= room.top - kSlackPx &&
         a.right() <= room.right() + kSlackPx && a.bottom() <= room.bottom() + kSlackPx;
}

bool overlap(const Box& a, const Box& b) {
  return a.left < b.right() && b.left < a.right() && a.top < b.bottom() && b.top < a.bottom();
}

struct Drawn {
  int status = -1;
  Box window;
  std::vector<Line> lines;
  std::string err;
};

Drawn drawAt(const std::string& size, const std::string& script) {
  TempFile script_file(script), texts;
  const std::string png = texts.path() + ".png";
  // A screen as large as the largest window tried; the window at `size` on it.
  const testing::XvfbRun run = testing::runUnderXvfb(
      shellQuoted(NINEBALL_BINARY) + " --mute --size " + size + " --script " +
          shellQuoted(script_file.path()) + " --screenshot " + shellQuoted(png),
      3840, 2160, "NINEBALL_HUD_TEXTS=" + shellQuoted(texts.path()));
  Drawn d;
  d.status = run.status;
  d.err = run.err;
  std::remove(png.c_str());
  std::istringstream in(texts.read());
  for (std::string kind; in >> kind;) {
    if (kind == "window") {
      in >> d.window.left >> d.window.top >> d.window.width >> d.window.height;
      continue;
    }
    Line l;
    std::string room_word, colon;
    in >> l.box.left >> l.box.top >> l.box.width >> l.box.height >> room_word >> l.room.left >>
        l.room.top >> l.room.width >> l.room.height >> colon;
    std::getline(in, l.text);
    d.lines.push_back(l);
  }
  return d;
}

const char* const kFoulWithBallsDown =
    R"({"physics": {"ball_restitution": 0.0},
        "balls": [{"id": 0, "x": 0.6, "y": 0.0}, {"id": 1, "x": 0.9, "y": 0.3},
                  {"id": 2, "x": -0.8, "y": -0.3}],
        "turns": [{"heading_deg": 45, "speed": 4}]})";
const char* const kPushOutChoice =
    R"({"turns": [{"heading_deg": 0, "speed": 10},
                  {"push_out": true, "heading_deg": 80, "speed": 1.0}]})";
const char* const kRackWon =
    R"({"balls": [{"id": 0, "x": 0.67003, "y": 0.22391}, {"id": 9, "x": 1.0, "y": 0.45}],
        "turns": [{"heading_deg": 34.41836, "speed": 2}]})";

TEST(HudText, FitsItsRoomAtEveryWindowSize) {
  ASSERT_EQ(std::system("command -v xvfb-run >/dev/null 2>&1"), 0) << "needs xvfb-run";
  for (const char* size : {"500x700", "640x480", "800x600", "1126x704", "3840x2160"}) {
    for (const auto& [name, script] :
         {std::pair{"a foul with a ball down", kFoulWithBallsDown},
          std::pair{"the push-out choice", kPushOutChoice}, std::pair{"the rack won", kRackWon}}) {
      SCOPED_TRACE(std::string(size) + ", " + name);
      const Drawn d = drawAt(size, script);
      ASSERT_EQ(d.status, 0) << d.err;
      ASSERT_GE(d.lines.size(), 12u) << "too few lines drawn";
      for (const Line& l : d.lines) {
        if (l.box.width == 0) continue;  // an empty message
        EXPECT_TRUE(inside(l.box, d.window)) << "off the window: " << l.text;
        EXPECT_TRUE(inside(l.box, l.room))
            << "spills out of its room: \"" << l.text << "\" box " << l.box.left << "+"
            << l.box.width << " room " << l.room.left << "+" << l.room.width;
      }
      for (std::size_t i = 0; i < d.lines.size(); ++i) {
        for (std::size_t j = i + 1; j < d.lines.size(); ++j) {
          EXPECT_FALSE(overlap(d.lines[i].box, d.lines[j].box))
              << "\"" << d.lines[i].text << "\" overlaps \"" << d.lines[j].text << "\"";
        }
      }
    }
  }
}

}  // namespace
}  // namespace nineball::testing

namespace nineball::testing {
namespace {

TEST(HudText, AJpegScreenshotIsAJpeg) {
  ASSERT_EQ(std::system("command -v xvfb-run >/dev/null 2>&1"), 0) << "needs xvfb-run";
  TempFile stem;
  const std::string jpg = stem.path() + ".jpg";
  const std::string cmd =
      "LSAN_OPTIONS=\"${LSAN_OPTIONS:+$LSAN_OPTIONS:}exitcode=0\" xvfb-run -a -n " +
      std::to_string(300 + getpid() % 600) + " -s '-screen 0 1280x800x24' " +
      shellQuoted(NINEBALL_BINARY) + " --mute --size 800x500 --screenshot " + shellQuoted(jpg) +
      " 2>/dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  std::ifstream in(jpg, std::ios::binary);
  unsigned char magic[3] = {};
  in.read(reinterpret_cast<char*>(magic), 3);
  EXPECT_EQ(magic[0], 0xFF);
  EXPECT_EQ(magic[1], 0xD8);
  EXPECT_EQ(magic[2], 0xFF);
  std::remove(jpg.c_str());
}

}  // namespace
}  // namespace nineball::testing
