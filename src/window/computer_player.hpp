#pragma once

#include <cstdint>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "nineball/games.hpp"
#include "nineball/planner.hpp"
#include "nineball/seat.hpp"
#include "window/game_session.hpp"

namespace nineball::window {

/// What the computer chose for one turn: a shot (or push-out, perhaps with a call), with the
/// plan's intent when the planner found it, or its answer to a pending decision.
struct ComputerMove {
  TurnInput turn;
  std::optional<ai::Plan> plan;  ///< nothing for a decision or a fallback shot
};

/// How the computer finds its move, on the worker thread: `deciding` when a decision is pending
/// (play or pass after a push-out or a pot not as called, play on or re-rack after an
/// illegal break).
using Thinker =
    std::function<ComputerMove(ai::Planner& planner, const ai::PlanInput& in, bool deciding)>;

/// The planner's move: its answer to the pending decision, or a planned shot (or push-out) cued
/// with the level's error.
ComputerMove planMove(ai::Planner& planner, const ai::PlanInput& in, bool deciding);

/// Plays Player 2's seat for the computer. The planner runs on a worker thread from a copy of
/// the position, so the window keeps drawing; then the shot is shown as a player makes it (the
/// cue ball carried to its spot, the cue turned to the aim, drawn back in proportion to the
/// speed, the strike) and handed to the session, which runs it like any other shot. No SFML:
/// the window (or a test) calls update() every frame.
class ComputerPlayer {
 public:
  static constexpr int kSeat = 1;  ///< the computer plays Player 2's seat

  /// What the computer is doing in its turn.
  enum class Stage { Idle, Thinking, Placing, Aiming, Cueing, Striking };

  /// `seed` fixes the computer's cueing errors (the game's --seed).
  explicit ComputerPlayer(std::uint64_t seed);
  /// Waits for any planning still under way.
  ~ComputerPlayer();
  ComputerPlayer(const ComputerPlayer&) = delete;
  ComputerPlayer& operator=(const ComputerPlayer&) = delete;

  const Seat& opponent() const { return opponent_; }
  /// Gives Player 2's seat to a person or to the computer at a level, and names the seat. A turn
  /// the computer had begun is dropped: the seat's new player takes it.
  void setOpponent(GameSession& session, const Seat& opponent);

  /// Waits for the planner instead of polling it, so that each frame shows the same picture
  /// however long planning takes (screenshots, tests). The window stalls while it waits.
  void setWaitForPlans(bool wait) { wait_ = wait; }
  /// Replaces how the move is found (planMove by default): tests give a slow or failing one.
  void setThinker(Thinker thinker) { thinker_ = std::move(thinker); }

  /// True while the turn is the computer's: the keyboard and the mouse must not play it.
  bool controls(const GameSession& session) const;

  /// One frame of `seconds`: starts planning when the computer's turn comes, moves through
  /// the stages of showing the shot, and strikes (or decides after a push-out) at the end.
  void update(GameSession& session, double seconds);

  Stage stage() const { return stage_; }
  /// True once the computer holds the cue at its aim: the cue and the aim guide show.
  bool showsCue() const;
  /// How far the cue is drawn back now (m).
  double pull() const { return pull_; }
  /// Where the cue ball is while the computer carries it to its spot.
  std::optional<Vec2> carriedCue() const;
  /// What the status line says during the computer's turn.
  std::string status(const GameSession& session) const;

 private:
  bool computerTurn(const GameSession& session) const;
  void startThinking(const GameSession& session);
  std::optional<ComputerMove> takeMove(const GameSession& session);
  void beginMove(GameSession& session, const ComputerMove& move);
  void startAiming(GameSession& session);
  void callIfDue(GameSession& session);
  void strike(GameSession& session);
  void abandon();
  void reapAbandoned(bool wait);

  std::uint64_t seed_;
  long planners_made_ = 0;
  Seat opponent_;
  std::shared_ptr<ai::Planner> planner_;  // shared with the worker planning with it
  std::future<ComputerMove> job_;
  std::vector<std::future<ComputerMove>> abandoned_;  // dropped turns still planning
  Thinker thinker_ = planMove;
  bool wait_ = false;
  bool deciding_ = false;       // the turn is a decision: after a push-out, or a re-rack
  bool rerack_choice_ = false;  // ... the one after an illegal break
  bool stuck_ = false;          // neither the plan nor the fallback was allowed: a person plays it
  Stage stage_ = Stage::Idle;
  double elapsed_ = 0.0;  // s in the current stage
  double duration_ = 0.0;
  std::optional<ComputerMove> move_;
  Vec2 cue_from_;
  double heading_from_ = 0.0;
  double turn_by_ = 0.0;  // rad the cue turns while aiming
  double pull_ = 0.0;
};

/// What a plan means to do, for the status line: "pot the 3 in the top-right pocket", with
/// "(called)" when the rules want a call (another call is named).
std::string describePlan(const ai::Plan& plan, int ball_on, const GameDef& game = defaultGame());

}  // namespace nineball::window
