#pragma once

#include <SFML/Graphics/RenderWindow.hpp>
#include <string>

namespace nineball::render {

/// Saves what the window shows now (its back buffer, before display) as a PNG. The file is
/// written whole or not at all (nineball/atomic_file.hpp). False with `why` on failure.
bool saveWindowPng(const sf::RenderWindow& window, const std::string& path, std::string& why);

}  // namespace nineball::render
