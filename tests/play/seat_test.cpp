// Who plays a seat: its helpers and the names the JSON contracts use.
#include "nineball/seat.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "nineball/planner.hpp"

namespace nineball {
namespace {

TEST(Seat, APersonIsNoComputerAndHasNoLevel) {
  const Seat seat = HumanSeat{};
  EXPECT_FALSE(isComputer(seat));
  EXPECT_FALSE(computerLevel(seat));
  EXPECT_EQ(seatName(seat), "human");
}

TEST(Seat, TheComputerPlaysAtItsLevel) {
  const Seat seat = ComputerSeat{ai::Level::Master};
  EXPECT_TRUE(isComputer(seat));
  ASSERT_TRUE(computerLevel(seat));
  EXPECT_EQ(*computerLevel(seat), ai::Level::Master);
  EXPECT_EQ(seatName(seat), "ai:master");
}

TEST(Seat, TheOlderNamesAreTheirLadderLevels) {
  EXPECT_EQ(seatFromName("ai:easy"), Seat{ComputerSeat{ai::Level::Casual}});
  EXPECT_EQ(seatFromName("ai:medium"), Seat{ComputerSeat{ai::Level::Club}});
  EXPECT_EQ(seatFromName("ai:hard"), Seat{ComputerSeat{ai::Level::Master}});
  const std::vector<std::string> names = seatNames();
  EXPECT_EQ(names.size(), 1u + ai::allLevels().size() + 3u);
  for (const std::string& name : names) EXPECT_TRUE(seatFromName(name)) << name;
}

TEST(Seat, ADefaultSeatIsAPerson) {
  EXPECT_EQ(Seat{}, Seat{HumanSeat{}});
  EXPECT_NE(Seat{ComputerSeat{ai::Level::Casual}}, Seat{ComputerSeat{ai::Level::Club}});
}

TEST(Seat, NamesReadBackAndUnknownOnesAreRefused) {
  std::vector<Seat> seats = {HumanSeat{}};
  for (ai::Level l : ai::allLevels()) seats.emplace_back(ComputerSeat{l});
  for (const Seat& seat : seats) {
    const auto back = seatFromName(seatName(seat));
    ASSERT_TRUE(back) << seatName(seat);
    EXPECT_EQ(*back, seat);
  }
  for (const char* name : {"", "Human", "ai:", "ai:grandmaster", "ai:Easy", "easy", "ai:easy ",
                           "ai:Pro", "computer"}) {
    EXPECT_FALSE(seatFromName(name)) << name;
  }
}

}  // namespace
}  // namespace nineball
