#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "nineball/match.hpp"
#include "nineball/planner.hpp"
#include "nineball/table.hpp"

// One table of a game environment for learning agents: an episode is a rack of a game (the agent
// against the computer, or both sides itself) or one stroke of the potting task; a step is one
// turn of the agent. The Python package's nineball.env steps many of them (VecTables).
namespace nineball::env {

/// What the agent is paid, per step (docs/python.md, "Environments").
struct Rewards {
  double pot = 1.0;     ///< each ball the agent pots in a legal stroke (a point in carom)
  double point = 1.0;   ///< each point the agent scores in a game that keeps a score (snooker)
  double foul = -1.0;   ///< each foul of the agent
  double win = 10.0;    ///< the rack won
  double loss = -10.0;  ///< the rack lost
};

/// What an environment is: the task, who the agent plays, how its strokes err.
struct EnvSpec {
  std::string name;                   ///< a game's name, or "pot"
  std::optional<rules::Game> game;    ///< none: the potting task
  std::optional<ai::Level> opponent;  ///< none: the agent plays both players
  std::string noise = "none";         ///< cueing errors, by ai::cueingNamed's names
  ai::LevelSettings cueing;           ///< ... as settings
  Rewards rewards;
  int max_turns = 200;  ///< the agent's turns before an episode is truncated
  TableDef table;       ///< the game's own unless set by the caller
  PhysicsParams physics;
  StepParams step;

  /// The spec for `name` ("pot" or a game), its table and physics the game's own (the pot
  /// task's: nine-ball's), run by `engine` (the reference engine by default: exact, and half
  /// Box2D's cost a stroke). Throws std::invalid_argument naming what is unknown.
  static EnvSpec named(const std::string& name, const std::optional<std::string>& opponent,
                       const std::string& noise, const std::string& engine = "reference");
};

/// The rules' state as the observation's "state" row, in this order (kStateNames).
inline constexpr int kStateSize = 13;
extern const char* const kStateNames[kStateSize];

/// A stroke of the agent, as a match turn: the shot, and the cue ball's place, the call or the
/// decision when due.
using Action = TurnInput;

/// What one step gave.
struct StepOutcome {
  double reward = 0.0;
  bool terminated = false;  ///< the rack (the pot task's stroke) is over
  bool truncated = false;   ///< max_turns reached first
  TurnInput executed;       ///< the agent's turn as played (its errors included)
  bool legal = true;        ///< the agent's stroke was no foul
  int potted = 0;           ///< balls the agent potted
  int opponent_turns = 0;   ///< the computer's turns played after it
  std::optional<rules::Player> winner;
  /// The table's episode was already over (a vector of tables without autoreset): nothing
  /// was played.
  bool idle = false;
};

/// One table.
class TableEnv {
 public:
  explicit TableEnv(EnvSpec spec);
  ~TableEnv();
  TableEnv(TableEnv&&) noexcept;
  TableEnv& operator=(TableEnv&&) noexcept;

  /// A new episode from `seed`: the game's rack (the agent breaks, as A) or a random pot; or,
  /// for a game, `start` (balls and standing) when given.
  void reset(std::uint64_t seed, const std::optional<MatchSetup>& start = std::nullopt);
  /// Plays the agent's turn (and the computer's after it). Throws IllegalAction when the rules
  /// do not allow it; the table is then as it was.
  StepOutcome step(const Action& action);
  /// Why `action` cannot be played now, or nothing.
  std::optional<std::string> actionProblem(const Action& action) const;
  /// The computer's turn at `level` for the position (a teacher), as intended (no errors).
  Action teacher(ai::Level level) const;

  /// The ball ids of the observation's rows.
  const std::vector<int>& ids() const { return ids_; }
  /// Writes the observation: `places` ids().size() x 2 (m; 0 off the table), `on_table`
  /// ids().size(), `state` kStateSize.
  void observe(double* places, std::uint8_t* on_table, double* state) const;
  /// Fills what a flat action leaves out: the cue ball's place when it must be placed, the call
  /// when one is required, the decision when one is due.
  Action completed(Action action) const;
  const EnvSpec& spec() const { return spec_; }
  const Match& match() const { return *match_; }
  int turns() const { return turns_; }
  /// The episode ended (terminated or truncated): only reset plays on.
  bool over() const { return over_; }

 private:
  StepOutcome stepPot(const Action& action);
  StepOutcome stepGame(const Action& action);
  ai::StrokeDifficulty difficultyOf(const Shot& shot) const;
  rules::Player agentSide() const;

  EnvSpec spec_;
  std::unique_ptr<Match> match_;
  std::unique_ptr<ai::Planner> opponent_;
  std::unique_ptr<TableGeometry> geometry_;  // built once: where the pot task's balls fit
  std::vector<int> ids_;
  std::uint64_t rng_ = 1;
  int turns_ = 0;
  bool over_ = false;
};

}  // namespace nineball::env
