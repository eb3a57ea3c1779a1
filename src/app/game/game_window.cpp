#include "app/game/game_window.hpp"

#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/System/Clock.hpp>
#include <SFML/System/Err.hpp>
#include <SFML/System/Sleep.hpp>
#include <algorithm>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <ostream>
#include <sstream>

#include "app/exit_codes.hpp"
#include "app/game/computer_player.hpp"
#include "app/game/display_probe.hpp"
#include "app/game/frame_builder.hpp"
#include "app/game/frame_timer.hpp"
#include "app/game/game_input.hpp"
#include "app/game/game_session.hpp"
#include "app/game/window_icon.hpp"
#include "app/game/window_placement.hpp"
#include "audio/impact_sounds.hpp"
#include "nineball/atomic_file.hpp"
#include "nineball/log.hpp"
#include "render/fonts.hpp"
#include "render/png_capture.hpp"
#include "render/scene_painter.hpp"

namespace nineball::app {
namespace {

constexpr const char* kTitle = "nineball";
// A screenshot run steps a fixed 1/60 s per frame, so that its picture is always the same.
constexpr double kFixedFrame = 1.0 / 60.0;
// A frame longer than this (a stall, a dragged window) counts as this long.
constexpr double kMaxFrame = 0.25;
// Without vertical sync, an interactive window sleeps so as not to exceed this rate.
constexpr double kMaxFps = 240.0;
constexpr unsigned kAntialiasing = 0;

// Sends SFML's error stream to the "sfml" logger, one line per message.
class SfmlErrToLog : public std::stringbuf {
 public:
  SfmlErrToLog() : saved_(sf::err().rdbuf(this)) {}
  ~SfmlErrToLog() override {
    sync();
    sf::err().rdbuf(saved_);
  }
  SfmlErrToLog(const SfmlErrToLog&) = delete;
  SfmlErrToLog& operator=(const SfmlErrToLog&) = delete;

 protected:
  int sync() override {
    std::istringstream lines(str());
    for (std::string line; std::getline(lines, line);) {
      if (!line.empty()) logger("sfml")->info("{}", line);
    }
    str("");
    return 0;
  }

 private:
  std::streambuf* saved_;
};

void openWindow(sf::RenderWindow& window, bool fullscreen, unsigned width, unsigned height,
                bool vsync) {
  sf::ContextSettings settings;
  settings.antialiasingLevel = kAntialiasing;
  if (fullscreen) {
    window.create(sf::VideoMode::getDesktopMode(), kTitle, sf::Style::Fullscreen, settings);
  } else {
    window.create(sf::VideoMode(width, height), kTitle, sf::Style::Default, settings);
    const sf::VideoMode desktop = sf::VideoMode::getDesktopMode();
    window.setPosition(centredOnDesktop(window.getSize(), {desktop.width, desktop.height}));
  }
  setWindowIcon(window);
  window.setKeyRepeatEnabled(false);
  window.setVerticalSyncEnabled(vsync);
}

// The window fits the desktop unless its size was asked for.
void fitDesktop(GameOptions& o) {
  if (o.size_given) return;
  const sf::VideoMode desktop = sf::VideoMode::getDesktopMode();
  const double fit =
      std::min({1.0, 0.92 * desktop.width / o.width, 0.88 * desktop.height / o.height});
  o.width = static_cast<unsigned>(o.width * fit);
  o.height = static_cast<unsigned>(o.height * fit);
}

std::string timestampedName() {
  const std::time_t now = std::time(nullptr);
  char name[64];
  std::strftime(name, sizeof name, "nineball-%Y%m%d-%H%M%S.png", std::localtime(&now));
  return name;
}

void logFrameRate(const FrameTimer& moving, long frames) {
  if (moving.count() == 0) {
    logger("game")->info("{} frames drawn, none while balls moved", frames);
    return;
  }
  const double median = moving.quantile(0.5);
  logger("game")->info(
      "{} frames drawn; {} while balls moved: median {:.2f} ms ({:.0f} fps), 95th percentile "
      "{:.2f} ms ({:.0f} fps)",
      frames, moving.count(), median * 1e3, 1.0 / median, moving.quantile(0.95) * 1e3,
      1.0 / moving.quantile(0.95));
}

// For the tests that check that no text spills: each line drawn, its box and its room.
void writeHudTexts(const std::string& path, const std::vector<render::DrawnText>& texts,
                   unsigned width, unsigned height) {
  std::ofstream out(path);
  out << "window 0 0 " << width << ' ' << height << '\n';
  for (const render::DrawnText& t : texts) {
    out << "text " << t.box.left << ' ' << t.box.top << ' ' << t.box.width << ' ' << t.box.height
        << " room " << t.room.left << ' ' << t.room.top << ' ' << t.room.width << ' '
        << t.room.height << " : " << t.text << '\n';
  }
}

}  // namespace

int runGame(const GameOptions& options_in, const GameStart& start, std::ostream& err) {
  GameSession session(start.setup, options_in.practice);
  ComputerPlayer computer(start.setup.seed);
  if (!options_in.practice) {
    computer.setOpponent(session, opponentFromName(options_in.opponent).value_or(std::nullopt));
  }
  for (std::size_t i = 0; i < start.turns.size(); ++i) {
    try {
      session.playTurn(start.turns[i]);
    } catch (const IllegalAction& e) {
      err << "nineball: " << start.script_name << ": turns[" << i << "]: " << e.what() << '\n';
      return 2;
    }
  }

  const DisplayConnection display;
  if (!display.connected()) {
    err << "nineball: no display found; run the game under a virtual display, e.g. xvfb-run -a "
           "nineball\n";
    return 1;
  }
  std::string why;
  const auto fonts = render::loadFonts(why);
  if (!fonts) {
    err << "nineball: " << why << '\n';
    return 1;
  }
  SfmlErrToLog sfml_log;
  GameOptions options = options_in;
  const bool capture = !options.screenshot.empty();
  // Refused before a window opens and frames are drawn for nothing.
  if (capture && !canWriteFile(options.screenshot, why)) {
    err << "nineball: --screenshot: " << why << '\n';
    return kExitBadInput;
  }
  const bool benchmark = !capture && options.frames.has_value();
  if (!capture) fitDesktop(options);
  bool fullscreen = options.fullscreen && !capture;
  sf::RenderWindow window;
  openWindow(window, fullscreen, options.width, options.height, !capture && !benchmark);
  render::ScenePainter painter(session.match().world().table(), *fonts);
  painter.resize(window.getSize().x, window.getSize().y);
  const auto sounds = options.mute ? nullptr : audio::ImpactSounds::open();
  UiState ui;
  GameInput input(session, ui, computer);
  // A picture taken after N fixed frames must not depend on how fast the planner was.
  computer.setWaitForPlans(capture);
  const long frame_limit = options.frames.value_or(capture ? 1 : -1);
  if (options.frames && start.turns.empty()) session.shoot();  // the opening break, as a demo
  if (options.replay) session.startReplay(false);
  logger("game")->info("window {}x{}, {}", window.getSize().x, window.getSize().y,
                       sounds ? "sound on" : "no sound");

  FrameTimer moving;
  sf::Clock frame_clock;
  sf::Clock display_clock;
  long frame = 0;
  while (window.isOpen()) {
    sf::Event event;
    while (window.pollEvent(event)) {
      if (event.type == sf::Event::Closed) {
        window.close();
      } else if (event.type == sf::Event::Resized) {
        const float w = static_cast<float>(event.size.width);
        const float h = static_cast<float>(event.size.height);
        window.setView(sf::View(sf::FloatRect(0.0f, 0.0f, w, h)));
        painter.resize(w, h);
      } else {
        input.handle(event, painter.view());
      }
    }
    if (!window.isOpen()) break;
    const double dt =
        capture ? kFixedFrame : std::min<double>(frame_clock.restart().asSeconds(), kMaxFrame);
    input.update(dt);
    // The computer waits while the help or the quit question is open, as a player would.
    if (!ui.help && !ui.confirm_quit && !session.replaying()) computer.update(session, dt);
    const bool rolling = session.phase() == Phase::Rolling;
    const auto impacts = session.advance(dt);
    if (sounds && !impacts.empty()) sounds->play(impacts);
    painter.draw(window, buildFrame(session, ui, computer));
    ++frame;

    if (capture && frame >= frame_limit) {
      if (!render::saveWindowPng(window, options.screenshot, why)) {
        err << "nineball: --screenshot: " << why << '\n';
        return kExitBadInput;
      }
      logger("game")->info("saved {} after {} frames", options.screenshot, frame);
      if (const char* boxes = std::getenv("NINEBALL_HUD_TEXTS")) {
        writeHudTexts(boxes, painter.hudTexts(), window.getSize().x, window.getSize().y);
      }
      break;
    }
    WindowRequests& requests = input.requests();
    if (requests.screenshot) {
      requests.screenshot = false;
      const std::string name = timestampedName();
      if (render::saveWindowPng(window, name, why)) {
        session.say("Screenshot saved: " + name);
      } else {
        session.say("Screenshot failed: " + why, render::Tone::Warning);
      }
    }
    window.display();
    const double frame_time = display_clock.restart().asSeconds();
    if (rolling) moving.add(frame_time);
    if (benchmark && frame >= frame_limit) break;
    if (requests.quit) window.close();
    if (requests.toggle_fullscreen) {
      requests.toggle_fullscreen = false;
      fullscreen = !fullscreen;
      openWindow(window, fullscreen, options.width, options.height, true);
      window.setView(sf::View(sf::FloatRect(0.0f, 0.0f, static_cast<float>(window.getSize().x),
                                            static_cast<float>(window.getSize().y))));
      painter.resize(window.getSize().x, window.getSize().y);
    }
    if (!capture && !benchmark) {
      const double spare = 1.0 / kMaxFps - frame_clock.getElapsedTime().asSeconds();
      if (spare > 0.0) sf::sleep(sf::seconds(static_cast<float>(spare)));
    }
  }
  logFrameRate(moving, frame);
  return 0;
}

}  // namespace nineball::app
