#include "render/fonts.hpp"

#include <fstream>

namespace nineball::render {

std::optional<Fonts> loadFonts(std::string& why) {
  Fonts fonts;
  for (auto [path, font] : {std::pair{kFontPath, &fonts.regular}, {kBoldFontPath, &fonts.bold}}) {
    // sf::Font only says "failed" on stderr; check the file first to give the reason.
    if (!std::ifstream(path)) {
      why = std::string("font not found: ") + path +
            " (install Debian's fonts-dejavu-core, e.g. bash scripts/setup.sh)";
      return std::nullopt;
    }
    if (!font->loadFromFile(path)) {
      why = std::string("cannot read the font ") + path;
      return std::nullopt;
    }
  }
  return fonts;
}

}  // namespace nineball::render
