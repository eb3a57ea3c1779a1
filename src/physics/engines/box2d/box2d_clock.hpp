#pragma once

// Box2D 2.4.1 times every part of b2World::Step with b2Timer to fill a b2Profile, and nineball
// never reads it: about 36,000 gettimeofday calls a break, a quarter of its time on this
// machine's clock. Debian's library has no switch for it and nothing is vendored, so this
// executable defines gettimeofday itself (the dynamic linker binds libbox2d's calls to it)
// and answers 0 at once while a thread is inside a Box2D step; everyone else, and every other
// moment, gets the real clock.
namespace nineball::physics {

/// While one lives, this thread's Box2D steps read no clock.
class MutedBox2DClock {
 public:
  MutedBox2DClock();
  ~MutedBox2DClock();
  MutedBox2DClock(const MutedBox2DClock&) = delete;
  MutedBox2DClock& operator=(const MutedBox2DClock&) = delete;
};

/// The clock reads this thread has answered with 0 so far: 0 would mean Box2D's timers reach
/// the real clock again (the override lost at link time).
long mutedClockReads();

}  // namespace nineball::physics
