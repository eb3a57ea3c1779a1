#!/usr/bin/env bash
# Installs this build into a temporary prefix (cmake --install) and builds a project outside the
# tree against it (tests/install/consumer: find_package(nineball), nineball::core and
# nineball::io), then runs it: a cut shot built in code and the same scene read from JSON must
# both run to rest through the installed library and leave the object ball at one place.
# Usage: consumer_test.sh CMAKE BUILD_DIR SOURCE_DIR
set -euo pipefail
cmake=$1
build=$2
source=$3
export LC_ALL=C

tmp=$(mktemp -d "${TMPDIR:-/tmp}/nineball_consumer_XXXXXX")
trap 'rm -rf "$tmp"' EXIT
fail() {
  echo "consumer test: $*" >&2
  exit 1
}

"$cmake" --install "$build" --prefix "$tmp/prefix" >"$tmp/install.log" 2>&1 ||
  { cat "$tmp/install.log" >&2; fail "cmake --install failed"; }
[[ -f $tmp/prefix/include/nineball/nineball.hpp ]] || fail "no umbrella header in the prefix"
# A copy, so that nothing of nineball's tree is within reach but the prefix.
cp -r "$source/tests/install/consumer" "$tmp/consumer"
"$cmake" -S "$tmp/consumer" -B "$tmp/consumer/build" -G Ninja -DCMAKE_PREFIX_PATH="$tmp/prefix" \
  >"$tmp/configure.log" 2>&1 || { cat "$tmp/configure.log" >&2; fail "find_package(nineball) failed"; }
"$cmake" --build "$tmp/consumer/build" >"$tmp/build.log" 2>&1 ||
  { cat "$tmp/build.log" >&2; fail "the project did not build against nineball::core"; }
out=$("$tmp/consumer/build/cut_shot") || fail "the program failed: $out"
code=$(echo "$out" | sed -n 's/^code: //p')
json=$(echo "$out" | sed -n 's/^json: //p')
[[ -n $code && $code == "$json" ]] || fail "built in code and read from JSON differ: $out"
read -r end x _ <<<"$code"
[[ $end == rest ]] || fail "the shot ended $end, not at rest"
awk -v x="$x" 'BEGIN { exit !(x > 0.1) }' || fail "the object ball did not move on: $out"
echo "consumer test: $out"
