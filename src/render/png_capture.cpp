#include "render/png_capture.hpp"

#include <SFML/Graphics/Image.hpp>
#include <SFML/Graphics/Texture.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace nineball::render {

bool saveWindowPng(const sf::RenderWindow& window, const std::string& path, std::string& why) {
  sf::Texture texture;
  if (!texture.create(window.getSize().x, window.getSize().y)) {
    why = "cannot create a texture of the window's size";
    return false;
  }
  texture.update(window);
  const sf::Image image = texture.copyToImage();
  // SFML picks the format from the extension, so the temporary file ends in .png too.
  const std::string tmp = path + ".tmp.png";
  if (!image.saveToFile(tmp)) {
    std::remove(tmp.c_str());
    why = "cannot write " + tmp;
    return false;
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    why = "cannot rename " + tmp + " to " + path + ": " + std::strerror(errno);
    std::remove(tmp.c_str());
    return false;
  }
  return true;
}

}  // namespace nineball::render
