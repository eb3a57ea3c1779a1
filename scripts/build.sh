#!/usr/bin/env bash
# Configures and builds one tree: scripts/build.sh BUILD_DIR [extra cmake args...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dir=$1
shift
# A unity build (the sources of a target compiled several to a unit: each header parsed and each
# template instantiated once a unit) takes half the compile time of one source a unit; working
# on the code, a build folder configured with -DCMAKE_UNITY_BUILD=OFF rebuilds less per change.
cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_UNITY_BUILD=ON "$@" >/dev/null
cmake --build "$dir" -j "$(nproc)"
