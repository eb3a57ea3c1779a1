#include "window/window_icon.hpp"

#include <SFML/Graphics/Image.hpp>
#include <string>

#include "app/resource_dir.hpp"
#include "common/log.hpp"

namespace nineball::window {

void setWindowIcon(sf::Window& window) {
  const auto dir = app::findResourceDir();
  if (!dir) {
    logger("game")->warn("no resource folder holding {} found; the window has no icon",
                         app::kIconFile);
    return;
  }
  const std::string path = *dir + "/" + app::kIconFile;
  sf::Image icon;
  // sf::Image says only "failed" on SFML's error stream; the warning names the file.
  if (!icon.loadFromFile(path)) {
    logger("game")->warn("cannot read the window icon {}; the window has no icon", path);
    return;
  }
  window.setIcon(icon.getSize().x, icon.getSize().y, icon.getPixelsPtr());
}

}  // namespace nineball::window
