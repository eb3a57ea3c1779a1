#include "window/rack_seed.hpp"

#include <chrono>
#include <random>

namespace nineball::window {
namespace {

constexpr std::uint64_t kMostFreshSeed = 1'000'000'000;

}  // namespace

std::uint64_t freshSeed() {
  std::random_device device;
  const auto now = static_cast<std::uint64_t>(
      std::chrono::high_resolution_clock::now().time_since_epoch().count());
  std::uint64_t seed = (static_cast<std::uint64_t>(device()) << 32) ^ device();
  // A random_device without entropy gives the same numbers each run: the clock still differs.
  seed ^= now * 0x9E3779B97F4A7C15ull;
  // Kept to what a match script's "seed" takes (0 to 2^31 - 1), with room for the racks that
  // follow (rack n plays seed + n - 1): a saved rack is a script that plays again.
  return 1 + seed % kMostFreshSeed;
}

bool drawsFreshSeeds(const app::GameOptions& options) {
  return !options.seed_given && options.script.empty() && options.screenshot.empty() &&
         !options.frames && options.join.empty();
}

}  // namespace nineball::window
