#pragma once

namespace nineball::app {

/// Exit statuses of the nineball executable.
constexpr int kExitOk = 0;
/// A bug or a failure of the machine (not the input's fault).
constexpr int kExitInternal = 1;
/// Bad input: a refused scene, an unreadable file, a command-line usage error.
constexpr int kExitBadInput = 2;
/// A valid input whose run stopped at step.max_time or at the work budget with balls still
/// moving: the result printed is partial and flagged so.
constexpr int kExitPartial = 3;

/// `nineball online`: the two sides' states differed and the host's state did not heal it.
constexpr int kExitOutOfStep = 4;
/// `nineball online`: the link failed (nobody came, or the other side left, stopped answering
/// or misbehaved, and did not come back in time).
constexpr int kExitLinkFailed = 5;
/// `nineball fit`, `calibrate`: stopped by Ctrl-C (SIGINT) or SIGTERM, as a shell reports a
/// process Ctrl-C ended (128 + SIGINT).
constexpr int kExitInterrupted = 130;
}  // namespace nineball::app
