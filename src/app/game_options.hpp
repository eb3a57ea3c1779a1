#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "nineball/games.hpp"

namespace nineball::app {

/// Options of the game window (`nineball` with no subcommand).
struct GameOptions {
  std::string game = defaultGame().name;  ///< a game of the registry (nineball/games.hpp)
  std::string rules = "wpa";              ///< wpa | paper (the games GameDef::rule_sets allows)
  std::uint64_t seed = 1;          ///< rack order of balls 2-8, and the computer's cueing errors
  std::string opponent = "human";  ///< Player 2: human or ai:<level> (seatNames)
  bool mute = false;               ///< no sound at all
  bool fullscreen = false;         ///< start in full screen
  std::string screenshot;          ///< draw, save this PNG and exit
  std::string script;              ///< a match script played before the first frame
  std::optional<long> frames;      ///< run this many frames, then capture (or exit)
  bool replay = false;             ///< after the script, replay its last shot
  bool watch = false;              ///< the script's turns played on screen, one after another
  bool practice = false;           ///< practice mode: no rules, any ball anywhere, undo
  unsigned width = 1280;           ///< window size in pixels
  unsigned height = 800;
  bool size_given = false;  ///< --size was given (else the desktop may shrink it)
  bool menu = false;        ///< show the start menu even with --screenshot / --frames
  // Given on the command line (a default value too): they then win over the remembered menu.
  bool game_given = false;
  bool rules_given = false;
  bool opponent_given = false;
  bool seed_given = false;  ///< else a person's games draw fresh seeds (window/rack_seed.hpp)
  // Online play (docs/playing.md, "Playing online"): host on a port, or join a host.
  std::optional<unsigned short> host_port;  ///< --host [PORT]: wait for a friend on this port
  std::string join;                         ///< --join HOST[:PORT]: play the host there
  std::string code;                         ///< --code: the join code (host: made when empty)
  std::string name;                         ///< --name: this player's name (else the settings')
};

}  // namespace nineball::app
