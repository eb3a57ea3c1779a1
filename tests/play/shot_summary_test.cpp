// The physics events read as the rules need them, pockets included.
#include "play/shot_summary.hpp"

#include <gtest/gtest.h>

#include "nineball/ball.hpp"

namespace nineball {
namespace {

Event pocketEvent(int ball, PocketId pocket) {
  Event e;
  e.type = EventType::Pocket;
  e.a = ball;
  e.pocket = pocket;
  return e;
}

TEST(ShotSummary, RecordsWhereEachBallDropped) {
  Event contact;
  contact.type = EventType::BallBall;
  contact.a = kCueBall;
  contact.b = 3;
  const auto s = play::summarize({contact, pocketEvent(8, PocketId::TopSide),
                                  pocketEvent(kCueBall, PocketId::BottomLeft),
                                  pocketEvent(3, PocketId::TopRight)});
  EXPECT_EQ(s.first_contact, 3);
  EXPECT_EQ(s.pocketed, (std::vector<int>{8, 3}));
  EXPECT_EQ(s.pockets, (std::vector<PocketId>{PocketId::TopSide, PocketId::TopRight}));
  EXPECT_TRUE(s.cue_pocketed);
  EXPECT_EQ(s.pocketOf(3), PocketId::TopRight);
  EXPECT_FALSE(s.pocketOf(5));
  EXPECT_FALSE(s.call);
}

}  // namespace
}  // namespace nineball
