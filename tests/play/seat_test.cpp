// Who plays a seat: its helpers and the names the JSON contracts use.
#include "nineball/seat.hpp"

#include <gtest/gtest.h>

namespace nineball {
namespace {

TEST(Seat, APersonIsNoComputerAndHasNoLevel) {
  const Seat seat = HumanSeat{};
  EXPECT_FALSE(isComputer(seat));
  EXPECT_FALSE(computerLevel(seat));
  EXPECT_EQ(seatName(seat), "human");
}

TEST(Seat, TheComputerPlaysAtItsLevel) {
  const Seat seat = ComputerSeat{ai::Level::Hard};
  EXPECT_TRUE(isComputer(seat));
  ASSERT_TRUE(computerLevel(seat));
  EXPECT_EQ(*computerLevel(seat), ai::Level::Hard);
  EXPECT_EQ(seatName(seat), "ai:hard");
}

TEST(Seat, ADefaultSeatIsAPerson) {
  EXPECT_EQ(Seat{}, Seat{HumanSeat{}});
  EXPECT_NE(Seat{ComputerSeat{ai::Level::Easy}}, Seat{ComputerSeat{ai::Level::Medium}});
}

TEST(Seat, NamesReadBackAndUnknownOnesAreRefused) {
  for (const Seat& seat :
       {Seat{HumanSeat{}}, Seat{ComputerSeat{ai::Level::Easy}},
        Seat{ComputerSeat{ai::Level::Medium}}, Seat{ComputerSeat{ai::Level::Hard}}}) {
    const auto back = seatFromName(seatName(seat));
    ASSERT_TRUE(back) << seatName(seat);
    EXPECT_EQ(*back, seat);
  }
  for (const char* name :
       {"", "Human", "ai:", "ai:pro", "ai:Easy", "easy", "ai:easy ", "computer"}) {
    EXPECT_FALSE(seatFromName(name)) << name;
  }
}

}  // namespace
}  // namespace nineball
