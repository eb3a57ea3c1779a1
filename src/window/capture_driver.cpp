#include "window/capture_driver.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <ostream>

#include "app/exit_codes.hpp"
#include "common/atomic_file.hpp"
#include "common/log.hpp"
#include "render/png_capture.hpp"
#include "window/menu_screen.hpp"
#include "window/online_play.hpp"

namespace nineball::window {
namespace {

// A picture run steps a fixed 1/60 s per frame, so that its picture is always the same.
constexpr double kFixedFrame = 1.0 / 60.0;
// A frame longer than this (a stall, a dragged window) counts as this long.
constexpr double kMaxFrame = 0.25;
// A picture run online must end: nobody joining, coming back or playing on ends it after these
// (s); NINEBALL_ONLINE_WAIT may shorten the first within its bounds.
constexpr double kPictureJoinWait = 60.0;
constexpr double kPictureRejoinWait = 20.0;
constexpr double kPictureStall = 60.0;
constexpr double kOnlineWaitMin = 1.0;
constexpr double kOnlineWaitMax = 600.0;

std::optional<std::string> read(const CaptureDriver::Environment& env, const char* name) {
  const char* value = env ? env(name) : nullptr;
  if (!value) return std::nullopt;
  return std::string(value);
}

CaptureDriver::Mode modeOf(const app::GameOptions& options) {
  if (!options.screenshot.empty()) return CaptureDriver::Mode::Picture;
  if (options.frames) return CaptureDriver::Mode::Benchmark;
  return CaptureDriver::Mode::Person;
}

}  // namespace

CaptureDriver::CaptureDriver(const app::GameOptions& options, const Environment& env)
    : mode_(modeOf(options)),
      screenshot_(options.screenshot),
      frames_given_(options.frames.has_value()),
      frame_limit_(options.frames.value_or(mode_ == Mode::Picture ? 1 : -1)),
      menu_keys_(read(env, "NINEBALL_MENU_KEYS")),
      hud_texts_(read(env, "NINEBALL_HUD_TEXTS")) {
  if (const auto wait = read(env, "NINEBALL_ONLINE_WAIT")) {
    online_wait_ = std::clamp(std::atof(wait->c_str()), kOnlineWaitMin, kOnlineWaitMax);
  }
}

CaptureDriver CaptureDriver::fromProcess(const app::GameOptions& options) {
  return CaptureDriver(options, [](const char* name) { return std::getenv(name); });
}

double CaptureDriver::frameSeconds(double measured) const {
  return picture() ? kFixedFrame : std::min(measured, kMaxFrame);
}

std::optional<int> CaptureDriver::refuseBeforeWindow(std::ostream& err) const {
  std::string why;
  if (picture() && !canWriteFile(screenshot_, why)) {
    err << "nineball: --screenshot: " << why << '\n';
    return app::kExitBadInput;
  }
  return std::nullopt;
}

std::optional<std::vector<MenuKey>> CaptureDriver::typedMenuKeys(std::ostream& err,
                                                                 int& status) const {
  // Keys are typed only into the menu of a picture run: a person types their own.
  if (!picture() || !menu_keys_) return std::vector<MenuKey>{};
  std::string why;
  std::optional<std::vector<MenuKey>> keys = parseMenuKeys(*menu_keys_, why);
  if (!keys) {
    err << "nineball: NINEBALL_MENU_KEYS: " << why << '\n';
    status = app::kExitBadInput;
  }
  return keys;
}

bool CaptureDriver::picturesMenu(bool menu_shown) const {
  return menu_shown && picture() && !menu_keys_;
}

void CaptureDriver::boundOnlineWaits(OnlineConfig& config) const {
  if (!picture()) return;
  config.wait_s = online_wait_.value_or(kPictureJoinWait);
  config.rejoin_s = kPictureRejoinWait;
  config.stall_s = kPictureStall;
}

CaptureDriver::Next CaptureDriver::afterDraw(long frames, const std::optional<OnlineEnd>& online,
                                             sf::RenderWindow& window,
                                             const render::ScenePainter& painter, std::ostream& err,
                                             int& status) const {
  if (!picture()) return Next::Go;
  // Online, a picture of the game as it stands after --frames, else once the rack is done.
  const bool due = online && !frames_given_ ? online->done : frames >= frame_limit_;
  if (!due) return Next::Go;
  if (online && !online->failure.empty() && !frames_given_) {
    err << "nineball: online: " << online->failure << '\n';
    status = app::kExitInternal;
    return Next::Fail;
  }
  if (!savePicture(window, err)) {
    status = app::kExitBadInput;
    return Next::Fail;
  }
  logger("game")->info("saved {} after {} frames", screenshot_, frames);
  writeHudTexts(painter, window.getSize().x, window.getSize().y);
  return Next::Finish;
}

bool CaptureDriver::benchmarkDone(long frames) const {
  return mode_ == Mode::Benchmark && frames >= frame_limit_;
}

bool CaptureDriver::savePicture(sf::RenderWindow& window, std::ostream& err) const {
  std::string why;
  if (!render::saveWindowPng(window, screenshot_, why)) {
    err << "nineball: --screenshot: " << why << '\n';
    return false;
  }
  return true;
}

// For the tests that check that no text spills: each line drawn, its box and its room.
void CaptureDriver::writeHudTexts(const render::ScenePainter& painter, unsigned width,
                                  unsigned height) const {
  if (!hud_texts_) return;
  std::ofstream out(*hud_texts_);
  out << "window 0 0 " << width << ' ' << height << '\n';
  for (const render::DrawnText& t : painter.hudTexts()) {
    out << "text " << t.box.left << ' ' << t.box.top << ' ' << t.box.width << ' ' << t.box.height
        << " room " << t.room.left << ' ' << t.room.top << ' ' << t.room.width << ' '
        << t.room.height << " : " << t.text << '\n';
  }
}

}  // namespace nineball::window
