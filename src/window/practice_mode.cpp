#include "window/practice_mode.hpp"

#include "nineball/games.hpp"
#include "window/turn_message.hpp"

namespace nineball::window {

PracticeMode::PracticeMode(const Match& racked)
    : table_(racked.world().table(), racked.world().physics().ball_radius, racked.balls()),
      racked_(gameDef(racked.rack().game()).balls) {}

std::vector<int> PracticeMode::offTable() const {
  std::vector<int> off;
  for (int id : racked_) {
    if (!table_.has(id)) off.push_back(id);
  }
  return off;
}

bool PracticeMode::moveBall(PracticeHost& host, int id, Vec2 pos) {
  if (!host.aiming()) return false;
  if (const auto problem = table_.placementProblem(id, pos)) {
    host.say("The ball cannot go there: " + *problem + ".", render::Tone::Warning);
    return false;
  }
  table_.place(id, pos);
  host.rebuildPractice();
  return true;
}

void PracticeMode::toggleBall(PracticeHost& host, int id, Vec2 near) {
  if (!host.aiming() || id == kCueBall) return;
  const std::string ball = std::to_string(id);
  if (table_.has(id)) {
    table_.remove(id);
    host.say("The " + ball + " is off the table (" + ball + " puts it back).", render::Tone::Info);
  } else if (const auto spot = table_.freeSpotNear(id, near)) {
    table_.place(id, *spot);
    host.say("The " + ball + " is on the table: Shift+drag it where you want it.",
             render::Tone::Info);
  } else {
    host.say("No room for the " + ball + ".", render::Tone::Warning);
    return;
  }
  host.rebuildPractice();
}

void PracticeMode::undo(PracticeHost& host) {
  if (!host.aiming()) return;
  const auto step = table_.undo();
  if (!step) {
    host.say("Nothing to undo: no shot played or ball moved yet.", render::Tone::Warning);
    return;
  }
  const std::string more = " (" + std::to_string(table_.stepsRemembered()) + " more to undo).";
  host.rebuildPractice();
  if (!step->shot) {
    host.say("The last ball moved is back where it was" + more, render::Tone::Info);
    return;
  }
  host.takeCue(step->before);
  host.say("Back to before the last shot" + more, render::Tone::Info);
}

void PracticeMode::retry(PracticeHost& host) {
  if (!host.aiming()) return;
  const auto shot = table_.retry();
  if (!shot) {
    host.say("Nothing to retry: no shot played yet.", render::Tone::Warning);
    return;
  }
  host.rebuildPractice();
  host.takeCue(*shot);
  host.say("The last shot set up again: same position, aim, power and spin.", render::Tone::Info);
}

void PracticeMode::recordShot(const Shot& shot) {
  table_.recordShot({table_.layout(), shot.heading_rad, shot.speed, shot.tip, shot.elevation_rad});
}

void PracticeMode::finishShot(PracticeHost& host, const std::vector<BallState>& after) {
  std::vector<int> down;
  for (const BallState& b : after) {
    if (b.pocket && b.id != kCueBall && table_.has(b.id)) down.push_back(b.id);
  }
  const bool cue_back = table_.settle(after);
  host.rebuildPractice();
  std::string text = down.empty() ? "Nothing down." : sentence(ballList(down)) + " down.";
  if (cue_back) text += " The cue ball dropped: it is back where it was struck from.";
  host.say(text + " U: undo, Y: retry.", cue_back ? render::Tone::Foul : render::Tone::Info);
}

}  // namespace nineball::window
