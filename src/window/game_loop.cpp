#include "window/game_loop.hpp"

#include <SFML/System/Sleep.hpp>
#include <algorithm>
#include <ctime>
#include <ostream>
#include <string>
#include <vector>

#include "app/exit_codes.hpp"
#include "common/atomic_file.hpp"
#include "common/log.hpp"
#include "nineball/games.hpp"
#include "nineball/seat.hpp"
#include "play/bank_guide.hpp"
#include "render/png_capture.hpp"
#include "window/frame_builder.hpp"
#include "window/menu_screen.hpp"
#include "window/online_start.hpp"
#include "window/rack_save.hpp"
#include "window/rack_seed.hpp"
#include "window/screens/settings_screen.hpp"
#include "window/screens/start_menu_screen.hpp"
#include "window/start_menu.hpp"
#include "window/window_icon.hpp"
#include "window/window_placement.hpp"

namespace nineball::window {
namespace {

constexpr const char* kTitle = "nineball";
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

}  // namespace

GameLoop::GameLoop(const app::GameOptions& options, const GameStart& start, std::ostream& err)
    : err_(err),
      options_(options),
      driver_(CaptureDriver::fromProcess(options)),
      // The start menu, the settings file and the saved rack belong to a game a person starts;
      // screenshots and scripts (the tests) see none of them unless --menu asks.
      show_menu_(!(options.host_port || !options.join.empty()) &&
                 (options.menu || (driver_.person() && options.script.empty()))),
      keep_rack_(driver_.person() && options.script.empty() &&
                 !(options.host_port || !options.join.empty())),
      online_start_(options.host_port || !options.join.empty()),
      table_(makeTable(start)) {
  setup_status_ = setUp(start);
}

TableScreen& GameLoop::makeTable(const GameStart& start) {
  auto table = std::make_unique<TableScreen>(start.setup, options_.practice, keep_rack_,
                                             options_.mute, static_cast<TableWindow&>(*this));
  TableScreen& kept = *table;
  screens_.push(std::move(table));
  return kept;
}

std::optional<int> GameLoop::setUp(const GameStart& start) {
  GameSession& session = table_.session();
  table_.setScriptSetup(start.script_setup);
  if (start.race.race_to > 0) {
    session.setBestOf(2 * start.race.race_to - 1);
    session.setBreaks(start.race.breaks);
  }
  table_.ui().leave_to_menu = show_menu_;
  table_.ui().rack_kept = keep_rack_;
  if (!options_.practice) {
    table_.seats().setOpponent(session, seatFromName(options_.opponent).value_or(HumanSeat{}));
  }
  if (!online_start_) {
    if (const auto status = playScript(start)) return status;
  }
  if (const auto status = openDisplay()) return status;
  // Refused before a window opens and frames are drawn for nothing.
  if (const auto status = driver_.refuseBeforeWindow(err_)) return status;
  readSettings(start);
  if (online_start_) {
    if (const auto status = startOnline(start)) return status;
  }
  openGameWindow();
  if (const auto status = startMenu()) return status;
  prepareFrames(start);
  return std::nullopt;
}

std::optional<int> GameLoop::playScript(const GameStart& start) {
  if (options_.watch) {
    // Played on screen as the frames go (playWatchedTurn), not before the first one.
    table_.watch(start.turns);
    return std::nullopt;
  }
  for (std::size_t i = 0; i < start.turns.size(); ++i) {
    try {
      table_.session().playTurn(start.turns[i]);
    } catch (const IllegalAction& e) {
      err_ << "nineball: " << start.script_name << ": turns[" << i << "]: " << e.what() << '\n';
      return 2;
    }
  }
  return std::nullopt;
}

std::optional<int> GameLoop::openDisplay() {
  display_.emplace();
  if (!display_->connected()) {
    err_ << "nineball: no display found; run the game under a virtual display, e.g. xvfb-run -a "
            "nineball\n";
    return 1;
  }
  std::string why;
  fonts_ = render::loadFonts(why);
  if (!fonts_) {
    err_ << "nineball: " << why << '\n';
    return 1;
  }
  sfml_log_.emplace();
  return std::nullopt;
}

void GameLoop::readSettings(const GameStart& start) {
  // An online game started from the command line still wants the player's remembered name.
  const bool remembered = show_menu_ || (online_start_ && driver_.person());
  settings_ = remembered ? loadSettings(settingsPath()) : Settings{};
  presetFromCommandLine(settings_, options_, start.setup);
}

void GameLoop::openGameWindow() {
  if (!driver_.picture()) fitDesktop(options_);
  fullscreen_ = options_.fullscreen && !driver_.picture();
  window_.emplace();
  openWindow(*window_, fullscreen_, options_.width, options_.height, driver_.person());
  painter_.emplace(table_.session().match().world().table(), *fonts_);
  painter_->resize(window_->getSize().x, window_->getSize().y);
  menu_painter_.emplace(*fonts_);
}

// What the start menu needs from the window: where it draws and the table behind it.
StartMenuContext GameLoop::menuContext() {
  return {*window_,
          *painter_,
          *menu_painter_,
          [this] { return buildFrame(table_.session(), table_.ui(), table_.seats()); },
          options_.mute,
          drawsFreshSeeds(options_),
          {}};
}

std::optional<int> GameLoop::startMenu() {
  if (!show_menu_) return std::nullopt;
  StartMenuContext menu = menuContext();
  if (driver_.picturesMenu(show_menu_)) {
    drawStartMenu(menu, settings_);
    return driver_.savePicture(*window_, err_) ? 0 : app::kExitBadInput;
  }
  int status = 0;
  const std::optional<std::vector<MenuKey>> typed = driver_.typedMenuKeys(err_, status);
  if (!typed) return status;
  if (typed->empty()) {
    showStartMenu();  // the player chooses as the frames go
    return std::nullopt;
  }
  // A picture run's choice, made before the first frame.
  menu.typed = *typed;
  MenuModel::Outcome outcome = MenuModel::Outcome::None;
  if (!chooseByTypedKeys(menu, table_.session(), table_.seats(), settings_, table_.turnCounter(),
                         &outcome)) {
    return 0;
  }
  startOnlineFromMenu(outcome);
  table_.followTable();
  return std::nullopt;
}

// The start menu over the table, on the one event loop; menuClosed() once the player chose.
void GameLoop::showStartMenu() {
  menu_open_ = true;
  screens_.push(std::make_unique<StartMenuScreen>(
      menuContext(), table_.session(), table_.seats(), settings_, table_.turnCounter(),
      [this](MenuModel::Outcome outcome, bool started) { menuClosed(outcome, started); },
      [this](const sf::Event& event) { table_.input().handle(event, painter_->view()); }));
}

void GameLoop::menuClosed(MenuModel::Outcome outcome, bool started) {
  menu_open_ = false;
  if (!started) {
    window_->close();
    return;
  }
  startOnlineFromMenu(outcome);
  table_.followTable();
  applySound();
  if (demo_due_) {
    demo_due_ = false;
    beginFrames();
  }
  frame_clock_.restart();
  display_clock_.restart();
  since_draw_.restart();
}

// F2: the settings over the table, applied as they change and saved as they close.
void GameLoop::openSettings() {
  SettingsScreen::Hooks hooks;
  hooks.changed = [this](const Settings& settings) {
    settings_ = settings;
    applySound();
  };
  hooks.let_go = [this](const sf::Event& event) { table_.input().handle(event, painter_->view()); };
  hooks.screenshot = [this] { table_.input().requests().screenshot = true; };
  hooks.closed = [this] { saveSettingsNow(); };
  screens_.push(std::make_unique<SettingsScreen>(settings_, options_.mute, *window_, *menu_painter_,
                                                 std::move(hooks)));
}

// --host / --join: the link, and this side's seat named. Nothing when the game goes on.
std::optional<int> GameLoop::startOnline(const GameStart& start) {
  OnlineConfig config = onlineConfigFromOptions(options_, start);
  driver_.boundOnlineWaits(config);
  std::string why;
  if (!table_.beginOnline(config, settings_.last.names[0], why)) {
    err_ << "nineball: --host " << config.address.port << ": " << why << '\n';
    return 1;
  }
  return std::nullopt;
}

// The start menu's "Play online": the table hosts or joins as the menu asked.
void GameLoop::startOnlineFromMenu(MenuModel::Outcome outcome) {
  const std::optional<OnlineConfig> config =
      onlineConfigFromMenu(outcome, settings_, table_.session().setup());
  std::string why;
  if (config && !table_.beginOnline(*config, settings_.last.names[0], why)) {
    table_.session().say("Cannot host: " + why + ". Playing at this computer instead.",
                         render::Tone::Warning);
  }
}

// How the online game stands, for a picture run's end: done once this side is done with the
// rack (or the game ended).
std::optional<CaptureDriver::OnlineEnd> GameLoop::onlineEnd() {
  OnlinePlay* online = table_.online();
  if (!online) return std::nullopt;
  CaptureDriver::OnlineEnd end;
  end.done = online->finished(table_.session()) || online->stage() == OnlinePlay::Stage::Over;
  if (online->failed()) end.failure = online->why();
  return end;
}

void GameLoop::prepareFrames(const GameStart& start) {
  sounds_ = options_.mute ? nullptr : audio::ImpactSounds::open();
  applySound();
  // A picture taken after N fixed frames must not depend on how fast the planner was.
  table_.seats().computer().setWaitForPlans(driver_.picture());
  demo_break_ = driver_.breaksForDemo() && start.turns.empty() && !table_.online();
  // Under a start menu, the game the frames show is the one chosen there.
  if (menu_open_) {
    demo_due_ = true;
  } else {
    beginFrames();
  }
  logger("game")->info("window {}x{}, {}", window_->getSize().x, window_->getSize().y,
                       sounds_ ? "sound on" : "no sound");
  // The frames' clocks start with the first frame, not with the setup and its menu.
  frame_clock_.restart();
  display_clock_.restart();
  since_draw_.restart();
}

// --frames' demo break, --replay's shot again: the first frames' play.
void GameLoop::beginFrames() {
  if (demo_break_) table_.session().shoot();
  if (options_.replay) table_.session().startReplay(false);
}

void GameLoop::applySound() {
  if (sounds_) audio::ImpactSounds::setVolume(settings_.muted ? 0.0 : settings_.volume);
}

void GameLoop::saveSettingsNow() {
  if (!show_menu_) return;
  std::string whynot;
  if (!saveSettings(settings_, settingsPath(), whynot)) {
    logger("game")->warn("settings not saved: {}", whynot);
  }
}

int GameLoop::run() {
  if (setup_status_) return *setup_status_;
  while (window_->isOpen()) {
    const bool changed = handleEvents();
    if (!window_->isOpen()) break;
    // A screen that came or went (the menu opened by Esc) is drawn at once.
    if (waitWhileIdle(screens_.takeChanged() || changed)) continue;
    screens_.update(driver_.frameSeconds(frame_clock_.restart().asSeconds()));
    // A screen the frame ended (the online lobby once the friend came) leaves at once.
    if (screens_.removeFinished()) table_.followTable();
    // The frame's play may have ended the rack or called for a choice.
    table_.followDialog();
    draw();
    int status = 0;
    const CaptureDriver::Next next =
        driver_.afterDraw(frame_, onlineEnd(), *window_, *painter_, err_, status);
    if (next == CaptureDriver::Next::Fail) return status;
    if (next == CaptureDriver::Next::Finish) break;
    takeRequestedScreenshot();
    present(table_.takeRolled());
    if (driver_.benchmarkDone(frame_)) break;
    answerRequests();
    capFrameRate();
  }
  return finish();
}

// True when anything came (or on the first frame): the picture must be drawn again.
bool GameLoop::handleEvents() {
  // The pointer maps to the table the session plays on, whatever changed it since the last frame.
  table_.followTable();
  sf::Event event;
  bool changed = frame_ == 0;
  while (window_->pollEvent(event)) {
    changed = true;
    if (event.type == sf::Event::Closed) {
      window_->close();
    } else if (event.type == sf::Event::Resized) {
      const float w = static_cast<float>(event.size.width);
      const float h = static_cast<float>(event.size.height);
      window_->setView(sf::View(sf::FloatRect(0.0f, 0.0f, w, h)));
      painter_->resize(w, h);
    } else {
      screens_.event(event);
    }
    // A screen done (a game chosen, the settings closed) leaves before the next event, and
    // the next event finds the dialog the table now calls for.
    if (screens_.removeFinished()) table_.followTable();
    table_.followDialog();
  }
  return changed;
}

// True when the frame is skipped.
bool GameLoop::waitWhileIdle(bool changed) {
  // Nothing moving, nobody thinking, no key held, nothing new: look again a little later
  // instead of drawing the same picture again (the idle window costs next to nothing).
  if (driver_.person() && !screens_.busy() && !changed &&
      since_draw_.getElapsedTime().asSeconds() < kIdleRedraw) {
    sf::sleep(sf::seconds(static_cast<float>(kIdlePoll)));
    frame_clock_.restart();
    return true;
  }
  return false;
}

void GameLoop::draw() {
  screens_.draw(*window_);
  since_draw_.restart();
  ++frame_;
}

// F12: the picture as drawn, before it is shown.
void GameLoop::takeRequestedScreenshot() {
  WindowRequests& requests = table_.input().requests();
  if (!requests.screenshot) return;
  requests.screenshot = false;
  const std::string name = timestampedName();
  std::string why;
  if (render::saveWindowPng(*window_, name, why)) {
    table_.session().say("Screenshot saved: " + name);
  } else {
    table_.session().say("Screenshot failed: " + why, render::Tone::Warning);
  }
}

void GameLoop::present(bool rolling) {
  window_->display();
  const double frame_time = display_clock_.restart().asSeconds();
  if (rolling) moving_.add(frame_time);
}

// Quit and full screen, asked for by a key.
void GameLoop::answerRequests() {
  WindowRequests& requests = table_.input().requests();
  if (requests.quit) window_->close();
  if (requests.menu) {
    requests.menu = false;
    backToMenu();
  }
  if (requests.save_rack) {
    requests.save_rack = false;
    table_.saveRackScript();
  }
  if (requests.cycle_guide) {
    requests.cycle_guide = false;
    settings_.guide = nextGuide(settings_.guide);
    saveSettingsNow();
    table_.session().say(std::string("Aim guide: ") + guideLengthName(settings_.guide) +
                         " (G changes it; the menu's settings keep it).");
  }
  if (requests.toggle_fullscreen) {
    requests.toggle_fullscreen = false;
    fullscreen_ = !fullscreen_;
    openWindow(*window_, fullscreen_, options_.width, options_.height, true);
    window_->setView(sf::View(sf::FloatRect(0.0f, 0.0f, static_cast<float>(window_->getSize().x),
                                            static_cast<float>(window_->getSize().y))));
    painter_->resize(window_->getSize().x, window_->getSize().y);
  }
}

void GameLoop::capFrameRate() {
  if (driver_.person() && settings_.frame_cap > 0) {
    const double spare = 1.0 / settings_.frame_cap - frame_clock_.getElapsedTime().asSeconds();
    if (spare > 0.0) sf::sleep(sf::seconds(static_cast<float>(spare)));
  }
}

// Esc: the rack kept as on quitting, then the start menu (its Resume picks the rack up).
void GameLoop::backToMenu() {
  table_.leave("the player left to the menu");
  table_.leaveForMenu();
  showStartMenu();
}

int GameLoop::finish() {
  // A screen still open over the table closes as its own way out would (the settings kept).
  screens_.closeDownTo(1);
  logFrameRate(moving_, frame_);
  table_.leave("the player quit");
  return 0;
}

}  // namespace nineball::window
