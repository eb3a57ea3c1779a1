// The start menu under Xvfb at small, usual and huge window sizes: its panel is drawn where
// MenuLayout puts it and every text stays inside it, long names and the resume entry too.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <SFML/Graphics/Image.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "render/menu_layout.hpp"
#include "support/xvfb_run.hpp"
#include "window/menu.hpp"
#include "window/rack_save.hpp"
#include "window/settings.hpp"

namespace nineball::window {
namespace {

bool haveXvfbRun() {
  return std::system("command -v xvfb-run >/dev/null 2>&1") == 0;
}

// Runs `nineball --menu --screenshot` at a size with its settings and saved rack in `dir`.
int shootMenu(const std::filesystem::path& dir, unsigned w, unsigned h, const std::string& png) {
  // A leak report that names nineball's own code fails the run (the GL driver's do not).
  const testing::XvfbRun run = testing::runGameUnderXvfb(
      "--menu --screenshot " + testing::shellWord(png), w, h,
      "XDG_CONFIG_HOME=" + testing::shellWord((dir / "config").string()) +
          " XDG_STATE_HOME=" + testing::shellWord((dir / "state").string()));
  EXPECT_EQ(run.err.find("nineball::"), std::string::npos) << run.err;
  return run.status;
}

// Text is drawn near white (236, 236, 230) or in the title's yellow; everything behind the
// panel is dimmed well below this.
bool bright(sf::Color c) {
  return c.r > 180 && c.g > 180 && c.b > 60;
}

// `rows` rows, `lit` of them drawn bright (the rest greyed: the computer's level when Player 2
// is a person, the points of a game won on a ball, the break of racks without end).
void expectMenuFits(const std::filesystem::path& dir, unsigned w, unsigned h, int rows, int lit) {
  SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
  const std::string png = (dir / ("menu-" + std::to_string(w) + ".png")).string();
  ASSERT_EQ(shootMenu(dir, w, h, png), 0);
  sf::Image image;
  ASSERT_TRUE(image.loadFromFile(png));
  ASSERT_EQ(image.getSize(), sf::Vector2u(w, h));
  const render::MenuLayout m = render::MenuLayout::of(w, h, rows);
  const render::PixelRect& p = m.panel;
  ASSERT_GE(p.left, 0.0);
  ASSERT_GE(p.top, 0.0);
  ASSERT_LE(p.left + p.width, w);
  ASSERT_LE(p.top + p.height, h);
  // The panel's own colour in its empty lower-right corner (beside "Quit").
  const render::PixelRect& last = m.rows.back();
  const sf::Color inside = image.getPixel(static_cast<unsigned>(last.left + last.width * 0.8),
                                          static_cast<unsigned>(last.top + last.height / 2));
  EXPECT_LE(inside.r, 30);
  EXPECT_LE(inside.g, 34);
  EXPECT_LE(inside.b, 38);
  // Every bright pixel (text) lies inside the panel, within its margins; every row has some.
  const double margin = m.pad * 0.5;
  int outside = 0;
  std::vector<int> per_row(m.rows.size(), 0);
  for (unsigned y = 0; y < h; ++y) {
    for (unsigned x = 0; x < w; ++x) {
      if (!bright(image.getPixel(x, y))) continue;
      const Vec2 px{x + 0.5, y + 0.5};
      const bool in = px.x >= p.left + margin && px.x <= p.left + p.width - margin &&
                      px.y >= p.top + margin * 0.5 && px.y <= p.top + p.height - margin * 0.5;
      if (!in) ++outside;
      const int r = m.rowAt(px);
      if (r >= 0) ++per_row[r];
    }
  }
  EXPECT_EQ(outside, 0) << "text pixels outside the panel";
  for (std::size_t r = 0; r < per_row.size(); ++r) {
    // Greyed rows (practice, and the level when Player 2 is a person) are not bright.
    if (per_row[r] == 0) continue;
    EXPECT_GT(per_row[r], 10) << "row " << r;
  }
  int lit_rows = 0;
  for (int n : per_row) lit_rows += n > 0 ? 1 : 0;
  EXPECT_GE(lit_rows, lit);
}

// The rows the menu shows, as its model lists them (nine-ball's: its Match and Break rows
// too), and how many of them are enabled.
std::pair<int, int> menuRows(const Settings& settings, std::optional<std::string> resume) {
  const std::vector<MenuRow> rows = MenuModel(settings, std::move(resume)).rows();
  int enabled = 0;
  for (const MenuRow& r : rows) enabled += r.enabled ? 1 : 0;
  return {static_cast<int>(rows.size()), enabled};
}

class MenuScreenshots : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(haveXvfbRun())
        << "xvfb-run not found: install xvfb and xauth (bash scripts/setup.sh)";
    dir_ = std::filesystem::temp_directory_path() /
           ("nineball-menu-" + std::to_string(getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

TEST_F(MenuScreenshots, TheMenuFitsEveryWindowSize) {
  for (auto [w, h] : {std::pair{640u, 480u}, {1280u, 800u}, {3840u, 2160u}}) {
    const auto [rows, lit] = menuRows(Settings{}, std::nullopt);
    expectMenuFits(dir_, w, h, rows, lit);
  }
}

TEST_F(MenuScreenshots, LongNamesAndTheResumeEntryStillFit) {
  Settings s;
  s.last.names = {"Bartholomew Montgomery", "Maximilian Fitzgerald"};
  std::string why;
  ASSERT_TRUE(saveSettings(s, (dir_ / "config" / "nineball" / "settings.json").string(), why))
      << why;
  SavedRack rack;
  rack.names = s.last.names;
  rack.rack_index = 23;
  rack.racks_won = {12, 11};
  ASSERT_TRUE(saveRack(rack, (dir_ / "state" / "nineball" / "rack.json").string(), why)) << why;
  const auto [rows, lit] = menuRows(s, std::string("resume"));
  for (auto [w, h] : {std::pair{640u, 480u}, {1280u, 800u}}) expectMenuFits(dir_, w, h, rows, lit);
}

}  // namespace
}  // namespace nineball::window
