// A cut shot built in code and the same scene read as the command line reads it, both
// simulated through the installed library: prints where the object ball stopped each way.
#include <cstdio>
#include <nineball/json.hpp>
#include <nineball/nineball.hpp>
#include <variant>

namespace {

bool report(const char* how, const nineball::Scene& scene) {
  if (auto refused = nineball::validateScene(scene)) {
    std::fprintf(stderr, "%s: scene refused: %s\n", how, refused->c_str());
    return false;
  }
  const nineball::SimResult result = nineball::simulate(scene);
  for (const nineball::BallState& b : result.balls) {
    if (b.id == 1)
      std::printf("%s: %s %.6f %.6f\n", how, nineball::simEndName(result.end), b.pos.x, b.pos.y);
  }
  return true;
}

}  // namespace

int main() {
  nineball::Scene scene;
  scene.balls = {nineball::BallState::at(nineball::kCueBall, {-0.6, 0.0}),
                 nineball::BallState::at(1, {0.0, 0.03})};
  scene.shot = nineball::Shot::withSpeed(0.0, 2.0);
  const auto read = nineball::readScene(
      R"({"balls": [{"id": 0, "x": -0.6, "y": 0}, {"id": 1, "x": 0, "y": 0.03}],
          "shot": {"heading_deg": 0, "speed": 2}})");
  if (const auto* refusal = std::get_if<nineball::SceneRefusal>(&read)) {
    std::fprintf(stderr, "json: %s\n", refusal->message.c_str());
    return 1;
  }
  return report("code", scene) && report("json", std::get<nineball::Scene>(read)) ? 0 : 1;
}
