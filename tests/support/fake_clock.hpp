#pragma once

#include <atomic>

#include "net/clock.hpp"

// A clock a test moves by hand: a timeout of the net layer is reached by advance(), never by
// sleeping, so the test takes no time and gives the same answer on a loaded machine. Safe to
// move from the test's thread while a rack reads it on its own.
namespace nineball::testing {

class FakeClock final : public net::Clock {
 public:
  explicit FakeClock(double start = 1000.0) : now_(start) {}
  double now() const override { return now_.load(); }
  void advance(double seconds) { now_.store(now_.load() + seconds); }

 private:
  std::atomic<double> now_;
};

}  // namespace nineball::testing
