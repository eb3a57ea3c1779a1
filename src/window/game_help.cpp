#include "window/game_help.hpp"

#include "games/game_texts.hpp"
#include "nineball/games.hpp"

namespace nineball::window {

std::vector<std::string> controlHelpLines() {
  return {
      "Mouse: point where to aim; press, drag back and let go to strike",
      "  (the further you drag, the harder the shot; right click cancels)",
      "Left / Right: turn the aim (Shift: finer, Ctrl or Alt: 0.01 deg)    Up / Down: power",
      "Wheel: aim 0.01 deg a notch (Shift: 0.1)    Space: shoot    E / Q: raise / lower the cue",
      "X: lock the aim    Shift + mouse: fine-tune it (0.02 deg a pixel)    G: aim guide style",
      "Z / Shift+Z: zoom in / out round the cue ball (Ctrl + wheel: at the pointer)",
      "T / B / L / R: top / back / left / right spin",
      "Click the cue-ball icon for side spin, the arc by it to tilt the cue (C: reset)",
      "The aim line is the ghost ball's: throw, squirt and swerve bend the real paths",
      "Ball in hand: drag the cue ball, or move it with W A S D",
      "P: declare a push-out when offered; then S: play or P: pass",
      "Hold F: fast-forward a shot    V: replay the last shot (Shift+V: slowed)    R: rematch",
      "Esc: menu    M: mute    F1: full screen    F2: settings    F5: save game    F12: screenshot",
  };
}

std::vector<std::string> gameHelpLines(rules::Game game) {
  return gameTexts(game).help;
}

std::string groupLabel(const rules::Groups& groups, rules::Player player) {
  const auto g = groups.of(player);
  return g ? rules::groupName(*g) : "open table";
}

}  // namespace nineball::window
