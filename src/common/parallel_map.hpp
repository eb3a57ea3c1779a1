#pragma once

#include <cstddef>
#include <functional>

namespace nineball {

/// The threads to run on when `asked` for: itself, or one per core for 0 (or less).
int threadsFor(int asked);

/// Calls `work(i)` for every i in [0, count) on up to `threads` threads (the caller's own
/// included). Each call must write only its own slot of the caller's results, so that the
/// results do not depend on which thread ran which index. The first exception thrown by a call
/// is rethrown once every thread has stopped. When no more threads can be started, the ones
/// started (and the caller's) do all the work.
void parallelFor(std::size_t count, int threads, const std::function<void(std::size_t)>& work);

}  // namespace nineball
