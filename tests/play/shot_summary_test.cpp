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

Event event(EventType type, int a, int b = -1) {
  Event e;
  e.type = type;
  e.a = a;
  e.b = b;
  return e;
}

// Carom: the shooter's ball is any ball; every touch is kept with the cushions before it.
TEST(ShotSummary, ReadsTheShootersOwnBallsTouchesAndCushions) {
  const std::vector<Event> events{
      event(EventType::Cushion, 1),     event(EventType::BallBall, 2, 1),
      event(EventType::Cushion, 0),  // another ball's cushion
      event(EventType::Cushion, 1),     event(EventType::Cushion, 1),
      event(EventType::BallBall, 1, 0), event(EventType::Cushion, 1)};
  const auto s = play::summarize(events, 1);
  EXPECT_EQ(s.first_contact, 2);
  EXPECT_EQ(s.cue_touches, (std::vector<int>{2, 0}));
  EXPECT_EQ(s.cue_cushions_before, (std::vector<int>{1, 3}));
  EXPECT_EQ(s.cue_cushions, 4);
  EXPECT_EQ(s.object_balls_to_rail, 1);
  EXPECT_FALSE(s.miscue);
  EXPECT_TRUE(play::summarize({event(EventType::Miscue, 1)}, 1).miscue);
}

}  // namespace
}  // namespace nineball
