#include "nineball/planner.hpp"

namespace nineball::ai {

const char* levelName(Level level) {
  switch (level) {
    case Level::Easy:
      return "easy";
    case Level::Medium:
      return "medium";
    case Level::Hard:
      return "hard";
  }
  return "?";
}

std::optional<Level> levelFromName(const std::string& name) {
  for (Level l : {Level::Easy, Level::Medium, Level::Hard}) {
    if (name == levelName(l)) return l;
  }
  return std::nullopt;
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
  }
  return "?";
}

LevelSettings LevelSettings::of(Level level) {
  LevelSettings s;
  switch (level) {
    case Level::Easy:
      s.pot_speeds = {1.6, 3.0};
      s.tips = {{0.0, 0.0}};
      s.safety_speeds = {1.2};
      s.safety_angles = 5;
      s.pocket_aims = 1;
      s.max_pot_lines = 3;
      s.placements = 3;
      s.sweep_headings = 36;
      s.break_spots = 1;
      s.break_speeds = {9.0};
      s.push_out_headings = 12;
      s.aim_noise_deg = 1.5;
      s.speed_noise = 0.08;
      break;
    case Level::Medium:
      s.pot_speeds = {1.0, 1.8, 3.0, 4.5};
      s.tips = {{0.0, 0.0}, {0.0, 0.3}, {0.0, -0.3}};
      s.safety_speeds = {0.8, 1.4, 2.2};
      s.safety_angles = 9;
      s.pocket_aims = 1;
      s.max_pot_lines = 5;
      s.combinations = true;
      s.placements = 8;
      s.sweep_headings = 90;
      s.break_spots = 1;
      s.break_speeds = {9.0};
      s.robust_top = 8;
      s.robust_steps = 4;
      s.robust_aim_deg = 0.75;
      s.robust_speed = 0.06;
      s.lookahead_top = 4;
      s.lookahead_lines = 2;
      s.lookahead_speeds = {1.2, 2.5};
      s.lookahead_tips = {{0.0, 0.0}, {0.0, 0.3}, {0.0, -0.3}};
      s.push_out_headings = 24;
      s.aim_noise_deg = 0.5;
      s.speed_noise = 0.04;
      break;
    case Level::Hard:
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
      s.break_spots = 1;
      s.break_speeds = {8.0, 9.5};
      s.robust_top = 12;
      s.robust_steps = 5;
      s.robust_aim_deg = 0.15;
      s.robust_speed = 0.03;
      s.lookahead_top = 6;
      s.lookahead_lines = 3;
      s.lookahead_speeds = {1.0, 1.9, 3.2};
      s.lookahead_tips = {{0.0, 0.0}, {0.0, 0.3}, {0.0, -0.3}};
      s.push_out_headings = 36;
      s.aim_noise_deg = 0.1;
      s.speed_noise = 0.02;
      break;
  }
  return s;
}

}  // namespace nineball::ai
