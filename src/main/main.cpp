#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstring>
#include <exception>
#include <iostream>

#include "app/ai_bench_command.hpp"
#include "app/bench_command.hpp"
#include "app/break_command.hpp"
#include "app/exit_codes.hpp"
#include "app/fit_command.hpp"
#include "app/game_launcher.hpp"
#include "app/game_options_cli.hpp"
#ifdef NINEBALL_WINDOW
#include "window/game_command.hpp"
#include "window/shot_png.hpp"
#endif
#include "app/match_command.hpp"
#include "app/online_command.hpp"
#include "app/plan_command.hpp"
#include "app/resource_dir.hpp"
#include "app/sim_command.hpp"
#include "app/stress_command.hpp"
#include "common/log.hpp"
#include "net/wire.hpp"

namespace nineball::app {
namespace {

int run(int argc, char** argv) {
  CLI::App app{
      "nineball: pool on a real table's physics. Without a command, opens the game window.",
      "nineball"};
  // Global options may follow the subcommand too.
  app.fallthrough();
  app.require_subcommand(0, 1);

  std::string log_level = "warn";
  app.add_option("--log-level", log_level, "Log level on stderr")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "critical", "off"}))
      ->capture_default_str();
  // Two players online need the same build: this is the name the handshake compares.
  app.set_version_flag("--version", nineball::net::buildId(), "Print the build's name and exit");
  // Hidden (a diagnostic, not a feature): where the icon and desktop files are found.
  bool resource_dir = false;
  app.add_flag("--resource-dir", resource_dir, "Print the resource folder found and exit")
      ->group("");

  SimOptions sim_options;
  CLI::App* sim = addSimCommand(app, sim_options);
  MatchOptions match_options;
  CLI::App* match = addMatchCommand(app, match_options);
  OnlineOptions online_options;
  CLI::App* online = addOnlineCommand(app, online_options);
  PlanOptions plan_options;
  CLI::App* plan = addPlanCommand(app, plan_options);
  AiBenchOptions ai_bench_options;
  CLI::App* ai_bench = addAiBenchCommand(app, ai_bench_options);
  BenchOptions bench_options;
  CLI::App* bench = addBenchCommand(app, bench_options);
  StressCommandOptions stress_options;
  CLI::App* stress = addStressCommand(app, stress_options);
  BreakOptions break_options;
  CLI::App* brk = addBreakCommand(app, break_options);
  FitCommandOptions fit_options;
  CLI::App* fit = addFitCommand(app, fit_options);
  CalibrateCommandOptions calibrate_options;
  CLI::App* calibrate = addCalibrateCommand(app, calibrate_options);
  GameOptions game_options;
  const std::vector<CLI::Option*> game_flags = addGameOptions(app, game_options);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e, std::cout, std::cerr);  // --help
    // Every usage error exits 2, whatever CLI11's own code for it.
    std::cerr << "nineball: " << e.what() << " (nineball --help lists the options)\n";
    return kExitBadInput;
  }
  if (!setLogLevel(log_level)) {
    std::cerr << "nineball: --log-level: unknown level \"" << log_level << "\"\n";
    return kExitBadInput;
  }

  if (app.get_subcommands().size() > 0) {
    for (const CLI::Option* o : game_flags) {
      if (o->count() > 0) {
        std::cerr << "nineball: " << o->get_name() << " is an option of the game window, not of "
                  << app.get_subcommands().front()->get_name()
                  << " (nineball --help lists the options)\n";
        return kExitBadInput;
      }
    }
  }
  if (resource_dir) return printResourceDir(std::cout, std::cerr);
#ifdef NINEBALL_WINDOW
  setShotPngWriter(&window::writeShotPng);
#else
  // Drawing with the game's renderer needs the display libraries: nineball-game has them.
  if (sim->parsed() && sim_options.png_path && !sim_options.jsonl) {
    return launchGameWindow(argv, std::cerr);
  }
#endif
  if (sim->parsed()) return runSim(sim_options, std::cin, std::cout, std::cerr);
  if (match->parsed()) return runMatch(match_options, std::cin, std::cout, std::cerr);
  if (online->parsed()) return runOnline(online_options, std::cin, std::cout, std::cerr);
  if (plan->parsed()) return runPlan(plan_options, std::cin, std::cout, std::cerr);
  if (ai_bench->parsed()) return runAiBench(ai_bench_options, std::cout, std::cerr);
  if (bench->parsed()) return runBench(bench_options, std::cout, std::cerr);
  if (stress->parsed()) return runStressCommand(stress_options, std::cout);
  if (brk->parsed()) return runBreak(break_options, std::cout, std::cerr);
  if (fit->parsed()) return runFit(fit_options, std::cin, std::cout, std::cerr);
  if (calibrate->parsed()) {
    return runCalibrate(calibrate_options, std::cin, std::cout, std::cerr);
  }
#ifdef NINEBALL_WINDOW
  return window::runGameCommand(game_options, std::cin, std::cerr);
#else
  return launchGameWindow(argv, std::cerr);
#endif
}

}  // namespace
}  // namespace nineball::app

int main(int argc, char** argv) {
  try {
    const int status = nineball::app::run(argc, argv);
    // Output that could not be written (a full disk, a closed pipe) is said, never silent.
    std::cout.flush();
    if (!std::cout) {
      std::cerr << "nineball: cannot write to standard output: "
                << (errno ? std::strerror(errno) : "write error") << '\n';
      return nineball::app::kExitBadInput;
    }
    return status;
  } catch (const std::exception& e) {
    std::cerr << "nineball: internal error: " << e.what() << '\n';
  } catch (...) {
    std::cerr << "nineball: internal error: unknown exception\n";
  }
  return nineball::app::kExitInternal;
}
