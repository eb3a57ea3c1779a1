#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/engine.hpp"
#include "nineball/games.hpp"
#include "nineball/params.hpp"
#include "nineball/rules.hpp"
#include "nineball/shot.hpp"
#include "nineball/table.hpp"

namespace nineball {

/// An action the rules do not allow now (cue ball on another ball, push-out not available,
/// a shot after the game ended...). The message says why.
class IllegalAction : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Where a rack given by its balls stands when play joins it in the middle: who is to shoot
/// and what the rules carry from the turns before (a game state to start from).
struct RackStanding {
  rules::Player shooter = rules::Player::A;
  bool ball_in_hand = false;  ///< the shooter places the cue ball first (pool's games)
  int fouls[2] = {0, 0};      ///< consecutive fouls of A and B
  rules::Groups groups;       ///< eight-ball's groups (open when unset)
  int score[2] = {0, 0};      ///< points of A and B (the games that keep a score)
};

/// How a rack starts.
struct MatchSetup {
  rules::Game game = defaultGame().id;
  rules::RuleSet rules =
      rules::RuleSet::Wpa;  ///< Paper: only the games that GameDef::rule_sets says
  std::uint64_t seed = 1;   ///< places the rack's free balls
  TableDef table;
  PhysicsParams physics;
  StepParams step;
  /// A custom layout instead of the rack; the first turn is then an ordinary shot.
  std::optional<std::vector<BallState>> balls;
  /// Where the rack of `balls` stands (none: A to shoot, nothing carried over). Only with
  /// `balls`; Match refuses a standing its game cannot be in (IllegalAction).
  std::optional<RackStanding> standing;
  /// The distance of a game played to points (GameDef::default_points; 0 for pool's games).
  int points = 0;
  /// Who plays the rack's first stroke (the break, the break-off): the later racks of a race
  /// are opened by the players in turn or by the last rack's winner. Carom's rules know only
  /// A as the opener (A plays the white).
  rules::Player opener = rules::Player::A;

  /// Plays `g` by its default rules, with its equipment (GameDef::physics), on the first of the
  /// tables it is played on (GameDef::tables), to its default distance.
  void setGame(rules::Game g);
  /// The balls a rack starts with: the game's rack, and the cue ball on the head spot unless
  /// the rack places it (carom's opening position).
  std::vector<BallState> openingBalls() const;
};

/// One turn of a player: a shot (perhaps a push-out, perhaps placing the cue ball first), or
/// the choice after the opponent's push-out.
struct TurnInput {
  enum class Kind { Shot, PushOut, Decision };
  Kind kind = Kind::Shot;
  Shot shot;
  std::optional<Vec2> cue;  ///< where to place the cue ball (ball in hand, or the break)
  /// The called ball and pocket: needed when Rack::callRequired() (the game's rules say
  /// when: GameDef::called_shots); a push-out needs none.
  std::optional<rules::Call> call;
  /// Decision: shoot / play on (true), or pass the shot back / re-rack (false).
  bool shoot = true;
  /// Decision, snooker after a miss: the balls replaced and the offender plays again
  /// (GameDef::decision's `replace` word); `shoot` is then false.
  bool replace = false;
};

/// One player's standing in a game played to points.
struct PlayerScore {
  int points = 0;
  int innings = 0;   ///< the one being played included
  int run = 0;       ///< points of the current inning (0 once it is over)
  int high_run = 0;  ///< the best inning
};

/// Both players' standing after a turn.
struct Score {
  PlayerScore a, b;
};

/// The standing in `rack` (all zeros for pool's games).
Score scoreOf(const rules::Rack& rack);

/// What a turn gave.
struct TurnRecord {
  rules::Player shooter = rules::Player::A;
  TurnInput::Kind kind = TurnInput::Kind::Shot;
  rules::Verdict verdict;           ///< for a decision: no foul, next = who shoots now
  int ball_on = 0;                  ///< the ball on after the turn
  std::optional<rules::Call> call;  ///< the shot's call, when it had one
  rules::Decision answered = rules::Decision::None;  ///< for a decision: the choice it made
  bool shoot = true;     ///< for a decision: shoot / play on (true), or pass / rerack (false)
  bool replace = false;  ///< for a decision: the balls replaced (snooker after a miss)
  Score score;           ///< after the turn, for games played to points and snooker
  /// Snooker, after the turn: the points the balls left can give, and the next stroke is a
  /// free ball (the match judged the incoming striker snookered after a foul).
  int points_remaining = 0;
  bool free_ball_next = false;
};

/// Everything a Match carries from one turn to the next: restoring it into a Match of the same
/// setup gives the same state, to the bit (the same snapshotHash). The engine is built anew from
/// the balls, and an engine keeps a history (Box2D's contact lists, the clock), so a restored
/// match may play on differently from the one the snapshot came from: two matches restored from
/// one snapshot play on identically (what online play does to heal a peer out of step: both
/// sides restore).
struct MatchSnapshot {
  std::vector<BallState> balls;
  rules::RackState rack;
  bool cue_pocketed = false;            ///< the cue ball is off the table, waiting to be placed
  std::vector<BallState> balls_before;  ///< snooker: where a replace after a miss puts them
};

/// A fingerprint of a snapshot, bit for bit: the balls (stateHash) and the rack's state.
std::uint64_t snapshotHash(const MatchSnapshot& snapshot);

/// A rack of any game of the registry (nineball/games.hpp) played through the real physics: the
/// table, the balls, the rules. Headless and deterministic. A window drives it with beginShot /
/// step / finishShot; a script with play().
class Match {
 public:
  explicit Match(const MatchSetup& setup);
  ~Match();

  /// Plays one whole turn: places the cue ball if asked, shoots, runs to rest, judges.
  /// Throws IllegalAction when the turn is not allowed.
  TurnRecord play(const TurnInput& turn);

  /// Checks and starts a shot (push-out or not); the world then has moving balls.
  void beginShot(const TurnInput& turn);
  /// True while a shot begun with beginShot is still rolling.
  bool shotInProgress() const { return in_progress_; }
  /// Runs the shot rolling on by one fixed step (less when the balls come to rest within it);
  /// true once it is over: every ball rests, or it has run StepParams::max_time. The window
  /// calls it frame by frame and play() in a row, so both give the same turn bit for bit.
  bool stepShot();
  /// Judges the shot, first running it on to its end.
  TurnRecord finishShot();

  /// Why the cue ball may not go to `pos` now, or nothing when it may.
  std::optional<std::string> cuePlacementProblem(Vec2 pos) const;
  /// True when the player to move must (or may) place the cue ball before shooting.
  bool cueInHand() const;
  /// True when placement is limited to behind the head string (the break).
  bool cueBehindHeadString() const;
  /// Where the cue ball in hand may go now (GameDef::break_area or in_hand_area).
  CueArea cueArea() const;
  /// True when the coming turn must place the cue ball (off the table, or in hand in the D).
  bool cueMustBePlaced() const;

  const rules::Rack& rack() const { return rack_; }
  Engine& world() { return *world_; }
  const Engine& world() const { return *world_; }
  std::vector<BallState> balls() const { return world_->balls(); }
  /// Snooker: the balls as they lay before the last shot, where a replace after a miss puts
  /// them (empty before the first shot).
  const std::vector<BallState>& ballsBeforeShot() const { return before_shot_; }

  /// The state between turns (throws IllegalAction while a shot rolls).
  MatchSnapshot snapshot() const;
  /// Puts the match in a state snapshot() gave (of a match of the same setup): the engine is
  /// rebuilt from the balls, so two matches restored from one snapshot play on identically.
  /// Throws IllegalAction while a shot rolls.
  void restore(const MatchSnapshot& snapshot);

 private:
  void joinStanding(const RackStanding& standing);
  void placeCue(Vec2 pos);
  void rerack();
  void spot(int ball);
  void returnCueToHeadSpot();
  void setUpFrozenBalls();
  Vec2 freeSpotOnLine(Vec2 from, Vec2 step_dir) const;
  bool cueSnookered() const;
  void replaceBalls();

  MatchSetup setup_;
  std::unique_ptr<Engine> world_;
  rules::Rack rack_;
  bool in_progress_ = false;
  bool push_out_ = false;
  bool cue_pocketed_ = false;  // the cue ball is off the table, waiting to be placed
  int ball_on_at_start_ = 0;
  int cue_ = kCueBall;                  // the ball the shot rolling was struck on
  double shot_deadline_ = 0.0;          // the world's time at which the shot rolling is cut off
  std::optional<rules::Call> call_;     // of the shot rolling
  std::vector<BallState> before_shot_;  // the balls before the last shot (snooker's replace)
  bool snookered_before_ = false;       // the striker of the shot rolling was snookered
  std::vector<int> touching_before_;    // the balls the cue ball rested against
};

}  // namespace nineball
