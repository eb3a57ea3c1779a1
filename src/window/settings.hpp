#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "window/menu_choice.hpp"

namespace nineball::window {

/// The aim guide as the player chooses it: the full guide with its lines after the contact
/// short, normal or long; the cue ball's line alone (to the ghost ball, nothing after); off.
enum class GuideLength { Short, Normal, Long, CueLine, Off };
/// Every style, in the order the menu and G go round them.
inline constexpr GuideLength kGuideStyles[] = {GuideLength::Short, GuideLength::Normal,
                                               GuideLength::Long, GuideLength::CueLine,
                                               GuideLength::Off};

/// "short", "normal", "long", "cue-ball line", "off".
const char* guideLengthName(GuideLength g);
/// How much longer than normal the guide's lines are drawn (short 0.4, normal 1, long 2.5;
/// 0 for the cue-ball line and off).
double guideLengthFactor(GuideLength g);
/// The style after `g`, round again after off.
GuideLength nextGuide(GuideLength g);

/// The player's preferences, kept between runs. No SFML.
struct Settings {
  static constexpr int kFrameCaps[] = {30, 60, 120, 240, 0};  ///< 0: no cap, vertical sync

  int volume = 80;     ///< 0-100 % of the sounds' full loudness
  bool muted = false;  ///< M in the window
  GuideLength guide = GuideLength::Normal;
  bool bank_line = false;    ///< draw the cue ball's path on from the first cushion it meets
  int frame_cap = 60;        ///< frames per second at most; 0: as fast as vertical sync allows
  MenuChoice last;           ///< the game chosen last time (resume is never kept)
  std::string join_address;  ///< the host last joined online, HOST[:PORT] (empty: none yet)
  /// The host's join code typed on the Join screen (not saved: each hosting has its own).
  std::string join_code;

  bool operator==(const Settings& o) const;
  bool operator!=(const Settings& o) const { return !(*this == o); }
};

/// The settings file: $XDG_CONFIG_HOME/nineball/settings.json, else
/// $HOME/.config/nineball/settings.json; empty when neither variable gives an absolute path.
std::string settingsPath();

/// The settings as JSON: {"volume", "muted", "aim_guide", "bank_line", "frame_cap", "last":
/// {"game", "opponent", "rules", "points", "best_of", "names"}, "join_address"}.
nlohmann::ordered_json settingsToJson(const Settings& s);
/// Reads what it can: a missing or wrong field keeps its default, with a warning in `warnings`.
Settings settingsFromJson(const nlohmann::json& j, std::string& warnings);

/// Loads the file; a missing, unreadable or bad one gives the defaults (a bad field its
/// default) and logs a warning. Never throws.
Settings loadSettings(const std::string& path);
/// Writes the file atomically, making its directory; false with `why` on failure.
bool saveSettings(const Settings& s, const std::string& path, std::string& why);

/// $XDG_<kind>_HOME/nineball/<file>, else $HOME/<fallback>/nineball/<file>; empty when neither
/// is an absolute path. `env` is e.g. "XDG_CONFIG_HOME", `fallback` ".config".
std::string xdgFile(const char* env, const char* fallback, const char* file);

}  // namespace nineball::window
