#include "app/plan_command.hpp"

#include <istream>
#include <ostream>

#include "app/exit_codes.hpp"
#include "app/read_input.hpp"
#include "common/log.hpp"
#include "io/plan_json.hpp"

namespace nineball::app {

CLI::App* addPlanCommand(CLI::App& app, PlanOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "plan", "Print the shot the computer opponent would play from a JSON scene");
  cmd->add_option("scene", options.scene_path, "Scene file, or - to read standard input")
      ->required();
  return cmd;
}

int runPlan(const PlanOptions& options, std::istream& in, std::ostream& out, std::ostream& err) {
  const std::string prefix = "nineball plan: " + shownPath(options.scene_path) + ": ";
  std::string why;
  const auto text = readInput(options.scene_path, in, why);
  if (!text) {
    err << prefix << why << '\n';
    return kExitBadInput;
  }
  auto parsed = io::parsePlanScene(*text);
  if (const auto* refused = std::get_if<io::ParseError>(&parsed)) {
    err << prefix << refused->message << '\n';
    return kExitBadInput;
  }
  const io::PlanScene& scene = std::get<io::PlanScene>(parsed);
  ai::Planner planner(scene.level);
  const ai::Plan plan = planner.plan(scene.input);
  logger("app")->info("plan: {} of ball {} worth {:.3f} after {} simulations",
                      ai::shotKindName(plan.kind), plan.target, plan.value, plan.simulations);
  out << io::planToJson(plan).dump(2) << '\n' << std::flush;
  return out ? kExitOk : kExitInternal;
}

}  // namespace nineball::app
