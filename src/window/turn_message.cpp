#include "window/turn_message.hpp"

#include <algorithm>
#include <cctype>

namespace nineball::window {
namespace {

std::string foulReason(rules::Foul foul, const rules::ShotSummary& summary, int ball_on,
                       bool any_first = false) {
  const std::string on = "the " + std::to_string(ball_on);
  switch (foul) {
    case rules::Foul::Scratch:
      return "the cue ball went into a pocket";
    case rules::Foul::WrongBallFirst:
      return "the cue ball hit the " + std::to_string(summary.first_contact.value_or(0)) +
             " before " + on;
    case rules::Foul::NoContact:
      return "the cue ball hit no ball";
    case rules::Foul::NoRail:
      return "no ball reached a cushion after the hit";
    case rules::Foul::BadBreak:
      if (!any_first && summary.first_contact != ball_on) {
        return "the break must hit " + on + " first";
      }
      return "no ball dropped on the break and fewer than four reached a cushion";
    case rules::Foul::ThreeFouls:
      return "a third foul in a row";
    case rules::Foul::EightEarly:
      return "the 8 dropped before the shooter's group was cleared";
    case rules::Foul::WrongGroupFirst:
      return "the cue ball hit the " + std::to_string(summary.first_contact.value_or(0)) +
             " first, not a ball of the shooter's";
    case rules::Foul::WrongPocket:
      return "the called ball dropped in another pocket than the one called";
    case rules::Foul::NoCall:
      return "a ball dropped that was not called";
    case rules::Foul::PottedNotOn:
      return "a ball not on went into a pocket";
    case rules::Foul::ThreeMisses:
      return "a third miss in a row";
    case rules::Foul::JumpedBall:
      return summary.off_table.size() == 1
                 ? (summary.off_table.front() == 0
                        ? std::string("the cue ball left the table")
                        : "the " + std::to_string(summary.off_table.front()) + " left the table")
                 : std::string("balls left the table");
    case rules::Foul::JumpShot:
      return "the cue ball jumped over a ball before hitting one";
    case rules::Foul::None:
      break;
  }
  return "";
}

// The foul that a third foul in a row stands for.
rules::Foul underlyingFoul(const rules::ShotSummary& summary, int ball_on) {
  if (summary.cue_pocketed) return rules::Foul::Scratch;
  if (!summary.first_contact) return rules::Foul::NoContact;
  if (*summary.first_contact != ball_on) return rules::Foul::WrongBallFirst;
  return rules::Foul::NoRail;
}

// The object balls pocketed on a foul stay down (but any the rules spot): the message says so,
// or the ball on would change with no word why.
std::string downOnFoul(const rules::Verdict& v) {
  std::vector<int> stay;
  for (int b : v.pocketed) {
    if (std::find(v.to_spot.begin(), v.to_spot.end(), b) == v.to_spot.end()) stay.push_back(b);
  }
  if (stay.empty()) return "";
  return " " + sentence(ballList(stay)) +
         (stay.size() == 1 ? " went down and stays down." : " went down and stay down.");
}

}  // namespace

std::string sentence(std::string text) {
  if (!text.empty()) text[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])));
  return text;
}

std::string ballList(const std::vector<int>& balls) {
  std::string s;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    if (i > 0) s += i + 1 == balls.size() ? " and " : ", ";
    s += "the " + std::to_string(balls[i]);
  }
  return s;
}

TurnMessage describeTurn(const TurnRecord& record, const rules::ShotSummary& summary, int ball_on,
                         const std::string& shooter, const std::string& opponent,
                         const rules::Groups& groups_before) {
  const rules::Verdict& v = record.verdict;
  const std::string& next = v.next == record.shooter ? shooter : opponent;
  TurnMessage m;
  if (record.kind == TurnInput::Kind::Decision) {
    if (record.answered == rules::Decision::RerackOrPlayOn) {
      m.text = record.shoot ? shooter + " plays the table as it lies."
                            : shooter + " has the balls re-racked and breaks.";
      return m;
    }
    m.text = v.next == record.shooter ? shooter + " plays from there."
                                      : shooter + " passes: " + next + " shoots.";
    return m;
  }
  const std::string potted = v.pocketed.empty() ? "" : ballList(v.pocketed);
  const bool spotted = !v.to_spot.empty();
  const std::string spot_note = spotted
                                    ? " " + sentence(ballList(v.to_spot)) +
                                          (v.to_spot.size() == 1 ? " is spotted." : " are spotted.")
                                    : "";
  if (v.winner) {
    m.tone = render::Tone::Win;
    const bool shooter_won = *v.winner == record.shooter;
    if (v.foul == rules::Foul::ThreeFouls) {
      m.text = "Third foul in a row by " + shooter + " (" +
               foulReason(underlyingFoul(summary, ball_on), summary, ball_on) + "): " + next +
               " wins the rack.";
    } else if (!shooter_won && !v.legal()) {
      m.text = "Foul with " + potted + " down (" + foulReason(v.foul, summary, ball_on) +
               "): " + next + " wins the rack.";
    } else if (!shooter_won) {
      m.text = "Foul with " + potted + " down: " + next + " wins the rack.";
    } else {
      m.text = shooter + " pockets " + potted + " and wins the rack!";
    }
    return m;
  }
  if (record.kind == TurnInput::Kind::PushOut) {
    m.text = shooter + " pushed out" + (potted.empty() ? "" : " (" + potted + " down)") + "." +
             spot_note + " " + next + ": play from here or pass it back.";
    return m;
  }
  std::string groups_note;
  if (groups_before.open() && !v.groups.open()) {
    if (const auto g = v.groups.of(record.shooter)) {
      const auto o = v.groups.of(rules::other(record.shooter));
      groups_note = " " + shooter + " has the " + rules::groupName(*g) + ", " + opponent + " the " +
                    (o ? rules::groupName(*o) : "others") + ".";
    }
  }
  if (v.decision == rules::Decision::RerackOrPlayOn) {
    m.tone = render::Tone::Foul;
    // Eight-ball's break may hit any ball first: only the count of balls down or to a cushion
    // makes it illegal.
    m.text = "Illegal break by " + shooter + ": " + foulReason(v.foul, summary, ball_on, true) +
             "." + downOnFoul(v) + spot_note + " " + next + ": play on as it lies, or re-rack.";
    return m;
  }
  if (v.call_breach != rules::Foul::None) {
    m.text = shooter + " pockets " + potted + " but not as called (" +
             foulReason(v.call_breach, summary, ball_on) + "): the turn ends." + spot_note + " " +
             next + ": play from there or pass it back.";
    return m;
  }
  if (!v.legal()) {
    m.tone = render::Tone::Foul;
    m.text = "Foul by " + shooter + ": " + foulReason(v.foul, summary, ball_on) + "." +
             downOnFoul(v) + spot_note;
    if (v.ball_in_hand) {
      m.text += " Ball in hand for " + next + ".";
    } else if (v.cue_to_head_spot) {
      m.text += " Cue ball to the head spot, " + next + " to shoot.";
    } else {
      m.text += " " + next + " to shoot.";
    }
    m.text += groups_note;
    return m;
  }
  if (!potted.empty()) {
    m.text =
        shooter + " pockets " + potted + (v.next == record.shooter ? " and shoots again." : ".");
  } else {
    m.text = "Nothing down. " + next + " to shoot.";
  }
  m.text += groups_note;
  return m;
}

TurnMessage describeCaromTurn(const TurnRecord& record, const rules::Rack& rack,
                              const std::string& shooter, const std::string& opponent) {
  const rules::Verdict& v = record.verdict;
  const std::string cushions =
      std::to_string(v.cushions) + (v.cushions == 1 ? " cushion" : " cushions");
  const bool point = v.points[0] + v.points[1] > 0;
  TurnMessage m;
  if (v.foul == rules::Foul::WrongBallFirst) {
    m.text = "No point - foul: the opening shot goes straight onto the red. ";
    m.tone = render::Tone::Foul;
  } else if (point) {
    m.text = "Point for " + shooter + "! " + cushions + " before the second ball. ";
    m.tone = render::Tone::Win;
  } else {
    m.text = "No point: " + cushions + " before the second ball" +
             (v.cushions >= 3 ? " (it missed a ball). " : ". ");
  }
  const Score s = scoreOf(rack);
  const std::string score = std::to_string(s.a.points) + "-" + std::to_string(s.b.points);
  if (v.draw) {
    m.text += "A draw, " + score + ": both reached " + std::to_string(rack.targetPoints()) +
              " in as many innings.";
    m.tone = render::Tone::Win;
  } else if (v.winner) {
    m.text += (*v.winner == record.shooter ? shooter : opponent) + " wins " + score + ".";
    m.tone = render::Tone::Win;
  } else if (v.next == record.shooter) {
    m.text += shooter + " plays on.";
  } else {
    m.text += opponent + " to play.";
  }
  return m;
}

}  // namespace nineball::window
