#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "audio/impact.hpp"
#include "nineball/match.hpp"
#include "nineball/race.hpp"
#include "play/aim_guide.hpp"
#include "render/hud_state.hpp"
#include "window/cue_setup.hpp"
#include "window/fixed_step_clock.hpp"
#include "window/menu_choice.hpp"
#include "window/practice_mode.hpp"
#include "window/session_message.hpp"
#include "window/shot_playback.hpp"

namespace nineball::window {

/// What the players are doing now.
enum class Phase {
  Aiming,         ///< the player to move aims (and places the cue ball when in hand)
  Rolling,        ///< a shot is on: the physics runs
  PushOutChoice,  ///< a decision: after a push-out (or a pot not as called) the player
                  ///< shoots or passes; after an illegal break, plays on or re-racks
  GameOver,       ///< the rack is won; a rematch racks again
};

/// Two players at one table, rack after rack: the match, whose turn it is, the aim, power
/// and spin being set, the cue ball in hand, the physics stepped in fixed steps for the
/// window, and the messages about each turn. No SFML: the window drives it.
class GameSession : private PracticeHost {
 public:
  static constexpr double kMaxSpeed = CueSetup::kMaxSpeed;
  static constexpr double kMinSpeed = CueSetup::kMinSpeed;
  static constexpr double kMaxTip = 0.5;  ///< the tip's useful range, fraction of R
  static constexpr double kMaxElevationDeg = CueSetup::kMaxElevationDeg;
  static constexpr double kBreakSpeed = 10.0;  ///< m/s the break starts with
  /// m/s snooker's break-off starts with: a thin contact on the reds that brings the cue ball
  /// back to baulk, not a pool break.
  static constexpr double kBreakOffSpeed = 4.0;
  static constexpr double kShotSpeed = 3.0;    ///< m/s the first shot after the break starts with
  static constexpr double kSlowReplay = 0.25;  ///< play time per real second in a slow replay

  /// Starts the first rack; `setup` gives the rules, seed, table and perhaps a layout.
  explicit GameSession(const MatchSetup& setup, bool practice = false);
  ~GameSession();
  GameSession(GameSession&&) noexcept;
  GameSession& operator=(GameSession&&) noexcept;

  /// Practice mode: no rules and no turns; any ball placed anywhere, added or taken away; the
  /// last shot undone or retried.
  bool practice() const { return practice_ != nullptr; }
  /// Practice: the steps (shots, balls moved by hand) that undo can take back.
  std::size_t practiceSteps() const { return practice_ ? practice_->table().stepsRemembered() : 0; }
  /// The ball under a point on the table (practice: the balls that may be moved), or nothing.
  std::optional<int> ballAt(Vec2 pos) const;
  /// Why ball `id` may not stand at `pos` now, or nothing (practice).
  std::optional<std::string> ballPlacementProblem(int id, Vec2 pos) const;
  /// Practice: moves a ball; false (and a message) when it does not fit there.
  bool moveBall(int id, Vec2 pos);
  /// Practice: takes ball `id` off the table, or puts it on (at `near`, or the nearest free
  /// spot to it).
  void toggleBall(int id, Vec2 near);
  /// Practice: back to before the last shot, with its aim, power and spin, or to before the
  /// last ball moved, added or taken away by hand.
  void undoShot();
  /// Practice: the last shot's position and cue again, to play it once more (after an undo too).
  void retryShot();

  const Match& match() const { return *match_; }
  const MatchSetup& setup() const { return setup_; }

  /// The turns of the rack in play so far, as played, the cue ball's placement filled in (a
  /// save and a replay play them again). In practice, the last shot alone.
  const std::vector<TurnInput>& rackTurns() const { return rack_turns_; }
  /// Racks again as rack `rack_index` of the session (its seed and breaker) with the score
  /// given: where a saved rack resumes. The match's turns before it are not known: F5 then
  /// saves the rack alone.
  void resumeRack(int rack_index, int racks_won0, int racks_won1,
                  std::optional<int> breaker_seat = std::nullopt);
  /// Racks `first_rack` as the first of a new match at 0-0: a saved match replays from there.
  void startMatchAt(int first_rack);
  /// The turns of the match in play (a race: bestOf() > 0) from its first rack, as played;
  /// with the seed of its first rack (matchSeed) and the break order they are the match as a
  /// `nineball match` script. matchKnown() is false after resumeRack.
  const std::vector<TurnInput>& matchTurns() const { return match_turns_; }
  std::uint64_t matchSeed() const;
  int matchFirstRack() const { return match_first_rack_; }
  bool matchKnown() const { return match_known_; }
  /// Who breaks the racks after a match's first: in turn (the default) or the last winner.
  void setBreaks(BreakOrder order) { breaks_ = order; }
  BreakOrder breaks() const { return breaks_; }
  /// Called with each turn's record as the turn ends: the seat that played it and whether
  /// it was the rack's break (the session statistics).
  using TurnObserver = std::function<void(int seat, const TurnRecord& record, bool was_break)>;
  void setTurnObserver(TurnObserver observer) { observer_ = std::move(observer); }
  /// Online play: every turn played through shoot() and decide() passes `prepare` first (the
  /// turn to play instead, the wire's exact form; nothing refuses it) and `begun` once it is
  /// under way; rematch() asks `rematch` (false: the rematch is only offered).
  struct TurnRelay {
    std::function<std::optional<TurnInput>(const TurnInput&)> prepare;
    std::function<void(const TurnInput&)> begun;
    std::function<bool()> rematch;
  };
  void setTurnRelay(TurnRelay relay) { relay_ = std::move(relay); }
  bool hasTurnRelay() const { return static_cast<bool>(relay_.prepare); }
  /// Online play: the seats keep their sides (seat 0 is Player A, and breaks, in every rack),
  /// as the two sides of a network game do.
  void setFixedSeats(bool fixed) { fixed_seats_ = fixed; }
  bool fixedSeats() const { return fixed_seats_; }
  /// Puts the rack in a state Match::snapshot() gave (online play's heal), between turns.
  void restoreMatch(const MatchSnapshot& snapshot);
  Phase phase() const { return phase_; }

  /// Seat 0 is "Player 1", seat 1 "Player 2"; seat 0 breaks a match's first rack, the later
  /// racks as breaks() says.
  const std::string& seatName(int seat) const { return names_[seat]; }
  /// Renames a seat ("Computer" when the computer plays it); later messages use the name.
  void setSeatName(int seat, const std::string& name) { names_[seat] = name; }
  int seatOf(rules::Player p) const;
  int seatToMove() const { return seatOf(match_->rack().shooter()); }
  int racksWon(int seat) const { return racks_won_[seat]; }
  int rackNumber() const { return rack_ + 1; }
  /// A match of `best_of` frames (GameTexts::best_of_choices): the first seat to win
  /// framesToWinMatch(best_of) of them wins it, and the next rematch starts a new match at
  /// 0-0. 0 (the default): racks simply follow one another, counted without an end.
  void setBestOf(int best_of) { best_of_ = best_of; }
  int bestOf() const { return best_of_; }
  /// The seat that has won the match of bestOf() frames, once one has.
  std::optional<int> matchWinner() const;

  // The cue being set (CueSetup).
  double heading() const { return cue_.heading(); }
  void setHeading(double radians) { cue_.setHeading(radians); }
  double speed() const { return cue_.speed(); }
  void setSpeed(double mps) { cue_.setSpeed(mps); }
  /// The gauge, 0 to 1, linear in speed from kMinSpeed to kMaxSpeed.
  double power() const { return cue_.power(); }
  void setPower(double fraction) { cue_.setPower(fraction); }
  Vec2 tip() const { return cue_.tip(); }
  /// The largest tip offset allowed: the useful range, within the physics' miscue limit.
  double maxTip() const;
  /// Sets the tip, pulled in to the useful range.
  void setTip(Vec2 tip) { cue_.setTip(tip, maxTip()); }
  /// The cue's tilt above the table, radians: an elevated cue curves the ball (swerve).
  double elevation() const { return cue_.elevation(); }
  /// Sets the tilt, held within 0 to kMaxElevationDeg.
  void setElevation(double radians) { cue_.setElevation(radians); }

  /// The object balls pocketed this rack (and not spotted), in the order they dropped.
  const std::vector<int>& pocketedThisRack() const { return pocketed_; }

  bool pushOutAvailable() const;
  bool pushOutDeclared() const { return push_out_; }
  void togglePushOut();

  /// True while the player to move may move the cue ball.
  bool cueInHand() const;
  /// Where the cue ball is, or will be shot from when in hand.
  Vec2 cuePosition() const;
  /// The ball the player to move strikes: pool's cue ball, or carom's own ball.
  int shooterBall() const;
  /// Carom: the live count of the cushions before the second ball while a shot rolls, then the
  /// last shot's count and whether it scored, until the next shot; nothing in other games.
  std::optional<std::string> caromCount() const;
  /// Why the cue ball may not go there now, or nothing.
  std::optional<std::string> placementProblem(Vec2 pos) const;
  /// Moves the cue ball in hand; false (and a message saying why) for an illegal spot. A
  /// placement that succeeds clears the message of one refused before.
  bool placeCue(Vec2 pos);
  /// Turns the aim at the ball on (a rack, a turn, a cue ball just dropped start this way).
  void aimAtBallOn();
  // A heading from `cue` that meets a ball on before any other ball: at the nearest ball on's
  // centre, else a thin contact on the nearest; nothing when every ball on is hidden.
  std::optional<double> clearHeadingToBallOn(Vec2 cue) const;

  /// The aim guide from the cue ball along the current heading.
  AimGuide aimGuide() const;

  /// The coming shot must carry a call (the game's rules say when) and
  /// the player to move is aiming (a push-out needs none).
  bool callRequired() const;
  /// The ball being called: the one picked (where any ball may be called), else the ball on. 0 when
  /// no call is due.
  int callBall() const;
  /// The call made so far: set once a pocket is picked.
  std::optional<rules::Call> call() const;
  /// A click on the table while a call is due: picks the pocket near `pos`, or, where any ball may
  /// be called, the ball there. True when the click was taken as part of the call.
  bool clickCall(Vec2 pos);
  /// The pocket a click at `pos` would call, while a call is due.
  std::optional<PocketId> callPocketAt(Vec2 pos) const;
  /// Calls the obvious shot: the aim guide's object ball (when it may be called), else the
  /// ball on, into the pocket nearest its path.
  void callObvious();
  /// Makes call `c` as the clicks would (the computer's call, shown like a person's). False
  /// when no call is due.
  bool setCall(const rules::Call& c);

  /// Strikes with the current aim, power and spin; false (and a message) when refused.
  bool shoot();
  /// Strikes with exactly this shot or push-out (the computer's), placing the cue ball at
  /// `turn.cue` when in hand (at the current spot if none is given); the aim, gauge and spin
  /// show it. False (and a message) when refused.
  bool shoot(const TurnInput& turn);
  /// After the opponent's push-out (or a pot not as called): shoot from there (true) or pass
  /// the shot back. After an illegal break: play on (true) or re-rack. After a snooker foul:
  /// play on (true) or put the offender back in; after a miss also `replace` the balls.
  void decide(bool shoot_now, bool replace = false);
  /// Racks again after a game over, broken as breaks() says. After a match won (bestOf()), a
  /// new match: the racks won go back to 0-0.
  void rematch();
  /// Plays a whole turn at once, as `nineball match` does (a script before the window opens).
  /// Throws IllegalAction.
  void playTurn(const TurnInput& turn);

  /// True when the rack has a last shot to replay and nothing is rolling.
  bool replayAvailable() const;
  /// Replays the rack's last shot from the physics, at normal speed or a quarter of it.
  void startReplay(bool slow);
  void stopReplay();
  bool replaying() const { return playback_.replaying(); }
  /// The setup this rack began from (its seed and layout).
  const MatchSetup& rackSetup() const { return rack_setup_; }

  /// Runs the physics for one frame's time in fixed steps (times the play rate); returns the
  /// sounds it made.
  std::vector<audio::Impact> advance(double frame_seconds);
  /// Fast-forward: the physics runs `rate` times as fast, in the same steps (more of them a
  /// frame), so the shot ends exactly as at normal speed. 1 is normal.
  void setPlayRate(double rate) { playback_.setPlayRate(rate); }
  double playRate() const { return playback_.playRate(); }
  /// The balls where the frame should draw them: between the last two steps while rolling,
  /// the cue ball at its spot in hand otherwise.
  std::vector<BallState> ballsToDraw() const;
  /// The physics' clock at the balls ballsToDraw gives (s; the replay's own while it plays),
  /// running on a moment after the balls stop so that a ball just dropped sinks out of sight.
  double drawTime() const;
  /// The shot being played, for the stick's stroke through the ball: where the cue ball
  /// stood, the heading and speed, and how long ago it was struck (s of the physics' clock).
  struct Strike {
    Vec2 from;
    double heading_rad = 0.0;
    double power = 0.0;  ///< 0-1, as power()
    double since = 0.0;
  };
  /// While a shot rolls (not in a replay).
  std::optional<Strike> strike() const;
  /// Simulated seconds since the shot began.
  double shotTime() const;

  /// What the player to move should do now.
  std::string status() const;
  const std::string& message() const { return message_.text(); }
  render::Tone tone() const { return message_.tone(); }
  /// Replaces the message line (a refusal, a saved screenshot...).
  void say(const std::string& text, render::Tone tone = render::Tone::Info) override;

 private:
  void startRack();
  void startTurn();
  void finishShot();
  // What the practice part asks of the session (PracticeHost).
  bool aiming() const override { return phase_ == Phase::Aiming; }
  void rebuildPractice() override;
  void takeCue(const PracticeShot& shot) override;
  void afterTurn(const TurnRecord& record, int ball_on_before);
  /// The seat that breaks the rack being racked (the match's break order, or a resumed rack's).
  int breakerOfRack();
  /// A script's turn after a rack of a race ended: racks the next one. Throws IllegalAction
  /// when the game or the match is over.
  void nextRackForScript();
  Vec2 freeCueSpot() const;

  MatchSetup setup_;
  MatchSetup rack_setup_;
  std::unique_ptr<Match> match_;
  std::vector<TurnInput> rack_turns_;
  std::vector<TurnInput> match_turns_;
  std::unique_ptr<PracticeMode> practice_;
  Phase phase_ = Phase::Aiming;
  std::string names_[2] = {"Player 1", "Player 2"};
  int racks_won_[2] = {0, 0};
  int rack_ = 0;
  int best_of_ = 0;
  BreakOrder breaks_ = BreakOrder::Alternate;
  int breaker_seat_ = 0;                 // the seat that broke the rack in play (is its Player A)
  int match_first_rack_ = 0;             // the rack the match in play began with
  std::optional<int> last_winner_seat_;  // the seat that won the rack before, in this match
  bool match_known_ = true;              // match_turns_ hold the whole match
  std::optional<int> resumed_breaker_;   // the breaker of the rack resumeRack() racks
  CueSetup cue_{kShotSpeed};  // the aim, power, spin and tilt, the cue ball's spot in hand
  bool push_out_ = false;
  int ball_on_at_shot_ = 0;
  std::optional<int> call_ball_;         // the ball picked to call (GameDef::call_any_ball)
  std::optional<PocketId> call_pocket_;  // the pocket called
  rules::Groups groups_at_shot_;         // the groups before the turn (its message)
  bool breaking_ = false;                // the shot rolling is the break
  std::string last_count_;  // carom: the last shot's cushions and point, shown after it
  ShotPlayback playback_;   // the shot rolling, its steps, its replay
  std::vector<int> pocketed_;
  SessionMessage message_;  // the HUD's message line
  TurnObserver observer_;
  TurnRelay relay_;
  bool fixed_seats_ = false;
};

}  // namespace nineball::window
