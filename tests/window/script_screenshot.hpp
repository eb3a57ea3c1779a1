#pragma once

// The game window's picture after it plays a match script, for the tests that read its pixels.
#include <unistd.h>

#include <SFML/Graphics/Image.hpp>
#include <cstdio>
#include <fstream>
#include <string>

#include "support/xvfb_run.hpp"

namespace nineball::testing {

/// Writes `script` (a `nineball match` script) to a file of its own, runs the game on it under
/// Xvfb at width x height with --screenshot, and loads the picture into `image`. The run's
/// status and stderr come back; the files are removed.
inline XvfbRun screenshotOfScript(const std::string& script, const std::string& tag, unsigned width,
                                  unsigned height, sf::Image& image) {
  const std::string stem = "/tmp/nineball-test-" + tag + "-" + std::to_string(getpid());
  {
    std::ofstream out(stem + ".json");
    out << script;
  }
  XvfbRun run = runGameUnderXvfb("--script '" + stem + ".json' --screenshot '" + stem + ".png'",
                                 width, height);
  if (run.status == 0 && !image.loadFromFile(stem + ".png")) {
    run.status = -1;
    run.err += "\nno picture at " + stem + ".png";
  }
  std::remove((stem + ".png").c_str());
  std::remove((stem + ".json").c_str());
  return run;
}

}  // namespace nineball::testing
