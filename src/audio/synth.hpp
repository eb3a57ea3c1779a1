#pragma once

#include <cstdint>
#include <vector>

namespace nineball::audio {

/// Sample rate of the synthesized sounds (mono, 16-bit).
constexpr unsigned kSampleRate = 44100;

/// Two phenolic balls meeting: a short bright click.
std::vector<std::int16_t> synthClick();
/// A ball into a rubber cushion: a dull low thud.
std::vector<std::int16_t> synthThud();
/// The cue's leather tip on the cue ball: a soft knock, lower and shorter than a ball click.
std::vector<std::int16_t> synthCueStrike();
/// A ball dropping into a pocket: a knock on the jaw, a rattle, a low roll away.
std::vector<std::int16_t> synthPocketDrop();

}  // namespace nineball::audio
