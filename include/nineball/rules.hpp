#pragma once

#include <optional>
#include <string>
#include <vector>

namespace nineball::rules {

/// Which rules decide a shot.
enum class RuleSet {
  Wpa,    ///< World Pool-Billiard Association nine-ball
  Paper,  ///< the seed paper's finite state machine ("The UseFSM method")
};

const char* ruleSetName(RuleSet r);
std::optional<RuleSet> ruleSetFromName(const std::string& name);

enum class Foul { None, Scratch, WrongBallFirst, NoContact, NoRail, BadBreak, ThreeFouls };

/// "scratch", "wrong-ball-first", "no-contact", "no-rail", "bad-break", "three-fouls".
const char* foulName(Foul f);

enum class Player { A, B };
inline Player other(Player p) {
  return p == Player::A ? Player::B : Player::A;
}
inline const char* playerName(Player p) {
  return p == Player::A ? "A" : "B";
}

/// What happened in one shot, as the physics events tell it.
struct ShotSummary {
  std::optional<int> first_contact;  ///< first object ball the cue ball touched
  std::vector<int> pocketed;         ///< object balls pocketed, in the order they dropped
  bool cue_pocketed = false;
  bool rail_after_contact = false;  ///< some ball (cue included) met a cushion after contact
  int object_balls_to_rail = 0;     ///< distinct object balls that met a cushion
};

/// The rules' answer to a shot.
struct Verdict {
  Player shooter = Player::A;
  Foul foul = Foul::None;
  bool legal() const { return foul == Foul::None; }
  std::vector<int> pocketed;        ///< object balls that went down on the shot
  std::vector<int> to_spot;         ///< balls to put back on the foot spot (the 9 on a foul)
  Player next = Player::A;          ///< who shoots next
  bool ball_in_hand = false;        ///< next shooter places the cue ball anywhere
  bool cue_to_head_spot = false;    ///< paper rules: after a scratch the cue ball goes there
  bool push_out_available = false;  ///< the next shot may be declared a push-out
  bool awaiting_decision = false;   ///< after a push-out: the opponent shoots or passes
  std::optional<Player> winner;
};

/// The rules of one rack as a pure state machine: shots in, verdicts out. It knows ball
/// numbers and players, nothing of physics or drawing.
class Rack {
 public:
  /// `object_balls` are the balls on the table at the start; `opening_break` says whether
  /// the first shot is a break (a racked table) or an ordinary shot (a custom layout).
  Rack(RuleSet rules, std::vector<int> object_balls, bool opening_break = true);

  RuleSet rules() const { return rules_; }
  Player shooter() const { return shooter_; }
  /// Lowest-numbered object ball still on the table (0 when none is left).
  int ballOn() const;
  const std::vector<int>& ballsOnTable() const { return on_table_; }
  bool isBreak() const { return break_next_; }
  bool ballInHand() const { return ball_in_hand_; }
  bool pushOutAvailable() const { return push_out_available_; }
  /// After a push-out the opponent must choose (decide) before anyone shoots.
  bool awaitingDecision() const { return awaiting_decision_; }
  bool over() const { return winner_.has_value(); }
  std::optional<Player> winner() const { return winner_; }
  int consecutiveFouls(Player p) const { return fouls_[p == Player::A ? 0 : 1]; }

  /// Judges a shot. `push_out` declares it a push-out (only when pushOutAvailable()).
  /// Throws std::logic_error when the shot is not allowed now (game over, push-out not
  /// available, a decision pending).
  Verdict shoot(const ShotSummary& shot, bool push_out = false);

  /// After a push-out: the player to move either shoots (`shoot` true) or passes the shot
  /// back to the one who pushed out. Throws std::logic_error when no decision is pending.
  void decide(bool shoot);

  /// Puts a spotted ball back on the table (the caller found the spot).
  void respot(int ball);

 private:
  Verdict judgeWpa(const ShotSummary& shot, bool push_out);
  Verdict judgePaper(const ShotSummary& shot);
  void removePocketed(const std::vector<int>& balls);
  int& foulCount(Player p) { return fouls_[p == Player::A ? 0 : 1]; }

  RuleSet rules_;
  std::vector<int> on_table_;
  Player shooter_ = Player::A;
  bool break_next_ = true;
  bool ball_in_hand_ = false;
  bool push_out_available_ = false;
  bool awaiting_decision_ = false;
  std::optional<Player> winner_;
  int fouls_[2] = {0, 0};
};

}  // namespace nineball::rules
