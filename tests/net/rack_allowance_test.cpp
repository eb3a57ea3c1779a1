// The heals and rejoins one rack may take, counted once for the window and `nineball online`.
#include "net/rack_allowance.hpp"

#include <gtest/gtest.h>

#include "net/online_rack.hpp"

namespace nineball::net {
namespace {

TEST(RackAllowance, TakesAsManyRejoinsAsAllowedAndRefusesTheNext) {
  RackAllowance allowance(3, 2);
  EXPECT_TRUE(allowance.takeRejoin());
  EXPECT_TRUE(allowance.takeRejoin());
  EXPECT_FALSE(allowance.takeRejoin());
  EXPECT_EQ(allowance.rejoins(), 3);
}

TEST(RackAllowance, ANewRackCountsItsRejoinsFromZero) {
  RackAllowance allowance(3, 1);
  EXPECT_TRUE(allowance.takeRejoin());
  EXPECT_FALSE(allowance.takeRejoin());
  allowance.newRack();
  EXPECT_EQ(allowance.rejoins(), 0);
  EXPECT_TRUE(allowance.takeRejoin());
}

TEST(RackAllowance, HealsAreSpentOnceTheRackHasHealedAsOftenAsAllowed) {
  const RackAllowance allowance(2, 20);
  EXPECT_FALSE(allowance.healsSpent(0));
  EXPECT_FALSE(allowance.healsSpent(1));
  EXPECT_TRUE(allowance.healsSpent(2));
  EXPECT_TRUE(allowance.healsSpent(3));
}

TEST(RackAllowance, TheWindowAndTheHeadlessRackShareTheDefaults) {
  const RackAllowance window_default;
  const OnlineRackOptions headless_default;
  EXPECT_EQ(window_default.mostHeals(), 3);
  EXPECT_EQ(window_default.mostRejoins(), 20);
  EXPECT_EQ(headless_default.most_heals, window_default.mostHeals());
  EXPECT_EQ(headless_default.most_rejoins, window_default.mostRejoins());
}

}  // namespace
}  // namespace nineball::net
