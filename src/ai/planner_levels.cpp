#include <algorithm>

#include "common/named.hpp"
#include "nineball/planner.hpp"

namespace nineball::ai {

const std::vector<Level>& allLevels() {
  static const std::vector<Level> levels = {Level::Beginner, Level::Casual,   Level::Club,
                                            Level::League,   Level::Advanced, Level::Pro,
                                            Level::Master};
  return levels;
}

const char* levelName(Level level) {
  switch (level) {
    case Level::Beginner:
      return "beginner";
    case Level::Casual:
      return "casual";
    case Level::Club:
      return "club";
    case Level::League:
      return "league";
    case Level::Advanced:
      return "advanced";
    case Level::Pro:
      return "pro";
    case Level::Master:
      return "master";
  }
  return "?";
}

namespace {

struct OlderName {
  const char* name;
  Level level;
};
// The three levels before the ladder, kept so that saved settings, scripts and habits still work.
constexpr OlderName kOlderNames[] = {
    {"easy", Level::Casual}, {"medium", Level::Club}, {"hard", Level::Master}};

}  // namespace

std::optional<Level> levelFromName(const std::string& name) {
  for (Level l : allLevels()) {
    if (name == levelName(l)) return l;
  }
  for (const OlderName& o : kOlderNames) {
    if (name == o.name) return o.level;
  }
  return std::nullopt;
}

std::vector<std::string> levelNames() {
  std::vector<std::string> names;
  for (Level l : allLevels()) names.emplace_back(levelName(l));
  for (const OlderName& o : kOlderNames) names.emplace_back(o.name);
  return names;
}

std::string levelNamesText() {
  return listed(levelNames());
}

const char* shotKindName(ShotKind kind) {
  switch (kind) {
    case ShotKind::Break:
      return "break";
    case ShotKind::Pot:
      return "pot";
    case ShotKind::Combination:
      return "combination";
    case ShotKind::Bank:
      return "bank";
    case ShotKind::Kick:
      return "kick";
    case ShotKind::Safety:
      return "safety";
    case ShotKind::PushOut:
      return "push-out";
    case ShotKind::Point:
      return "point";
    case ShotKind::Jump:
      return "jump";
  }
  return "?";
}

namespace {

// What a level looks at: few lines at one or two paces for a beginner, every pocket mouth, eleven
// tips, banks, kicks and the next shot for the strongest.
void searchLikeABeginner(LevelSettings& s) {
  s.pot_speeds = {2.2, 3.5};
  s.tips = {{0.0, 0.0}};
  s.safety_speeds = {1.5};
  s.safety_angles = 3;
  s.max_pot_lines = 2;
  s.placements = 2;
  s.sweep_headings = 24;
  s.break_speeds = {6.5};
}

void searchLikeACasualPlayer(LevelSettings& s) {
  s.pot_speeds = {1.6, 3.0};
  s.tips = {{0.0, 0.0}};
  s.safety_speeds = {1.2};
  s.safety_angles = 5;
  s.max_pot_lines = 3;
  s.placements = 3;
  s.sweep_headings = 36;
  s.break_speeds = {7.5};
  s.push_out_headings = 12;
}

void searchLikeAClubPlayer(LevelSettings& s) {
  s.pot_speeds = {1.0, 1.8, 3.0, 4.5};
  s.tips = {{0.0, 0.0}, {0.0, 0.3}, {0.0, -0.3}};
  s.safety_speeds = {0.8, 1.4, 2.2};
  s.safety_angles = 9;
  s.max_pot_lines = 5;
  s.combinations = true;
  s.placements = 8;
  s.sweep_headings = 90;
  s.break_speeds = {7.0, 8.0};
  s.robust_top = 8;
  s.robust_steps = 4;
  s.lookahead_top = 4;
  s.lookahead_lines = 2;
  s.lookahead_speeds = {1.2, 2.5};
  s.lookahead_tips = {{0.0, 0.0}, {0.0, 0.3}, {0.0, -0.3}};
  s.push_out_headings = 24;
  s.group_sense = true;
}

void searchLikeAnExpert(LevelSettings& s) {
  s.pot_speeds = {0.7, 1.0, 1.4, 1.9, 2.5, 3.2, 4.2, 5.5};
  s.tips = {{0.0, 0.0},  {0.0, 0.2},   {0.0, 0.4},    {0.0, -0.2},   {0.0, -0.4},   {0.3, 0.0},
            {-0.3, 0.0}, {0.25, 0.25}, {-0.25, 0.25}, {0.25, -0.25}, {-0.25, -0.25}};
  s.safety_speeds = {0.7, 1.1, 1.6, 2.4};
  s.safety_angles = 13;
  s.pocket_aims = 3;
  s.max_pot_lines = 8;
  s.combinations = true;
  s.banks = true;
  s.kicks = true;
  s.placements = 16;
  s.sweep_headings = 240;
  s.break_speeds = {8.0, 9.5};
  s.robust_top = 12;
  s.robust_steps = 5;
  s.lookahead_top = 6;
  s.lookahead_lines = 3;
  s.lookahead_speeds = {1.0, 1.9, 3.2};
  s.lookahead_tips = {{0.0, 0.0}, {0.0, 0.3}, {0.0, -0.3}};
  s.push_out_headings = 36;
  s.group_sense = true;
}

// An expert's search without side spin or banks, aiming at two points of each pocket.
void searchLikeALeaguePlayer(LevelSettings& s) {
  searchLikeAnExpert(s);
  s.tips = {{0.0, 0.0}, {0.0, 0.2}, {0.0, 0.4}, {0.0, -0.2}, {0.0, -0.4}};
  s.pocket_aims = 2;
  s.max_pot_lines = 6;
  s.banks = false;
  s.placements = 12;
  s.sweep_headings = 150;
  s.break_speeds = {7.5, 8.5};
  s.robust_top = 10;
  s.robust_steps = 4;
  s.lookahead_top = 5;
  s.push_out_headings = 30;
}

// Carom: how finely each level looks round the table, with which strokes, and whether it
// checks its choice against its cueing and plays for the next point.
void caromLikeABeginner(CaromSearch& c) {
  c.heading_step_deg = 3.0;
  c.speeds = {2.5, 3.5};
  c.tips = {{0.0, 0.0}, {0.3, 0.2}, {-0.3, 0.2}};
}

void caromLikeACasualPlayer(CaromSearch& c) {
  caromLikeABeginner(c);
  c.heading_step_deg = 2.0;
  c.robust_top = 4;
}

void caromLikeAClubPlayer(CaromSearch& c) {
  c.heading_step_deg = 1.0;
  c.fine_step_deg = 0.5;
  c.speeds = {2.5, 3.5, 4.5};
  c.tips = {{0.0, 0.0}, {0.35, 0.2}, {-0.35, 0.2}, {0.35, -0.2}, {-0.35, -0.2}};
  c.robust_top = 6;
}

void caromLikeALeaguePlayer(CaromSearch& c) {
  caromLikeAClubPlayer(c);
  c.robust_top = 8;
}

// + finer across the balls, and the next point looked for from the best three.
void caromLikeAnExpert(CaromSearch& c) {
  caromLikeALeaguePlayer(c);
  c.fine_step_deg = 0.25;
  c.robust_top = 10;
  c.position_top = 3;
  c.position_headings = 40;
  c.position_weight = 0.5;
}

// + a raised cue (15 degrees) with running side, for swerve round a ball.
void caromLikeAMaster(CaromSearch& c) {
  caromLikeAnExpert(c);
  c.robust_top = 12;
  c.position_top = 4;
  c.position_headings = 48;
  c.raised_elevations_deg = {15.0};
  c.raised_step_deg = 3.0;
}

// The finest errors a level's candidates are checked against (degrees; relative speed).
constexpr double kFinestCheckedAimDeg = 0.15;
constexpr double kFinestCheckedSpeed = 0.03;

// How a level cues (docs/ai.md, "The stroke model"): the heading's deviation on an easy stroke,
// its growth with cut, reach and pace, the speed's relative deviation and the tip's, m.
struct StrokeNoise {
  double aim_deg, cut_growth, reach_growth, pace_growth, speed, tip_m;
};

void cue(LevelSettings& s, const StrokeNoise& k) {
  s.aim_noise_deg = k.aim_deg;
  s.cut_growth = k.cut_growth;
  s.reach_growth = k.reach_growth;
  s.pace_growth = k.pace_growth;
  s.speed_noise = k.speed;
  s.tip_noise_m = k.tip_m;
  // The level checks its candidates against somewhat larger errors than it makes on an easy
  // stroke (its usual strokes are harder), and never against finer ones than a pro's.
  s.robust_aim_deg = std::max(kFinestCheckedAimDeg, 1.5 * k.aim_deg);
  s.robust_speed = std::max(kFinestCheckedSpeed, 1.5 * k.speed);
}

// The strongest jump the cue ball over a ball in the way; the rest kick round it. A raised cue is
// harder to hold steady than a level one: the elevation errs by `elevation_deg` on a jump.
void jumpLike(LevelSettings& s, double elevation_deg) {
  s.jumps = true;
  s.jump_elevation_noise_deg = elevation_deg;
}

}  // namespace

LevelSettings LevelSettings::of(Level level) {
  LevelSettings s;
  switch (level) {
    case Level::Beginner:
      searchLikeABeginner(s);
      caromLikeABeginner(s.carom);
      cue(s, {2.2, 1.0, 0.5, 0.5, 0.12, 0.004});
      break;
    case Level::Casual:
      searchLikeACasualPlayer(s);
      caromLikeACasualPlayer(s.carom);
      cue(s, {1.2, 0.8, 0.4, 0.4, 0.08, 0.003});
      break;
    case Level::Club:
      searchLikeAClubPlayer(s);
      caromLikeAClubPlayer(s.carom);
      cue(s, {0.32, 0.6, 0.35, 0.35, 0.05, 0.002});
      break;
    case Level::League:
      searchLikeALeaguePlayer(s);
      caromLikeALeaguePlayer(s.carom);
      cue(s, {0.16, 0.45, 0.3, 0.3, 0.035, 0.0012});
      break;
    case Level::Advanced:
      searchLikeAnExpert(s);
      caromLikeAnExpert(s.carom);
      cue(s, {0.15, 0.4, 0.25, 0.25, 0.03, 0.001});
      break;
    case Level::Pro:
      searchLikeAnExpert(s);
      caromLikeAMaster(s.carom);
      cue(s, {0.13, 0.3, 0.2, 0.2, 0.025, 0.0006});
      jumpLike(s, 1.0);
      break;
    case Level::Master:
      searchLikeAnExpert(s);
      caromLikeAMaster(s.carom);
      cue(s, {0.05, 0.15, 0.1, 0.1, 0.015, 0.0002});
      jumpLike(s, 0.5);
      break;
  }
  return s;
}

}  // namespace nineball::ai
