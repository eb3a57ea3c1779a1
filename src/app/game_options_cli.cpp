// The game window's options, parsed by nineball (which starts the window in nineball-game)
// and by nineball-game alike, so that both refuse the same things in the same words.
#include <charconv>

#include "app/cli_checks.hpp"
#include "app/game/opponent.hpp"
#include "app/game_command.hpp"

namespace nineball::app {
namespace {

bool parseSize(const std::string& text, unsigned& w, unsigned& h) {
  const auto x = text.find('x');
  if (x == std::string::npos) return false;
  const char* b = text.data();
  const char* e = b + text.size();
  const auto [wend, wec] = std::from_chars(b, b + x, w);
  const auto [hend, hec] = std::from_chars(b + x + 1, e, h);
  return wec == std::errc() && hec == std::errc() && wend == b + x && hend == e && w >= 200 &&
         h >= 150 && w <= 8192 && h <= 8192;
}

}  // namespace

std::vector<CLI::Option*> addGameOptions(CLI::App& app, GameOptions& o) {
  std::vector<CLI::Option*> opts;
  opts.push_back(app.add_option("--rules", o.rules, "Game window: rules of nine-ball")
                     ->check(CLI::IsMember({"wpa", "paper"}))
                     ->capture_default_str());
  opts.push_back(
      app.add_option("--seed", o.seed,
                     "Game window: rack order of balls 2-8, and the computer's cueing errors")
          ->check(seedCheck())
          ->capture_default_str());
  opts.push_back(app.add_option("--opponent", o.opponent,
                                "Game window: who plays Player 2, a second person (human) or the "
                                "computer at a level (O switches in the window)")
                     ->check(CLI::IsMember(opponentNames()))
                     ->capture_default_str());
  opts.push_back(app.add_flag("--mute", o.mute, "Game window: no sound"));
  opts.push_back(app.add_flag("--fullscreen", o.fullscreen, "Game window: start in full screen"));
  opts.push_back(app.add_flag("--menu", o.menu,
                              "Game window: show the start menu (shown anyway unless --screenshot, "
                              "--script or --frames is given)"));
  opts.push_back(
      app.add_option("--screenshot", o.screenshot, "Draw the scene into this PNG file and exit")
          ->check([](const std::string& name) {
            return name.empty() ? std::string("needs a file name") : std::string();
          }));
  opts.push_back(app.add_option("--script", o.script,
                                "Play this match script (as nineball match does) before the "
                                "first frame; - reads standard input"));
  opts.push_back(app.add_option_function<long>(
                        "--frames", [&o](long n) { o.frames = n; },
                        "Run N frames, then capture (--screenshot) or exit; without --script the "
                        "opening break is shot at the first frame")
                     ->check(CLI::Range(1L, 100000000L)));
  opts.push_back(app.add_option_function<std::string>(
      "--size",
      [&o](const std::string& s) {
        if (!parseSize(s, o.width, o.height)) {
          throw CLI::ValidationError("--size", "expected WIDTHxHEIGHT, found " + s);
        }
        o.size_given = true;
      },
      "Window size in pixels, WIDTHxHEIGHT (default 1280x800)"));
  return opts;
}

}  // namespace nineball::app
