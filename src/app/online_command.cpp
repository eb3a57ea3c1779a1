#include "app/online_command.hpp"

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <memory>
#include <ostream>
#include <vector>

#include "app/exit_codes.hpp"
#include "app/read_input.hpp"
#include "io/json_reader.hpp"
#include "io/match_json.hpp"
#include "net/handshake.hpp"
#include "net/online_rack.hpp"

namespace nineball::app {
namespace {

using Outcome = net::OnlineRackResult::Outcome;

int exitFor(Outcome outcome) {
  switch (outcome) {
    case Outcome::InStep:
      return kExitOk;
    case Outcome::Partial:
      return kExitPartial;
    case Outcome::OutOfStep:
      return kExitOutOfStep;
    case Outcome::Refused:
    case Outcome::BadTurn:
      return kExitBadInput;
    case Outcome::LinkLost:
    case Outcome::NoPeer:
    case Outcome::Quit:
      return kExitLinkFailed;
  }
  return kExitInternal;
}

// Where this side plays: the host's port or the address joined; nothing, with `why`.
std::optional<net::OnlineRackOptions> sideOf(const OnlineOptions& o, std::string& why) {
  net::OnlineRackOptions r;
  if (o.host_port.empty() == o.join.empty()) {
    why = "give one of --host PORT or --join HOST[:PORT]";
    return std::nullopt;
  }
  if (!o.host_port.empty()) {
    const auto port = net::parsePort(o.host_port, why);
    if (!port) return std::nullopt;
    r.side = net::Side::Host;
    r.address.port = *port;
  } else {
    const auto address = net::parseAddress(o.join, why);
    if (!address) return std::nullopt;
    r.side = net::Side::Joiner;
    r.address = *address;
  }
  return r;
}

// --seat-token: the token itself, or a file that holds it (read when it exists, written with
// the token each welcome hands out, so a restarted joiner takes its seat back).
bool takeSeatToken(const std::string& given, net::OnlineRackOptions& o, std::string& why) {
  if (given.empty()) return true;
  if (net::isSeatToken(given)) {
    o.seat_token = given;
    return true;
  }
  std::ifstream in(given);
  std::string token;
  if (in && std::getline(in, token) && !token.empty()) {
    if (!net::isSeatToken(token)) {
      why = "--seat-token: " + given + " does not hold a seat token (" +
            std::to_string(net::kSeatTokenChars) + " hexadecimal digits)";
      return false;
    }
    o.seat_token = token;
  }
  o.on_seat_token = [given](const std::string& t) {
    std::ofstream out(given);
    out << t << '\n';
  };
  return true;
}

// Ctrl-C (or a kill) while a rack is on: the other side is told before this one goes.
std::atomic<bool> quit_requested{false};

extern "C" void requestQuit(int) {
  quit_requested.store(true);
}

class QuitOnSignals {
 public:
  QuitOnSignals() {
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) previous_.push_back(std::signal(sig, requestQuit));
  }
  ~QuitOnSignals() {
    std::size_t i = 0;
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, previous_[i++]);
  }
  QuitOnSignals(const QuitOnSignals&) = delete;
  QuitOnSignals& operator=(const QuitOnSignals&) = delete;

 private:
  std::vector<void (*)(int)> previous_;
};

}  // namespace

CLI::App* addOnlineCommand(CLI::App& app, OnlineOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "online",
      "Play a rack with another nineball over the network (host or join), this side's turns "
      "from a match script; print the rack's result as JSON with the state hash after every "
      "turn");
  cmd->add_option("--host", options.host_port, "Host the rack, listening on this TCP port");
  cmd->add_option("--join", options.join, "Join the rack hosted at HOST[:PORT] (port 47047)");
  cmd->add_option("script", options.script_path,
                  "This side's match script (the host's sets the game), or - for standard input")
      ->required();
  cmd->add_option("--name", options.name, "The name the other player sees")->capture_default_str();
  cmd->add_option("--code", options.code,
                  "The join code: the host's (made at random when not given, printed beside "
                  "the address), which the joiner must give");
  cmd->add_option("--seat-token", options.seat_token,
                  "Joiner: the seat token of an earlier welcome (to take the seat back from a "
                  "new process), or a file to keep it in (read when it exists, written on "
                  "welcome)");
  cmd->add_option("--turn-time", options.turn_s,
                  "Seconds the other player may take over a turn before the rack is given up")
      ->check(CLI::Range(1.0, 86400.0))
      ->capture_default_str();
  cmd->add_option("--wait", options.wait_s, "Host: seconds to wait for the other player")
      ->check(CLI::Range(1.0, 86400.0))
      ->capture_default_str();
  cmd->add_option("--rejoin", options.rejoin_s,
                  "Seconds a lost link may take to come back before the rack is given up")
      ->check(CLI::Range(0.0, 3600.0))
      ->capture_default_str();
  cmd->add_option("--timeout", options.silence_s,
                  "Seconds of silence after which the other side is taken as gone")
      ->check(CLI::Range(1.0, 600.0))
      ->capture_default_str();
  cmd->add_option("--test-nudge-after", options.nudge_after)->group("");
  cmd->add_option("--test-drop-before", options.drop_before)->group("");
  cmd->add_option("--test-quit-before", options.quit_before)->group("");
  return cmd;
}

int runOnline(const OnlineOptions& options, std::istream& in, std::ostream& out,
              std::ostream& err) {
  const std::string prefix = "nineball online: ";
  std::string why;
  auto side = sideOf(options, why);
  if (!side) {
    err << prefix << why << '\n';
    return kExitBadInput;
  }
  const std::string where = prefix + shownPath(options.script_path) + ": ";
  const auto text = readInput(options.script_path, in, why);
  if (!text) {
    err << where << why << '\n';
    return kExitBadInput;
  }
  auto parsed = io::parseMatchScript(*text);
  if (const auto* refused = std::get_if<io::ParseError>(&parsed)) {
    err << where << refused->message << '\n';
    return kExitBadInput;
  }
  net::OnlineRackOptions& o = *side;
  o.script = std::get<io::MatchScript>(std::move(parsed));
  if (o.script.race.race_to > 0) {
    err << where
        << "race_to: nineball online plays one rack a script (a race online is the window's, "
           "from the host's menu)\n";
    return kExitBadInput;
  }
  o.match = net::matchPart(io::readJson(*text));
  o.name = options.name;
  if (options.code.size() > net::kMostCodeChars) {
    err << prefix << "--code: longer than " << net::kMostCodeChars << " characters\n";
    return kExitBadInput;
  }
  o.code = options.code;
  if (o.side == net::Side::Host) {
    if (o.code.empty()) o.code = net::makeJoinCode();
    err << prefix << "hosting on port " << o.address.port << ": join with nineball --join "
        << net::localAddress() << ":" << o.address.port << " --code " << o.code << '\n'
        << std::flush;
  } else if (o.code.empty()) {
    err << prefix << "--join needs the host's join code (--code CODE)\n";
    return kExitBadInput;
  }
  if (!takeSeatToken(options.seat_token, o, why)) {
    err << prefix << why << '\n';
    return kExitBadInput;
  }
  o.wait_s = options.wait_s;
  o.turn_s = options.turn_s;
  o.rejoin_s = options.rejoin_s;
  o.limits.silence_s = options.silence_s;
  if (const auto n = options.nudge_after) {
    o.after_turn = [n](Match& match, std::size_t turn) {
      if (static_cast<long>(turn) != *n) return;
      MatchSnapshot s = match.snapshot();
      s.balls.front().pos.x += 1e-6;
      match.restore(s);
    };
  }
  if (const auto n = options.quit_before) {
    // A crash: the process ends without a word to the other side, which waits for a rejoin.
    o.drop_before_turn = [n](std::size_t index) {
      if (static_cast<long>(index) >= *n) std::_Exit(kExitInternal);
      return false;
    };
  }
  if (const auto n = options.drop_before) {
    // Once: the turn is sent again after the rejoin.
    auto dropped = std::make_shared<bool>(false);
    o.drop_before_turn = [n, dropped](std::size_t index) {
      if (*dropped || static_cast<long>(index) != *n) return false;
      *dropped = true;
      return true;
    };
  }
  const QuitOnSignals signals;
  o.quit = &quit_requested;
  const net::OnlineRackResult result = net::playOnlineRack(o);
  if (!result.doc.is_null()) out << result.doc.dump(2) << '\n' << std::flush;
  if (result.outcome != Outcome::InStep) err << prefix << result.why << '\n';
  if (result.heals > 0) {
    err << prefix << "healed " << result.heals
        << " time(s): the states differed and the host's was taken\n";
  }
  return exitFor(result.outcome);
}

}  // namespace nineball::app
