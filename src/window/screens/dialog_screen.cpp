#include "window/screens/dialog_screen.hpp"

namespace nineball::window {
void DialogScreen::event(const sf::Event& event) {
  // The table hears every event first (the window's keys, the held keys, the pointer), as it
  // did under any dialog; the dialog then answers, while its table still calls for it.
  table_.passDown(event);
  if (finished()) return;
  if (event.type == sf::Event::KeyPressed) {
    key(event.key.code);
  } else if (event.type == sf::Event::MouseButtonPressed &&
             event.mouseButton.button == sf::Mouse::Left) {
    click(table_.buttonAt(
        {static_cast<double>(event.mouseButton.x), static_cast<double>(event.mouseButton.y)}));
  }
}

void HelpScreen::key(sf::Keyboard::Key code) {
  if (code == sf::Keyboard::H || code == sf::Keyboard::Escape) table().closeHelp();
}

void HelpScreen::click(DialogButton button) {
  if (button == DialogButton::Right) table().closeHelp();
}

void QuitScreen::key(sf::Keyboard::Key code) {
  if (code == sf::Keyboard::Y || code == sf::Keyboard::Enter) table().leave();
  if (code == sf::Keyboard::N || code == sf::Keyboard::Escape) table().closeQuestion();
}

void QuitScreen::click(DialogButton button) {
  if (button == DialogButton::Left) table().leave();
  if (button == DialogButton::Right) table().closeQuestion();
}

void PushOutScreen::key(sf::Keyboard::Key code) {
  if (table().othersDecide()) return;
  if (code == sf::Keyboard::S) table().decide(true, false);
  if (code == sf::Keyboard::P) table().decide(false, false);
  if (code == sf::Keyboard::R) table().decide(false, true);
}

void PushOutScreen::click(DialogButton button) {
  if (table().othersDecide()) return;
  if (button == DialogButton::Left) table().decide(true, false);
  if (button == DialogButton::Right) table().decide(false, false);
  if (button == DialogButton::Middle) table().decide(false, true);
}

void RackEndScreen::key(sf::Keyboard::Key code) {
  if (table().othersDecide()) return;
  if (code == sf::Keyboard::R || code == sf::Keyboard::Enter) table().rematch();
}

void RackEndScreen::click(DialogButton button) {
  // A click answers even while the other side has the table, as it always did.
  if (button == DialogButton::Left) table().rematch();
  if (button == DialogButton::Right) table().quit();
}

std::unique_ptr<DialogScreen> makeDialog(DialogKind kind, DialogTable& table) {
  switch (kind) {
    case DialogKind::Help:
      return std::make_unique<HelpScreen>(table);
    case DialogKind::ConfirmQuit:
      return std::make_unique<QuitScreen>(table);
    case DialogKind::PushOutChoice:
      return std::make_unique<PushOutScreen>(table);
    case DialogKind::GameOver:
      return std::make_unique<RackEndScreen>(table);
    case DialogKind::None:
      break;
  }
  return nullptr;
}

void DialogSlot::follow(ScreenStack& screens, DialogTable& table) {
  // A dialog finished on top may already have left with the loop's other finished screens.
  if (shown_ && !screens.holds(*shown_)) shown_ = nullptr;
  const DialogKind wanted = table.dialogWanted();
  if (shown_ && shown_->kind() == wanted) return;
  if (shown_) screens.remove(*shown_);
  shown_ = nullptr;
  std::unique_ptr<DialogScreen> dialog = makeDialog(wanted, table);
  if (!dialog) return;
  shown_ = dialog.get();
  screens.insert(1, std::move(dialog));
}

bool DialogSlot::onTop(ScreenStack& screens) const {
  return shown_ && !screens.empty() && &screens.top() == shown_;
}

}  // namespace nineball::window
