// The window's screen stack, with screens that write down what the one event loop asks of them:
// the top takes the events, the screens in sight are updated top first and drawn bottom first,
// a screen that covers hides the ones beneath, and a finished screen leaves and is told.
#include "window/screens/screen_stack.hpp"

#include <gtest/gtest.h>

#include <SFML/Graphics/RenderTarget.hpp>
#include <functional>
#include <string>
#include <vector>

namespace nineball::window {
namespace {

// Nothing is drawn: the screens below only write down that they were asked to draw.
struct NoTarget : sf::RenderTarget {
  sf::Vector2u getSize() const override { return {1, 1}; }
  bool setActive(bool) override { return true; }
};

struct Trace {
  std::vector<std::string> calls;
};

class NamedScreen : public Screen {
 public:
  NamedScreen(std::string name, bool covers, Trace& trace)
      : name_(std::move(name)), covers_(covers), trace_(trace) {}
  void event(const sf::Event&) override { trace_.calls.push_back(name_ + " event"); }
  void update(double, bool on_top) override {
    trace_.calls.push_back(name_ + (on_top ? " update on top" : " update beneath"));
  }
  void draw(sf::RenderTarget&) override { trace_.calls.push_back(name_ + " draw"); }
  bool covers() const override { return covers_; }
  bool busy() const override { return busy_; }
  bool finished() const override { return finished_; }
  void closed() override {
    trace_.calls.push_back(name_ + " closed");
    if (on_close) on_close();
  }

  bool busy_ = false;
  bool finished_ = false;
  std::function<void()> on_close;

 private:
  std::string name_;
  bool covers_;
  Trace& trace_;
};

struct Stack {
  Trace trace;
  ScreenStack screens;
  NoTarget target;
  NamedScreen& push(const std::string& name, bool covers) {
    auto screen = std::make_unique<NamedScreen>(name, covers, trace);
    NamedScreen& kept = *screen;
    screens.push(std::move(screen));
    return kept;
  }
  std::vector<std::string> frame() {
    trace.calls.clear();
    screens.event(sf::Event{});
    screens.update(1.0 / 60.0);
    screens.draw(target);
    return trace.calls;
  }
};

TEST(ScreenStack, TheSettingsOverTheTableLeaveItDrawnAndPlayingBeneath) {
  Stack s;
  s.push("table", true);
  s.push("settings", false);
  EXPECT_EQ(s.frame(),
            (std::vector<std::string>{"settings event", "settings update on top",
                                      "table update beneath", "table draw", "settings draw"}));
}

TEST(ScreenStack, TheMenuCoversTheTableWhichNeitherPlaysNorShows) {
  Stack s;
  NamedScreen& table = s.push("table", true);
  s.push("menu", true);
  EXPECT_EQ(s.frame(), (std::vector<std::string>{"menu event", "menu update on top", "menu draw"}));
  table.busy_ = true;  // a ball rolling under the menu does not keep the frames going
  EXPECT_FALSE(s.screens.busy());
}

TEST(ScreenStack, AScreenInSightThatIsBusyKeepsTheFramesGoing) {
  Stack s;
  NamedScreen& table = s.push("table", true);
  s.push("settings", false);
  EXPECT_FALSE(s.screens.busy());
  table.busy_ = true;
  EXPECT_TRUE(s.screens.busy());
}

TEST(ScreenStack, AFinishedScreenLeavesAndIsToldAndMayOpenAnother) {
  Stack s;
  s.push("table", true);
  NamedScreen& menu = s.push("menu", true);
  EXPECT_FALSE(s.screens.removeFinished());
  menu.finished_ = true;
  menu.on_close = [&s] { s.push("settings", false); };
  s.trace.calls.clear();
  EXPECT_TRUE(s.screens.removeFinished());
  EXPECT_EQ(s.trace.calls, std::vector<std::string>{"menu closed"});
  EXPECT_EQ(s.screens.size(), 2u);
  EXPECT_EQ(s.frame(),
            (std::vector<std::string>{"settings event", "settings update on top",
                                      "table update beneath", "table draw", "settings draw"}));
}

TEST(ScreenStack, AScreenThatCameOrWentAsksForThePictureAtOnce) {
  Stack s;
  s.push("table", true);
  EXPECT_TRUE(s.screens.takeChanged());
  EXPECT_FALSE(s.screens.takeChanged());
  NamedScreen& menu = s.push("menu", true);  // Esc's menu, with no event to draw it
  EXPECT_TRUE(s.screens.takeChanged());
  s.screens.removeFinished();
  EXPECT_FALSE(s.screens.takeChanged());
  menu.finished_ = true;
  s.screens.removeFinished();
  EXPECT_TRUE(s.screens.takeChanged());
}

TEST(ScreenStack, ClosingTheWindowClosesWhatLiesOverTheTable) {
  Stack s;
  s.push("table", true);
  s.push("menu", true);
  s.push("settings", false);
  s.trace.calls.clear();
  s.screens.closeDownTo(1);
  EXPECT_EQ(s.trace.calls, (std::vector<std::string>{"settings closed", "menu closed"}));
  EXPECT_EQ(s.screens.size(), 1u);
}

}  // namespace
}  // namespace nineball::window
