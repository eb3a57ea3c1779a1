#include "window/snooker_turn_message.hpp"

#include "nineball/games.hpp"
#include "nineball/snooker_rack.hpp"
#include "rules/snooker_balls.hpp"

namespace nineball::window {
namespace {

int indexOf(rules::Player p) {
  return p == rules::Player::A ? 0 : 1;
}

std::string points(int n) {
  return std::to_string(n) + (n == 1 ? " point" : " points");
}

// "the red", "the red and the black", "two reds and the black".
std::string snookerBalls(const std::vector<int>& balls) {
  const GameDef& game = gameDef(rules::Game::Snooker);
  std::vector<std::string> words;
  int reds = 0;
  for (int b : balls) reds += rules::snooker::isRed(b);
  if (reds > 1) words.push_back(std::to_string(reds) + " reds");
  for (int b : balls) {
    if (reds > 1 && rules::snooker::isRed(b)) continue;
    words.push_back(game.theBall(b));
  }
  std::string s;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i > 0) s += i + 1 == words.size() ? " and " : ", ";
    s += words[i];
  }
  return s;
}

std::string foulWords(rules::Foul foul) {
  switch (foul) {
    case rules::Foul::Scratch:
      return "in-off";
    case rules::Foul::NoContact:
      return "no ball hit";
    case rules::Foul::WrongBallFirst:
      return "a ball not on hit first";
    case rules::Foul::PottedNotOn:
      return "a ball not on potted";
    case rules::Foul::ThreeMisses:
      return "a third miss";
    case rules::Foul::JumpedBall:
      return "a ball forced off the table";
    case rules::Foul::JumpShot:
      return "a jump shot";
    default:
      return rules::foulName(foul);
  }
}

TurnMessage decision(const TurnRecord& record, const std::string& shooter,
                     const std::string& opponent) {
  TurnMessage m;
  if (record.replace) {
    m.text = shooter + " has the balls replaced: " + opponent + " plays again.";
  } else if (record.shoot) {
    m.text = shooter + " plays from there.";
  } else {
    m.text = shooter + " puts " + opponent + " back in.";
  }
  return m;
}

}  // namespace

TurnMessage describeSnookerTurn(const TurnRecord& record, const rules::Rack& rack,
                                const std::string& shooter, const std::string& opponent) {
  if (record.kind == TurnInput::Kind::Decision) return decision(record, shooter, opponent);
  const rules::Verdict& v = record.verdict;
  const int me = indexOf(record.shooter);
  TurnMessage m;
  if (!v.legal()) {
    m.tone = render::Tone::Foul;
    m.text = "Foul by " + shooter + " (" + foulWords(v.foul) + (v.miss ? ", and a miss" : "") +
             "): " + points(v.points[1 - me]) + " to " + opponent + ".";
    if (!v.pocketed.empty()) m.text += " " + sentence(snookerBalls(v.pocketed)) + " went down.";
  } else if (v.pocketed.empty()) {
    m.text = shooter + (v.free_ball ? " plays the free ball and" : "") +
             " pots nothing: " + opponent + " to play.";
  } else {
    m.text = shooter + " pots " + snookerBalls(v.pocketed) + (v.free_ball ? " (free ball)" : "") +
             ": " + points(v.points[me]) + ", break " + std::to_string(rack.currentRun()) + ".";
  }
  if (v.black_respotted) m.text += " Scores level: the black is re-spotted.";
  if (v.winner) {
    m.tone = render::Tone::Win;
    const bool a_won = *v.winner == rules::Player::A;
    const std::string& winner = *v.winner == record.shooter ? shooter : opponent;
    const int wp = rack.score(*v.winner),
              lp = rack.score(a_won ? rules::Player::B : rules::Player::A);
    m.text +=
        " " + winner + " wins the frame " + std::to_string(wp) + "-" + std::to_string(lp) + ".";
    return m;
  }
  if (rules::freeBall(rack)) m.text += " Free ball.";
  if (rack.pendingDecision() == rules::Decision::PlayPutBackOrReplace) {
    m.text += " " + opponent + ": play on, put " + shooter + " back in, or replace the balls.";
  } else if (rack.pendingDecision() == rules::Decision::PlayOrPutBack) {
    m.text += " " + opponent + ": play on, or put " + shooter + " back in.";
  }
  return m;
}

}  // namespace nineball::window
