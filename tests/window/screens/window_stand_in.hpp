#pragma once

#include <gtest/gtest.h>

#include <cstdlib>

#include "window/screens/table_screen.hpp"

namespace nineball::window::test {

// The window as the table sees it: a view for the pointer (no painter: nothing is drawn, and
// there is no display), the settings, the stack, and what the table asked of it written down.
class WindowStandIn : public TableWindow {
 public:
  render::ScenePainter& painter() override {
    ADD_FAILURE() << "the table's keys need no painter";
    std::abort();
  }
  const render::ViewTransform& pointerView() override { return view_; }
  Settings& settings() override { return settings_; }
  ScreenStack& screens() override { return screens_; }
  audio::ImpactSounds* sounds() override { return nullptr; }
  void openSettings() override { ++settings_opened; }
  void applySound() override { ++sound_applied; }
  void saveSettingsNow() override { ++settings_saved; }

  int settings_opened = 0, sound_applied = 0, settings_saved = 0;

 private:
  render::ViewTransform view_{TableDef{}, 1280, 800};
  Settings settings_;
  ScreenStack screens_;
};

}  // namespace nineball::window::test
