#include "app/sim_command.hpp"

#include <cmath>
#include <istream>
#include <optional>
#include <ostream>

#include "app/exit_codes.hpp"
#include "app/read_input.hpp"
#include "app/shot_svg.hpp"
#include "common/atomic_file.hpp"
#include "common/limits.hpp"
#include "common/log.hpp"
#include "io/result_json.hpp"
#include "io/scene_json.hpp"

namespace nineball::app {

std::string traceTruncatedNote(const Trace& trace) {
  double last = 0.0;
  if (!trace.balls.empty() && trace.balls.front().size() > 0) last = trace.balls.front().t.back();
  return "the trace ends at t = " + std::to_string(last) + " s: the run needed more than " +
         std::to_string(limits::kMaxTraceSamples) + " samples (balls x instants)";
}

namespace {
ShotPngWriter g_png_writer = nullptr;
}  // namespace

void setShotPngWriter(ShotPngWriter writer) {
  g_png_writer = writer;
}

bool haveShotPngWriter() {
  return g_png_writer != nullptr;
}

CLI::App* addSimCommand(CLI::App& app, SimOptions& options) {
  CLI::App* sim =
      app.add_subcommand("sim", "Simulate a JSON scene and print the result as JSON on stdout");
  sim->add_option("scene", options.scene_path, "Scene file, or - to read standard input")
      ->required();
  sim->add_flag("--jsonl", options.jsonl,
                "One scene per line in, one result per line out (a bad line gets an error "
                "object on its line and the rest go on)");
  sim->add_option("--svg", options.svg_path,
                  "Also draw the shot (table, paths, events) into this SVG file");
  sim->add_option("--png", options.png_path,
                  "Also draw the shot with the game's renderer into this PNG file (needs a "
                  "display: xvfb-run -a nineball sim ...)");
  return sim;
}

int runSim(const SimOptions& options, std::istream& in, std::ostream& out, std::ostream& err) {
  std::string why;
  for (const auto& [flag, path] :
       {std::pair{"--svg", &options.svg_path}, {"--png", &options.png_path}}) {
    if (!*path) continue;
    if (options.jsonl) {
      err << "nineball sim: " << flag << " draws one scene and cannot be used with --jsonl\n";
      return kExitBadInput;
    }
    // Refused before the run, not after it.
    if (!canWriteFile(**path, why)) {
      err << "nineball sim: " << flag << ": " << why << '\n';
      return kExitBadInput;
    }
  }
  if (options.png_path && !g_png_writer) {
    err << "nineball sim: --png: this program has no renderer (run nineball, which starts "
           "nineball-game for it)\n";
    return kExitInternal;
  }
  if (options.jsonl) return runSimLines(options, in, out, err);
  const std::string shown = shownPath(options.scene_path);
  const std::string prefix = "nineball sim: " + shown + ": ";
  const auto text = readInput(options.scene_path, in, why);
  if (!text) {
    err << prefix << why << '\n';
    return kExitBadInput;
  }
  auto parsed = io::parseScene(*text);
  if (const auto* refused = std::get_if<io::ParseError>(&parsed)) {
    err << prefix << refused->message << '\n';
    return kExitBadInput;
  }
  const Scene& scene = std::get<Scene>(parsed);
  logger("app")->debug("{}: {} balls, {}", shown, scene.balls.size(),
                       scene.until ? "for " + std::to_string(*scene.until) + " s" : "until rest");
  SimResult result;
  if (options.svg_path || options.png_path) {
    // The picture traces at its own rate; the printed result keeps the scene's own trace.
    Scene traced = scene;
    traced.trace = TraceRequest{kShotSvgHz, false};
    const SimResult pictured = simulate(traced);
    if (const auto fault = resultFault(traced, pictured)) {
      err << prefix << "internal error: " << *fault << '\n';
      return kExitInternal;
    }
    if (options.svg_path &&
        !writeFileAtomically(*options.svg_path, shotSvg(scene, pictured), why)) {
      err << "nineball sim: --svg: " << why << '\n';
      return kExitBadInput;
    }
    if (options.png_path && !g_png_writer(scene, pictured, *options.png_path, why)) {
      err << "nineball sim: --png: " << why << '\n';
      return kExitBadInput;
    }
    if (scene.trace) {
      result = simulate(scene);
    } else {
      result = pictured;
      result.trace.reset();
    }
  } else {
    result = simulate(scene);
  }
  if (const auto fault = resultFault(scene, result)) {
    err << prefix << "internal error: " << *fault << '\n';
    return kExitInternal;
  }
  io::writeResult(out, result, true);
  out << '\n' << std::flush;
  if (!out) return kExitInternal;
  if (result.trace && result.trace->truncated) {
    err << prefix << traceTruncatedNote(*result.trace) << '\n';
  }
  if (result.end == SimEnd::MaxTime) {
    err << prefix << "stopped at step.max_time (" << scene.step.max_time
        << " s of simulated time) with balls still moving: the result is partial\n";
    return kExitPartial;
  }
  if (result.end == SimEnd::Budget) {
    err << prefix << "stopped at the work budget (" << result.budget << ") at t = " << result.time
        << " s with balls still moving: the result is partial\n";
    return kExitPartial;
  }
  return kExitOk;
}

}  // namespace nineball::app
