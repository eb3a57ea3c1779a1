#include "window/game_input.hpp"

#include <algorithm>
#include <cmath>

#include "app/opponent.hpp"
#include "render/cue_stick_shape.hpp"
#include "render/hud_layout.hpp"
#include "window/frame_builder.hpp"
#include "window/screens/dialog_contents.hpp"

namespace nineball::window {
namespace {

using Key = sf::Keyboard::Key;

// One tap of an arrow turns the aim this far (deg) or changes the speed this much (m/s); with
// Ctrl or Alt, and a notch of the mouse wheel, turn it a tenth as far: a thin cut at the far
// end of the table needs aims a hundredth of a degree apart.
constexpr double kAimNudgeDeg = 0.1;
constexpr double kAimFineNudgeDeg = 0.01;
// Shift held, the pointer turns the line this far per pixel it travels across (deg): a
// thousand pixels of travel are 20 degrees, a pixel a fiftieth.
constexpr double kFineDegPerPixel = 0.02;
// The closest view of the table (times the whole table's).
constexpr double kMaxZoom = 4.0;
constexpr double kSpeedNudge = 0.1;
// Held keys repeat after this delay (s), slowly for a while, then fast.
constexpr double kHoldDelay = 0.3;
constexpr double kSlowPhase = 1.0;
constexpr double kAimSlowDegPerS = 4.0;
constexpr double kAimFastDegPerS = 30.0;
constexpr double kAimFineDegPerS = 1.0;
constexpr double kAimFinestDegPerS = 0.1;
constexpr double kSpeedPerS = 3.0;
constexpr double kSpinStep = 0.1;
// Degrees of cue elevation per E / Q press: a few presses reach a swerve, twelve a masse.
constexpr double kElevationStepDeg = 5.0;
// The cue ball in hand moves this fast with W A S D (m/s), in steps no longer than this (m).
constexpr double kCueMoveSpeed = 0.4;
constexpr double kCueMoveStep = 0.002;
// A power drag shorter than this (m) is a click: it aims, it does not shoot.
constexpr double kMinPull = 0.01;
// The pointer this close to the cue ball (in ball radii) does not aim: the direction from the
// ball to a point on it is noise, and would swing the cue round (after a drop, say).
constexpr double kAimDeadZone = 2.0;
// An aim held this long (s) is the one a call click keeps: moving the pointer to a pocket
// to call it swings the cue on the way.
constexpr double kAimSettle = 0.25;
// Fast-forward runs the physics this many times as fast (same steps, more per frame).
constexpr double kFastForward = 4.0;

bool inside(const render::PixelRect& r, Vec2 p) {
  return r.contains(p);
}

// The bottom band holds the controls (the power gauge, the spin icon and its tilt ring): the
// pointer there is on its way to one of them, never aiming.
bool overControls(Vec2 px, const render::ViewTransform& view) {
  const render::HudLayout layout = render::HudLayout::of(view);
  return inside(view.bottomBand(), px) ||
         length(px - layout.spin_centre) <= layout.tilt_outer + 0.15 * layout.spin_radius;
}

// Rate of a held key: nothing until it repeats, slow, then fast.
double heldRate(double held, double slow, double fast) {
  if (held < kHoldDelay) return 0.0;
  return held < kHoldDelay + kSlowPhase ? slow : fast;
}

}  // namespace

bool GameInput::dialogOpen() const {
  return dialogCalledFor(session_, ui_) != DialogKind::None;
}

void GameInput::trackModifiers(const sf::Event::KeyEvent& key, bool pressed) {
  // The event of a modifier key itself may not carry its own state yet.
  const bool shift_key = key.code == Key::LShift || key.code == Key::RShift;
  const bool fine_key = key.code == Key::LControl || key.code == Key::RControl ||
                        key.code == Key::LAlt || key.code == Key::RAlt;
  shift_ = shift_key ? pressed : key.shift;
  fine_ = fine_key ? pressed : key.control || key.alt;
}

void GameInput::handle(const sf::Event& event, const render::ViewTransform& view) {
  switch (event.type) {
    case sf::Event::KeyPressed:
      trackModifiers(event.key, true);
      if (held_.count(event.key.code) == 0) {
        held_[event.key.code] = 0.0;
        keyPressed(event.key);
      }
      break;
    case sf::Event::KeyReleased:
      trackModifiers(event.key, false);
      held_.erase(event.key.code);
      break;
    case sf::Event::LostFocus:
      held_.clear();
      shift_ = fine_ = false;
      break;
    case sf::Event::MouseWheelScrolled: {
      if (event.mouseWheelScroll.wheel != sf::Mouse::VerticalWheel) break;
      const float notches = event.mouseWheelScroll.delta;
      if (fine_) {
        // Ctrl (or Alt) with the wheel zooms at the pointer.
        const Vec2 at = view.toWorld({static_cast<double>(event.mouseWheelScroll.x),
                                      static_cast<double>(event.mouseWheelScroll.y)});
        zoomBy(notches > 0 ? 1 : -1, at);
      } else if (mayAim()) {
        // A notch turns the line a hundredth of a degree, with Shift a tenth.
        const double step = shift_ ? kAimNudgeDeg : kAimFineNudgeDeg;
        session_.setHeading(session_.heading() + degToRad(step * notches));
      }
      break;
    }
    case sf::Event::MouseButtonPressed: {
      const Vec2 px{static_cast<double>(event.mouseButton.x),
                    static_cast<double>(event.mouseButton.y)};
      if (event.mouseButton.button == sf::Mouse::Left) {
        mousePressed(px, view);
      } else if (event.mouseButton.button == sf::Mouse::Right && ui_.drag == Drag::Power) {
        session_.setSpeed(ui_.speed_before_drag);
        ui_.drag = Drag::None;
        ui_.pull = 0.0;
      }
      break;
    }
    case sf::Event::MouseMoved:
      mouseMoved({static_cast<double>(event.mouseMove.x), static_cast<double>(event.mouseMove.y)},
                 view);
      break;
    case sf::Event::MouseButtonReleased:
      if (event.mouseButton.button == sf::Mouse::Left) mouseReleased();
      break;
    default:
      break;
  }
}

void GameInput::keyPressed(const sf::Event::KeyEvent& key) {
  const DialogKind dialog = dialogCalledFor(session_, ui_);
  if (key.code == Key::F1) requests_.toggle_fullscreen = true;
  if (key.code == Key::F12) requests_.screenshot = true;
  if (key.code == Key::F5) requests_.save_rack = true;
  if (session_.replaying()) {
    if (key.code != Key::F1 && key.code != Key::F12) session_.stopReplay();
    return;
  }
  // The help and the quit question answer their own keys (their screens); the game waits.
  if (dialog == DialogKind::ConfirmQuit || dialog == DialogKind::Help) return;
  if (key.code == Key::Escape) {
    if (ui_.drag == Drag::Power) {
      session_.setSpeed(ui_.speed_before_drag);
      ui_.drag = Drag::None;
      ui_.pull = 0.0;
    } else if (leavingLosesNothing(session_, ui_)) {
      requests_.menu = true;
    } else {
      ui_.confirm_quit = true;
    }
    return;
  }
  if (key.code == Key::H) {
    ui_.help = true;
    return;
  }
  if (key.code == Key::O) {
    switchOpponent();
    return;
  }
  if (key.code == Key::Z) {
    zoomBy(key.shift ? -1 : 1);
    return;
  }
  if (key.code == Key::G) {
    requests_.cycle_guide = true;
    return;
  }
  if (key.code == Key::V && ui_.drag == Drag::None) {
    session_.startReplay(key.shift);
    return;
  }
  if (seats_.controls(session_)) return;
  // The push-out choice and the rack's end answer their own keys (their screens).
  if (dialog != DialogKind::None) return;
  if (session_.phase() != Phase::Aiming || ui_.drag != Drag::None) return;
  if (session_.practice() && practiceKey(key)) return;
  switch (key.code) {
    case Key::Space:
      session_.shoot();
      break;
    case Key::Left:
    case Key::Right: {
      const double nudge = fine_ ? kAimFineNudgeDeg : kAimNudgeDeg;
      session_.setHeading(session_.heading() + degToRad(key.code == Key::Left ? nudge : -nudge));
      break;
    }
    case Key::Up:
      session_.setSpeed(session_.speed() + kSpeedNudge);
      break;
    case Key::Down:
      session_.setSpeed(session_.speed() - kSpeedNudge);
      break;
    case Key::T:
      session_.setTip(session_.tip() + Vec2{0.0, kSpinStep});
      break;
    case Key::B:
      session_.setTip(session_.tip() - Vec2{0.0, kSpinStep});
      break;
    case Key::L:
      session_.setTip(session_.tip() - Vec2{kSpinStep, 0.0});
      break;
    case Key::R:
      session_.setTip(session_.tip() + Vec2{kSpinStep, 0.0});
      break;
    case Key::E:
      session_.setElevation(session_.elevation() + degToRad(kElevationStepDeg));
      break;
    case Key::Q:
      session_.setElevation(session_.elevation() - degToRad(kElevationStepDeg));
      break;
    case Key::C:
      session_.setTip({});
      session_.setElevation(0.0);
      break;
    case Key::P:
      session_.togglePushOut();
      break;
    case Key::K:
      session_.callObvious();
      break;
    case Key::X:
      ui_.aim_locked = !ui_.aim_locked;
      session_.say(ui_.aim_locked ? "Aim locked: the pointer leaves the line (Shift+pointer, the "
                                    "arrows and the wheel fine-tune it; X unlocks)."
                                  : "Aim unlocked: the pointer aims.");
      break;
    default:
      break;
  }
}

bool GameInput::practiceKey(const sf::Event::KeyEvent& key) {
  const int code = static_cast<int>(key.code);
  for (auto [first, last] : {std::pair{Key::Num1, Key::Num9}, {Key::Numpad1, Key::Numpad9}}) {
    if (code >= static_cast<int>(first) && code <= static_cast<int>(last)) {
      session_.toggleBall(1 + code - static_cast<int>(first), ui_.pointer);
      return true;
    }
  }
  if (key.code == Key::U || key.code == Key::BackSpace) {
    session_.undoShot();
    return true;
  }
  if (key.code == Key::Y) {
    session_.retryShot();
    return true;
  }
  return false;
}

void GameInput::switchOpponent() {
  if (ui_.drag != Drag::None) return;
  if (session_.practice()) {
    session_.say("Practice is played alone: pick an opponent in a game from the menu.");
    return;
  }
  const Seat next = app::nextOpponent(seats_.opponent());
  seats_.setOpponent(session_, next);
  if (session_.phase() == Phase::GameOver) return;  // the dialog shows the rack's last word
  const std::optional<ai::Level> level = computerLevel(next);
  session_.say(level ? "Player 2 is now the computer, " + std::string(ai::levelName(*level)) +
                           " level (O changes it)."
                     : "Two players: Player 2 plays at this computer too (O changes it).");
}

bool GameInput::mayAim() const {
  return session_.phase() == Phase::Aiming && !session_.replaying() && !dialogOpen() &&
         !seats_.controls(session_) && ui_.drag == Drag::None;
}

void GameInput::followSettledAim(double seconds) {
  // A locked line is the turn's: the next turn aims afresh.
  if (session_.phase() != Phase::Aiming || seats_.controls(session_)) ui_.aim_locked = false;
  // Only the player's own aim is kept: the computer's, a shot's or a dialog's are not, and a
  // turn begins with the aim it was handed.
  if (!mayAim()) {
    settled_heading_.reset();
    last_heading_ = session_.heading();
    heading_still_for_ = 0.0;
    return;
  }
  if (!settled_heading_) settled_heading_ = session_.heading();
  if (session_.heading() != last_heading_) {
    last_heading_ = session_.heading();
    heading_still_for_ = 0.0;
    return;
  }
  heading_still_for_ += seconds;
  if (heading_still_for_ >= kAimSettle) settled_heading_ = last_heading_;
}

void GameInput::update(double seconds) {
  for (auto& [key, held] : held_) held += seconds;
  followSettledAim(seconds);
  session_.setPlayRate(held_.count(Key::F) != 0 ? kFastForward : 1.0);
  if (session_.replaying() || dialogOpen() || seats_.controls(session_)) return;
  if (session_.phase() != Phase::Aiming || ui_.drag != Drag::None) return;
  auto heldFor = [&](Key k) {
    const auto it = held_.find(k);
    return it == held_.end() ? -1.0 : it->second;
  };
  double turn_deg = 0.0;
  for (auto [key, sign] : {std::pair{Key::Left, 1.0}, {Key::Right, -1.0}}) {
    const double h = heldFor(key);
    if (h < 0.0) continue;
    const double fine_rate = fine_ ? kAimFinestDegPerS : kAimFineDegPerS;
    const double rate = shift_ || fine_ ? (h < kHoldDelay ? 0.0 : fine_rate)
                                        : heldRate(h, kAimSlowDegPerS, kAimFastDegPerS);
    turn_deg += sign * rate * seconds;
  }
  if (turn_deg != 0.0) session_.setHeading(session_.heading() + degToRad(turn_deg));
  for (auto [key, sign] : {std::pair{Key::Up, 1.0}, {Key::Down, -1.0}}) {
    const double h = heldFor(key);
    if (h >= kHoldDelay) session_.setSpeed(session_.speed() + sign * kSpeedPerS * seconds);
  }
  if (session_.cueInHand()) {
    Vec2 d;
    if (heldFor(Key::W) >= 0.0) d.y += 1.0;
    if (heldFor(Key::S) >= 0.0) d.y -= 1.0;
    if (heldFor(Key::A) >= 0.0) d.x -= 1.0;
    if (heldFor(Key::D) >= 0.0) d.x += 1.0;
    if (d != Vec2{}) moveCueBy(normalized(d) * (kCueMoveSpeed * seconds));
  }
}

void GameInput::moveCueBy(Vec2 d) {
  // Small steps, so that a fast frame does not jump over a ball; stop at the first refusal.
  const int n = std::max(1, static_cast<int>(std::ceil(length(d) / kCueMoveStep)));
  for (int i = 0; i < n; ++i) {
    const Vec2 next = session_.cuePosition() + d / static_cast<double>(n);
    if (session_.placementProblem(next)) {
      session_.placeCue(next);  // says why it cannot go there
      return;
    }
    session_.placeCue(next);
  }
}

void GameInput::setTipFromIcon(Vec2 px, const render::ViewTransform& view) {
  const render::HudLayout layout = render::HudLayout::of(view);
  const Vec2 d = (px - layout.spin_centre) / layout.spin_radius;
  session_.setTip({d.x, -d.y});
}

void GameInput::mousePressed(Vec2 px, const render::ViewTransform& view) {
  if (session_.replaying()) {
    session_.stopReplay();
    return;
  }
  // A dialog's buttons are its screen's to answer (DialogScreen).
  if (dialogOpen()) return;
  const bool computer_turn = seats_.controls(session_);
  if (session_.phase() != Phase::Aiming || computer_turn) return;
  const render::HudLayout layout = render::HudLayout::of(view);
  if (length(px - layout.spin_centre) <= layout.spin_radius * 1.1) {
    ui_.drag = Drag::Spin;
    setTipFromIcon(px, view);
    return;
  }
  if (const auto tilt = layout.tiltAt(px)) {
    ui_.drag = Drag::Tilt;
    session_.setElevation(*tilt);
    return;
  }
  const Vec2 m = view.toWorld(px);
  const double r = session_.match().world().physics().ball_radius;
  // Practice moves a ball only with Shift held: a plain press on a ball aims and shoots, as
  // the pointer on the ball aimed at is where a player presses.
  if (session_.practice() && shift_) {
    if (const auto id = session_.ballAt(m)) {
      ui_.drag = Drag::Ball;
      ui_.ghost = render::CueGhost{m, true, "", *id};
      return;
    }
  }
  if (session_.cueInHand() && length(m - session_.cuePosition()) <= 1.6 * r) {
    ui_.drag = Drag::Cue;
    ui_.ghost = render::CueGhost{session_.cuePosition(), true, ""};
    return;
  }
  ui_.drag = Drag::Power;
  ui_.drag_anchor = m;
  ui_.pull = 0.0;
  ui_.speed_before_drag = session_.speed();
  session_.setPower(0.0);
}

void GameInput::mouseMoved(Vec2 px, const render::ViewTransform& view) {
  const Vec2 m = view.toWorld(px);
  ui_.pointer = m;
  switch (ui_.drag) {
    case Drag::Ball: {
      const int id = ui_.ghost ? ui_.ghost->id : kCueBall;
      const auto problem = session_.ballPlacementProblem(id, m);
      ui_.ghost = render::CueGhost{m, !problem, problem.value_or(""), id};
      return;
    }
    case Drag::Spin:
      setTipFromIcon(px, view);
      return;
    case Drag::Tilt:
      session_.setElevation(render::HudLayout::of(view).tiltToward(px));
      return;
    case Drag::Cue: {
      const auto problem = session_.placementProblem(m);
      ui_.ghost = render::CueGhost{m, !problem, problem.value_or("")};
      return;
    }
    case Drag::Power: {
      const Vec2 dir = fromAngle(session_.heading());
      ui_.pull = std::clamp(dot(ui_.drag_anchor - m, dir), 0.0, render::CueStickShape::kMaxPull);
      session_.setPower(ui_.pull / render::CueStickShape::kMaxPull);
      return;
    }
    case Drag::None:
      break;
  }
  if (!mayAim()) return;
  if (shift_) {
    fineTune(px);
    return;
  }
  last_px_ = px;
  if (ui_.aim_locked) return;
  if (session_.callPocketAt(m) || overControls(px, view)) {
    // The pointer went to a pocket to call it, or to the spin icon, the tilt ring or the power
    // gauge to use them, not to aim there: the aim held before it set out stays.
    if (settled_heading_) session_.setHeading(*settled_heading_);
    return;
  }
  const Vec2 cue = session_.cuePosition();
  const double r = session_.match().world().physics().ball_radius;
  if (length(m - cue) > kAimDeadZone * r) {
    session_.setHeading(std::atan2(m.y - cue.y, m.x - cue.x));
  }
}

void GameInput::fineTune(Vec2 px) {
  // The line locks as it is fine-tuned, so that letting go of Shift does not throw it back to
  // the pointer.
  ui_.aim_locked = true;
  if (last_px_) {
    // Rightwards turns the line clockwise, as the pointer would swing it over the far end.
    session_.setHeading(session_.heading() - degToRad(kFineDegPerPixel * (px.x - last_px_->x)));
  }
  last_px_ = px;
}

void GameInput::zoomBy(int steps, std::optional<Vec2> at) {
  ui_.zoom = std::clamp(ui_.zoom + steps, 1.0, kMaxZoom);
  if (ui_.zoom == 1.0) {
    ui_.zoom_at.reset();
  } else if (at) {
    ui_.zoom_at = at;
  } else if (steps > 0) {
    ui_.zoom_at.reset();  // Z: round the cue ball, following it
  }
}

void GameInput::mouseReleased() {
  const Drag drag = ui_.drag;
  ui_.drag = Drag::None;
  if (seats_.controls(session_)) {
    ui_.pull = 0.0;
    ui_.ghost.reset();
    return;
  }
  if (drag == Drag::Cue) {
    // From its new spot the cue looks at the ball on, not wherever the pointer lies on it.
    if (ui_.ghost && session_.placeCue(ui_.ghost->pos) && !ui_.aim_locked) {
      session_.aimAtBallOn();
    }
    ui_.ghost.reset();
  } else if (drag == Drag::Ball) {
    if (ui_.ghost) session_.moveBall(ui_.ghost->id, ui_.ghost->pos);
    ui_.ghost.reset();
  } else if (drag == Drag::Power) {
    const bool strike = ui_.pull >= kMinPull;
    ui_.pull = 0.0;
    if (!strike) {
      session_.setSpeed(ui_.speed_before_drag);
      session_.clickCall(
          ui_.drag_anchor);  // a click calls a pocket (or a ball, where any ball may be called)
    } else {
      session_.shoot();
    }
  }
}

}  // namespace nineball::window
