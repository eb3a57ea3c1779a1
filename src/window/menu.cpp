#include "window/menu.hpp"

#include <algorithm>
#include <iterator>

#include "games/game_texts.hpp"
#include "net/protocol.hpp"
#include "net/wire.hpp"
#include "nineball/games.hpp"
#include "window/player_name.hpp"

namespace nineball::window {
namespace {

const char* rulesLabel(rules::RuleSet r) {
  switch (r) {
    case rules::RuleSet::Wpa:
      return "WPA";
    case rules::RuleSet::Paper:
      return "Paper (the seed paper's)";
    case rules::RuleSet::Umb:
      return "UMB (the world rules of carom)";
    case rules::RuleSet::Wpbsa:
      return "WPBSA (the official rules of snooker)";
  }
  return "?";
}

constexpr int kVolumeStep = 10;
// An address to join: a host name or IP and a port fit in this many characters.
constexpr std::size_t kMaxAddressBytes = 80;

std::string utf8(char32_t c) {
  std::string out;
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
  return out;
}

// Removes the last UTF-8 character.
void popChar(std::string& s) {
  while (!s.empty()) {
    const auto byte = static_cast<unsigned char>(s.back());
    s.pop_back();
    if ((byte & 0xC0) != 0x80) break;
  }
}

// "eight-ball" as "Eight-ball" for the menu.
std::string capitalised(std::string s) {
  s[0] = static_cast<char>(s[0] - 'a' + 'A');
  return s;
}

// "Best of 5 (first to 3)" in snooker; "Race to 5 racks" or "No limit" in pool.
std::string matchLengthLabel(rules::Game game, int best_of) {
  if (best_of == 0) return "No limit (the racks add up)";
  const std::string first = std::to_string(framesToWinMatch(best_of));
  if (gameDef(game).snookers)
    return "Best of " + std::to_string(best_of) + " (first to " + first + ")";
  return "Race to " + first + " racks";
}

// WPA's standard format alternates the break, as WPBSA's frames alternate the break-off.
std::string breaksLabel(BreakOrder order, bool snooker) {
  if (order == BreakOrder::Winner) return "Winner of the last rack";
  return snooker ? "In turn (WPBSA)" : "In turn (WPA standard)";
}

std::string capLabel(int cap) {
  return cap == 0 ? "Unlimited (vsync)" : std::to_string(cap) + " fps";
}

}  // namespace

MenuModel::MenuModel(const Settings& settings, std::optional<std::string> resume)
    : settings_(settings), resume_(std::move(resume)) {
  const std::optional<ai::Level> level = computerLevel(settings_.last.opponent);
  computer_ = level.has_value();
  if (level) level_ = *level;
  selectFirst();
}

MenuModel MenuModel::settingsOnly(const Settings& settings) {
  MenuModel m(settings, std::nullopt);
  m.screen_ = Screen::Settings;
  m.settings_only_ = true;
  m.selectFirst();
  return m;
}

std::vector<MenuModel::Item> MenuModel::items() const {
  if (screen_ == Screen::Settings) {
    return {Item::Volume, Item::Sound, Item::Guide, Item::Bank, Item::FrameCap, Item::Back};
  }
  if (screen_ == Screen::Online)
    return {Item::Host, Item::Join, Item::JoinAddress, Item::JoinCode, Item::Back};
  std::vector<Item> v;
  if (resume_) v.push_back(Item::Resume);
  for (Item i : {Item::Play, Item::Practice, Item::Versus, Item::Level, Item::Game, Item::Rules,
                 Item::Points, Item::Frames, Item::Breaks, Item::Name1, Item::Name2,
                 Item::OpenOnline, Item::OpenSettings, Item::Quit}) {
    // Only a game played in frames has a match length to choose.
    const bool in_frames = i == Item::Frames || i == Item::Breaks;
    if (in_frames && gameTexts(settings_.last.game).best_of_choices.empty()) continue;
    v.push_back(i);
  }
  return v;
}

bool MenuModel::enabled(Item item) const {
  switch (item) {
    case Item::Practice:
      return true;
    case Item::Join:
      return joinable();
    case Item::Level:
      return computer_;
    case Item::Rules:
      return severalRules();
    case Item::Points:
      return !gameTexts(settings_.last.game).points_choices.empty();
    case Item::Breaks:
      return bestOf() > 0;  // a single rack or racks without end: each seat breaks in turn
    case Item::Name2:
      return !computer_;  // the computer's seat is called "Computer"
    case Item::Sound:
      return !muted_by_option_;
    default:
      return true;
  }
}

MenuRow MenuModel::row(Item item) const {
  using Kind = MenuRow::Kind;
  MenuRow r;
  r.enabled = enabled(item);
  switch (item) {
    case Item::Resume:
      r.label = "Resume rack";
      r.value = resume_.value_or("");
      break;
    case Item::Play:
      r.label = std::string("Play ") + rules::gameName(settings_.last.game);
      break;
    case Item::Practice:
      r.label = "Practice";
      r.value = "no rules, any ball anywhere";
      break;
    case Item::OpenOnline:
      r.label = "Play online: host / join";
      r.value = "a friend at another computer";
      break;
    case Item::Host:
      r.label = "Host";
      r.value = "a friend joins you (port " + std::to_string(net::kDefaultPort) + ")";
      break;
    case Item::Join:
      r.label = "Join";
      r.value = joinable() ? settings_.join_address : std::string("type the address below");
      break;
    case Item::JoinAddress:
      r.kind = Kind::Text;
      r.label = "Friend's address";
      r.value = settings_.join_address;
      r.editing = editing_ && items()[selected_] == item;
      break;
    case Item::JoinCode:
      r.kind = Kind::Text;
      r.label = "Join code";
      r.value = settings_.join_code;
      r.editing = editing_ && items()[selected_] == item;
      break;
    case Item::Versus:
      r = {Kind::Choice, "Opponent", computer_ ? "Computer" : "Human (2 players)", r.enabled,
           false};
      break;
    case Item::Level:
      r = {Kind::Choice, "Computer level", capitalised(ai::levelName(level_)), r.enabled, false};
      break;
    case Item::Game:
      r = {Kind::Choice, "Game", capitalised(rules::gameName(settings_.last.game)), true, false};
      break;
    case Item::Rules:
      r = {Kind::Choice, "Rules", rulesLabel(choice().rules), r.enabled, false};
      if (!severalRules() && choice().rules == rules::RuleSet::Wpa) {
        r.value = "WPA (the paper's are " + gamesPlayedBy(rules::RuleSet::Paper) + "'s only)";
      }
      break;
    case Item::Points:
      r = {Kind::Choice, "Points to win",
           r.enabled ? std::to_string(pointsToWin()) : std::string("(a game won on a ball)"),
           r.enabled, false};
      break;
    case Item::Breaks:
      r = {Kind::Choice, gameDef(settings_.last.game).snookers ? "Break-off" : "Break",
           breaksLabel(settings_.last.breaks, gameDef(settings_.last.game).snookers), r.enabled,
           false};
      break;
    case Item::Frames:
      r = {Kind::Choice, gameDef(settings_.last.game).snookers ? "Frames" : "Match",
           matchLengthLabel(settings_.last.game, bestOf()), true, false};
      break;
    case Item::Name1:
    case Item::Name2: {
      const int seat = item == Item::Name1 ? 0 : 1;
      r.kind = Kind::Text;
      r.label = seat == 0 ? "Player 1 name" : "Player 2 name";
      r.value = seat == 1 && computer_ ? "Computer" : settings_.last.names[seat];
      r.editing = editing_ && items()[selected_] == item;
      break;
    }
    case Item::OpenSettings:
      r.label = "Settings";
      break;
    case Item::Quit:
      r.label = "Quit";
      break;
    case Item::Volume:
      r = {Kind::Choice, "Volume", std::to_string(settings_.volume) + " %", true, false};
      break;
    case Item::Sound:
      r = {Kind::Choice, "Sound (M)", settings_.muted ? "Muted" : "On", r.enabled, false};
      if (muted_by_option_) r.value = "Off this run (--mute)";
      break;
    case Item::Guide:
      r = {Kind::Choice, "Aim guide", guideLengthName(settings_.guide), true, false};
      r.value[0] = static_cast<char>(r.value[0] - 'a' + 'A');
      break;
    case Item::Bank:
      r = {Kind::Choice, "Bank line off the first cushion", settings_.bank_line ? "On" : "Off",
           true, false};
      break;
    case Item::FrameCap:
      r = {Kind::Choice, "Frame cap", capLabel(settings_.frame_cap), true, false};
      break;
    case Item::Back:
      r.label = settings_only_ ? "Back to the game (F2)" : "Back";
      break;
  }
  return r;
}

std::string MenuModel::title() const {
  if (screen_ == Screen::Online) return "Play online";
  return screen_ == Screen::Settings ? "Settings" : "nineball";
}

std::vector<MenuRow> MenuModel::rows() const {
  std::vector<MenuRow> out;
  for (Item i : items()) out.push_back(row(i));
  return out;
}

bool MenuModel::severalRules() const {
  return gameDef(settings_.last.game).rule_sets.size() > 1;
}

void MenuModel::selectFirst() {
  selected_ = 0;
  editing_ = false;
  const auto v = items();
  while (selected_ + 1 < static_cast<int>(v.size()) && !enabled(v[selected_])) ++selected_;
}

void MenuModel::move(int step) {
  const auto v = items();
  const int n = static_cast<int>(v.size());
  for (int k = 1; k <= n; ++k) {
    const int i = ((selected_ + step * k) % n + n) % n;
    if (enabled(v[i])) {
      selected_ = i;
      return;
    }
  }
}

void MenuModel::change(Item item, int step) {
  switch (item) {
    case Item::Versus:
      computer_ = !computer_;
      break;
    case Item::Level: {
      const int n = static_cast<int>(ai::allLevels().size());
      const int l = (static_cast<int>(level_) + step + n) % n;
      level_ = static_cast<ai::Level>(l);
      break;
    }
    case Item::Game: {
      const auto& games = allGames();
      const int n = static_cast<int>(games.size());
      int at = 0;
      for (int i = 0; i < n; ++i) {
        if (games[i].id == settings_.last.game) at = i;
      }
      settings_.last.game = games[((at + step) % n + n) % n].id;
      break;
    }
    case Item::Points: {
      const std::vector<int>& choices = gameTexts(settings_.last.game).points_choices;
      const int n = static_cast<int>(choices.size());
      int at = 0;
      for (int i = 0; i < n; ++i) {
        if (choices[i] == pointsToWin()) at = i;
      }
      settings_.last.points = choices[((at + step) % n + n) % n];
      break;
    }
    case Item::Frames: {
      const std::vector<int>& choices = gameTexts(settings_.last.game).best_of_choices;
      const int n = static_cast<int>(choices.size());
      const int at =
          static_cast<int>(std::find(choices.begin(), choices.end(), bestOf()) - choices.begin());
      settings_.last.best_of = choices[((at + step) % n + n) % n];
      break;
    }
    case Item::Breaks:
      settings_.last.breaks = settings_.last.breaks == BreakOrder::Alternate
                                  ? BreakOrder::Winner
                                  : BreakOrder::Alternate;
      break;
    case Item::Rules:
      settings_.last.rules =
          settings_.last.rules == rules::RuleSet::Wpa ? rules::RuleSet::Paper : rules::RuleSet::Wpa;
      break;
    case Item::Volume:
      settings_.volume = std::clamp(settings_.volume + step * kVolumeStep, 0, 100);
      break;
    case Item::Sound:
      settings_.muted = !settings_.muted;
      break;
    case Item::Guide:
      for (int i = 0; i < (step > 0 ? 1 : static_cast<int>(std::size(kGuideStyles)) - 1); ++i) {
        settings_.guide = nextGuide(settings_.guide);
      }
      break;
    case Item::Bank:
      settings_.bank_line = !settings_.bank_line;
      break;
    case Item::FrameCap: {
      const auto& caps = Settings::kFrameCaps;
      const int n = static_cast<int>(std::size(caps));
      const int at = static_cast<int>(
          std::find(std::begin(caps), std::end(caps), settings_.frame_cap) - std::begin(caps));
      settings_.frame_cap = caps[((at + step) % n + n) % n];
      break;
    }
    default:
      break;
  }
}

void MenuModel::activate(Item item) {
  if (!enabled(item)) return;
  switch (item) {
    case Item::Resume:
      outcome_ = Outcome::Resume;
      break;
    case Item::Play:
    case Item::Practice:
      settings_.last.mode = item == Item::Practice ? GameMode::Practice : GameMode::Match;
      settings_.last = choice();
      outcome_ = Outcome::Play;
      break;
    case Item::Host:
    case Item::Join:
      settings_.last.mode = GameMode::Match;
      settings_.last = choice();
      outcome_ = item == Item::Host ? Outcome::Host : Outcome::Join;
      break;
    case Item::Name1:
    case Item::Name2:
    case Item::JoinAddress:
    case Item::JoinCode:
      editing_ = true;
      break;
    case Item::OpenSettings:
      screen_ = Screen::Settings;
      selectFirst();
      break;
    case Item::OpenOnline:
      screen_ = Screen::Online;
      selectFirst();
      break;
    case Item::Quit:
      outcome_ = Outcome::Quit;
      break;
    case Item::Back:
      if (settings_only_) {
        outcome_ = Outcome::Close;
      } else {
        screen_ = Screen::Main;
        selectFirst();
      }
      break;
    default:
      change(item, 1);
      break;
  }
}

void MenuModel::key(MenuKey k) {
  const auto v = items();
  const Item item = v[selected_];
  if (editing_) {
    std::string& name = editedText();
    if (k == MenuKey::Backspace) popChar(name);
    if (k == MenuKey::Enter || k == MenuKey::Escape || k == MenuKey::Tab || k == MenuKey::Up ||
        k == MenuKey::Down) {
      editing_ = false;
      if (name.empty() && item != Item::JoinAddress && item != Item::JoinCode) {
        name = item == Item::Name1 ? "Player 1" : "Player 2";
      }
      if (k == MenuKey::Up) move(-1);
      if (k == MenuKey::Down || k == MenuKey::Tab) move(1);
    }
    return;
  }
  switch (k) {
    case MenuKey::Up:
      move(-1);
      break;
    case MenuKey::Down:
    case MenuKey::Tab:
      move(1);
      break;
    case MenuKey::Left:
    case MenuKey::Right:
      change(item, k == MenuKey::Left ? -1 : 1);
      break;
    case MenuKey::Enter:
      activate(item);
      break;
    case MenuKey::Escape:
      if (screen_ != Screen::Main) {
        activate(Item::Back);
      } else {
        outcome_ = Outcome::Quit;
      }
      break;
    case MenuKey::Backspace:
      break;
  }
}

void MenuModel::text(char32_t c) {
  if (!editing_) return;
  // Printable characters only; control keys arrive as their own key events.
  if (c < 0x20 || c == 0x7F || (c >= 0xD800 && c <= 0xDFFF) || c > 0x10FFFF) return;
  if (items()[selected_] == Item::JoinAddress) {
    // A host name, an IPv4 address and a port: no spaces, nothing past ASCII.
    if (c > 0x20 && c < 0x7F && settings_.join_address.size() < kMaxAddressBytes) {
      settings_.join_address += static_cast<char>(c);
    }
    return;
  }
  if (items()[selected_] == Item::JoinCode) {
    // The host's code: letters, digits and dashes, as it shows it.
    const bool fits =
        (c >= '0' && c <= '9') || (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '-';
    if (fits && settings_.join_code.size() < net::kMostCodeChars) {
      settings_.join_code += static_cast<char>(c);
    }
    return;
  }
  std::string& name = editedText();
  const std::string add = utf8(c);
  if (name.size() + add.size() <= kMaxNameBytes) name += add;
}

std::string& MenuModel::editedText() {
  const Item item = items()[selected_];
  if (item == Item::JoinAddress) return settings_.join_address;
  if (item == Item::JoinCode) return settings_.join_code;
  return settings_.last.names[item == Item::Name1 ? 0 : 1];
}

bool MenuModel::joinable() const {
  std::string why;
  return net::parseAddress(settings_.join_address, why).has_value();
}

void MenuModel::hover(int i) {
  const auto v = items();
  if (editing_ || i < 0 || i >= static_cast<int>(v.size()) || !enabled(v[i])) return;
  selected_ = i;
}

void MenuModel::click(int i) {
  const auto v = items();
  if (i < 0 || i >= static_cast<int>(v.size()) || !enabled(v[i])) return;
  if (editing_ && i != selected_) key(MenuKey::Enter);  // a click elsewhere ends the edit
  selected_ = i;
  if (!editing_) activate(v[i]);
}

int MenuModel::pointsToWin() const {
  const GameDef& g = gameDef(settings_.last.game);
  const auto& choices = gameTexts(g.id).points_choices;
  const bool offered =
      std::find(choices.begin(), choices.end(), settings_.last.points) != choices.end();
  return offered ? settings_.last.points : g.default_points;
}

int MenuModel::bestOf() const {
  const auto& choices = gameTexts(settings_.last.game).best_of_choices;
  if (choices.empty()) return 0;
  const bool offered =
      std::find(choices.begin(), choices.end(), settings_.last.best_of) != choices.end();
  return offered ? settings_.last.best_of : choices.front();
}

MenuChoice MenuModel::choice() const {
  MenuChoice c = settings_.last;
  c.opponent = computer_ ? Seat(ComputerSeat{level_}) : Seat(HumanSeat{});
  // Online the other seat is the friend's, whatever the Opponent row says.
  if (outcome_ == Outcome::Host || outcome_ == Outcome::Join) c.opponent = HumanSeat{};
  if (!gameDef(c.game).playedBy(c.rules)) c.rules = gameDef(c.game).rule_sets.front();
  c.points = pointsToWin();
  c.best_of = bestOf();
  c.resume = outcome_ == Outcome::Resume;
  return c;
}

}  // namespace nineball::window
