#pragma once

#include <SFML/Graphics/Font.hpp>
#include <optional>
#include <string>

namespace nineball::render {

/// DejaVu Sans from Debian's fonts-dejavu-core.
constexpr const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr const char* kBoldFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";

/// The HUD's font and the bold one for ball numbers.
struct Fonts {
  sf::Font regular;
  sf::Font bold;
};

/// Loads both fonts; on failure returns nothing and says which file is missing in `why`.
std::optional<Fonts> loadFonts(std::string& why);

}  // namespace nineball::render
