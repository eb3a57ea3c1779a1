#pragma once

#include <atomic>

// A run stopped from outside at its next event: the Python module raises the flag when Ctrl-C
// comes, and the engines look at it where they look at their work budget. A run that stops so
// ends as a spent budget ("cancelled"); its result is the caller's to throw away.
namespace nineball {

/// While it lives, runs on this thread stop once `flag` is true.
class CancelScope {
 public:
  explicit CancelScope(const std::atomic<bool>* flag);
  ~CancelScope();
  CancelScope(const CancelScope&) = delete;
  CancelScope& operator=(const CancelScope&) = delete;

 private:
  const std::atomic<bool>* outer_;
};

/// True when the flag of this thread's CancelScope is raised.
bool cancelRequested();

/// What a cancelled run's budget says it spent.
inline constexpr const char* kCancelledBudget = "cancelled";

}  // namespace nineball
