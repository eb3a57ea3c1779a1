#!/usr/bin/env bash
# Installs this build into a temporary prefix as a user would (cmake --install) and checks the
# installed tree: only the two programs in bin, the library others build on (headers, two
# static libraries, a CMake package), the icon, desktop entry and metainfo where desktops look,
# a headless command that runs, the game launcher that finds nineball-game
# beside it, and resources found in the prefix, not in the source tree the build came from.
# With PYTHON and SITE (the Python module built), also the module in PREFIX/SITE, imported
# from there.
# Usage: installed_tree_test.sh CMAKE BUILD_DIR [PYTHON SITE]
set -euo pipefail
cmake=$1
build=$2
python=${3:-}
site=${4:-}
export LC_ALL=C

tmp=$(mktemp -d "${TMPDIR:-/tmp}/nineball_install_XXXXXX")
trap 'rm -rf "$tmp"' EXIT
# The real path: the installed program knows itself by /proc/self/exe, symlinks resolved.
prefix=$(cd "$tmp" && pwd -P)/prefix

fail() {
  echo "install test: $*" >&2
  exit 1
}

if ! "$cmake" --install "$build" --prefix "$prefix" >"$tmp/install.log" 2>&1; then
  cat "$tmp/install.log" >&2
  fail "cmake --install $build --prefix $prefix failed"
fi

top=$(cd "$prefix" && echo *)
[[ $top == "bin include lib share" ]] || fail "the prefix holds: $top (expected bin, include, lib and share)"
# The library others build on: the public headers, the core and io libraries, the CMake package
# (tests/install/consumer_test.sh builds a project on it).
headers=$(cd "$prefix/include" && find . -type f | sort)
expected=$(cd "$(dirname "$0")/../../include" && find . -type f | sort)
[[ $headers == "$expected" ]] || fail "include holds: $headers (expected the public headers alone)"
libs=$(cd "$prefix/lib" && find . -type f -not -path "./python*" | sort)
expected=$(printf '%s\n' ./cmake/nineball/nineballConfig.cmake ./cmake/nineball/nineballConfigVersion.cmake \
  ./cmake/nineball/nineballTargets-*.cmake ./cmake/nineball/nineballTargets.cmake \
  ./libnineball_core.a ./libnineball_io.a)
[[ $(echo "$libs" | sed 's/nineballTargets-[a-z]*\.cmake/nineballTargets-*.cmake/') == "$expected" ]] ||
  fail "lib holds: $libs (expected the two libraries and the CMake package)"
if [[ -n $python ]]; then
  modules=$(cd "$prefix/lib" && find . -type f -path "./python*" | sort)
  # The package's files are those of python/nineball in the source tree.
  expected=$(cd "$(dirname "$0")/../../python/nineball" && ls | grep -v __pycache__ |
    sed "s|^|./${site#lib/}/nineball/|" | sort)
  so=$(echo "$modules" | grep '/nineball/_core\..*\.so$')
  [[ -n $so && $(echo "$modules" | grep -v '/nineball/_core\..*\.so$') == "$expected" ]] ||
    fail "lib holds: $modules (expected the package nineball alone, in $site)"
  out=$(PYTHONPATH="$prefix/$site" "$python" -c 'import nineball
r = nineball.simulate({"balls": [{"id": 0, "x": 0, "y": 0}], "shot": {"heading_deg": 0, "speed": 1}})
print(nineball.__file__, r["end"])') || fail "the installed Python module did not run"
  [[ $out == "$prefix/$site/nineball/__init__.py rest" ]] || fail "the Python module said: $out"
fi
programs=$(cd "$prefix/bin" && echo *)
[[ $programs == "nineball nineball-game" ]] ||
  fail "bin holds: $programs (expected nineball and nineball-game only: no tests, no benchmarks)"

for f in share/icons/hicolor/256x256/apps/nineball.png share/icons/hicolor/64x64/apps/nineball.png \
  share/icons/hicolor/scalable/apps/nineball.svg share/applications/nineball.desktop \
  share/metainfo/io.github.nineball.metainfo.xml share/nineball/nineball-256.png \
  share/nineball/nineball-64.png share/nineball/nineball.svg share/nineball/nineball.desktop \
  share/nineball/io.github.nineball.metainfo.xml; do
  [[ -s $prefix/$f ]] || fail "missing or empty: $prefix/$f"
done

out=$("$prefix/bin/nineball" break --seed 7 --speed 12 </dev/null) || fail "nineball break exited $?"
if ! grep -q '^Break (seed 7, 12 m/s)$' <<<"$out" || ! grep -q '^Pocketed: ' <<<"$out" \
  || ! grep -q '^Simulated [0-9.]* s in [0-9]* steps' <<<"$out"; then
  fail "unexpected output of nineball break: $out"
fi

dir=$("$prefix/bin/nineball" --resource-dir </dev/null) || fail "nineball --resource-dir exited $?"
[[ $dir == "$prefix/share/nineball" ]] ||
  fail "the installed nineball finds its resources in $dir, not in $prefix/share/nineball"

# Without a display the window cannot open; nineball-game, started by nineball from beside
# itself, says so. Any other message means the launcher did not find it.
status=0
msg=$(env -u DISPLAY -u WAYLAND_DISPLAY "$prefix/bin/nineball" --mute 2>&1 </dev/null) || status=$?
[[ $status -eq 1 && $msg == *"no display found"* ]] ||
  fail "nineball without a display: exit status $status, \"$msg\" (expected nineball-game's \"no display found\")"

# The validators are optional (desktop-file-utils, appstream); check when they are there.
if command -v desktop-file-validate >/dev/null; then
  desktop-file-validate "$prefix/share/applications/nineball.desktop" ||
    fail "desktop-file-validate refused the desktop entry"
fi
if command -v appstreamcli >/dev/null; then
  appstreamcli validate --no-net "$prefix/share/metainfo/io.github.nineball.metainfo.xml" \
    >"$tmp/appstream.log" 2>&1 || {
    cat "$tmp/appstream.log" >&2
    fail "appstreamcli refused the metainfo"
  }
fi
echo "install test: ok ($prefix)"
