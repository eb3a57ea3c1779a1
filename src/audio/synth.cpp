#include "audio/synth.hpp"

#include <algorithm>
#include <cmath>

namespace nineball::audio {
namespace {

constexpr double kTwoPi = 6.283185307179586;

// A fixed linear congruential noise: the same sound on every run.
class Noise {
 public:
  double next() {
    state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state_ >> 11) / 9007199254740992.0 * 2.0 - 1.0;
  }

 private:
  std::uint64_t state_ = 0x2545F4914F6CDD1DULL;
};

struct Partial {
  double hz;
  double amplitude;
  double decay_s;  // time for the amplitude to fall by e
};

// Adds decaying sine partials and a decaying noise burst starting at `at` seconds.
void addStrike(std::vector<double>& out, double at, const std::vector<Partial>& partials,
               double noise_amp, double noise_decay_s) {
  Noise noise;
  const std::size_t start = static_cast<std::size_t>(at * kSampleRate);
  double low = 0.0;
  for (std::size_t i = start; i < out.size(); ++i) {
    const double t = static_cast<double>(i - start) / kSampleRate;
    double s = 0.0;
    for (const Partial& p : partials)
      s += p.amplitude * std::exp(-t / p.decay_s) * std::sin(kTwoPi * p.hz * t);
    // A one-pole low-pass softens the noise into a knock.
    low += 0.35 * (noise.next() - low);
    s += noise_amp * std::exp(-t / noise_decay_s) * low;
    out[i] += s;
  }
}

std::vector<std::int16_t> toSamples(const std::vector<double>& wave) {
  double peak = 1e-9;
  for (double v : wave) peak = std::max(peak, std::abs(v));
  std::vector<std::int16_t> out(wave.size());
  // A short fade-in avoids a click of its own at the first sample.
  const std::size_t fade = kSampleRate / 2000;
  for (std::size_t i = 0; i < wave.size(); ++i) {
    const double gain = i < fade ? static_cast<double>(i) / fade : 1.0;
    out[i] = static_cast<std::int16_t>(std::lround(wave[i] / peak * 30000.0 * gain));
  }
  return out;
}

std::vector<double> silence(double seconds) {
  return std::vector<double>(static_cast<std::size_t>(seconds * kSampleRate), 0.0);
}

}  // namespace

std::vector<std::int16_t> synthClick() {
  std::vector<double> w = silence(0.06);
  addStrike(w, 0.0, {{2950.0, 1.0, 0.006}, {4400.0, 0.6, 0.004}, {6300.0, 0.35, 0.003}}, 0.5,
            0.0015);
  return toSamples(w);
}

std::vector<std::int16_t> synthThud() {
  std::vector<double> w = silence(0.15);
  addStrike(w, 0.0, {{105.0, 1.0, 0.03}, {175.0, 0.5, 0.02}, {420.0, 0.15, 0.01}}, 0.6, 0.008);
  return toSamples(w);
}

std::vector<std::int16_t> synthCueStrike() {
  std::vector<double> w = silence(0.05);
  addStrike(w, 0.0, {{1400.0, 1.0, 0.004}, {2300.0, 0.45, 0.003}, {650.0, 0.3, 0.006}}, 0.7, 0.001);
  return toSamples(w);
}

std::vector<std::int16_t> synthPocketDrop() {
  std::vector<double> w = silence(0.55);
  addStrike(w, 0.0, {{1250.0, 0.5, 0.01}, {2100.0, 0.25, 0.006}}, 0.4, 0.004);
  addStrike(w, 0.05, {{330.0, 0.6, 0.03}, {520.0, 0.3, 0.02}}, 0.5, 0.01);
  addStrike(w, 0.11, {{300.0, 0.45, 0.03}, {480.0, 0.2, 0.02}}, 0.35, 0.01);
  addStrike(w, 0.17, {{280.0, 0.3, 0.03}}, 0.25, 0.01);
  addStrike(w, 0.2, {{82.0, 0.5, 0.12}, {123.0, 0.25, 0.08}}, 0.15, 0.1);
  return toSamples(w);
}

}  // namespace nineball::audio
