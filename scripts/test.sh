#!/usr/bin/env bash
# Sets up, builds and runs every test: once in Release, once under AddressSanitizer + UBSan.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"

"$root/scripts/build.sh" "$root/build" -DCMAKE_BUILD_TYPE=Release
(cd "$root/build" && ctest --output-on-failure -j "$(nproc)")

# -O1 -g1: what the sanitizers need (line numbers in their reports), at half the compile time
# of -O2 -g.
"$root/scripts/build.sh" "$root/build-asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNINEBALL_SANITIZE=ON \
  -DNINEBALL_BENCH=OFF -DNINEBALL_WINDOW_TESTS=OFF "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG"
# Under the sanitizers: the quick set, the network's tests and the fuzzers: the code that
# strangers' files and messages reach. Not the window's (the same game logic as the quick
# GameSession tests, drawn through SFML under Xvfb one X server at a time) nor the other slow
# tests (whole computer games, fits and calibrations: long, deterministic runs of the code the
# quick set already runs under the sanitizers); the Release run above runs both.
(cd "$root/build-asan" && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --output-on-failure -j "$(nproc)" -L 'quick|net|fuzz')
