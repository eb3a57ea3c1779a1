#include "audio/impact_sounds.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <SFML/Audio/Listener.hpp>
#include <SFML/System/Err.hpp>
#include <algorithm>
#include <sstream>

#include "audio/synth.hpp"
#include "common/log.hpp"

namespace nineball::audio {
namespace {

// Sounds started in one frame at most: a break's dozens of contacts would only be noise.
constexpr std::size_t kMaxPerFrame = 5;
constexpr float kMasterVolume = 45.0f;

// Sends stderr (ALSA and OpenAL write there directly) and sf::err() away while alive.
class QuietStderr {
 public:
  QuietStderr() : saved_fd_(dup(STDERR_FILENO)), saved_buf_(sf::err().rdbuf(sfml_.rdbuf())) {
    const int null_fd = ::open("/dev/null", O_WRONLY);
    if (null_fd >= 0) {
      dup2(null_fd, STDERR_FILENO);
      close(null_fd);
    }
  }
  ~QuietStderr() {
    if (saved_fd_ >= 0) {
      dup2(saved_fd_, STDERR_FILENO);
      close(saved_fd_);
    }
    sf::err().rdbuf(saved_buf_);
  }
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;
  std::string sfmlSaid() const { return sfml_.str(); }

 private:
  std::ostringstream sfml_;
  int saved_fd_;
  std::streambuf* saved_buf_;
};

bool load(sf::SoundBuffer& buffer, const std::vector<std::int16_t>& samples) {
  return buffer.loadFromSamples(samples.data(), samples.size(), 1, kSampleRate);
}

}  // namespace

std::unique_ptr<ImpactSounds> ImpactSounds::open() {
  std::unique_ptr<ImpactSounds> sounds;
  std::string said;
  bool loaded = false;
  {
    // The device opens with the first sound object, so everything is made in here.
    QuietStderr quiet;
    sounds.reset(new ImpactSounds());
    loaded = load(sounds->click_, synthClick()) && load(sounds->thud_, synthThud()) &&
             load(sounds->drop_, synthPocketDrop()) && load(sounds->strike_, synthCueStrike());
    said = quiet.sfmlSaid();
  }
  if (!loaded || said.find("Failed to open the audio device") != std::string::npos ||
      said.find("internal OpenAL call failed") != std::string::npos) {
    logger("audio")->info("no audio device: the game plays silently");
    QuietStderr quiet;  // the buffers' destructors complain too
    sounds.reset();
    return nullptr;
  }
  // Headroom: a break starts several full-volume clicks in the same instant.
  sf::Listener::setGlobalVolume(kMasterVolume);
  logger("audio")->info("sound on");
  return sounds;
}

void ImpactSounds::setVolume(double percent) {
  const double f = std::clamp(percent, 0.0, 100.0) / 100.0;
  sf::Listener::setGlobalVolume(static_cast<float>(kMasterVolume * f));
}

sf::SoundBuffer& ImpactSounds::buffer(ImpactKind kind) {
  switch (kind) {
    case ImpactKind::Cushion:
      return thud_;
    case ImpactKind::Pocket:
      return drop_;
    case ImpactKind::Cue:
      return strike_;
    case ImpactKind::Ball:
      break;
  }
  return click_;
}

void ImpactSounds::play(std::vector<Impact> impacts) {
  std::sort(impacts.begin(), impacts.end(),
            [](const Impact& a, const Impact& b) { return impactVolume(a) > impactVolume(b); });
  for (std::size_t i = 0; i < impacts.size() && i < kMaxPerFrame; ++i) {
    const double volume = impactVolume(impacts[i]);
    if (volume <= 0.0) break;
    sf::Sound& voice = voices_[next_voice_];
    next_voice_ = (next_voice_ + 1) % voices_.size();
    voice.stop();
    voice.setBuffer(buffer(impacts[i].kind));
    voice.setVolume(static_cast<float>(volume));
    voice.play();
  }
}

}  // namespace nineball::audio
