#pragma once

// The time every timeout of the net layer reads (the hello gate, a silent link, the rejoin
// window, the turn time, the joiner's retries): monotonic seconds from any origin, injected so
// that a test moves it by hand (tests/support/fake_clock.hpp) instead of sleeping.
namespace nineball::net {

class Clock {
 public:
  virtual ~Clock() = default;
  /// Seconds since an origin of the clock's choosing; never goes back.
  virtual double now() const = 0;
};

/// The machine's steady clock (its origin: the first call): what real play reads.
const Clock& steadyClock();

}  // namespace nineball::net
