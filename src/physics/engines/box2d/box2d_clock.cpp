#include "physics/engines/box2d/box2d_clock.hpp"

#include <sys/time.h>

#include <ctime>

namespace {

thread_local int t_muted = 0;
thread_local long t_reads = 0;

}  // namespace

namespace nineball::physics {

MutedBox2DClock::MutedBox2DClock() {
  ++t_muted;
}

MutedBox2DClock::~MutedBox2DClock() {
  --t_muted;
}

long mutedClockReads() {
  return t_reads;
}

}  // namespace nineball::physics

// Replaces the C library's gettimeofday for the whole process (see box2d_clock.hpp), with the
// same answer outside a muted Box2D step. glibc declares `tv` never null. The time zone
// argument is obsolete: glibc fills it with zeros, and so does this.
extern "C" int gettimeofday(struct timeval* __restrict tv, void* __restrict tz) noexcept {
  if (t_muted > 0) {
    ++t_reads;
    *tv = timeval{};
    return 0;
  }
  timespec now{};
  clock_gettime(CLOCK_REALTIME, &now);
  tv->tv_sec = now.tv_sec;
  tv->tv_usec = static_cast<suseconds_t>(now.tv_nsec / 1000);
  if (tz) *static_cast<struct timezone*>(tz) = {};
  return 0;
}
