#pragma once

#include <future>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "net/clock.hpp"
#include "net/connection.hpp"
#include "net/host_gate.hpp"
#include "net/lockstep.hpp"
#include "net/protocol.hpp"
#include "net/wire.hpp"

// The other nineball as one object, never blocking: the listening port and the gate (host),
// the attempts to connect and the hello (joiner), the link, and every timeout of a game's life
// (nobody came, no welcome, a lost link's rejoin window) read from an injected clock. A driver
// calls poll() once a step and acts on the events it returns; what the rack does with a turn,
// a hash or a state (the lockstep, the heal) stays the driver's, which owns the table.
namespace nineball::net {

struct PeerConfig {
  Side side = Side::Host;
  /// Host: the port (address.port). Joiner: where the host is.
  Address address;
  /// Host: the join code every hello must carry (made at random when empty).
  std::string code;
  /// Joiner: what it says once linked (the seat token is updated by each welcome).
  Hello hello;
  double wait_s = 0.0;     ///< nobody joined (host) or answered (joiner) in this long (0: no limit)
  double rejoin_s = 60.0;  ///< a lost link: how long the other side has to come back
  double connect_s = 4.0;  ///< joiner: each attempt to connect
  double retry_s = 1.0;    ///< joiner: between attempts
  double welcome_s = 10.0;  ///< joiner: how long the host may take to answer the hello
  /// Joiner: the answer is awaited no longer than what is left of wait_s (rejoin_s when a
  /// link was lost), but at least half a second.
  bool welcome_within_wait = false;
  LinkLimits limits;
  GateLimits gate;
  /// What every timeout reads (tests: a fake clock); never null.
  const Clock* clock = &steadyClock();
};

/// Host: a newcomer the gate let in, now the linked peer; its hello is to be answered.
struct PeerJoined {
  Hello hello;
};
/// A message from the linked peer, read and checked (the welcome and refusals among them).
struct PeerMessage {
  Message message;
};
/// The peer sent something no message is: nothing more is read from it until the driver
/// refuses it (send a Refuse, then lose()) or drop()s it.
struct PeerBadMessage {
  std::string why;
};
/// The link dropped; the peer waits for (host) or retries (joiner) a new one.
struct PeerLost {
  std::string reason;
};
/// Joiner: an attempt to reach the host failed (another follows after retry_s).
struct PeerUnreachable {
  std::string why;
};
/// A limit passed. NobodyCame and NoRejoin end the game with this peer (Over); after NoWelcome
/// the link is closed and the joiner tries again (after retry_s) unless the driver ends.
struct PeerTimedOut {
  enum class What {
    NobodyCame,  ///< wait_s passed with no link (lastProblem(): the joiner's last failure)
    NoWelcome,   ///< joiner: the host did not answer the hello within welcome_s
    NoRejoin,    ///< a lost link was not made again within rejoin_s
  };
  What what;
};
using PeerEvent =
    std::variant<PeerJoined, PeerMessage, PeerBadMessage, PeerLost, PeerUnreachable, PeerTimedOut>;

/// One attempt of the joiner to reach the host, made on a worker (connectTo blocks).
struct ConnectAttempt {
  std::unique_ptr<sf::TcpSocket> socket;
  std::string why;  ///< nobody answered: why
};

class Peer {
 public:
  enum class Stage {
    Waiting,    ///< host: listening; joiner: connecting
    Handshake,  ///< linked, hello / welcome under way
    Playing,    ///< the rack goes on
    Lost,       ///< the link dropped during a rack: waiting for a rejoin
    Over,       ///< the game with this peer is over
  };

  /// Host: opens the listening port; nothing, with `why`, when it is taken.
  static std::unique_ptr<Peer> start(const PeerConfig& config, std::string& why);
  ~Peer();
  Peer(const Peer&) = delete;
  Peer& operator=(const Peer&) = delete;

  /// One step: newcomers, connect attempts, the link's messages, the timeouts. A host admits a
  /// newcomer (closing the link it replaces) only when `admit` (the window: between shots).
  std::vector<PeerEvent> poll(bool admit = true);

  /// Queues a message. Until the handshake is done only its own words go out (hello, welcome,
  /// refuse, bye): a hash of a turn that ended meanwhile must not come before the welcome.
  void send(const Message& message);
  /// The handshake went through: the rack is on (a lost link now opens the rejoin window).
  void handshakeDone();
  /// Host: the linked newcomer may not play: told why, dropped, and the host waits on.
  void refuseNewcomer(const std::string& why);
  /// Closes the link (the peer broke the protocol).
  void drop(const std::string& reason);
  /// The link is taken for lost, as a dropped one is (a busy host's refusal, a peer refused):
  /// the rejoin window opens once the rack began; a joiner tries again (after retry_s when
  /// `retry_later`).
  void lose(std::string reason, bool retry_later = false);
  /// Closes the link; the next poll() reports it lost (tests drop a link so).
  void closeLink(const std::string& reason);
  /// Sends what is queued, for up to `seconds` of real time (before a goodbye or an end).
  void flush(double seconds = 0.5);
  /// Reads until the other side closes the link, for up to `seconds` of real time: the side
  /// that closes first holds its port a while (TCP's TIME_WAIT), so a host lets the joiner.
  void awaitClose(double seconds);
  /// The game is over (`why`): newcomers are told so, the link stays until leave().
  void end(const std::string& why);
  /// Says `bye` if linked and given, then closes the link; Over.
  void leave(const std::optional<Bye>& bye, const std::string& reason);

  Stage stage() const { return stage_; }
  bool linked() const { return link_ && !link_->closed(); }
  bool handshaking() const { return handshaking_; }
  /// True once a handshake went through (the rack with this peer began).
  bool begun() const { return begun_; }
  /// Host: the join code.
  const std::string& code() const { return config_.code; }
  /// Host: the seat token the gate handed out (empty before the seat was taken).
  std::string seatToken() const;
  /// Host: the last refusal of a newcomer that knew the code but runs another build.
  std::string buildRefusal() const;
  /// Joiner: the seat token sent with the next hello.
  void setSeatToken(const std::string& token) { config_.hello.token = token; }
  /// Joiner: why the last attempt to reach the host failed; any side: the last link's loss.
  const std::string& lastProblem() const { return problem_; }
  /// Seconds left of the rejoin window (Lost).
  double rejoinLeft() const;
  double now() const { return config_.clock->now(); }

 private:
  explicit Peer(const PeerConfig& config);
  void refuseLate();
  void hostStep(bool admit, std::vector<PeerEvent>& out);
  void joinerStep(std::vector<PeerEvent>& out);
  void linkUp(std::unique_ptr<Connection> link);
  void timedOut(PeerTimedOut::What what, std::vector<PeerEvent>& out);
  void timeouts(std::vector<PeerEvent>& out);
  void readLink(std::vector<PeerEvent>& out);

  PeerConfig config_;
  Stage stage_ = Stage::Waiting;
  bool handshaking_ = false;
  bool begun_ = false;
  std::string problem_;
  std::string over_why_;
  std::unique_ptr<Listener> listener_;
  std::unique_ptr<HostGate> gate_;
  std::optional<Admitted> admitted_;  // host: heard, linked when admitting
  std::unique_ptr<Connection> link_;
  std::future<ConnectAttempt> connecting_;
  double next_attempt_ = 0.0;
  double waiting_since_ = 0.0;
  double welcome_by_ = 0.0;  // joiner: the hello's answer is due by then
  bool answered_ = false;    // joiner: the host said something to the hello
  double lost_at_ = 0.0;
};

}  // namespace nineball::net
