#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "net/connection.hpp"
#include "net/protocol.hpp"

// Who may sit down at a host, the same for the window and `nineball online`: everyone who
// connects is heard at once (never one after another), must say hello within a second or two,
// must know the join code, and, once the joiner's seat has been taken, must hold its seat
// token. Wrong codes from one address are slowed down; connections are capped per address.
namespace nineball::net {

struct GateLimits {
  /// A newcomer that has not said hello within this is dropped.
  double hello_s = 1.5;
  /// Newcomers heard at once, and from one address; more are refused at once ("busy: ...").
  std::size_t most_newcomers = 16;
  std::size_t most_per_address = 4;
  /// Wrong codes (or seat tokens) an address may send before it must wait; each one more
  /// doubles the wait, up to most_penalty_s.
  int free_wrong_guesses = 3;
  double first_penalty_s = 1.0;
  double most_penalty_s = 60.0;
};

/// A newcomer let in: its link, its hello, and whether it takes back a seat held before.
struct Admitted {
  std::unique_ptr<Connection> link;
  Hello hello;
  bool rejoin = false;
};

/// A refusal reason that means "try again soon" (a full host), not "you may not play".
bool isBusyRefusal(const std::string& reason);

class HostGate {
 public:
  /// `code`: the join code every hello must carry (normalCode compares).
  HostGate(std::string code, LinkLimits link_limits, GateLimits limits = {});

  const std::string& code() const { return code_; }
  /// The joiner's seat token: made when the seat is first taken, empty before.
  const std::string& seatToken() const { return token_; }
  /// Frees the seat (a new match with nobody seated): the next good hello takes it anew.
  void clearSeat() { token_.clear(); }

  /// Accepts whoever is waiting on `listener`, hears every newcomer, refuses the ones that may
  /// not sit down (by name, then closed) and returns the first that may. Never blocks.
  std::optional<Admitted> poll(Listener& listener, double now);

  /// The last refusal of a hello that knew the code but runs another build or protocol (the
  /// host's friend on another build): what `nineball online` ends with.
  const std::string& buildRefusal() const { return build_refusal_; }
  /// Newcomers being heard now.
  std::size_t listening() const { return newcomers_.size(); }

 private:
  struct Newcomer {
    std::unique_ptr<Connection> link;
    std::string address;
    double deadline = 0.0;
  };
  struct Guesses {
    int wrong = 0;
    double wait_until = 0.0;
  };
  void acceptAll(Listener& listener, double now);
  /// Why `hello` from `address` may not sit down, or nothing.
  std::optional<std::string> refusalOf(const Hello& hello, const std::string& address, double now);
  void wrongGuess(const std::string& address, double now);

  std::string code_;
  LinkLimits link_limits_;
  GateLimits limits_;
  std::string token_;
  std::vector<Newcomer> newcomers_;
  std::map<std::string, Guesses> guesses_;
  std::string build_refusal_;
};

/// Tells a peer why it is refused (cut to what it reads) and closes its link, waiting at most
/// half a second for the words to go out.
void refuseLink(Connection& c, const std::string& why);

}  // namespace nineball::net
