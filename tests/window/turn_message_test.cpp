// The messages about a finished turn: whose names they use, and that every sentence they join
// starts with a capital.
#include "window/turn_message.hpp"

#include <gtest/gtest.h>

#include <cctype>

namespace nineball::window {
namespace {

// Every ". x" in the text is followed by a capital (or a digit).
void expectSentencesCapitalised(const std::string& text) {
  for (std::size_t i = 0; i + 2 < text.size(); ++i) {
    if ((text[i] == '.' || text[i] == '!') && text[i + 1] == ' ') {
      EXPECT_FALSE(std::islower(static_cast<unsigned char>(text[i + 2])))
          << "at " << i << ": " << text;
    }
  }
}

TEST(TurnMessage, TheGroupsGoToTheShooterAndTheOpponentWhenTheShooterPlaysOn) {
  // The first legal pot after an eight-ball break: the shooter keeps the table.
  TurnRecord r;
  r.shooter = rules::Player::A;
  r.verdict.pocketed = {3};
  r.verdict.next = rules::Player::A;
  r.verdict.groups = {rules::Group::Solids, rules::Group::Stripes};
  const std::string text = describeTurn(r, {}, 1, "Ann", "Bob", rules::Groups{}).text;
  EXPECT_NE(text.find("Ann has the solids, Bob the stripes."), std::string::npos) << text;
  EXPECT_NE(text.find("Ann pockets the 3 and shoots again."), std::string::npos) << text;
}

TEST(TurnMessage, AFoulPassesTheTurnToTheOpponentByName) {
  TurnRecord r;
  r.shooter = rules::Player::B;
  r.verdict.foul = rules::Foul::Scratch;
  r.verdict.next = rules::Player::A;
  r.verdict.ball_in_hand = true;
  rules::ShotSummary summary;
  summary.cue_pocketed = true;
  const std::string text = describeTurn(r, summary, 1, "Bob", "Ann").text;
  EXPECT_NE(text.find("Foul by Bob"), std::string::npos) << text;
  EXPECT_NE(text.find("Ball in hand for Ann."), std::string::npos) << text;
}

TEST(TurnMessage, JoinedSentencesStartWithACapital) {
  // A foul that pockets the 5 and the 9: the 5 stays down, the 9 is spotted.
  TurnRecord r;
  r.shooter = rules::Player::A;
  r.verdict.foul = rules::Foul::WrongPocket;
  r.verdict.pocketed = {5, 9};
  r.verdict.to_spot = {9};
  r.verdict.next = rules::Player::B;
  r.verdict.ball_in_hand = true;
  const std::string text = describeTurn(r, {}, 1, "Ann", "Bob").text;
  EXPECT_NE(text.find(" The 9 is spotted."), std::string::npos) << text;
  EXPECT_NE(text.find(" The 5 went down and stays down."), std::string::npos) << text;
  expectSentencesCapitalised(text);

  TurnRecord push;
  push.kind = TurnInput::Kind::PushOut;
  push.shooter = rules::Player::A;
  push.verdict.pocketed = {9};
  push.verdict.to_spot = {9};
  push.verdict.next = rules::Player::B;
  const std::string pushed = describeTurn(push, {}, 1, "Ann", "Bob").text;
  EXPECT_NE(pushed.find(". The 9 is spotted."), std::string::npos) << pushed;
  expectSentencesCapitalised(pushed);
}

TEST(TurnMessage, SentenceCapitalisesTheFirstLetterOnly) {
  EXPECT_EQ(sentence("the 9 and the 3"), "The 9 and the 3");
  EXPECT_EQ(sentence(""), "");
}

}  // namespace
}  // namespace nineball::window
