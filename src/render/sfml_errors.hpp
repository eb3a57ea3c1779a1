#pragma once

#include <sstream>
#include <streambuf>

namespace nineball::render {

/// While alive, sends SFML's error stream (sf::err()) to the "sfml" logger, one line per
/// message, rather than to stderr: SFML's own words ("Failed to save image", "Corrupt PNG")
/// would otherwise come before nineball's message about the same failure.
class SfmlErrorsToLog : public std::stringbuf {
 public:
  SfmlErrorsToLog();
  ~SfmlErrorsToLog() override;
  SfmlErrorsToLog(const SfmlErrorsToLog&) = delete;
  SfmlErrorsToLog& operator=(const SfmlErrorsToLog&) = delete;

 protected:
  int sync() override;

 private:
  std::streambuf* saved_;
};

}  // namespace nineball::render
