#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/colours.hpp"
#include "nineball/rules.hpp"
#include "nineball/table.hpp"

namespace nineball {

/// The standard rack of a game on `table` for balls of `ball_radius`: the object balls on
/// their spots (the order the seed gives where the rules leave it free), `gap` apart. A game
/// whose opening places the cue ball too (carom) includes it (id 0).
using RackMaker = std::vector<BallState> (*)(const TableDef& table, double ball_radius,
                                             std::uint64_t seed, double gap);

/// The two answers to a choice a game gives the next player, as `nineball match` takes them.
struct DecisionWords {
  const char* yes = "shoot";  ///< play from here (on)
  const char* no = "pass";    ///< pass back (re-rack)
  const char* about = "the choice after a push-out";
  /// A third answer where the game has one (snooker after a miss: the balls replaced and the
  /// offender plays again); null for none.
  const char* replace = nullptr;
};

/// Where a cue ball in hand may be placed.
enum class CueArea {
  Anywhere,          ///< anywhere it fits (pool's ball in hand)
  BehindHeadString,  ///< at or behind the head string, x <= -length/4 (pool's break)
  TheD,              ///< in snooker's D (SnookerLayout::inD): the break and after an in-off
};

/// True when a cue ball centred at `c` lies in `area` of `table` (fitting on the table and
/// clear of the other balls is checked apart).
bool inCueArea(CueArea area, const TableDef& table, Vec2 c);
/// The area in words for a message: "behind the head string (x <= -0.635)", "in the D
/// (x <= -1.0475, within 0.2920 m of (-1.0475, 0))"; empty for Anywhere.
std::string cueAreaText(CueArea area, const TableDef& table);

/// Where a ball the rules put back on the table goes: `balls` are every ball as they lie.
using SpotFinder = Vec2 (*)(int ball, const TableGeometry& table, double ball_radius,
                            const std::vector<BallState>& balls);

/// The kind of cue sport a game is: pool's games pocket object balls with one cue ball; carom's
/// score with each player's own ball on a table without pockets. The computer plans each kind
/// its own way.
enum class GameFamily { Pool, Carom };

/// One game as data: everything outside its rule book that differs from game to game. The
/// match, the planner, the JSON readers and writers, the HUD and the menus read it, so that a
/// new game is a rule book (src/rules), a definition (src/games/<game>/) and a registry line.
/// What it shows people (help lines, the menu's choices) is beside it, in its folder.
struct GameDef {
  rules::Game id = rules::Game::NineBall;
  GameFamily family = GameFamily::Pool;
  /// As scripts, the menu and --game name it.
  const char* name = "";
  /// The object balls of a full rack (sorted): the numbers a layout may hold.
  std::vector<int> balls;
  /// A custom layout must hold these, and why (eight-ball's 8: the rack is won on it).
  std::vector<int> required_balls;
  const char* required_why = "";
  /// Highest ball number a custom layout may hold; 0 for any (nine-ball's, as the paper's).
  int highest_ball = 0;
  /// The rule sets it is played by; the first is its default.
  std::vector<rules::RuleSet> rule_sets{rules::RuleSet::Wpa};
  RackMaker rack = nullptr;
  /// Its set of balls: how each is drawn (colours, stripes, numbers).
  BallLooks looks = poolBallLook;
  /// Its balls' names ("the blue"), or null where players call a ball by its number.
  BallNames ball_name = nullptr;
  /// The tables it is played on (TableDef::named), the first by default.
  std::vector<std::string> tables{"9ft", "8ft", "7ft"};
  /// Players take groups of balls (the HUD's panels, the tray, the script's "groups").
  bool groups = false;
  /// A call may name any ball on the table (a ball is clicked before its pocket); otherwise
  /// the ball called is the one to be hit first.
  bool call_any_ball = false;
  /// A pot not as called ends the turn without a foul, and the opponent plays or passes it
  /// (the script's "call_breach").
  bool pot_not_as_called_passes = false;
  /// Which shots must be called, for the message refusing one without a call.
  const char* called_shots = "";
  DecisionWords decision;
  /// The computer's break tries every spot on the head string (else the centre only).
  bool break_from_every_spot = false;
  /// The physics preset its equipment is (PhysicsParams::preset).
  const char* physics = "real";
  /// The cue ball is ever placed by hand (the break, ball in hand); carom never.
  bool cue_in_hand = true;
  /// Where the cue ball is placed for the break, and in hand after a foul. In the D the turn
  /// must place it ("cue"): it is not on the table until then.
  CueArea break_area = CueArea::BehindHeadString;
  CueArea in_hand_area = CueArea::Anywhere;
  /// Where a ball the rules spot goes; null for pool's foot spot (or behind it on the long
  /// axis).
  SpotFinder spot = nullptr;
  /// The rules ask whether the striker is snookered (snooker: the free ball after a foul and
  /// the miss): the match judges it from the balls' places (play/snookered.hpp) and tells the
  /// rules (ShotSummary::snookered_before, rules::stateFreeBall).
  bool snookers = false;
  /// The rules call a jump shot (the cue ball over an object ball before it hits one) a foul:
  /// snooker's (WPBSA Section 2, "Jump Shot"). The pool games and carom allow one.
  bool jump_shot_foul = false;
  /// Played to a number of points (three-cushion): the default distance; 0 for a game won on
  /// a ball.
  int default_points = 0;
  /// The shot after the break may be declared a push-out (nine-ball, ten-ball).
  bool push_outs = false;
  /// The game gives a choice between turns (the script's "decision" turns); carom none.
  bool decisions = true;
  /// A shot may carry a call (a call or, in snooker, a nomination): pocket games whose rules
  /// read one; nine-ball and carom take none.
  bool takes_calls = false;

  /// "the 9", "the blue", "the white": a ball as messages name it.
  std::string theBall(int ball) const;

  /// True when it is played by `rules`.
  bool playedBy(rules::RuleSet rules) const;
  /// The players score points: the games played to a distance (carom's) and snooker's frames.
  bool keepsScore() const { return default_points > 0 || snookers; }
};

/// Every game, in the order the menu offers them; the first is the default.
const std::vector<GameDef>& allGames();
/// The definition of `game`.
const GameDef& gameDef(rules::Game game);
/// The game played when none is chosen.
const GameDef& defaultGame();
/// The game of that name, or null.
const GameDef* gameNamed(const std::string& name);
/// Every game's name, in the registry's order.
std::vector<std::string> gameNames();
/// The games played by `rules`, for a message: "nine-ball", "nine-ball and ten-ball".
std::string gamesPlayedBy(rules::RuleSet rules);
/// "eight-ball, ten-ball and snooker": the games whose shots may carry a call.
std::string gamesTakingCalls();
/// Why `game` is not played on `table` (carom needs a table without pockets), naming both;
/// empty when it is.
std::string tableProblem(const GameDef& game, const TableDef& table);
/// "the paper's rules are nine-ball's only": why `rules` cannot be played in another game.
std::string rulesOnlyFor(rules::RuleSet rules);

}  // namespace nineball
