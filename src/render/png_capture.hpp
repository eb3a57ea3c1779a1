#pragma once

#include <SFML/Graphics/Image.hpp>
#include <SFML/Graphics/RenderWindow.hpp>
#include <string>

namespace nineball::render {

/// Saves what the window shows now (its back buffer, before display) as a PNG. The file is
/// written whole or not at all (nineball/atomic_file.hpp). False with `why` on failure.
bool saveWindowPng(const sf::RenderWindow& window, const std::string& path, std::string& why);

/// Saves an image in the format its name ends with (PNG when it has none), whole or not at
/// all: written to a temporary file, read back, then renamed (nineball/atomic_file.hpp).
/// SFML's own error lines go to the log; `why` says what failed.
bool saveImage(const sf::Image& image, const std::string& path, std::string& why);

}  // namespace nineball::render
