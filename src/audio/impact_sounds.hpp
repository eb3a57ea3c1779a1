#pragma once

#include <SFML/Audio/Sound.hpp>
#include <SFML/Audio/SoundBuffer.hpp>
#include <array>
#include <memory>
#include <vector>

#include "audio/impact.hpp"

namespace nineball::audio {

/// The table's sounds: clicks, thuds and pocket drops synthesized in code, played on a small
/// pool of voices, each as loud as its impact.
class ImpactSounds {
 public:
  /// Opens the audio device and builds the sounds; nothing when there is no device (the game
  /// then plays silently). SFML's and OpenAL's complaints are kept off the terminal.
  static std::unique_ptr<ImpactSounds> open();

  /// Plays the loudest few of one frame's impacts.
  void play(std::vector<Impact> impacts);
  /// How loud the sounds are, 0 (silent) to 100 % of their full loudness.
  static void setVolume(double percent);

 private:
  ImpactSounds() = default;
  sf::SoundBuffer& buffer(ImpactKind kind);

  sf::SoundBuffer click_;
  sf::SoundBuffer thud_;
  sf::SoundBuffer drop_;
  sf::SoundBuffer strike_;
  std::array<sf::Sound, 16> voices_;
  std::size_t next_voice_ = 0;
};

}  // namespace nineball::audio
