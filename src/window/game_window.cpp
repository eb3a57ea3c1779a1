#include "window/game_window.hpp"

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
#include "audio/impact_sounds.hpp"
#include "nineball/atomic_file.hpp"
#include "nineball/bank_guide.hpp"
#include "nineball/games.hpp"
#include "nineball/log.hpp"
#include "render/fonts.hpp"
#include "render/png_capture.hpp"
#include "render/scene_painter.hpp"
#include "render/sfml_errors.hpp"
#include "window/computer_player.hpp"
#include "window/display_probe.hpp"
#include "window/frame_builder.hpp"
#include "window/frame_timer.hpp"
#include "window/game_input.hpp"
#include "window/game_session.hpp"
#include "window/menu_screen.hpp"
#include "window/rack_save.hpp"
#include "window/session_stats.hpp"
#include "window/settings.hpp"
#include "window/start_menu.hpp"
#include "window/window_icon.hpp"
#include "window/window_placement.hpp"

namespace nineball::window {
namespace {

constexpr const char* kTitle = "nineball";
// A screenshot run steps a fixed 1/60 s per frame, so that its picture is always the same.
constexpr double kFixedFrame = 1.0 / 60.0;
// A frame longer than this (a stall, a dragged window) counts as this long.
constexpr double kMaxFrame = 0.25;
// When nothing moves and no key is held, the window looks at its events this often (s) and
// redraws only when one came, or at this interval (a window uncovered shows itself again).
constexpr double kIdlePoll = 0.03;
constexpr double kIdleRedraw = 2.0;
constexpr unsigned kAntialiasing = 0;

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
void fitDesktop(app::GameOptions& o) {
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

int runGame(const app::GameOptions& options_in, const GameStart& start, std::ostream& err) {
  GameSession session(start.setup, options_in.practice);
  SessionStats stats;
  const GameSession::TurnObserver count = [&stats](int seat, const TurnRecord& record,
                                                   bool was_break) {
    stats.record(seat, record, was_break);
  };
  session.setTurnObserver(count);
  ComputerPlayer computer(start.setup.seed);
  if (!options_in.practice) {
    computer.setOpponent(session, seatFromName(options_in.opponent).value_or(HumanSeat{}));
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
  const render::SfmlErrorsToLog sfml_log;
  app::GameOptions options = options_in;
  const bool capture = !options.screenshot.empty();
  // Refused before a window opens and frames are drawn for nothing.
  if (capture && !canWriteFile(options.screenshot, why)) {
    err << "nineball: --screenshot: " << why << '\n';
    return app::kExitBadInput;
  }
  const bool benchmark = !capture && options.frames.has_value();
  const bool interactive = !capture && !benchmark;
  // The start menu, the settings file and the saved rack belong to a game a person starts;
  // screenshots and scripts (the tests) see none of them unless --menu asks.
  const bool show_menu = options.menu || (interactive && options.script.empty());
  const bool keep_rack = interactive && options.script.empty();
  Settings settings = show_menu ? loadSettings(settingsPath()) : Settings{};
  // An opponent or rules asked for on the command line preset the menu.
  if (options.opponent != "human") {
    settings.last.opponent = seatFromName(options.opponent).value_or(HumanSeat{});
  }
  if (options.rules != "wpa") settings.last.rules = start.setup.rules;
  if (options.game != defaultGame().name) settings.last.game = start.setup.game;
  if (!capture) fitDesktop(options);
  bool fullscreen = options.fullscreen && !capture;
  sf::RenderWindow window;
  openWindow(window, fullscreen, options.width, options.height, interactive);
  render::ScenePainter painter(session.match().world().table(), *fonts);
  painter.resize(window.getSize().x, window.getSize().y);
  UiState ui;
  render::MenuPainter menu_painter(*fonts);
  StartMenuContext menu{window, painter, menu_painter,
                        [&] { return buildFrame(session, ui, computer); }};
  if (show_menu && capture) {
    drawStartMenu(menu, settings);
    if (!render::saveWindowPng(window, options.screenshot, why)) {
      err << "nineball: --screenshot: " << why << '\n';
      return app::kExitBadInput;
    }
    return 0;
  }
  if (show_menu) {
    if (!runStartMenu(menu, session, computer, settings, count)) return 0;
  }
  const auto sounds = options.mute ? nullptr : audio::ImpactSounds::open();
  const auto applySound = [&] {
    if (sounds) audio::ImpactSounds::setVolume(settings.muted ? 0.0 : settings.volume);
  };
  applySound();
  const auto saveSettingsNow = [&] {
    if (!show_menu) return;
    std::string whynot;
    if (!saveSettings(settings, settingsPath(), whynot)) {
      logger("game")->warn("settings not saved: {}", whynot);
    }
  };
  std::optional<MenuModel> settings_menu;  // F2: the settings over the game
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
  sf::Clock since_draw;
  int forgotten_rack = 0;
  long frame = 0;
  while (window.isOpen()) {
    sf::Event event;
    bool changed = frame == 0;
    while (window.pollEvent(event)) {
      changed = true;
      if (event.type == sf::Event::Closed) {
        window.close();
      } else if (event.type == sf::Event::Resized) {
        const float w = static_cast<float>(event.size.width);
        const float h = static_cast<float>(event.size.height);
        window.setView(sf::View(sf::FloatRect(0.0f, 0.0f, w, h)));
        painter.resize(w, h);
      } else if (settings_menu) {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::F2) {
          settings_menu->key(MenuKey::Escape);
        }
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::F12) {
          input.requests().screenshot = true;
        }
        // A key held when the settings opened is still let go in the game.
        if (event.type == sf::Event::KeyReleased || event.type == sf::Event::LostFocus) {
          input.handle(event, painter.view());
        }
        handleMenuEvent(*settings_menu, event, window.getSize().x, window.getSize().y);
        settings = settings_menu->settings();
        applySound();
        if (settings_menu->outcome() != MenuModel::Outcome::None) {
          settings_menu.reset();
          saveSettingsNow();
        }
      } else if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::F2 &&
                 ui.drag == Drag::None) {
        settings_menu = MenuModel::settingsOnly(settings);
      } else if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::M) {
        settings.muted = !settings.muted;
        applySound();
        saveSettingsNow();
        session.say(settings.muted ? "Sound off (M turns it on)." : "Sound on (M mutes it).");
      } else {
        input.handle(event, painter.view());
      }
    }
    if (!window.isOpen()) break;
    // Nothing moving, nobody thinking, no key held, nothing new: look again a little later
    // instead of drawing the same picture again (the idle window costs next to nothing).
    const bool still = session.phase() != Phase::Rolling && !session.replaying() &&
                       !computer.controls(session) && !input.keysHeld() && ui.drag == Drag::None;
    if (interactive && still && !changed && since_draw.getElapsedTime().asSeconds() < kIdleRedraw) {
      sf::sleep(sf::seconds(static_cast<float>(kIdlePoll)));
      frame_clock.restart();
      continue;
    }
    const double dt =
        capture ? kFixedFrame : std::min<double>(frame_clock.restart().asSeconds(), kMaxFrame);
    input.update(dt);
    // The computer waits while the help or the quit question is open, as a player would.
    if (!ui.help && !ui.confirm_quit && !settings_menu && !session.replaying()) {
      computer.update(session, dt);
    }
    const bool rolling = session.phase() == Phase::Rolling;
    const auto impacts = session.advance(dt);
    if (keep_rack && session.phase() == Phase::GameOver && forgotten_rack != session.rackNumber()) {
      forgetRack(rackSavePath());  // a finished rack has nothing to resume
      forgotten_rack = session.rackNumber();
    }
    if (sounds && !impacts.empty()) sounds->play(impacts);
    render::Frame picture = buildFrame(session, ui, computer);
    picture.guide_scale = guideLengthFactor(settings.guide);
    if (settings.bank_line && picture.guide) {
      picture.bank = bankGuide(session.match().world().table(), picture.ball_radius, picture.balls,
                               *picture.guide);
    }
    if (picture.hud.overlay == render::Overlay::GameOver) {
      for (int seat = 0; seat < 2; ++seat) {
        picture.hud.overlay_lines.push_back(session.seatName(seat) + ": " + stats.line(seat));
      }
    }
    painter.draw(window, picture);
    if (settings_menu) {
      menu_painter.draw(window, window.getSize().x, window.getSize().y,
                        menuPicture(*settings_menu));
    }
    since_draw.restart();
    ++frame;

    if (capture && frame >= frame_limit) {
      if (!render::saveWindowPng(window, options.screenshot, why)) {
        err << "nineball: --screenshot: " << why << '\n';
        return app::kExitBadInput;
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
    if (interactive && settings.frame_cap > 0) {
      const double spare = 1.0 / settings.frame_cap - frame_clock.getElapsedTime().asSeconds();
      if (spare > 0.0) sf::sleep(sf::seconds(static_cast<float>(spare)));
    }
  }
  logFrameRate(moving, frame);
  if (keep_rack && !session.practice()) {
    // A rack in play is kept for the next start (a finished one was forgotten as it ended;
    // a rack not yet broken leaves an older save alone).
    const std::string path = rackSavePath();
    if (session.phase() != Phase::GameOver && !session.rackTurns().empty()) {
      if (saveRack(saveOf(session, computer.opponent()), path, why)) {
        logger("game")->info("rack saved to {}", path);
      } else {
        logger("game")->warn("rack not saved: {}", why);
      }
    }
  }
  return 0;
}

}  // namespace nineball::window
