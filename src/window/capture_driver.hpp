#pragma once

#include <SFML/Graphics/RenderWindow.hpp>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "app/game_options.hpp"
#include "render/scene_painter.hpp"
#include "window/menu.hpp"

namespace nineball::window {

struct OnlineConfig;

/// Who runs the window's frames: a person (the frames follow the clock, the window waits when
/// nothing moves), a picture run (--screenshot: fixed frames, then the PNG) or a benchmark
/// (--frames alone: as fast as it goes, then exit). Everything the tests and the screenshots
/// need lives here, the environment variables they set included, so that the loop asks one
/// object and has no test-only branch of its own:
///
/// - NINEBALL_MENU_KEYS="down,right,enter": keys typed into the start menu before it shows
///   (--menu --screenshot), then the picture of the game picked;
/// - NINEBALL_ONLINE_WAIT=S: a picture run hosting waits S seconds (1-600) for its friend;
/// - NINEBALL_HUD_TEXTS=PATH: with the picture, every line the HUD drew, its box and its room.
class CaptureDriver {
 public:
  /// How the environment is read: std::getenv, or a test's own table.
  using Environment = std::function<const char*(const char*)>;

  enum class Mode { Person, Picture, Benchmark };

  /// What the frame just drawn asks of the loop.
  enum class Next { Go, Finish, Fail };

  CaptureDriver(const app::GameOptions& options, const Environment& env);
  /// The driver of `options`, reading the process's environment.
  static CaptureDriver fromProcess(const app::GameOptions& options);

  Mode mode() const { return mode_; }
  /// A person plays: frames follow the clock, vsync and the frame cap, the idle wait.
  bool person() const { return mode_ == Mode::Person; }
  /// The frames after the setup are fixed, for the same picture every run (--screenshot).
  bool picture() const { return mode_ == Mode::Picture; }
  /// The number of frames the run draws; -1 when a person plays until closing the window.
  long frameLimit() const { return frame_limit_; }

  /// --frames on a table with no script: the frames show a break (the benchmark's moving balls).
  bool breaksForDemo() const { return frames_given_; }
  /// A frame's time step: the fixed 1/60 s of a picture run, else what the clock measured
  /// (a stall counted as at most a quarter second).
  double frameSeconds(double measured) const;

  /// Refused before a window opens: a picture that cannot be written. Nothing when it may go.
  std::optional<int> refuseBeforeWindow(std::ostream& err) const;
  /// The keys the start menu is given before it shows; empty when none. Nothing, with the
  /// exit status said on `err`, when NINEBALL_MENU_KEYS names no key.
  std::optional<std::vector<MenuKey>> typedMenuKeys(std::ostream& err, int& status) const;
  /// True when the run's picture is the start menu itself (a picture run with the menu and no
  /// keys typed into it).
  bool picturesMenu(bool menu_shown) const;
  /// A picture run online must end: nobody joining or coming back ends it, and
  /// NINEBALL_ONLINE_WAIT shortens the wait for a friend.
  void boundOnlineWaits(OnlineConfig& config) const;

  /// How the online game stands for a picture run's end (nothing when not online).
  struct OnlineEnd {
    bool done = false;    ///< this side is done with the rack, or the game is over
    std::string failure;  ///< why the game failed; empty when it did not
  };

  /// After frame `frames` is drawn (not yet shown): Finish once a picture run has its picture
  /// (saved, with the HUD's texts when asked), Fail when it could not be saved or the online
  /// game failed (said on `err`, the exit status in `status`), else Go. Online, the picture is
  /// taken once the rack is done, unless --frames asked for a count.
  Next afterDraw(long frames, const std::optional<OnlineEnd>& online, sf::RenderWindow& window,
                 const render::ScenePainter& painter, std::ostream& err, int& status) const;
  /// After frame `frames` is shown: true when a benchmark has drawn all its frames.
  bool benchmarkDone(long frames) const;
  /// Saves the window's picture as the run's screenshot; false, said on `err`, when it cannot.
  bool savePicture(sf::RenderWindow& window, std::ostream& err) const;

 private:
  void writeHudTexts(const render::ScenePainter& painter, unsigned width, unsigned height) const;

  Mode mode_;
  std::string screenshot_;
  bool frames_given_;
  long frame_limit_;
  std::optional<std::string> menu_keys_;
  std::optional<double> online_wait_;
  std::optional<std::string> hud_texts_;
};

}  // namespace nineball::window
