#include "app/game_command.hpp"

#include <charconv>
#include <istream>
#include <ostream>

#include "app/exit_codes.hpp"
#include "app/game/game_window.hpp"
#include "app/game/opponent.hpp"
#include "app/read_input.hpp"
#include "io/match_json.hpp"

namespace nineball::app {
namespace {

// CLI11 alone would wrap -1 round to 2^64 - 1.
const CLI::Validator kSeedCheck(
    [](std::string& value) -> std::string {
      std::uint64_t v = 0;
      const char* end = value.data() + value.size();
      const auto [stop, ec] = std::from_chars(value.data(), end, v);
      if (ec == std::errc() && stop == end) return {};
      return "must be an integer from 0 to 2^64 - 1, found " + value;
    },
    "0..2^64-1");

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
          ->check(kSeedCheck)
          ->capture_default_str());
  opts.push_back(app.add_option("--opponent", o.opponent,
                                "Game window: who plays Player 2, a second person (human) or the "
                                "computer at a level (O switches in the window)")
                     ->check(CLI::IsMember(opponentNames()))
                     ->capture_default_str());
  opts.push_back(app.add_flag("--mute", o.mute, "Game window: no sound"));
  opts.push_back(app.add_flag("--fullscreen", o.fullscreen, "Game window: start in full screen"));
  opts.push_back(
      app.add_option("--screenshot", o.screenshot, "Draw the scene into this PNG file and exit"));
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

int runGameCommand(const GameOptions& options, std::istream& in, std::ostream& err) {
  GameStart start;
  start.setup.rules = *rules::ruleSetFromName(options.rules);
  start.setup.seed = options.seed;
  if (!options.script.empty()) {
    start.script_name = shownPath(options.script);
    const std::string prefix = "nineball: " + start.script_name + ": ";
    std::string why;
    const auto text = readInput(options.script, in, why);
    if (!text) {
      err << prefix << why << '\n';
      return kExitBadInput;
    }
    auto parsed = io::parseMatchScript(*text);
    if (const auto* refused = std::get_if<io::ParseError>(&parsed)) {
      err << prefix << refused->message << '\n';
      return kExitBadInput;
    }
    auto& script = std::get<io::MatchScript>(parsed);
    start.setup = script.setup;
    start.turns = std::move(script.turns);
  }
  return runGame(options, start, err);
}

}  // namespace nineball::app
