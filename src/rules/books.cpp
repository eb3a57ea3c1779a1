// Every game's rule books: one line a game. Its name, the books it is played by and the lookups
// by name all read this table.
#include <stdexcept>
#include <string>
#include <vector>

#include "nineball/rules.hpp"
#include "rules/eight_ball.hpp"
#include "rules/nine_ball.hpp"
#include "rules/snooker.hpp"
#include "rules/ten_ball.hpp"
#include "rules/three_cushion.hpp"

namespace nineball::rules {
namespace {

struct GameBooks {
  Game game;
  const char* name;
  std::vector<const RuleBook*> books;  // the rule sets it is played by, the default first
};

const std::vector<GameBooks>& books() {
  static const NineBallRules nine_wpa(RuleSet::Wpa);
  static const NineBallRules nine_paper(RuleSet::Paper);
  static const EightBallRules eight;
  static const TenBallRules ten;
  static const ThreeCushionRules three_cushion;
  static const SnookerRules snooker;
  static const std::vector<GameBooks> all{
      {Game::NineBall, "nine-ball", {&nine_wpa, &nine_paper}},
      {Game::EightBall, "eight-ball", {&eight}},
      {Game::TenBall, "ten-ball", {&ten}},
      {Game::ThreeCushion, "three-cushion", {&three_cushion}},
      {Game::Snooker, "snooker", {&snooker}},
  };
  return all;
}

const GameBooks* booksOf(Game game) {
  for (const GameBooks& g : books()) {
    if (g.game == game) return &g;
  }
  return nullptr;
}

}  // namespace

const char* gameName(Game g) {
  const GameBooks* b = booksOf(g);
  return b ? b->name : "?";
}

std::optional<Game> gameFromName(const std::string& name) {
  for (const GameBooks& g : books()) {
    if (name == g.name) return g.game;
  }
  return std::nullopt;
}

const RuleBook& ruleBook(Game game, RuleSet rules) {
  const GameBooks* b = booksOf(game);
  if (!b) throw std::invalid_argument("no rule book for this game");
  for (const RuleBook* book : b->books) {
    if (book->ruleSet() == rules) return *book;
  }
  throw std::invalid_argument(std::string("the ") + ruleSetName(rules) + " rules are not " +
                              b->name + "'s");
}

}  // namespace nineball::rules
