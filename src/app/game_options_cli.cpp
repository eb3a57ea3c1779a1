// The game window's options, parsed by nineball (which starts the window in nineball-game)
// and by nineball-game alike, so that both refuse the same things in the same words.
#include "app/game_options_cli.hpp"

#include <cctype>
#include <charconv>

#include "app/cli_checks.hpp"
#include "app/opponent.hpp"
#include "net/protocol.hpp"
#include "net/wire.hpp"
#include "nineball/games.hpp"

namespace nineball::app {
namespace {

// Smaller windows cannot hold the HUD's text; larger ones are beyond what GL textures hold.
constexpr unsigned kMinWidth = 320, kMinHeight = 240, kMaxSide = 8192;

// Reads WIDTHxHEIGHT; an empty answer when it is good, else what is wrong with it.
std::string parseSize(const std::string& text, unsigned& w, unsigned& h) {
  const auto x = text.find('x');
  const std::string form =
      "expected WIDTHxHEIGHT in pixels (e.g. 1280x800), found \"" + text + "\"";
  if (x == std::string::npos) return form;
  const char* b = text.data();
  const char* e = b + text.size();
  const auto [wend, wec] = std::from_chars(b, b + x, w);
  const auto [hend, hec] = std::from_chars(b + x + 1, e, h);
  if (wec != std::errc() || hec != std::errc() || wend != b + x || hend != e) return form;
  const std::string rule = " (the width must be " + std::to_string(kMinWidth) + "-" +
                           std::to_string(kMaxSide) + " and the height " +
                           std::to_string(kMinHeight) + "-" + std::to_string(kMaxSide) + ")";
  if (w < kMinWidth) return "width " + std::to_string(w) + " is too small" + rule;
  if (w > kMaxSide) return "width " + std::to_string(w) + " is too large" + rule;
  if (h < kMinHeight) return "height " + std::to_string(h) + " is too small" + rule;
  if (h > kMaxSide) return "height " + std::to_string(h) + " is too large" + rule;
  return "";
}

// The picture formats SFML writes, by the file name's extension.
std::string screenshotProblem(const std::string& name) {
  if (name.empty()) return "needs a file name";
  const auto dot = name.rfind('.');
  std::string ext = dot == std::string::npos ? "" : name.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* ok : {"png", "jpg", "jpeg", "bmp", "tga"}) {
    if (ext == ok) return "";
  }
  return "the file name must end in .png, .jpg, .jpeg, .bmp or .tga (the picture's format), "
         "found \"" +
         name + "\"";
}

}  // namespace

std::vector<CLI::Option*> addGameOptions(CLI::App& app, GameOptions& o) {
  std::vector<CLI::Option*> opts;
  opts.push_back(app.add_option("--game", o.game, "Game window: the game played")
                     ->check(CLI::IsMember(gameNames()))
                     ->each([&o](const std::string&) { o.game_given = true; })
                     ->capture_default_str());
  opts.push_back(app.add_option("--rules", o.rules,
                                "Game window: the rules (default: the game's own; paper: the seed "
                                "paper's, for " +
                                    gamesPlayedBy(rules::RuleSet::Paper) + ")")
                     ->check(CLI::IsMember({"wpa", "paper", "umb"}))
                     ->each([&o](const std::string&) { o.rules_given = true; })
                     ->capture_default_str());
  opts.push_back(
      app.add_option("--seed", o.seed,
                     "Game window: the racks and the computer's cueing errors (default: a new "
                     "seed for each game a person plays; 1 for --screenshot, --frames and scripts)")
          ->check(seedCheck())
          ->each([&o](const std::string&) { o.seed_given = true; })
          ->capture_default_str());
  opts.push_back(app.add_option("--opponent", o.opponent,
                                "Game window: who plays Player 2, a second person (human) or the "
                                "computer at a level (O switches in the window)")
                     ->check(CLI::IsMember(seatNames()))
                     ->each([&o](const std::string&) { o.opponent_given = true; })
                     ->capture_default_str());
  opts.push_back(app.add_flag("--mute", o.mute, "Game window: no sound"));
  opts.push_back(app.add_flag("--fullscreen", o.fullscreen, "Game window: start in full screen"));
  opts.push_back(app.add_flag("--menu", o.menu,
                              "Game window: show the start menu (shown anyway unless --screenshot, "
                              "--script or --frames is given)"));
  opts.push_back(
      app.add_option("--screenshot", o.screenshot,
                     "Draw the scene into this picture file (.png, .jpg, .bmp or .tga) and exit")
          ->check(screenshotProblem));
  auto* script = app.add_option("--script", o.script,
                                "Play this match script (as nineball match does) before the "
                                "first frame; - reads standard input");
  opts.push_back(script);
  opts.push_back(app.add_flag("--practice", o.practice,
                              "Game window: practice alone without rules (place, add and remove "
                              "balls; undo or retry a shot)"));
  opts.push_back(app.add_flag("--replay", o.replay,
                              "Game window: after --script, replay its last shot from the physics "
                              "(with --frames and --screenshot, a picture of the replay)"));
  opts.push_back(app.add_flag("--watch", o.watch,
                              "Game window: play --script's turns on screen one after another, "
                              "as they were played (a rack saved with F5 watched again)")
                     ->needs(script));
  opts.push_back(app.add_option_function<long>(
                        "--frames", [&o](long n) { o.frames = n; },
                        "Run N frames, then capture (--screenshot) or exit; without --script the "
                        "opening break is shot at the first frame")
                     ->check(CLI::Range(1L, 100000000L)));
  opts.push_back(app.add_option_function<std::string>(
      "--size",
      [&o](const std::string& s) {
        const std::string problem = parseSize(s, o.width, o.height);
        if (!problem.empty()) throw CLI::ValidationError("--size", problem);
        o.size_given = true;
      },
      "Window size in pixels, WIDTHxHEIGHT (default 1280x800)"));
  auto* host = app.add_option_function<std::vector<std::string>>(
                      "--host",
                      [&o](const std::vector<std::string>& v) {
                        o.host_port = net::kDefaultPort;
                        if (v.empty() || v.front().empty()) return;
                        std::string why;
                        const auto port = net::parsePort(v.front(), why);
                        if (!port) throw CLI::ValidationError("--host", why);
                        o.host_port = *port;
                      },
                      "Play online: wait for a friend to join, listening on PORT (default " +
                          std::to_string(net::kDefaultPort) + ")")
                   ->expected(0, 1)
                   ->allow_extra_args(false);
  opts.push_back(host);
  auto* join = app.add_option_function<std::string>(
                      "--join",
                      [&o](const std::string& text) {
                        std::string why;
                        if (!net::parseAddress(text, why))
                          throw CLI::ValidationError("--join", why);
                        o.join = text;
                      },
                      "Play online: join the friend hosting at HOST[:PORT] (the code their window "
                      "shows)")
                   ->type_name("HOST[:PORT]");
  opts.push_back(join);
  host->excludes(join);
  opts.push_back(app.add_option_function<std::string>(
                        "--code",
                        [&o](const std::string& text) {
                          if (text.size() > net::kMostCodeChars) {
                            throw CLI::ValidationError(
                                "--code", "longer than " + std::to_string(net::kMostCodeChars) +
                                              " characters");
                          }
                          o.code = text;
                        },
                        "Play online: the join code (the host's is made at random when not "
                        "given; the joiner gives the one the host's window shows)")
                     ->type_name("CODE"));
  opts.push_back(app.add_option_function<std::string>(
      "--name",
      [&o](const std::string& n) {
        if (n.empty()) throw CLI::ValidationError("--name", "needs a name");
        o.name = n;
      },
      "Game window: your name, shown to both players online (else the name "
      "the start menu remembers)"));
  return opts;
}

}  // namespace nineball::app
