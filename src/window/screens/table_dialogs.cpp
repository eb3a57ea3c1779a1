#include "window/screens/table_dialogs.hpp"

#include "render/hud_layout.hpp"
#include "window/frame_builder.hpp"
#include "window/screens/dialog_contents.hpp"

namespace nineball::window {

DialogKind TableDialogs::dialogWanted() const {
  return dialogCalledFor(session_, ui_);
}

DialogButton TableDialogs::buttonAt(Vec2 px) const {
  const bool replace = replaceOffered(session_, ui_);
  const render::HudLayout layout = render::HudLayout::of(
      hooks_.view(), lookOf(dialogCalledFor(session_, ui_)), dialogKeepClear(session_), replace);
  if (layout.button_left.contains(px)) return DialogButton::Left;
  if (layout.button_right.contains(px)) return DialogButton::Right;
  if (replace && layout.button_middle.contains(px)) return DialogButton::Middle;
  return DialogButton::None;
}

void TableDialogs::leave() {
  // To the menu when there is one, else out of the program.
  if (ui_.leave_to_menu) {
    requests_.menu = true;
  } else {
    requests_.quit = true;
  }
  ui_.confirm_quit = false;
}

}  // namespace nineball::window
