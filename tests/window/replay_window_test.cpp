// The replay in the real game window under Xvfb, pressed as a player presses it: a rack with
// fouls played to its end from a script, then Shift+V. The replay must play (the pictures
// change while it runs, idle or not), and the game must still be running afterwards and quit
// cleanly when asked.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <variant>

#include "io/match_json.hpp"
#include "nineball/match.hpp"
#include "nineball/planner.hpp"
#include "support/file_text.hpp"

namespace nineball {
namespace {

using nineball::testing::fileText;

using nlohmann::json;

void pause(double seconds) {
  std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
}

json scriptTurn(const TurnInput& t) {
  if (t.kind == TurnInput::Kind::Decision) return {{"decision", t.shoot ? "shoot" : "pass"}};
  json turn = {{"heading_deg", radToDeg(t.shot.heading_rad)},
               {"speed", t.shot.speed},
               {"tip", {t.shot.tip.x, t.shot.tip.y}},
               {"elevation_deg", radToDeg(t.shot.elevation_rad)}};
  if (t.cue) turn["cue"] = {t.cue->x, t.cue->y};
  if (t.kind == TurnInput::Kind::PushOut) turn["push_out"] = true;
  return turn;
}

// The turn as the window's --script reads it back (the degrees' round trip included).
TurnInput asScripted(const json& turn) {
  const auto parsed = io::parseMatchScript(json{{"turns", {turn}}}.dump());
  return std::get<io::MatchScript>(parsed).turns.at(0);
}

// A nine-ball rack between two easy computers, written as a script: the first seed whose
// rack has a foul and ends within 200 turns.
std::string rackWithFouls() {
  for (std::uint64_t seed = 1; seed < 50; ++seed) {
    MatchSetup setup;
    setup.seed = seed;
    Match match(setup);
    ai::Planner planner(ai::Level::Casual, seed, 1);
    json turns = json::array();
    int fouls = 0;
    while (!match.rack().over() && turns.size() < 200) {
      const json turn = scriptTurn(planner.turnFor(match));
      fouls += match.play(asScripted(turn)).verdict.legal() ? 0 : 1;
      turns.push_back(turn);
    }
    if (match.rack().over() && fouls > 0) {
      return json{{"seed", seed}, {"turns", turns}}.dump();
    }
  }
  return {};
}

class XvfbGame {
 public:
  XvfbGame(const std::string& dir, const std::string& args) : dir_(dir), args_(args) {
    start(dir, args);
  }
  // Now and then, with other Xvfb tests starting beside it, the game has found no display on a
  // server xdpyinfo had just reached (about once in four runs of the whole suite; once more
  // after two quick restarts in a row): the server and the game are then started again, up to
  // five times, a second apart so that whatever the other tests' servers were doing is over.
  // True when it did so.
  bool restartAfterNoDisplay() {
    if (running() || restarts_ >= kMaxRestarts) return false;
    if (fileText(dir_ + "/err.log").find("no display found") == std::string::npos) return false;
    ++restarts_;
    stop();
    pause(1.0);
    start(dir_, args_);
    return true;
  }
  void start(const std::string& dir, const std::string& args) {
    exited_ = false;
    display_ = -1;
    // Xvfb picks a free display itself and says which (-displayfd): the other Xvfb tests,
    // run at the same time, choose theirs by number, and a number chosen here could meet one.
    const std::string said = dir + "/display";
    std::remove(said.c_str());
    xvfb_ = spawn("exec Xvfb -displayfd 3 -screen 0 1280x800x24 -nolisten tcp 3>'" + said +
                  "' 2>/dev/null");
    for (int i = 0; i < 600 && display_ < 0; ++i) {
      const std::string text = fileText(said);
      if (!text.empty() && text.back() == '\n') display_ = std::stoi(text);
      if (display_ < 0) pause(0.1);
    }
    for (int i = 0;
         i < 100 && display_ >= 0 && std::system(x("xdpyinfo >/dev/null 2>&1").c_str()) != 0; ++i) {
      pause(0.1);
    }
    // Under LeakSanitizer the software GL driver leaks a little from code it cannot name:
    // such leaks do not fail the run (as the other Xvfb tests).
    game_ =
        spawn("cd '" + dir + "' && LSAN_OPTIONS=\"${LSAN_OPTIONS:+$LSAN_OPTIONS:}exitcode=0\" " +
              x("exec '" + std::string(NINEBALL_BINARY) + "' " + args + " 2>err.log"));
  }
  void stop() {
    if (game_ > 0 && running()) kill(game_, SIGKILL);
    if (game_ > 0) waitpid(game_, nullptr, 0);
    kill(xvfb_, SIGTERM);
    waitpid(xvfb_, nullptr, 0);
    game_ = -1;
  }
  ~XvfbGame() { stop(); }

  // The command run against this display.
  std::string x(const std::string& cmd) const {
    return "DISPLAY=:" + std::to_string(display_) + " " + cmd;
  }
  int run(const std::string& cmd) const { return std::system(x(cmd).c_str()); }
  bool running() {
    if (exited_) return false;
    int status = 0;
    if (waitpid(game_, &status, WNOHANG) == game_) {
      exited_ = true;
      status_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    return !exited_;
  }
  // Waits up to `seconds` for the game to end; its exit status, or -1 if it is still running.
  int waitExit(double seconds) {
    for (int i = 0; i < seconds * 10 && running(); ++i) pause(0.1);
    return running() ? -1 : status_;
  }

 private:
  static pid_t spawn(const std::string& cmd) {
    const pid_t pid = fork();
    if (pid == 0) {
      setpgid(0, 0);
      execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    return pid;
  }

  std::string dir_, args_;
  static constexpr int kMaxRestarts = 5;
  int restarts_ = 0;
  int display_ = -1;
  pid_t xvfb_ = -1;
  pid_t game_ = -1;
  bool exited_ = false;
  int status_ = -1;
};

TEST(ReplayWindow, ShiftVAtTheEndOfARackWithFoulsPlaysTheReplayAndTheGameGoesOn) {
  for (const char* tool : {"Xvfb", "xdotool", "xwd", "xdpyinfo"}) {
    ASSERT_EQ(std::system(("command -v " + std::string(tool) + " >/dev/null").c_str()), 0)
        << tool << " not found: bash scripts/setup.sh installs it";
  }
  const std::string script = rackWithFouls();
  ASSERT_FALSE(script.empty()) << "no seed gave a finished rack with a foul";
  char dir_template[] = "/tmp/nineball-replay-XXXXXX";
  const std::string dir = mkdtemp(dir_template);
  std::ofstream(dir + "/rack.json") << script;

  XvfbGame game(dir, "--mute --size 1280x800 --log-level info --script rack.json");
  // The window is up once it can be found; the rack's turns are played before it opens, which on
  // a machine loaded by the other tests (the stress test beside it, under the sanitizers) has
  // taken over 30 s: it is given two minutes, and a game that ends first fails at once.
  std::string window;
  for (int i = 0; i < 1200 && window.empty() && (game.running() || game.restartAfterNoDisplay());
       ++i) {
    const std::string ids = dir + "/ids";
    game.run("xdotool search --name '^nineball' >'" + ids + "' 2>/dev/null");
    std::istringstream(fileText(ids)) >> window;
    if (window.empty()) pause(0.1);
  }
  ASSERT_FALSE(window.empty()) << fileText(dir + "/err.log");
  pause(1.0);
  ASSERT_TRUE(game.running()) << fileText(dir + "/err.log");
  game.run("xdotool windowfocus " + window + " 2>/dev/null");
  game.run("xdotool mousemove --window " + window + " 640 400");

  // Shift+V: the last shot at a quarter speed, so it is still playing over the next seconds.
  ASSERT_EQ(game.run("xdotool key --window " + window + " shift+v"), 0);
  pause(0.3);
  // An idle window redraws only every 2 s: a replay that does not play changes the picture at
  // most twice in these 3 s, one that plays changes it between almost every two looks (the
  // software renderer draws well over 10 frames a second even on a loaded machine).
  constexpr int kLooks = 10;
  int changes = 0;
  std::string last;
  for (int i = 0; i < kLooks; ++i) {
    const std::string file = dir + "/frame.xwd";
    ASSERT_EQ(game.run("xwd -root -silent >'" + file + "'"), 0);
    const std::string picture = fileText(file);
    if (i > 0 && picture != last) ++changes;
    last = picture;
    pause(0.3);
  }
  EXPECT_GE(changes, 5) << "the replay does not play: " << changes << " changes in " << kLooks
                        << " looks";
  ASSERT_TRUE(game.running()) << fileText(dir + "/err.log");

  // The replay is let run to its end (on a loaded machine it may already be over, and the keys
  // below would then mean something else): the picture still for a second, within 60 s.
  for (int still = 0, i = 0; still < 4 && i < 240; ++i) {
    const std::string file = dir + "/frame.xwd";
    ASSERT_EQ(game.run("xwd -root -silent >'" + file + "'"), 0);
    const std::string picture = fileText(file);
    still = picture == last ? still + 1 : 0;
    last = picture;
    pause(0.25);
  }
  // Escape then asks to quit, and Y quits.
  game.run("xdotool key --window " + window + " Escape");
  pause(0.5);
  game.run("xdotool key --window " + window + " y");
  EXPECT_EQ(game.waitExit(20.0), 0) << fileText(dir + "/err.log");
  const std::string log = fileText(dir + "/err.log");
  EXPECT_EQ(log.find("internal error"), std::string::npos) << log;
  if (log.find("LeakSanitizer") != std::string::npos) {
    EXPECT_EQ(log.find("nineball::"), std::string::npos) << log;
  }
  std::system(("rm -rf '" + dir + "'").c_str());
}

}  // namespace
}  // namespace nineball
