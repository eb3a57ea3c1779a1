#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "nineball/ball.hpp"
#include "nineball/match.hpp"
#include "nineball/params.hpp"
#include "nineball/rules.hpp"
#include "nineball/shot.hpp"
#include "nineball/table.hpp"

// The computer opponent: a shot planner that tries candidate shots in the headless physics
// and judges each outcome with the rules. No drawing, no wall-clock input in its choices.
namespace nineball::ai {

/// How strong the computer opponent is: how much it searches and how well it cues. Seven
/// levels from an absolute beginner to a master (docs/ai.md, "The ladder").
enum class Level { Beginner, Casual, Club, League, Advanced, Pro, Master };

/// Every level, the weakest first.
const std::vector<Level>& allLevels();
/// "beginner", "casual", "club", "league", "advanced", "pro", "master".
const char* levelName(Level level);
/// A level by its name or by an older one (easy = casual, medium = club, hard = master).
std::optional<Level> levelFromName(const std::string& name);
/// The names levelFromName takes: the seven, then the older ones.
std::vector<std::string> levelNames();
/// The same for a message: "beginner, casual, ..., master or easy, medium, hard".
std::string levelNamesText();

/// The pace above which a stroke's aim grows less precise (m/s: a ball sent about three table
/// lengths on the cloth).
inline constexpr double kPaceReference = 2.0;

/// What a level searches in carom (three-cushion): the shooter's ball's path.
struct CaromSearch {
  double heading_step_deg = 2.0;       ///< headings round the table this far apart
  double fine_step_deg = 0.0;          ///< ... and this far apart across each object ball (0: not)
  std::vector<double> speeds{3.0};     ///< m/s tried on every heading
  std::vector<Vec2> tips{{0.0, 0.0}};  ///< [side, height] tried on every heading
  std::vector<double> elevations_deg{0.0};  ///< cue elevations tried on every heading
  /// A raised cue (swerve): these elevations with running side and a little follow, at the two
  /// slowest speeds, every raised_step_deg round the table (none: not tried).
  std::vector<double> raised_elevations_deg;
  double raised_step_deg = 2.0;
  int robust_top = 0;            ///< widest scoring windows checked against cueing errors
  int position_top = 0;          ///< best of those whose next point is looked for
  int position_headings = 0;     ///< ... with a sweep of this many headings
  double position_weight = 0.0;  ///< worth of the next point's chance against this one's
};

/// What one level searches and how precisely it executes the chosen shot.
struct LevelSettings {
  std::vector<double> pot_speeds;        ///< m/s tried on every pot line (slower ones are dropped)
  std::vector<Vec2> tips;                ///< [side, height] tried on every pot line
  std::vector<double> safety_speeds;     ///< m/s tried on every safety line
  int safety_angles = 0;                 ///< object-ball directions tried for safeties
  int pocket_aims = 1;                   ///< points across each pocket mouth aimed at
  int max_pot_lines = 0;                 ///< pot lines kept, the easiest first
  bool combinations = false;             ///< ball on into another ball into a pocket
  bool banks = false;                    ///< the ball on off one cushion into a pocket
  bool kicks = false;                    ///< the cue ball off two cushions to the ball on
  bool jumps = false;                    ///< the cue ball over a ball in the way
  double jump_elevation_noise_deg = 0;   ///< the executed elevation's deviation on a jump
  int sweep_headings = 0;                ///< directions tried when no aimed shot is worth much
  int placements = 1;                    ///< ball in hand: cue positions tried
  int break_spots = 1;                   ///< cue positions on the head string tried for the break
  std::vector<double> break_speeds;      ///< m/s tried for the break
  int robust_top = 0;                    ///< best candidates re-simulated with cueing errors
  int robust_steps = 0;                  ///< heading errors tried each way, in half deviations
  double robust_aim_deg = 0.0;           ///< standard deviation of the heading error of that check
  double robust_speed = 0.0;             ///< standard deviation of its relative speed error
  int lookahead_top = 0;                 ///< best candidates whose next shot is simulated
  int lookahead_lines = 0;               ///< ... the easiest pot lines of that next shot
  std::vector<double> lookahead_speeds;  ///< ... at these speeds (m/s)
  std::vector<Vec2> lookahead_tips;      ///< ... and tips
  int push_out_headings = 0;             ///< directions tried for a push-out (0: never pushes out)
  /// Eight-ball: plays safe on any ball of its group (else the two nearest the cue ball) and
  /// weighs how many balls of each group are left open to a pocket (clusters, blockers).
  bool group_sense = false;
  /// The stroke model: the executed heading's standard deviation is aim_noise_deg on a
  /// straight shot at touching distance and moderate pace, multiplied by (1 + cut_growth
  /// sin^2 cut), (1 + reach_growth * metres from cue ball to first ball) and (1 + pace_growth *
  /// how far the speed is above kPaceReference, relative).
  double aim_noise_deg = 0.0;
  double cut_growth = 0.0;
  double reach_growth = 0.0;
  double pace_growth = 0.0;
  double speed_noise = 0.0;  ///< standard deviation of the executed speed, relative
  /// ... and of the cue stick's speed, m/s (the tournaments' noise: the ball's speed follows
  /// from the stick's by the stroke, executeStroke)
  double speed_noise_ms = 0.0;
  double elevation_noise_deg = 0.0;  ///< standard deviation of the executed cue elevation
  double tip_noise_m = 0.0;          ///< ... of each tip offset, m on the ball
  bool noise_on_break = false;       ///< the break cued with the whole noise (else a third)
  CaromSearch carom;                 ///< the search in carom games

  /// The settings of a level (the table in README.md, "Computer opponent").
  static LevelSettings of(Level level);
};

/// Execution noise to play with instead of a level's own.
struct ExecutionNoise {
  double aim_deg = 0.0;        ///< standard deviation of the heading
  double elevation_deg = 0.0;  ///< ... of the cue's elevation
  double speed_ms = 0.0;       ///< ... of the cue stick's speed, m/s (not the ball's)
  double tip_m = 0.0;          ///< ... of each tip offset, m on the ball

  /// The computer-pool tournaments' (the Computer Olympiad's eight-ball, 2005-2008, played in
  /// FastFiz: Noise.h, GaussianNoise; Smith, "PickPocket: a computer billiards shark", Artificial
  /// Intelligence 171, 2007; Archibald, Altman and Shoham, "Analysis of a winning computational
  /// billiards player", IJCAI 2009): Gaussian, on every shot, 0.125 degree of aim, 0.1 degree
  /// of elevation, 0.075 m/s of the cue stick's speed and 0.5 mm of each tip offset; every
  /// deviation `magnitude` times that (FastFiz's magnitude, 5 for "olympiad-5x").
  static ExecutionNoise olympiad(double magnitude = 1.0);
  /// "none" (every shot struck as planned, to measure a level's choices apart from its
  /// cueing), "olympiad" or "olympiad-5x"; nothing for any other name ("level", the level's
  /// own, is the caller's).
  static std::optional<ExecutionNoise> named(const std::string& name);
  /// The names `named` knows, in order: "none", "olympiad", "olympiad-5x".
  static std::vector<std::string> names();
  /// The settings with this noise in place of their own.
  void applyTo(LevelSettings& s) const;
};

/// What makes a stroke hard for the stroke model: the cut on the first ball (degrees, 0 straight)
/// and the cue ball's distance to it (m); both 0 when not aimed at a ball directly.
struct StrokeDifficulty {
  double cut_deg = 0.0;
  double reach_m = 0.0;
  bool is_break = false;
  bool is_jump = false;
};
/// The cueing errors of a named model: a level's name ("beginner" ... "master": its own errors),
/// "none", "olympiad" or "olympiad-5x"; nothing for another name.
std::optional<LevelSettings> cueingNamed(const std::string& name);
/// The names cueingNamed knows, in order (levels first).
std::vector<std::string> cueingNames();
/// `intended` as a player with the cueing errors of `s` strikes it, the draws taken from `rng`.
Shot executeStroke(const Shot& intended, const LevelSettings& s, const StrokeDifficulty& d,
                   const PhysicsParams& physics, std::uint64_t& rng);

/// The position to plan for: the table, the balls and the rules' state of the rack.
struct PlanInput {
  TableDef table;
  PhysicsParams physics;
  StepParams step;
  /// Every ball; the cue ball is id 0. Pocketed balls are ignored, and so is the cue ball's
  /// position when it is in hand.
  std::vector<BallState> balls;
  /// Whose turn, the ball on, the break, push-out and foul counts. A rack still in play.
  rules::Rack rack{rules::RuleSet::Wpa, {}, false};
  bool cue_in_hand = false;              ///< the shooter places the cue ball first
  bool behind_head_string = false;       ///< ... and only behind the head string (the break)
  CueArea cue_area = CueArea::Anywhere;  ///< ... in this area (snooker: the D)
};

/// The position a match is in, for the player to move.
PlanInput planInputFrom(const Match& match);

/// What a planned shot means to do. A PushOut's turn has kind TurnInput::Kind::PushOut.
enum class ShotKind { Break, Pot, Combination, Bank, Kick, Safety, PushOut, Point, Jump };

/// "break", "pot", "combination", "bank", "kick", "safety", "push-out", "point" (a carom
/// point attempted), "jump" (the cue ball over a ball in the way: a pot when it has a pocket,
/// else a hit on the ball on).
const char* shotKindName(ShotKind kind);

/// The planner's answer for one position.
struct Plan {
  /// The shot as intended (no execution noise): kind Shot (or PushOut), `cue` set when
  /// placing the ball, `call` set when the rules need one (GameDef::called_shots): the target and
  /// its pocket, or for a safety the ball on and the pocket nearest to it.
  TurnInput turn;
  ShotKind kind = ShotKind::Safety;
  int target = 0;                  ///< the ball meant to drop (pot, combination, bank)
  std::optional<PocketId> pocket;  ///< where it is meant to drop
  /// The ball the cue ball is meant to hit first (0: none; in carom, where the white is ball 0,
  /// -1: a cushion first).
  int first = 0;
  /// The stroke's difficulty for the stroke model: the cut on the first ball (0 straight, up
  /// to 90 degrees) and the cue ball's distance to it, m (both 0 when it is not aimed at
  /// directly: a break, a kick, a sweep that misses).
  double cut_deg = 0.0;
  double reach_m = 0.0;
  /// Expected worth of the outcome to the shooter, 0 (loses the rack) to 1 (wins it), averaged
  /// over the robustness check when there was one.
  double value = 0.0;
  int simulations = 0;  ///< shots simulated to find it
};

/// How the computer values one shot from a position, as the planner values each candidate: the
/// shot simulated to rest, judged by the rules, and the position it leaves scored for the
/// shooter (0 loses the rack, 1 wins it). One value is one of the simulations `ai-bench` counts.
class ShotValuer {
 public:
  /// Reads the position once (the table built, the balls the cue ball may hit first found).
  explicit ShotValuer(PlanInput in);
  ~ShotValuer();
  ShotValuer(const ShotValuer&) = delete;
  ShotValuer& operator=(const ShotValuer&) = delete;

  /// The worth of `shot` struck from the cue ball where it lies.
  double value(const Shot& shot) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// A computer player. Choices depend only on the position, the level and the seed (never on
/// threads or time), so a match played with the same seeds is the same bit for bit.
class Planner {
 public:
  /// `threads` workers simulate candidates side by side (each with its own worlds).
  explicit Planner(Level level, std::uint64_t seed = 1, int threads = 2);
  /// The same level cueing with `noise` instead of its own (which it also judges its shots by).
  Planner(Level level, const ExecutionNoise& noise, std::uint64_t seed = 1, int threads = 2);

  /// The best shot found for the position, as intended. The rack must not be waiting for a
  /// decision after a push-out (see shootAfterPushOut).
  Plan plan(const PlanInput& in);
  /// The pending decision of `in.rack` (a play-or-pass choice, after a push-out or a pot not as
  /// called: true to shoot, false to pass back; a re-rack choice after an illegal break: true to
  /// play on, false to re-rack). Takes the table when its best shot from there is worth at least
  /// what the opponent would get.
  bool shootAfterPushOut(const PlanInput& in);
  /// The plan as this level cues it (executeStroke, with the plan's cut and reach), drawn from
  /// the planner's own seeded generator.
  TurnInput execute(const Plan& plan);
  /// A whole turn of a match for the player to move: the pending decision, or a planned and
  /// executed shot (a push-out when that is worth more than any shot).
  TurnInput turnFor(const Match& match);

  Level level() const { return level_; }
  const LevelSettings& settings() const { return settings_; }
  /// Shots simulated since construction, and the wall time spent planning (for benchmarks).
  long simulations() const { return simulations_; }
  double thinkSeconds() const { return think_seconds_; }
  /// Wall time of the last plan or decision.
  double lastThinkSeconds() const { return last_think_seconds_; }

 private:
  Plan planCaromShot(const PlanInput& in);
  /// Snooker after a foul (Decision::PlayOrPutBack, PlayPutBackOrReplace): the choice worth
  /// most to the chooser, each judged by planning the stroke that follows it.
  TurnInput decideAfterFoul(const Match& match);

  Level level_;
  LevelSettings settings_;
  std::uint64_t rng_state_;
  int threads_;
  PhysicsParams physics_;  // of the last plan, for the stroke's noise (the ball's size and mass)
  long simulations_ = 0;
  double think_seconds_ = 0.0;
  double last_think_seconds_ = 0.0;
};

}  // namespace nineball::ai
