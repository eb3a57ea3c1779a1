// The HUD's message line: a refused cue-ball placement is cleared by the next good one, any
// other message is not; a shot empties the line and keeps its tone, a new rack makes it plain.
#include "window/session_message.hpp"

#include <gtest/gtest.h>

namespace nineball::window {
namespace {

TEST(SessionMessage, AGoodPlacementClearsOnlyARefusal) {
  SessionMessage m;
  m.refusePlacement("The cue ball cannot go there: on a ball.");
  EXPECT_EQ(m.tone(), render::Tone::Warning);
  m.placementTaken();
  EXPECT_EQ(m.text(), "");
  EXPECT_EQ(m.tone(), render::Tone::Info);
  m.say("Foul: the 3 was hit first.", render::Tone::Foul);
  m.placementTaken();
  EXPECT_EQ(m.text(), "Foul: the 3 was hit first.");
  m.refusePlacement("off the table");
  m.say("Screenshot saved");  // a newer message is no refusal to clear
  m.placementTaken();
  EXPECT_EQ(m.text(), "Screenshot saved");
}

TEST(SessionMessage, AShotEmptiesTheLineAndANewRackMakesItPlain) {
  SessionMessage m;
  m.say("Foul", render::Tone::Foul);
  m.clear();
  EXPECT_EQ(m.text(), "");
  EXPECT_EQ(m.tone(), render::Tone::Foul);
  m.clearPlain();
  EXPECT_EQ(m.tone(), render::Tone::Info);
}

}  // namespace
}  // namespace nineball::window
