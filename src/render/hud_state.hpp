#pragma once

#include <optional>
#include <string>
#include <vector>

#include "nineball/vec2.hpp"

namespace nineball::render {

/// One player's corner of the HUD.
struct PlayerPanel {
  std::string name;
  int racks = 0;         ///< racks won
  int fouls = 0;         ///< fouls in a row (three lose the rack)
  bool to_move = false;  ///< it is this player's turn
  std::string detail;    ///< shown instead of the racks won when set (practice)
};

/// How a message reads: plain, a foul, a win, a refusal.
enum class Tone { Info, Foul, Win, Warning };

/// How a dialog over the table is laid out and lettered: a box in the middle of the table, or
/// a strip across it that leaves the balls in HudState::keep_clear in sight. Sizes are metres
/// at the table's scale (the HUD does not zoom). The window's dialogs choose their own look, so
/// a new dialog adds nothing here.
struct DialogLook {
  double width = 1.3;
  double height = 0.6;
  bool strip = false;        ///< across the table, clear of the balls
  bool small_print = false;  ///< many lines: a smaller type
  bool win = false;          ///< the title in the win colour

  /// A box in the middle (a question).
  static DialogLook box() { return {}; }
  /// A wide box of many lines (the help).
  static DialogLook wide() { return {2.0, 1.02, false, true, false}; }
  /// A strip `height` m high across the table, clear of the balls (a choice about them).
  static DialogLook across(double height) { return {1.5, height, true, false, false}; }
};

/// Everything the HUD shows, filled by the game each frame. No SFML.
struct HudState {
  PlayerPanel players[2];
  int ball_on = 0;            ///< 0 when none is left
  std::vector<int> on_table;  ///< object balls still on the table, lowest first
  std::vector<int> pocketed;  ///< object balls down this rack, in the order they dropped
  bool split_groups = false;  ///< a game of groups: a gap between the solids, the 8 and the stripes
  std::string rules;          ///< "WPA rules", "Paper rules"
  std::string mode;           ///< who plays: "2 players", "vs computer (medium)", and the key
  std::string status;         ///< what the player to move does now
  std::string message;        ///< what the last shot gave
  Tone tone = Tone::Info;
  double power = 0.0;          ///< 0..1 of the gauge
  double speed = 0.0;          ///< m/s the cue ball will get
  Vec2 tip;                    ///< [side, height] as fractions of R
  double max_tip = 0.5;        ///< the tip's useful range
  double elevation_deg = 0.0;  ///< the cue's tilt above the table
  double max_elevation_deg = 60.0;
  bool push_out_declared = false;
  std::optional<DialogLook> dialog;  ///< the dialog over the table (none: none)
  /// The points on the table (m) a dialog should not cover: the balls the choice is about.
  std::vector<Vec2> keep_clear;
  std::string keys = "H help   Esc quit";  ///< the keys named under the power gauge
  std::string overlay_title;
  std::vector<std::string> overlay_lines;
  std::string button_left;   ///< empty: no button
  std::string button_right;  ///< empty: no button
  /// A third answer between the two (snooker's "replace" after a miss); empty: none.
  std::string button_middle;
  /// Carom, while a shot rolls and just after: the cushions the shooter's ball has met before
  /// its second ball, and "point" / "no point" once that is decided (empty: not shown).
  std::string carom_count;
  /// Snooker: the break and the points remaining, and the referee's calls ("FREE BALL",
  /// "snookers required"), in the tray's place (empty: the tray).
  std::string score_line;
  bool score_call = false;  ///< the line carries a call: drawn in the accent colour
};

}  // namespace nineball::render
