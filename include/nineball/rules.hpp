#pragma once

#include <optional>
#include <string>
#include <vector>

#include "nineball/pocket_id.hpp"

namespace nineball::rules {

/// Which game is played.
enum class Game { NineBall, EightBall, TenBall, ThreeCushion, Snooker };

/// "nine-ball", "eight-ball", "ten-ball", "three-cushion", "snooker".
const char* gameName(Game g);
std::optional<Game> gameFromName(const std::string& name);

/// Which rules decide a shot.
enum class RuleSet {
  Wpa,    ///< World Pool-Billiard Association rules (every game)
  Paper,  ///< the seed paper's finite state machine ("The UseFSM method"); nine-ball only
  Umb,    ///< Union Mondiale de Billard's world rules of carom billiard (three-cushion)
  Wpbsa,  ///< the World Professional Billiards and Snooker Association's rules (snooker)
};

const char* ruleSetName(RuleSet r);
std::optional<RuleSet> ruleSetFromName(const std::string& name);

enum class Foul {
  None,
  Scratch,
  WrongBallFirst,
  NoContact,
  NoRail,
  BadBreak,
  ThreeFouls,
  EightEarly,       ///< eight-ball: the 8 down before the shooter's group is cleared
  WrongGroupFirst,  ///< eight-ball: the first ball hit is not one the shooter may hit
  WrongPocket,      ///< the called ball dropped in another pocket
  NoCall,           ///< a ball dropped that was not called (or nothing was called)
  PottedNotOn,      ///< snooker: a ball not on went down
  ThreeMisses,      ///< snooker: a third miss in a row with a ball on in view (frame lost)
  JumpedBall,       ///< a ball (the cue ball among them) left the table over a rail
  JumpShot,         ///< snooker: the cue ball jumped over an object ball before hitting one
};

/// "scratch", "wrong-ball-first", "no-contact", "no-rail", "bad-break", "three-fouls",
/// "eight-early", "wrong-group-first", "wrong-pocket", "no-call", "potted-not-on",
/// "three-misses", "jumped-ball", "jump-shot".
const char* foulName(Foul f);

enum class Player { A, B };
inline Player other(Player p) {
  return p == Player::A ? Player::B : Player::A;
}
inline const char* playerName(Player p) {
  return p == Player::A ? "A" : "B";
}

/// Eight-ball's groups: solids 1-7, stripes 9-15.
enum class Group { Solids, Stripes };
/// "solids", "stripes".
const char* groupName(Group g);
/// The group of an eight-ball object ball; nothing for the 8 (and for numbers past 15).
std::optional<Group> groupOf(int ball);

/// Who holds which group; both empty while the table is open.
struct Groups {
  std::optional<Group> a;
  std::optional<Group> b;
  std::optional<Group> of(Player p) const { return p == Player::A ? a : b; }
  bool open() const { return !a; }
  bool operator==(const Groups& o) const { return a == o.a && b == o.b; }
};

/// A called shot: this ball in that pocket.
struct Call {
  int ball = 0;
  PocketId pocket = PocketId::TopLeft;
  bool operator==(const Call& o) const { return ball == o.ball && pocket == o.pocket; }
};

/// What happened in one shot, as the physics events tell it, and what the shooter called.
struct ShotSummary {
  std::optional<int> first_contact;  ///< first object ball the cue ball touched
  std::vector<int> pocketed;         ///< object balls pocketed, in the order they dropped
  std::vector<PocketId> pockets;     ///< pockets[i]: where pocketed[i] dropped (may be short)
  bool cue_pocketed = false;
  /// Balls that left the table over a rail (the cue ball among them), in the order they left.
  std::vector<int> off_table;
  bool rail_after_contact = false;  ///< some ball (cue included) met a cushion after contact
  int object_balls_to_rail = 0;     ///< distinct object balls that met a cushion
  std::optional<Call> call;         ///< the shooter's call, when one was made
  /// Every touch of an object ball by the cue ball, in order (a ball touched twice is there
  /// twice), and the cushions the cue ball had met before each: carom's scoring reads them.
  std::vector<int> cue_touches;
  std::vector<int> cue_cushions_before;
  int cue_cushions = 0;  ///< cushions the cue ball met in the whole shot
  bool miscue = false;   ///< the tip slipped off the cue ball
  /// Snooker: the striker was snookered before the stroke (WPBSA's definition, judged by the
  /// match on the balls' places before it: play/snookered.hpp). A miss needs it false.
  bool snookered_before = false;
  /// Snooker: the balls the cue ball rested against before the stroke (a touching ball,
  /// WPBSA 3.13): one of them that is on counts as hit when the cue ball plays away.
  std::vector<int> touching_before;
  /// Snooker: the object balls the cue ball jumped over before it first touched one (WPBSA's
  /// jump shot, judged by the match: play/jump_shot.hpp).
  std::vector<int> jumped_over;

  /// Where `ball` dropped; nothing when it did not drop or the pocket is unknown.
  std::optional<PocketId> pocketOf(int ball) const;
};

/// A choice the next player must make before anyone shoots.
enum class Decision {
  None,
  PlayOrPass,      ///< after a push-out or a ten-ball pot not as called: shoot, or pass back
  RerackOrPlayOn,  ///< after an illegal eight-ball break: play the table as it lies, or re-rack
  PlayOrPutBack,   ///< snooker, after a foul (WPBSA 3.15): play from there, or the offender again
  /// Snooker, after a foul and a miss (WPBSA 3.14): also the balls replaced where they were
  /// before the stroke and the offender plays it again.
  PlayPutBackOrReplace,
};

/// The rules' answer to a shot.
struct Verdict {
  Player shooter = Player::A;
  Foul foul = Foul::None;
  bool legal() const { return foul == Foul::None; }
  std::vector<int> pocketed;      ///< object balls that went down on the shot
  std::vector<int> to_spot;       ///< balls to put back on the foot spot (the game ball: see rules)
  Player next = Player::A;        ///< who shoots (or decides) next
  bool ball_in_hand = false;      ///< next shooter places the cue ball anywhere
  bool cue_to_head_spot = false;  ///< paper rules: after a scratch the cue ball goes there
  bool push_out_available = false;  ///< the next shot may be declared a push-out
  bool awaiting_decision = false;   ///< `decision` is not None: `next` chooses first
  Decision decision = Decision::None;
  /// Ten-ball: a legal shot whose pot did not count as called (WrongPocket or NoCall). No
  /// foul and no ball in hand, but the turn ends and the opponent may play or pass it back.
  Foul call_breach = Foul::None;
  Groups groups;  ///< eight-ball: who holds which group after the shot
  /// Points the shot scored for each player (A, B), for games that keep a score (pool's
  /// racks are won on a ball, not on points: zero there).
  int points[2] = {0, 0};
  std::optional<Player> winner;
  bool draw = false;  ///< the game ended level (three-cushion: both reached the distance)
  /// Three-cushion: the cushions the cue ball met before its second object ball (or in the
  /// whole shot when it did not reach one), the count a point needs three of.
  int cushions = 0;
  /// Snooker: the foul was also a miss (WPBSA 3.14, in the form docs/cli.md, "Snooker", states).
  bool miss = false;
  /// Snooker: the ball nominated as on (the colour after a red, or the free ball); 0 for none.
  int nominated = 0;
  /// Snooker: the stroke was played as a free ball.
  bool free_ball = false;
  /// Snooker: the frame ended level on the black, which is re-spotted (WPBSA 3.4).
  bool black_respotted = false;
};

/// Snooker's part of a frame's state (WPBSA): what the RackState of pool does not hold.
struct SnookerState {
  /// The striker potted a red and is on a colour (of his nomination).
  bool colour_on = false;
  /// A free ball was stated for the coming stroke (WPBSA 3.12): the match judged the incoming
  /// striker snookered after a foul; void when the offender is put back in.
  bool free_ball = false;
  /// The frame ended level on the black, which was re-spotted: the first score or foul wins.
  bool respotted_black = false;
  /// Misses in a row of A and B (WPBSA 3.14(h): the third with a ball on in view loses).
  int misses[2] = {0, 0};
  /// The stroke before the last foul, for a put-back with the balls replaced (after a miss).
  bool colour_on_before = false;
  bool free_ball_before = false;
  std::vector<int> on_table_before;
};

/// Everything a rack remembers between shots. The rule books read and update it.
struct RackState {
  std::vector<int> racked;    ///< the object balls at the start (sorted): a re-rack restores them
  std::vector<int> on_table;  ///< object balls still on the table (sorted)
  Player shooter = Player::A;
  bool break_next = true;
  bool ball_in_hand = false;
  bool push_out_available = false;
  Decision decision = Decision::None;
  std::optional<Player> winner;
  int fouls[2] = {0, 0};  ///< consecutive fouls of A and B
  int score[2] = {0, 0};  ///< points of A and B, for games that keep a score
  Groups groups;
  // Games played to a number of points (three-cushion):
  int target = 0;            ///< the points that win; 0 for a game won on a ball
  int innings[2] = {0, 0};   ///< innings of A and B so far, the one being played included
  bool inning_open = false;  ///< the shooter's current inning is counted
  int run = 0;               ///< points of the inning being played
  int high_run[2] = {0, 0};  ///< the best inning of A and B
  bool equalising = false;   ///< the opener reached the distance: the other's last inning
  bool draw = false;
  SnookerState snooker;  ///< snooker's own state

  bool has(int ball) const;
  void remove(const std::vector<int>& balls);
  int& foulCount(Player p) { return fouls[p == Player::A ? 0 : 1]; }
};

/// One game's rules (and rule set): stateless, so one shared instance serves every rack.
/// Judging reads the state before the shot and updates what the game itself keeps (balls
/// down, foul counts, groups); the Rack applies the rest of the verdict.
class RuleBook {
 public:
  virtual ~RuleBook() = default;
  virtual Game game() const = 0;
  virtual RuleSet ruleSet() const = 0;
  /// The balls the cue ball may hit first now (the break: any).
  virtual std::vector<int> legalFirstBalls(const RackState& s) const = 0;
  /// The ball on, for the HUD and the planner's position play: by default the lowest of
  /// legalFirstBalls() (0 when none is left); a game whose next ball is not the lowest says so.
  virtual int ballOn(const RackState& s) const;
  /// The ball the shooter strikes: pool's cue ball for both players; in carom each player's
  /// own (white for the opener, yellow for the other).
  virtual int cueBall(const RackState& s) const;
  /// Whether the coming shot must carry a call (push-outs never need one).
  virtual bool callRequired(const RackState& s) const = 0;
  /// Judges one shot; `push_out` only when s.push_out_available.
  virtual Verdict judge(RackState& s, const ShotSummary& shot, bool push_out) const = 0;
  /// Points the balls left can still give (snooker's "points remaining"); 0 for a game won
  /// on a ball or played to a distance.
  virtual int pointsRemaining(const RackState&) const { return 0; }
};

/// The rule book of a game. Throws std::invalid_argument for a pair that does not exist (the
/// paper's rules are nine-ball's only).
const RuleBook& ruleBook(Game game, RuleSet rules = RuleSet::Wpa);

/// The rules of one rack as a pure state machine: shots in, verdicts out. It knows ball
/// numbers, pockets and players, nothing of physics or drawing. Any game; copyable.
class Rack {
 public:
  /// Nine-ball. `object_balls` are the balls on the table at the start; `opening_break` says
  /// whether the first shot is a break (a racked table) or an ordinary shot (a custom layout).
  Rack(RuleSet rules, std::vector<int> object_balls, bool opening_break = true);
  /// Any game. Throws std::invalid_argument for the paper's rules outside nine-ball.
  Rack(Game game, RuleSet rules, std::vector<int> object_balls, bool opening_break = true);
  /// A rack judged by `book`, which must outlive it (a game's book, or one of a test's own).
  Rack(const RuleBook& book, std::vector<int> object_balls, bool opening_break = true);

  Game game() const { return book_->game(); }
  RuleSet rules() const { return book_->ruleSet(); }
  Player shooter() const { return s_.shooter; }
  /// The balls the cue ball may legally hit first now.
  std::vector<int> legalFirstBalls() const { return book_->legalFirstBalls(s_); }
  /// The ball on (the rule book's RuleBook::ballOn; 0 when none is left).
  int ballOn() const { return book_->ballOn(s_); }
  /// Points of `p` so far, for games that keep a score.
  int score(Player p) const { return s_.score[p == Player::A ? 0 : 1]; }
  /// The ball the shooter strikes (RuleBook::cueBall).
  int cueBall() const { return book_->cueBall(s_); }
  /// Games played to a number of points: the distance and the points of the inning being
  /// played (carom's innings and best inning: nineball/carom_rack.hpp).
  int targetPoints() const { return s_.target; }
  void setTargetPoints(int points) { s_.target = points; }
  /// Who plays the first stroke: set before it.
  void setOpener(Player p);
  int currentRun() const { return s_.run; }
  /// The game ended level (no winner).
  bool drawn() const { return s_.draw; }
  /// The points the balls left can still give (RuleBook::pointsRemaining: snooker's; what only
  /// snooker's frame has is in nineball/snooker_rack.hpp).
  int pointsRemaining() const { return book_->pointsRemaining(s_); }
  /// The state the rule book keeps (snooker's nomination, misses, the state before a foul).
  const RackState& state() const { return s_; }
  const std::vector<int>& ballsOnTable() const { return s_.on_table; }
  bool isBreak() const { return s_.break_next; }
  bool ballInHand() const { return s_.ball_in_hand; }
  bool pushOutAvailable() const { return s_.push_out_available; }
  /// A choice is pending (pendingDecision() says which) before anyone shoots.
  bool awaitingDecision() const { return s_.decision != Decision::None; }
  Decision pendingDecision() const { return s_.decision; }
  /// The next shot must carry a call (ten-ball after the break, eight-ball on the 8).
  bool callRequired() const { return !over() && book_->callRequired(s_); }
  Groups groups() const { return s_.groups; }
  bool over() const { return s_.winner.has_value() || s_.draw; }
  std::optional<Player> winner() const { return s_.winner; }
  int consecutiveFouls(Player p) const { return s_.fouls[p == Player::A ? 0 : 1]; }

  /// Judges a shot. `push_out` declares it a push-out (only when pushOutAvailable()).
  /// Throws std::logic_error when the shot is not allowed now (game over, push-out not
  /// available, a decision pending).
  Verdict shoot(const ShotSummary& shot, bool push_out = false);

  /// The pending choice of the player to move. PlayOrPass: shoot (`shoot` true) or pass the
  /// shot back. RerackOrPlayOn: play on (`shoot` true) or re-rack, after which isBreak() is
  /// true again, every racked ball is back and the chooser breaks. Throws std::logic_error
  /// when no decision is pending.
  void decide(bool shoot);

  /// Puts a spotted ball back on the table (the caller found the spot).
  void respot(int ball);
  /// Puts the rack in a state another copy of it was in (a snapshot taken with state()).
  void setState(const RackState& s) { s_ = s; }

 private:
  const RuleBook* book_;
  RackState s_;
};

}  // namespace nineball::rules
