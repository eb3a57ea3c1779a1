#pragma once

// How many heals and rejoins one rack may take, written once for the window and `nineball
// online`: disagreeing, dropping and rejoining must not keep two sides at it for ever.
namespace nineball::net {

/// Heals and rejoins a rack may take unless told otherwise; one more ends the rack.
inline constexpr int kMostHealsPerRack = 3;
inline constexpr int kMostRejoinsPerRack = 20;

class RackAllowance {
 public:
  explicit RackAllowance(int most_heals = kMostHealsPerRack,
                         int most_rejoins = kMostRejoinsPerRack);

  /// Counts one rejoin; false when it is one more than the rack may take.
  bool takeRejoin();
  /// True when a rack that has healed `heals` times may heal no more.
  bool healsSpent(int heals) const { return heals >= most_heals_; }
  /// A new rack (a rematch): its rejoins count from zero. (Heals are the Lockstep's, per rack.)
  void newRack() { rejoins_ = 0; }

  int rejoins() const { return rejoins_; }
  int mostHeals() const { return most_heals_; }
  int mostRejoins() const { return most_rejoins_; }

 private:
  int most_heals_;
  int most_rejoins_;
  int rejoins_ = 0;
};

}  // namespace nineball::net
