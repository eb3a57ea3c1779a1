#include "nineball/rules.hpp"

namespace nineball::rules {

const char* ruleSetName(RuleSet r) {
  switch (r) {
    case RuleSet::Wpa:
      return "wpa";
    case RuleSet::Paper:
      return "paper";
    case RuleSet::Umb:
      return "umb";
    case RuleSet::Wpbsa:
      return "wpbsa";
  }
  return "?";
}

std::optional<RuleSet> ruleSetFromName(const std::string& name) {
  for (RuleSet r : {RuleSet::Wpa, RuleSet::Paper, RuleSet::Umb, RuleSet::Wpbsa}) {
    if (name == ruleSetName(r)) return r;
  }
  return std::nullopt;
}

const char* foulName(Foul f) {
  switch (f) {
    case Foul::None:
      return "none";
    case Foul::Scratch:
      return "scratch";
    case Foul::WrongBallFirst:
      return "wrong-ball-first";
    case Foul::NoContact:
      return "no-contact";
    case Foul::NoRail:
      return "no-rail";
    case Foul::BadBreak:
      return "bad-break";
    case Foul::ThreeFouls:
      return "three-fouls";
    case Foul::EightEarly:
      return "eight-early";
    case Foul::WrongGroupFirst:
      return "wrong-group-first";
    case Foul::WrongPocket:
      return "wrong-pocket";
    case Foul::NoCall:
      return "no-call";
    case Foul::PottedNotOn:
      return "potted-not-on";
    case Foul::ThreeMisses:
      return "three-misses";
    case Foul::JumpedBall:
      return "jumped-ball";
    case Foul::JumpShot:
      return "jump-shot";
  }
  return "?";
}

const char* groupName(Group g) {
  return g == Group::Solids ? "solids" : "stripes";
}

std::optional<Group> groupOf(int ball) {
  if (ball >= 1 && ball <= 7) return Group::Solids;
  if (ball >= 9 && ball <= 15) return Group::Stripes;
  return std::nullopt;
}

}  // namespace nineball::rules
