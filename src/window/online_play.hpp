#pragma once

#include <deque>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "net/clock.hpp"
#include "net/connection.hpp"
#include "net/host_gate.hpp"
#include "net/lockstep.hpp"
#include "net/lockstep_driver.hpp"
#include "net/peer.hpp"
#include "net/protocol.hpp"
#include "net/wire.hpp"
#include "window/computer_player.hpp"
#include "window/game_session.hpp"
#include "window/remote_aim.hpp"
#include "window/seats/remote_control.hpp"

// A rack in the window against a player at another computer (issue 35): the host listens,
// the joiner connects (and reconnects after a lost link), and every turn goes through the
// lockstep (net::LockstepDriver) as `nineball online` plays it, so a window can play a
// headless peer: the driver says what the peer's messages mean, this class what the player sees.
// The session plays each turn with its usual animation; this side's input is blocked while the
// other side has the move. SFML's network module only (through src/net); nothing is drawn here.
namespace nineball::window {

struct OnlineConfig {
  net::Side side = net::Side::Host;
  /// Host: the port (address.port). Joiner: where the host is.
  net::Address address;
  std::string name = "Player 1";
  /// Host: the join code a friend must give (made at random when empty). Joiner: the code
  /// typed.
  std::string code;
  /// Joiner: the seat token of an earlier welcome to this rack (kept with the saved online
  /// rack), to take the seat back from a new window.
  std::string seat_token;
  /// Joiner: the file the seat token is kept in for a restarted window (seat_token_file.hpp);
  /// empty: not kept.
  std::string seat_file;
  /// Host: the match offered (a script without turns and players, net::matchPart).
  nlohmann::json match;
  /// This side's own turns from a script, played in order as its moves come; with `scripted`,
  /// a move with none left ends this side's rack (Bye, finished).
  std::vector<TurnInput> script;
  bool scripted = false;
  double wait_s = 0.0;     ///< host: nobody joined in this long ends the game (0: no limit)
  double rejoin_s = 60.0;  ///< a lost link: how long the other side has to come back
  double connect_s = 4.0;  ///< joiner: each attempt to connect
  double retry_s = 1.0;    ///< joiner: between attempts
  /// A picture run's guard: the rack playing on with no turn and no hash for this long ends
  /// it (0: no limit; a person may think as long as they like).
  double stall_s = 0.0;
  net::LinkLimits limits;
  /// What every timeout reads (tests: a fake clock); never null.
  const net::Clock* clock = &net::steadyClock();
};

class OnlinePlay : public RemoteControl, private net::RackTable {
 public:
  /// Waiting, Handshake, Playing, Lost, Over (why()): the peer's.
  using Stage = net::Peer::Stage;

  /// Host: opens the listening port; nothing, with `why`, when it is taken.
  static std::unique_ptr<OnlinePlay> start(const OnlineConfig& config, std::string& why);
  /// Says goodbye (Bye) if still linked.
  ~OnlinePlay() override;
  OnlinePlay(const OnlinePlay&) = delete;
  OnlinePlay& operator=(const OnlinePlay&) = delete;

  /// One frame of `seconds`: the link, the messages, the turns, the aim. The session may be
  /// replaced (the joiner's welcome): sessionReplaced() says so once.
  void update(GameSession& session, double seconds);
  bool sessionReplaced() { return std::exchange(replaced_, false); }

  Stage stage() const { return peer_->stage(); }
  /// Why the game ended (Over), or the reason of the last problem.
  const std::string& why() const { return why_; }
  /// True once the out-of-step or refusal was final (exit status for tests).
  bool failed() const { return failed_; }
  /// The line the HUD shows while not playing: waiting, connecting, lost, over; else empty.
  std::string banner() const;
  /// This side is done with the rack (it is over and settled, this side's script ran out, or
  /// the other side's did): a --screenshot run takes its picture.
  bool finished(const GameSession& session) const;
  /// Leaves: Bye with `reason`.
  void leave(const std::string& reason);
  const std::string& peerName() const { return peer_name_; }
  net::Side side() const { return config_.side; }
  /// Host: the port it listens on. Joiner: the host's.
  unsigned short port() const { return config_.address.port; }
  /// Host: the join code. Joiner: the seat token the host handed out (empty before).
  const std::string& joinCode() const { return config_.code; }
  const std::string& seatToken() const { return config_.seat_token; }
  /// Host: the line a friend types to join: "nineball --join ADDRESS:PORT --code CODE".
  std::string joinLine() const;
  /// True once the rack with this peer began (the handshake went through once).
  bool started() const { return driver_.begun(); }
  /// Rematch offers so far (either side), for the HUD.
  bool rematchOffered() const { return local_offer_; }

  // RemoteControl
  bool controls(const GameSession& session) const override;
  bool showsCue() const override;
  double pull() const override;
  std::string status(const GameSession& session) const override;

 private:
  explicit OnlinePlay(const OnlineConfig& config);
  // net::RackTable: the session's match
  const Match& match() const override { return session_->match(); }
  void restore(const MatchSnapshot& state) override { session_->restoreMatch(state); }
  double now() const;
  void installRelay(GameSession& session);
  void connectionStep(const GameSession& session);
  void timedOut(net::PeerTimedOut::What what);
  // By value: the reason is often the dropped link's own, which goes with it.
  void linkLost(std::string reason);
  void end(const std::string& reason, bool failure);
  void protocolError(const std::string& reason);
  void send(const net::Message& message);
  void handle(GameSession& session, const net::Message& message);
  void onEvent(GameSession& session, const net::LockstepEvent& event);
  void onHello(GameSession& session, const net::Hello& hello);
  void onWelcome(GameSession& session, const net::Welcome& welcome);
  void onTurn(GameSession& session, const net::TurnReceived& turn);
  void onHealStarted(GameSession& session, std::size_t index);
  void onEnded(const net::LockstepEnded& ended);
  void onBye(const net::ByeHeard& bye);
  void onRematch(GameSession& session);
  void newRack(GameSession& session);
  void finishTurns(GameSession& session);
  void playScript(GameSession& session);
  void sendAim(const GameSession& session);
  void showPeerAim(GameSession& session, double seconds);
  bool ourMove(const GameSession& session) const;
  net::Race race(const GameSession& session) const;

  OnlineConfig config_;
  std::unique_ptr<net::Peer> peer_;  // the link, the gate, the handshake's and rejoin's clocks
  bool ended_ = false;
  std::string why_;
  bool failed_ = false;
  double progress_at_ = 0.0;        // the last turn or hash
  std::deque<net::Message> inbox_;  // messages held while a shot rolls
  net::LockstepDriver driver_;      // the turns, the hashes, the heal and the rack's allowance
  std::optional<net::WireTurn> pending_;      // the turn rolling, as it went over the wire
  std::optional<net::TurnMessage> outgoing_;  // this side's turn, sent once it has begun
  GameSession* session_ = nullptr;  // the session driven (its relay is cleared): must outlive this
  bool playing_peer_turn_ = false;
  bool rematch_now_ = false;
  bool local_offer_ = false;
  bool peer_offer_ = false;
  bool local_finished_ = false;
  bool peer_finished_ = false;
  bool replaced_ = false;
  std::size_t script_next_ = 0;
  std::string peer_name_;
  AimSmoother peer_aim_;
  bool peer_aiming_ = false;
  double peer_power_ = 0.0;
  AimThrottle throttle_;
  std::size_t rack_turns_seen_ = 0;
};

/// "m:ss" of a number of seconds (the rejoin's countdown).
std::string clockText(double seconds);

}  // namespace nineball::window
