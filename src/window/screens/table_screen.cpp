#include "window/screens/table_screen.hpp"

#include <string>

#include "common/atomic_file.hpp"
#include "common/log.hpp"
#include "play/bank_guide.hpp"
#include "window/frame_builder.hpp"
#include "window/rack_save.hpp"
#include "window/rack_script.hpp"
#include "window/screens/dialog_contents.hpp"
#include "window/screens/online_lobby_screen.hpp"
#include "window/seat_token_file.hpp"

namespace nineball::window {
namespace {

// --watch: the balls rest this long (s) before the next turn is played, as a player would.
constexpr double kWatchPause = 0.8;
// s the end of a rack stays on screen before a watched race racks the next.
constexpr double kRackOverPause = 2.5;

// A press of `key` (named apart from the other screens' helpers: one unity build unit may hold
// them all).
bool isTablePress(const sf::Event& event, sf::Keyboard::Key key) {
  return event.type == sf::Event::KeyPressed && event.key.code == key;
}

}  // namespace

TableScreen::TableScreen(const MatchSetup& setup, bool practice, bool keep_rack,
                         bool muted_by_option, TableWindow& window)
    : window_(window),
      session_(setup, practice),
      count_([this](int seat, const TurnRecord& record, bool was_break) {
        stats_.record(seat, record, was_break);
      }),
      seats_(setup.seed),
      input_(session_, ui_, seats_),
      dialogs_(session_, ui_, seats_, input_.requests(),
               {[this]() -> const render::ViewTransform& { return window_.pointerView(); },
                [this](const sf::Event& event) { TableScreen::event(event); },
                [this](sf::RenderTarget& target) {
                  window_.painter().drawDialog(target, dialog_hud_);
                }}),
      keep_rack_(keep_rack),
      muted_by_option_(muted_by_option) {
  session_.setTurnObserver(count_);
}

void TableScreen::event(const sf::Event& event) {
  Settings& settings = window_.settings();
  if (isTablePress(event, sf::Keyboard::F2) && ui_.drag == Drag::None) {
    window_.openSettings();
  } else if (isTablePress(event, sf::Keyboard::O) && online_) {
    session_.say("Online, the other seat is " + online_->peerName() + "'s.");
  } else if (isTablePress(event, sf::Keyboard::M) && muted_by_option_) {
    session_.say("No sound this run: the game was started with --mute.");
  } else if (isTablePress(event, sf::Keyboard::M)) {
    settings.muted = !settings.muted;
    window_.applySound();
    window_.saveSettingsNow();
    session_.say(settings.muted ? "Sound off (M turns it on)." : "Sound on (M mutes it).");
  } else {
    input_.handle(event, window_.pointerView());
    // The menu offers the opponent last played, O's change included.
    if (isTablePress(event, sf::Keyboard::O) && !session_.practice() &&
        !(settings.last.opponent == seats_.opponent())) {
      settings.last.opponent = seats_.opponent();
      window_.saveSettingsNow();
    }
  }
}

bool TableScreen::busy() const {
  const bool watching = next_watched_ < watched_.size();
  return online_ || watching || session_.phase() == Phase::Rolling || session_.replaying() ||
         seats_.controls(session_) || input_.keysHeld() || ui_.drag != Drag::None;
}

// One frame of play: the held keys, the computer, the balls. Notes whether the balls were
// rolling as the frame began (its time counts in the frame rate while balls move).
void TableScreen::update(double dt, bool on_top) {
  input_.update(dt);
  updateOnline(dt);
  playWatchedTurn(dt);
  // The computer waits while the help, the quit question or the settings are open, as a player
  // would; it plays on under the push-out choice and the rack's end (its choice to make).
  const bool nothing_over = on_top || dialog_.onTop(window_.screens());
  if (!ui_.help && !ui_.confirm_quit && nothing_over && !session_.replaying()) {
    seats_.update(session_, dt);
  }
  rolling_ = session_.phase() == Phase::Rolling;
  const auto impacts = session_.advance(dt);
  if (keep_rack_ && !online_ && session_.phase() == Phase::GameOver &&
      forgotten_rack_ != session_.rackNumber()) {
    forgetRack(rackSavePath());  // a finished rack has nothing to resume
    forgotten_rack_ = session_.rackNumber();
  }
  if (window_.sounds() && !impacts.empty()) window_.sounds()->play(impacts);
}

void TableScreen::draw(sf::RenderTarget& target) {
  const Settings& settings = window_.settings();
  render::ScenePainter& painter = window_.painter();
  render::Frame picture = buildFrame(session_, ui_, seats_);
  picture.guide_scale = guideLengthFactor(settings.guide);
  if (settings.guide == GuideLength::Off) {
    picture.guide.reset();
    picture.guide_foul.clear();
  }
  zoomView(picture);
  if (settings.bank_line && picture.guide) {
    picture.bank = bankGuide(session_.match().world().table(), picture.ball_radius, picture.balls,
                             *picture.guide);
  }
  if (dialogCalledFor(session_, ui_) == DialogKind::GameOver) {
    for (int seat = 0; seat < 2; ++seat) {
      picture.hud.overlay_lines.push_back(session_.seatName(seat) + ": " + stats_.line(seat));
    }
  }
  if (online_) {
    picture.hud.mode = online_->started() ? "online vs " + online_->peerName() : "online: waiting";
    // Before the game began, its lobby says how the link stands.
    if (online_->started() && online_->stage() != OnlinePlay::Stage::Playing) {
      picture.hud.status = online_->banner();
    }
  }
  // The dialog is its own screen's to draw, over this picture (DialogScreen).
  dialog_hud_ = picture.hud;
  picture.hud.dialog.reset();
  painter.draw(target, picture);
}

// One frame of the online game; a joiner's session is the host's match once welcomed.
void TableScreen::updateOnline(double dt) {
  if (!online_) return;
  online_->update(session_, dt);
  if (online_->sessionReplaced()) {
    session_.setTurnObserver(count_);
    stats_ = SessionStats{};
    followTable();
  }
}

bool TableScreen::beginOnline(OnlineConfig config, const std::string& remembered_name,
                              std::string& why) {
  if (config.name.empty()) config.name = remembered_name;
  // The default name on both sides would show both players as "Player 1".
  if (config.side == net::Side::Joiner && config.name == "Player 1") config.name = "Player 2";
  if (config.side == net::Side::Joiner) config.seat_file = seatTokenPath();
  std::unique_ptr<OnlinePlay> online = OnlinePlay::start(config, why);
  if (!online) return false;
  seats_.setOpponent(session_, HumanSeat{});
  const int own = config.side == net::Side::Host ? 0 : 1;
  seats_.setRemote(1 - own, *online);
  setOnline(std::move(online));
  session_.setSeatName(own, config.name);
  session_.setSeatName(1 - own, config.side == net::Side::Host ? "Your friend" : "Host");
  return true;
}

void TableScreen::setOnline(std::unique_ptr<OnlinePlay> online) {
  online_ = std::move(online);
  OnlineLobbyScreen::Hooks hooks;
  hooks.online = [this]() -> const OnlinePlay* { return online_.get(); };
  hooks.view = [this]() -> const render::ViewTransform& { return window_.pointerView(); };
  // Leaving the lobby leaves as Esc's question would: to the menu, or out of the program.
  hooks.cancel = [this] {
    WindowRequests& requests = input_.requests();
    (ui_.leave_to_menu ? requests.menu : requests.quit) = true;
  };
  hooks.draw = [this](sf::RenderTarget& target, const render::HudState& hud) {
    window_.painter().drawDialog(target, hud);
  };
  window_.screens().push(std::make_unique<OnlineLobbyScreen>(std::move(hooks)));
}

void TableScreen::leaveOnline(const std::string& why) {
  if (!online_) return;
  online_->leave(why);
  seats_.clearRemote();
  online_.reset();
}

void TableScreen::leave(const std::string& why) {
  if (online_) {
    // An online rack is not a saved rack to resume alone.
    leaveOnline(why);
  } else {
    saveRackInPlay();
  }
}

void TableScreen::saveRackInPlay() {
  if (!keep_rack_ || session_.practice()) return;
  // A rack in play is kept for the next start (a finished one was forgotten as it ended;
  // a rack not yet broken leaves an older save alone).
  if (session_.phase() == Phase::GameOver || session_.rackTurns().empty()) return;
  const std::string path = rackSavePath();
  std::string why;
  if (saveRack(saveOf(session_, seats_.opponent()), path, why)) {
    logger("game")->info("rack saved to {}", path);
  } else {
    logger("game")->warn("rack not saved: {}", why);
  }
}

void TableScreen::leaveForMenu() {
  const bool leave_to_menu = ui_.leave_to_menu, rack_kept = ui_.rack_kept;
  ui_ = UiState{};
  ui_.leave_to_menu = leave_to_menu;
  ui_.rack_kept = rack_kept;
  stats_ = SessionStats{};
  forgotten_rack_ = 0;
}

// The painter (and the view the pointer is read through) on the session's table.
void TableScreen::followTable() {
  window_.painter().showTable(session_.match().world().table());
}

// The table seen as close as the player asked, round the cue ball (following it as it rolls) or
// the point the wheel zoomed at; a dialog shows the whole table.
void TableScreen::zoomView(const render::Frame& picture) {
  const bool dialog = picture.hud.dialog.has_value();
  Vec2 focus = session_.cuePosition();
  const int shooter = session_.practice() ? kCueBall : session_.shooterBall();
  for (const BallState& b : picture.balls) {
    if (b.id == shooter && !b.pocket) focus = b.pos;
  }
  window_.painter().setZoom(dialog ? 1.0 : ui_.zoom, ui_.zoom_at.value_or(focus));
}

// --watch: the next turn once the balls have rested a moment, as a player would take it; a turn
// the rack refuses ends the watching with its reason on screen.
void TableScreen::playWatchedTurn(double dt) {
  if (next_watched_ >= watched_.size() || session_.replaying()) return;
  const Phase phase = session_.phase();
  if (phase == Phase::GameOver && session_.bestOf() > 0 && !session_.matchWinner()) {
    // A race's script goes on into the next rack once the last one's end has been seen.
    rested_ += dt;
    if (rested_ < kRackOverPause) return;
    rested_ = 0.0;
    session_.rematch();
    return;
  }
  if (phase != Phase::Aiming && phase != Phase::PushOutChoice) {
    rested_ = 0.0;
    return;
  }
  rested_ += dt;
  if (rested_ < kWatchPause) return;
  rested_ = 0.0;
  const TurnInput& turn = watched_[next_watched_++];
  if (turn.kind == TurnInput::Kind::Decision) {
    session_.decide(turn.shoot, turn.replace);
    return;
  }
  if (!session_.shoot(turn)) {
    logger("game")->warn("--watch: turns[{}] refused: {}", next_watched_ - 1, session_.message());
    next_watched_ = watched_.size();
  }
}

// F5: the match (or the rack) as a match script in the current directory, to play again
// headless or here.
void TableScreen::saveRackScript() {
  const bool match = savesMatch(session_);
  const auto script = gameScript(session_, script_setup_);
  const bool played = match ? !session_.matchTurns().empty() : !session_.rackTurns().empty();
  if (!script || !played) {
    session_.say("No rack to save yet: F5 saves a rack once it has a turn.", render::Tone::Warning);
    return;
  }
  const std::string name = gameScriptName(match);
  const std::string what = match ? "Match" : "Rack";
  std::string why;
  if (writeFileAtomically(name, script->dump(2) + "\n", why)) {
    session_.say(what + " saved: " + name + " (nineball match " + name + " plays it again).");
    logger("game")->info("{} saved as a match script: {}", match ? "match" : "rack", name);
  } else {
    session_.say(what + " not saved: " + why, render::Tone::Warning);
  }
}

}  // namespace nineball::window
