#include <cstdio>

#include "common/named.hpp"
#include "games/eight_ball/eight_ball.hpp"
#include "games/game_texts.hpp"
#include "games/nine_ball/nine_ball.hpp"
#include "games/snooker/snooker.hpp"
#include "games/ten_ball/ten_ball.hpp"
#include "games/three_cushion/three_cushion.hpp"
#include "nineball/games.hpp"
#include "nineball/table_markings.hpp"

namespace nineball {

namespace {

const std::vector<games::GameEntry>& registeredGames() {
  static const std::vector<games::GameEntry> all{
      games::nineBall(),     games::eightBall(), games::tenBall(),
      games::threeCushion(), games::snooker(),
  };
  return all;
}

}  // namespace

const std::vector<GameDef>& allGames() {
  static const std::vector<GameDef> all = [] {
    std::vector<GameDef> defs;
    for (const games::GameEntry& e : registeredGames()) defs.push_back(e.def);
    return defs;
  }();
  return all;
}

const GameTexts& gameTexts(rules::Game game) {
  for (const games::GameEntry& e : registeredGames()) {
    if (e.def.id == game) return e.texts;
  }
  return registeredGames().front().texts;
}

const GameDef& gameDef(rules::Game game) {
  for (const GameDef& g : allGames()) {
    if (g.id == game) return g;
  }
  return defaultGame();
}

const GameDef& defaultGame() {
  return allGames().front();
}

const GameDef* gameNamed(const std::string& name) {
  const auto i = placeNamed(allGames(), name);
  return i ? &allGames()[*i] : nullptr;
}

std::vector<std::string> gameNames() {
  return namesOf(allGames());
}

std::string gamesPlayedBy(rules::RuleSet rules) {
  std::vector<std::string> names;
  for (const GameDef& g : allGames()) {
    if (g.playedBy(rules)) names.emplace_back(g.name);
  }
  return listed(names, "and");
}

std::string gamesTakingCalls() {
  std::vector<std::string> names;
  for (const GameDef& g : allGames()) {
    if (g.takes_calls) names.emplace_back(g.name);
  }
  return listed(names, "and");
}

std::string tableProblem(const GameDef& game, const TableDef& table) {
  // Carom's rules know no pocket: a ball pocketed there would vanish unjudged.
  if (game.family == GameFamily::Carom && table.pockets) {
    return std::string(game.name) +
           " is played on a table without pockets (\"carom\", \"carom-small\", or a table with "
           "\"pockets\": false), not on one with pockets";
  }
  return "";
}

std::string rulesOnlyFor(rules::RuleSet rules) {
  const char* whose = rules == rules::RuleSet::Paper   ? "the paper's"
                      : rules == rules::RuleSet::Umb   ? "the UMB"
                      : rules == rules::RuleSet::Wpbsa ? "the WPBSA"
                                                       : "the WPA";
  return std::string(whose) + " rules are " + gamesPlayedBy(rules) + "'s only";
}

bool inCueArea(CueArea area, const TableDef& table, Vec2 c) {
  switch (area) {
    case CueArea::Anywhere:
      return true;
    case CueArea::BehindHeadString:
      return c.x <= -table.length / 4.0 + 1e-9;  // on the line counts as behind it
    case CueArea::TheD:
      return SnookerLayout::of(table).inD(c);
  }
  return false;
}

std::string cueAreaText(CueArea area, const TableDef& table) {
  const auto metres = [](double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4f", x);
    return std::string(text);
  };
  switch (area) {
    case CueArea::Anywhere:
      return "";
    case CueArea::BehindHeadString:
      return "behind the head string (x <= " + metres(-table.length / 4.0) + ")";
    case CueArea::TheD: {
      const SnookerLayout l = SnookerLayout::of(table);
      const std::string xb = metres(l.baulk_x);
      return "in the D (x <= " + xb + ", within " + metres(l.d_radius) + " m of (" + xb + ", 0))";
    }
  }
  return "";
}

std::string GameDef::theBall(int ball) const {
  const char* word = ball_name ? ball_name(ball) : nullptr;
  return "the " + (word ? std::string(word) : std::to_string(ball));
}

bool GameDef::playedBy(rules::RuleSet r) const {
  for (rules::RuleSet s : rule_sets) {
    if (s == r) return true;
  }
  return false;
}

}  // namespace nineball
