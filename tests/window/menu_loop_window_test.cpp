// The start menu and F2's settings on the window's one event loop (screens over the table),
// played by keys under Xvfb as a person plays them: the menu that opens the game, Enter's game,
// F2's settings over it and F2 back to the same table, Esc's menu (the same picture as the first)
// and Enter back to the same table, Esc's menu again and Esc on it to quit with status 0.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/xvfb_run.hpp"

namespace nineball::window {
namespace {

// Polls the screen (xwd) until `cond` holds for the picture now in `$cur`, for at most 30 s: a
// loaded machine draws slowly, but an idle window draws a picture once and keeps it.
constexpr const char* kScript = R"(#!/bin/bash
dir=$1; game=$2
cd "$dir" || exit 90
XDG_CONFIG_HOME=$dir/config XDG_STATE_HOME=$dir/state "$game" --mute --size 960x600 --seed 1 &
pid=$!
win=
for i in $(seq 1 300); do
  win=$(xdotool search --name '^nineball' 2>/dev/null | head -1)
  [ -n "$win" ] && break
  sleep 0.1
done
[ -n "$win" ] || { echo "no window" >&2; exit 91; }
# The picture once it has stayed the same for half a second, into $1.xwd.
settled() {
  local last= same=0
  for i in $(seq 1 300); do
    xwd -root -silent >cur.xwd
    if [ -n "$last" ] && cmp -s cur.xwd "$last"; then same=$((same + 1)); else same=0; fi
    cp cur.xwd prev.xwd; last=prev.xwd
    [ $same -ge 5 ] && { cp cur.xwd "$1.xwd"; return 0; }
    sleep 0.1
  done
  echo "$1: the picture never settled" >&2; exit 92
}
# Waits until the picture is $1.xwd again.
again() {
  for i in $(seq 1 300); do
    xwd -root -silent >cur.xwd
    cmp -s cur.xwd "$1.xwd" && return 0
    sleep 0.1
  done
  echo "$2: not the picture $1 again" >&2; exit 93
}
# Waits until the picture is no longer $1.xwd.
changed() {
  for i in $(seq 1 300); do
    xwd -root -silent >cur.xwd
    cmp -s cur.xwd "$1.xwd" || return 0
    sleep 0.1
  done
  echo "$2: the picture stayed $1" >&2; exit 94
}
xdotool mousemove --window "$win" 5 5
settled menu
xdotool key --window "$win" Return; changed menu "Enter on Play"; settled table
xdotool key --window "$win" F2; changed table "F2"; settled settings
xdotool key --window "$win" F2; again table "F2 again"
xdotool key --window "$win" Escape; again menu "Esc at the table"
xdotool key --window "$win" Return; again table "Enter on Play again"
# The menu once more; the table behind it may have moved on with the clock (the HUD's message),
# and only the menu quits on Esc (the table's Esc opens the menu).
xdotool key --window "$win" Escape; changed table "Esc at the table again"; settled menu2
xdotool key --window "$win" Escape
for i in $(seq 1 300); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
kill -0 $pid 2>/dev/null && { echo "Esc on the menu did not quit" >&2; kill $pid; exit 95; }
wait $pid
)";

TEST(MenuLoopWindow, TheMenuAndTheSettingsComeAndGoOverTheSameTable) {
  ASSERT_TRUE(testing::haveXvfbRun())
      << "xvfb-run not found: install xvfb and xauth (bash scripts/setup.sh)";
  for (const char* tool : {"xdotool", "xwd"}) {
    ASSERT_EQ(std::system(("command -v " + std::string(tool) + " >/dev/null").c_str()), 0)
        << tool << " not found: bash scripts/setup.sh installs it";
  }
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("nineball-menu-loop-" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "keys.sh") << kScript;
  const testing::XvfbRun run = testing::runUnderXvfb(
      "bash " + testing::shellWord((dir / "keys.sh").string()) + " " +
          testing::shellWord(dir.string()) + " " + testing::shellWord(NINEBALL_BINARY),
      960, 600);
  EXPECT_EQ(run.status, 0) << run.err;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace nineball::window
