#include "window/settings.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "common/log.hpp"
#include "net/wire.hpp"
#include "nineball/games.hpp"
#include "window/player_name.hpp"
#include "window/state_file.hpp"

namespace nineball::window {
namespace {

// A match length past any the menu offers is refused as a typo (the menu keeps to its own).
constexpr int kMostFramesInAMatch = 99;

void warn(std::string& warnings, const std::string& what) {
  if (!warnings.empty()) warnings += "; ";
  warnings += what;
}

}  // namespace

const char* guideLengthName(GuideLength g) {
  switch (g) {
    case GuideLength::Short:
      return "short";
    case GuideLength::Long:
      return "long";
    case GuideLength::CueLine:
      return "cue-ball line";
    case GuideLength::Off:
      return "off";
    case GuideLength::Normal:
      break;
  }
  return "normal";
}

GuideLength nextGuide(GuideLength g) {
  const int n = static_cast<int>(std::size(kGuideStyles));
  for (int i = 0; i < n; ++i) {
    if (kGuideStyles[i] == g) return kGuideStyles[(i + 1) % n];
  }
  return GuideLength::Normal;
}

double guideLengthFactor(GuideLength g) {
  switch (g) {
    case GuideLength::Short:
      return 0.4;
    case GuideLength::Long:
      return 2.5;
    case GuideLength::CueLine:
    case GuideLength::Off:
      return 0.0;
    case GuideLength::Normal:
      break;
  }
  return 1.0;
}

bool Settings::operator==(const Settings& o) const {
  return volume == o.volume && muted == o.muted && guide == o.guide && bank_line == o.bank_line &&
         frame_cap == o.frame_cap && last.mode == o.last.mode && last.game == o.last.game &&
         last.opponent == o.last.opponent && last.rules == o.last.rules &&
         last.points == o.last.points && last.best_of == o.last.best_of &&
         last.breaks == o.last.breaks && last.names == o.last.names &&
         join_address == o.join_address;
}

std::string xdgFile(const char* env, const char* fallback, const char* file) {
  const char* xdg = std::getenv(env);
  if (xdg && xdg[0] == '/') return std::string(xdg) + "/nineball/" + file;
  // The specification says a relative path is to be ignored.
  const char* home = std::getenv("HOME");
  if (home && home[0] == '/') return std::string(home) + "/" + fallback + "/nineball/" + file;
  return "";
}

std::string settingsPath() {
  return xdgFile("XDG_CONFIG_HOME", ".config", "settings.json");
}

nlohmann::ordered_json settingsToJson(const Settings& s) {
  nlohmann::ordered_json j;
  j["volume"] = s.volume;
  j["muted"] = s.muted;
  j["aim_guide"] = guideLengthName(s.guide);
  j["bank_line"] = s.bank_line;
  j["frame_cap"] = s.frame_cap;
  j["last"] = {{"game", s.last.mode == GameMode::Practice ? "practice" : gameDef(s.last.game).name},
               {"opponent", seatName(s.last.opponent)},
               {"rules", rules::ruleSetName(s.last.rules)},
               {"points", s.last.points},
               {"best_of", s.last.best_of},
               {"breaks", breakOrderName(s.last.breaks)},
               {"names", {s.last.names[0], s.last.names[1]}}};
  j["join_address"] = s.join_address;
  return j;
}

Settings settingsFromJson(const nlohmann::json& j, std::string& warnings) {
  Settings s;
  if (!j.is_object()) {
    warn(warnings, "not a JSON object");
    return s;
  }
  auto field = [&](const nlohmann::json& obj, const char* name) -> const nlohmann::json* {
    const auto it = obj.find(name);
    return it == obj.end() ? nullptr : &*it;
  };
  if (const auto* v = field(j, "volume")) {
    if (v->is_number_integer() && *v >= 0 && *v <= 100) {
      s.volume = v->get<int>();
    } else {
      warn(warnings, "volume: expected a whole number from 0 to 100");
    }
  }
  for (auto [name, flag] : {std::pair{"muted", &s.muted}, {"bank_line", &s.bank_line}}) {
    if (const auto* v = field(j, name)) {
      if (v->is_boolean()) {
        *flag = v->get<bool>();
      } else {
        warn(warnings, std::string(name) + ": expected true or false");
      }
    }
  }
  if (const auto* v = field(j, "aim_guide")) {
    bool ok = false;
    for (GuideLength g : kGuideStyles) {
      if (v->is_string() && v->get<std::string>() == guideLengthName(g)) {
        s.guide = g;
        ok = true;
      }
    }
    if (!ok) warn(warnings, "aim_guide: expected short, normal, long, cue-ball line or off");
  }
  if (const auto* v = field(j, "frame_cap")) {
    const auto& caps = Settings::kFrameCaps;
    if (v->is_number_integer() &&
        std::find(std::begin(caps), std::end(caps), v->get<int>()) != std::end(caps)) {
      s.frame_cap = v->get<int>();
    } else {
      warn(warnings, "frame_cap: expected 30, 60, 120, 240 or 0 (vertical sync)");
    }
  }
  if (const auto* v = field(j, "join_address")) {
    std::string why;
    if (v->is_string() &&
        (v->get<std::string>().empty() || net::parseAddress(v->get<std::string>(), why))) {
      s.join_address = v->get<std::string>();
    } else {
      warn(warnings, "join_address: expected HOST or HOST:PORT");
    }
  }
  const auto* last = field(j, "last");
  if (last && !last->is_object()) warn(warnings, "last: expected an object");
  if (!last || !last->is_object()) return s;
  if (const auto* v = field(*last, "game")) {
    if (v->is_string() && *v == "practice") {
      s.last.mode = GameMode::Practice;
    } else if (const auto g = v->is_string() ? gameNamed(v->get<std::string>()) : nullptr) {
      s.last.game = g->id;
    } else {
      std::string names;
      for (const std::string& name : gameNames()) names += name + ", ";
      warn(warnings, "last.game: expected " + names.substr(0, names.size() - 2) + " or practice");
    }
  }
  if (const auto* v = field(*last, "opponent")) {
    const auto o = v->is_string() ? seatFromName(v->get<std::string>()) : std::nullopt;
    if (o) {
      s.last.opponent = *o;
    } else {
      warn(warnings, "last.opponent: expected " + seatNamesText());
    }
  }
  if (const auto* v = field(*last, "rules")) {
    const auto r = v->is_string() ? rules::ruleSetFromName(v->get<std::string>()) : std::nullopt;
    if (r) {
      s.last.rules = *r;
    } else {
      warn(warnings, "last.rules: expected wpa, paper or umb");
    }
  }
  if (const auto* v = field(*last, "points")) {
    if (v->is_number_integer() && *v >= 0 && *v <= 100) {
      s.last.points = v->get<int>();
    } else {
      warn(warnings, "last.points: expected a whole number from 0 to 100");
    }
  }
  if (const auto* v = field(*last, "best_of")) {
    if (v->is_number_integer() && *v >= 0 && *v <= kMostFramesInAMatch) {
      s.last.best_of = v->get<int>();
    } else {
      warn(warnings, "last.best_of: expected a whole number from 0 to " +
                         std::to_string(kMostFramesInAMatch));
    }
  }
  if (const auto* v = field(*last, "breaks")) {
    const auto order = v->is_string() ? breakOrderFromName(v->get<std::string>().c_str())
                                      : std::optional<BreakOrder>{};
    if (order) {
      s.last.breaks = *order;
    } else {
      warn(warnings, "last.breaks: expected \"alternate\" or \"winner\"");
    }
  }
  if (const auto* v = field(*last, "names")) {
    if (v->is_array() && v->size() == 2 && (*v)[0].is_string() && (*v)[1].is_string()) {
      for (int i = 0; i < 2; ++i) {
        const std::string raw = (*v)[i].get<std::string>();
        if (raw.empty()) continue;
        if (const auto name = playerName(raw)) {
          s.last.names[i] = *name;
        } else {
          warn(warnings, "last.names[" + std::to_string(i) + "]: not valid UTF-8");
        }
      }
    } else {
      warn(warnings, "last.names: expected two strings");
    }
  }
  return s;
}

Settings loadSettings(const std::string& path) {
  if (path.empty()) {
    logger("game")->warn("settings: neither XDG_CONFIG_HOME nor HOME is set; using defaults");
    return {};
  }
  std::string text, why;
  if (!readStateFile(path, text, why)) {
    // No file yet is the normal first run; anything else is worth a word.
    std::error_code ec;
    if (std::filesystem::exists(path, ec)) {
      logger("game")->warn("settings: {}: {}; using defaults", path, why);
    } else {
      logger("game")->info("settings: no {} yet; using defaults", path);
    }
    return {};
  }
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  std::string warnings;
  const Settings s = j.is_discarded() ? Settings{} : settingsFromJson(j, warnings);
  if (j.is_discarded()) warnings = "not valid JSON";
  if (!warnings.empty())
    logger("game")->warn("settings: {}: {}; defaults used there", path, warnings);
  return s;
}

bool saveSettings(const Settings& s, const std::string& path, std::string& why) {
  return saveStateFile(path, settingsToJson(s).dump(2) + "\n",
                       "neither XDG_CONFIG_HOME nor HOME is set", why);
}

}  // namespace nineball::window
