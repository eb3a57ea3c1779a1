// The dialogs over the table as screens: the one the table's state calls for lies just above
// the table (beneath the settings when they are open) and leaves when the state moves on; the
// top dialog takes the events, lets the table hear each first, and answers its own keys and
// buttons; a choice that is the computer's is not the player's to make.
#include "window/screens/dialog_screen.hpp"

#include <gtest/gtest.h>

#include <SFML/Graphics/RenderTarget.hpp>
#include <optional>
#include <string>
#include <vector>

namespace nineball::window {
namespace {

// Writes down what the dialogs ask of it; `wanted` is the dialog its state calls for.
class RecordingTable : public DialogTable {
 public:
  DialogKind dialogWanted() const override { return wanted; }
  bool othersDecide() const override { return others_decide; }
  DialogButton buttonAt(Vec2 px) const override {
    return px.x < 100   ? DialogButton::Left
           : px.x < 200 ? DialogButton::Middle
                        : DialogButton::Right;
  }
  void passDown(const sf::Event& event) override {
    calls.push_back(event.type == sf::Event::KeyPressed ? "table key" : "table event");
    if (after_pass_down) wanted = *after_pass_down;
  }
  void drawDialog(sf::RenderTarget&) override { calls.push_back("dialog drawn"); }
  void closeHelp() override {
    calls.push_back("help closed");
    wanted = DialogKind::None;
  }
  void closeQuestion() override {
    calls.push_back("question closed");
    wanted = DialogKind::None;
  }
  void leave() override { calls.push_back("leave"); }
  void decide(bool shoot_now, bool replace) override {
    calls.push_back(std::string("decide ") + (shoot_now ? "shoot" : "pass") +
                    (replace ? " replace" : ""));
  }
  void rematch() override { calls.push_back("rematch"); }
  void quit() override { calls.push_back("quit"); }

  DialogKind wanted = DialogKind::None;
  bool others_decide = false;
  std::optional<DialogKind> after_pass_down;  // the dialog the table's own handling calls for
  std::vector<std::string> calls;
};

// A screen that is only there: the table at the bottom, the settings over it.
class PlainScreen : public Screen {
 public:
  explicit PlainScreen(bool covers) : covers_(covers) {}
  void event(const sf::Event&) override { ++events; }
  void update(double, bool) override {}
  void draw(sf::RenderTarget&) override {}
  bool covers() const override { return covers_; }
  bool finished() const override { return false; }
  int events = 0;

 private:
  bool covers_;
};

struct NoDialogTarget : sf::RenderTarget {
  sf::Vector2u getSize() const override { return {1, 1}; }
  bool setActive(bool) override { return true; }
};

sf::Event pressOf(sf::Keyboard::Key code) {
  sf::Event e{};
  e.type = sf::Event::KeyPressed;
  e.key.code = code;
  return e;
}

sf::Event leftPressAt(int x) {
  sf::Event e{};
  e.type = sf::Event::MouseButtonPressed;
  e.mouseButton.button = sf::Mouse::Left;
  e.mouseButton.x = x;
  e.mouseButton.y = 10;
  return e;
}

// The table at the bottom of a stack, and the slot its dialogs lie in.
struct DialogStack {
  RecordingTable table;
  ScreenStack screens;
  DialogSlot slot;
  PlainScreen* bottom = nullptr;
  DialogStack() {
    auto screen = std::make_unique<PlainScreen>(true);
    bottom = screen.get();
    screens.push(std::move(screen));
  }
  // The table's state calls for `kind`: the slot follows it.
  void want(DialogKind kind) {
    table.wanted = kind;
    slot.follow(screens, table);
  }
  // An event to the top screen, then the loop's tidying after it; what the table was asked.
  std::vector<std::string> send(const sf::Event& event) {
    table.calls.clear();
    screens.event(event);
    screens.removeFinished();
    slot.follow(screens, table);
    return table.calls;
  }
  DialogKind topKind() {
    const auto* dialog = dynamic_cast<const DialogScreen*>(&screens.top());
    return dialog ? dialog->kind() : DialogKind::None;
  }
};

TEST(DialogScreens, TheDialogTheTableCallsForLiesOverItAndLeavesWhenTheStateMovesOn) {
  DialogStack s;
  s.want(DialogKind::GameOver);
  ASSERT_EQ(s.screens.size(), 2u);
  EXPECT_EQ(s.topKind(), DialogKind::GameOver);
  EXPECT_FALSE(s.screens.top().covers());  // the table shows beneath, as it did
  s.want(DialogKind::Help);                // H over the rack's end: one dialog at a time
  EXPECT_EQ(s.screens.size(), 2u);
  EXPECT_EQ(s.topKind(), DialogKind::Help);
  s.want(DialogKind::None);
  EXPECT_EQ(s.screens.size(), 1u);
  EXPECT_EQ(&s.screens.top(), s.bottom);
}

TEST(DialogScreens, ADialogCalledForUnderTheSettingsLiesBeneathThem) {
  DialogStack s;
  auto settings = std::make_unique<PlainScreen>(false);
  PlainScreen& over = *settings;
  s.screens.push(std::move(settings));
  s.want(DialogKind::GameOver);  // the rack ended as the balls rolled on beneath the settings
  ASSERT_EQ(s.screens.size(), 3u);
  EXPECT_EQ(&s.screens.top(), &over);
  EXPECT_FALSE(s.slot.onTop(s.screens));
  s.screens.event(pressOf(sf::Keyboard::R));  // the settings' key, not the dialog's
  EXPECT_EQ(over.events, 1);
  EXPECT_TRUE(s.table.calls.empty());
  s.want(DialogKind::None);  // gone from beneath the settings, which stay
  EXPECT_EQ(s.screens.size(), 2u);
  EXPECT_EQ(&s.screens.top(), &over);
}

TEST(DialogScreens, TheHelpClosesOnHOrEscOrItsButtonAndLeavesOtherKeysToTheTable) {
  DialogStack s;
  s.want(DialogKind::Help);
  EXPECT_TRUE(s.slot.onTop(s.screens));
  EXPECT_EQ(s.send(pressOf(sf::Keyboard::F12)), std::vector<std::string>{"table key"});
  EXPECT_EQ(s.send(pressOf(sf::Keyboard::H)),
            (std::vector<std::string>{"table key", "help closed"}));
  EXPECT_EQ(s.screens.size(), 1u);
  s.want(DialogKind::Help);
  EXPECT_EQ(s.send(pressOf(sf::Keyboard::Escape)),
            (std::vector<std::string>{"table key", "help closed"}));
  s.want(DialogKind::Help);
  EXPECT_EQ(s.send(leftPressAt(50)), std::vector<std::string>{"table event"});
  EXPECT_EQ(s.send(leftPressAt(250)), (std::vector<std::string>{"table event", "help closed"}));
  EXPECT_EQ(s.screens.size(), 1u);
}

TEST(DialogScreens, TheQuitQuestionLeavesOnYOrEnterAndPlaysOnOnNOrEsc) {
  DialogStack s;
  s.want(DialogKind::ConfirmQuit);
  EXPECT_EQ(s.send(pressOf(sf::Keyboard::Space)), std::vector<std::string>{"table key"});
  EXPECT_EQ(s.send(pressOf(sf::Keyboard::Y)), (std::vector<std::string>{"table key", "leave"}));
  EXPECT_EQ(s.send(pressOf(sf::Keyboard::Enter)), (std::vector<std::string>{"table key", "leave"}));
  EXPECT_EQ(s.send(leftPressAt(50)), (std::vector<std::string>{"table event", "leave"}));
  EXPECT_EQ(s.send(pressOf(sf::Keyboard::N)),
            (std::vector<std::string>{"table key", "question closed"}));
  EXPECT_EQ(s.screens.size(), 1u);
  s.want(DialogKind::ConfirmQuit);
  EXPECT_EQ(s.send(leftPressAt(250)), (std::vector<std::string>{"table event", "question closed"}));
}

TEST(DialogScreens, ThePushOutChoiceIsThePlayersOnlyWhenTheComputerDoesNotHaveIt) {
  DialogStack s;
  s.want(DialogKind::PushOutChoice);
  EXPECT_EQ(s.send(pressOf(sf::Keyboard::S)),
            (std::vector<std::string>{"table key", "decide shoot"}));
  EXPECT_EQ(s.send(pressOf(sf::Keyboard::P)),
            (std::vector<std::string>{"table key", "decide pass"}));
  EXPECT_EQ(s.send(pressOf(sf::Keyboard::R)),
            (std::vector<std::string>{"table key", "decide pass replace"}));
  EXPECT_EQ(s.send(leftPressAt(150)),
            (std::vector<std::string>{"table event", "decide pass replace"}));
  s.table.others_decide = true;
  EXPECT_EQ(s.send(pressOf(sf::Keyboard::S)), std::vector<std::string>{"table key"});
  EXPECT_EQ(s.send(leftPressAt(50)), std::vector<std::string>{"table event"});
}

TEST(DialogScreens, TheRacksEndPlaysTheNextOnROrEnterAndItsRightButtonQuits) {
  DialogStack s;
  s.want(DialogKind::GameOver);
  EXPECT_EQ(s.send(pressOf(sf::Keyboard::Enter)),
            (std::vector<std::string>{"table key", "rematch"}));
  EXPECT_EQ(s.send(leftPressAt(250)), (std::vector<std::string>{"table event", "quit"}));
  s.table.others_decide = true;  // the computer's rack to rack again; a click still answers
  EXPECT_EQ(s.send(pressOf(sf::Keyboard::R)), std::vector<std::string>{"table key"});
  EXPECT_EQ(s.send(leftPressAt(50)), (std::vector<std::string>{"table event", "rematch"}));
}

TEST(DialogScreens, AKeyThatCalledAnotherDialogIsNotAnsweredByTheOneItLeft) {
  DialogStack s;
  s.want(DialogKind::GameOver);
  // The table, hearing the key first, calls for the quit question instead: the rack's end
  // no longer answers (no rematch), and the question takes its place.
  s.table.after_pass_down = DialogKind::ConfirmQuit;
  EXPECT_EQ(s.send(pressOf(sf::Keyboard::Enter)), std::vector<std::string>{"table key"});
  EXPECT_EQ(s.topKind(), DialogKind::ConfirmQuit);
  EXPECT_EQ(s.screens.size(), 2u);
}

TEST(DialogScreens, TheDialogIsDrawnByTheTableOverItsPicture) {
  DialogStack s;
  s.want(DialogKind::PushOutChoice);
  NoDialogTarget target;
  s.screens.draw(target);
  EXPECT_EQ(s.table.calls, std::vector<std::string>{"dialog drawn"});
}

}  // namespace
}  // namespace nineball::window
