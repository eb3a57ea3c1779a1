#pragma once

#include <CLI/CLI.hpp>
#include <charconv>
#include <cstdint>
#include <string>

namespace nineball::app {

/// A seed: CLI11 alone would wrap -1 round to 2^64 - 1 and clamp 2^64 down to it.
inline const CLI::Validator& seedCheck() {
  static const CLI::Validator check(
      [](std::string& value) -> std::string {
        std::uint64_t v = 0;
        const char* end = value.data() + value.size();
        const auto [stop, ec] = std::from_chars(value.data(), end, v);
        if (ec == std::errc() && stop == end) return {};
        return "must be an integer from 0 to 2^64 - 1, found " + value;
      },
      "0..2^64-1");
  return check;
}

}  // namespace nineball::app
