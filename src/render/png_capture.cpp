#include "render/png_capture.hpp"

#include <SFML/Graphics/Image.hpp>
#include <SFML/Graphics/Texture.hpp>

#include "common/atomic_file.hpp"
#include "render/sfml_errors.hpp"

namespace nineball::render {

bool saveWindowPng(const sf::RenderWindow& window, const std::string& path, std::string& why) {
  sf::Texture texture;
  if (!texture.create(window.getSize().x, window.getSize().y)) {
    why = "cannot create a texture of the window's size";
    return false;
  }
  texture.update(window);
  return saveImage(texture.copyToImage(), path, why);
}

bool saveImage(const sf::Image& image, const std::string& path, std::string& why) {
  const SfmlErrorsToLog quiet;
  // SFML reports no short write, so the file is read back before it takes the name asked for.
  // SFML picks the format from the extension, so the temporary file ends as the name does.
  const auto slash = path.rfind('/');
  const auto dot = path.rfind('.');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  const std::string ext = has_ext ? path.substr(dot) : ".png";
  return writeFileAtomicallyWith(
      path, ext, [&image](const std::string& tmp) { return image.saveToFile(tmp); },
      [&image](const std::string& tmp) {
        sf::Image back;
        return back.loadFromFile(tmp) && back.getSize() == image.getSize();
      },
      why);
}

}  // namespace nineball::render
