#pragma once

#include <cstddef>
#include <vector>

namespace nineball::physics {

/// Contacts met at one instant are one multi-body contact, resolved here pair by pair. A ball
/// driven into a wedge, or pressed by another against a lively cushion, then bounces back
/// and forth without end, each exchange a few per cent smaller (the "inelastic collapse" of
/// event-driven granular simulation). A real contact lasts about 0.2 ms, so such a ball is in
/// one lasting contact: past kJamContacts contacts at one instant it bounces no more (e = 0,
/// as in the TC model of Luding and McNamara, 1998), which ends the exchange in a few rounds.
/// A rack broken by the cue ball meets far fewer contacts per ball at one instant.
class JamCounter {
 public:
  static constexpr int kJamContacts = 32;

  static constexpr std::size_t kCushion = static_cast<std::size_t>(-1);

  /// Counts a contact of ball i with ball j (or kCushion) at time t; true once either ball
  /// has met more than kJamContacts contacts at this instant.
  bool jammed(double t, std::size_t i, std::size_t j);
  /// As new.
  void reset() {
    instant_ = -1.0;
    counts_.clear();
  }

 private:
  double instant_ = -1.0;
  std::vector<int> counts_;
};

}  // namespace nineball::physics
