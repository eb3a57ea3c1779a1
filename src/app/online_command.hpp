#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>
#include <optional>
#include <string>

namespace nineball::app {

/// Options of `nineball online`.
struct OnlineOptions {
  std::string host_port;    ///< --host PORT (one of the two)
  std::string join;         ///< --join HOST[:PORT]
  std::string script_path;  ///< this side's match script, or "-"
  std::string name = "Player";
  std::string code;        ///< --code: the join code (host: made at random when empty)
  std::string seat_token;  ///< --seat-token: a token, or a file holding one
  double wait_s = 300.0;
  double turn_s = 300.0;
  double rejoin_s = 60.0;
  double silence_s = 10.0;
  // Hidden, for tests: knock this side out of step after turn N (a ball nudged 1 um); drop the
  // link just before sending turn N (the joiner then rejoins); end the process without a word
  // before sending its first turn from N on (a crash: a new process rejoins).
  std::optional<long> nudge_after;
  std::optional<long> drop_before;
  std::optional<long> quit_before;
};

/// Registers `online (--host PORT | --join HOST[:PORT]) SCRIPT [--code CODE]` on the app.
CLI::App* addOnlineCommand(CLI::App& app, OnlineOptions& options);

/// Plays one rack with another nineball over the network, this side's turns from the script
/// (or the computer's, as its "players" says), and prints the `nineball match` result of the
/// rack with "hashes" on `out`. Exit: 0 the rack was played in step, 2 bad input or a refused
/// peer, 3 partial, 4 out of step and not healed, 5 the link failed (nobody came, the peer
/// left, stopped answering or misbehaved and did not come back).
int runOnline(const OnlineOptions& options, std::istream& in, std::ostream& out, std::ostream& err);

}  // namespace nineball::app
