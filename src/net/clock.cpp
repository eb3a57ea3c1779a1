#include "net/clock.hpp"

#include <chrono>

namespace nineball::net {
namespace {

class SteadyClock final : public Clock {
 public:
  double now() const override {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - origin_).count();
  }

 private:
  std::chrono::steady_clock::time_point origin_ = std::chrono::steady_clock::now();
};

}  // namespace

const Clock& steadyClock() {
  static const SteadyClock clock;
  return clock;
}

}  // namespace nineball::net
