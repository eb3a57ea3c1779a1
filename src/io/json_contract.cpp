#include <stdexcept>

#include "io/match_play.hpp"
#include "io/plan_json.hpp"
#include "io/result_json.hpp"
#include "io/scene_json.hpp"
#include "io/scene_parts.hpp"
#include "nineball/json.hpp"

namespace nineball {

std::variant<Scene, SceneRefusal> readScene(std::string_view text) {
  io::SceneResult parsed = io::parseScene(text);
  if (auto* refused = std::get_if<io::ParseError>(&parsed)) {
    return SceneRefusal{std::move(refused->message)};
  }
  return std::get<Scene>(std::move(parsed));
}

std::string resultJsonText(const SimResult& result) {
  return io::resultToJson(result).dump();
}

std::variant<std::string, SceneRefusal> matchJsonText(std::string_view text) {
  io::MatchScriptResult parsed = io::parseMatchScript(text);
  if (auto* refused = std::get_if<io::ParseError>(&parsed)) {
    return SceneRefusal{std::move(refused->message)};
  }
  io::MatchPlayed played = io::playMatchScript(std::get<io::MatchScript>(parsed));
  switch (played.outcome) {
    case io::MatchPlayed::Outcome::BadTurn:
      return SceneRefusal{std::move(played.why)};
    case io::MatchPlayed::Outcome::ComputerRefused:
      throw std::runtime_error("internal error: " + played.why);
    case io::MatchPlayed::Outcome::Done:
    case io::MatchPlayed::Outcome::Partial:
      break;
  }
  return played.doc.dump();
}

std::optional<std::string> presetJsonText(const std::string& name) {
  const std::optional<PhysicsParams> p = PhysicsParams::preset(name);
  if (!p) return std::nullopt;
  return physicsJsonText(*p);
}

std::string physicsJsonText(const PhysicsParams& p) {
  return io::physicsToJson(p).dump();
}

std::variant<std::string, SceneRefusal> planJsonText(std::string_view text) {
  io::PlanSceneResult parsed = io::parsePlanScene(text);
  if (auto* refused = std::get_if<io::ParseError>(&parsed)) {
    return SceneRefusal{std::move(refused->message)};
  }
  const io::PlanScene& scene = std::get<io::PlanScene>(parsed);
  ai::Planner planner(scene.level);
  return io::planToJson(planner.plan(scene.input)).dump();
}

}  // namespace nineball
