#include "render/sfml_errors.hpp"

#include <SFML/System/Err.hpp>
#include <string>

#include "common/log.hpp"

namespace nineball::render {

SfmlErrorsToLog::SfmlErrorsToLog() : saved_(sf::err().rdbuf(this)) {}

SfmlErrorsToLog::~SfmlErrorsToLog() {
  sync();
  sf::err().rdbuf(saved_);
}

int SfmlErrorsToLog::sync() {
  std::istringstream lines(str());
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty()) logger("sfml")->info("{}", line);
  }
  str("");
  return 0;
}

}  // namespace nineball::render
