#pragma once

#include <SFML/Network/TcpListener.hpp>
#include <SFML/Network/TcpSocket.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "net/wire.hpp"

// One TCP link to the other nineball, never blocking: messages queued out, messages read in,
// everything a peer sends bounded and checked before it is believed.
namespace nineball::net {

/// Limits a link holds the other side to.
struct LinkLimits {
  double silence_s = 10.0;  ///< nothing heard for this long: the peer stopped answering
  double ping_s = 1.0;      ///< we say something at least this often
  /// Messages a second the peer may send, counted over a second (aim updates are ~10).
  int messages_per_second = 120;
  /// Bytes waiting to go out past which the peer is not reading: the link is dropped.
  std::size_t most_unsent = 4 * kMaxMessageBytes;
};

/// A connected peer. The clock is the caller's (seconds, any origin), so tests can run it.
class Connection {
 public:
  Connection(std::unique_ptr<sf::TcpSocket> socket, double now, LinkLimits limits = {});
  ~Connection();
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  /// Queues one message (an object with "type"); sent by pump().
  void send(const nlohmann::json& message);
  /// Sends what is queued and reads what has arrived; the whole messages received, in order.
  /// A broken stream, a message too long, too deep or not JSON, or a flood is answered with
  /// `refuse` and closes the link (closed(), reason()); so does silence past the limit (only
  /// whole messages count as heard). Pings go out when we have been quiet.
  std::vector<nlohmann::json> pump(double now);
  /// Sends what is queued for up to `seconds` (a goodbye before closing).
  void flush(double seconds);
  /// Closes the link for `reason`.
  void close(const std::string& reason);

  bool closed() const { return closed_; }
  const std::string& reason() const { return reason_; }
  /// The peer's address, "ip:port".
  std::string remote() const;
  /// The peer's IP address alone (what limits per address count).
  const std::string& address() const { return address_; }

 private:
  void sendQueued();
  void receive(double now, std::vector<nlohmann::json>& out);
  bool accept(const std::string& text, double now, nlohmann::json& out);
  // Sends `refuse` ("disconnected: you <what_it_did>") and closes.
  void refuseAndClose(const std::string& what_it_did);

  std::unique_ptr<sf::TcpSocket> socket_;
  LinkLimits limits_;
  FrameReader reader_;
  std::string unsent_;
  double last_heard_ = 0.0;
  double last_said_ = 0.0;
  double window_start_ = 0.0;  // the second messages are being counted in
  int window_count_ = 0;
  bool closed_ = false;
  std::string reason_;
  std::string remote_;
  std::string address_;
};

/// A listening socket, accepting without blocking.
class Listener {
 public:
  /// Listens on `port` on every interface; nothing (with `why`) when the port is taken.
  static std::unique_ptr<Listener> open(unsigned short port, std::string& why);
  /// A peer that has connected since, if any.
  std::unique_ptr<sf::TcpSocket> accept();
  unsigned short port() const;

 private:
  sf::TcpListener listener_;
};

/// Connects to `address`, waiting up to `timeout_s`; nothing (with `why`) when no host answers.
std::unique_ptr<sf::TcpSocket> connectTo(const Address& address, double timeout_s,
                                         std::string& why);

/// The JSON text of a message, refused (with `why`) when nested deeper than a message can be:
/// checked before parsing, so a peer cannot exhaust the stack.
std::optional<nlohmann::json> parseMessage(const std::string& text, std::string& why);

/// This machine's address on the local network, and on the internet when a router lets SFML
/// find it (best effort, may be empty): what a host reads out to a friend.
std::string localAddress();

}  // namespace nineball::net
