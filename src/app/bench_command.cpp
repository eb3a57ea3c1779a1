#include "app/bench_command.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <sstream>
#include <vector>

#include "app/exit_codes.hpp"
#include "nineball/accuracy.hpp"

namespace nineball::app {
namespace {

struct Row {
  StepParams step;
  std::vector<CaseError> errors;
  BreakTiming timing;  // wall_ms holds the median
};

std::vector<StepParams> settings(bool quick) {
  std::vector<StepParams> out;
  if (quick) return {StepParams{}};
  for (ContactModel contacts : {ContactModel::Pairwise, ContactModel::Box2D}) {
    for (double scale : {1.0, 10.0, 50.0, 100.0, 200.0}) {
      for (double hz : {250.0, 500.0, 1000.0, 2000.0}) {
        StepParams s;
        s.scale = scale;
        s.hz = hz;
        s.contacts = contacts;
        out.push_back(s);
      }
    }
  }
  return out;
}

Row measure(const StepParams& step, int repeats) {
  Row row;
  row.step = step;
  row.errors = runAccuracyCases(step);
  std::vector<double> times;
  for (int i = 0; i < repeats; ++i) {
    row.timing = timeBreak(step);
    times.push_back(row.timing.wall_ms);
  }
  std::sort(times.begin(), times.end());
  row.timing.wall_ms = times[times.size() / 2];
  return row;
}

std::string scientific(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%9.2e", v);
  return buf;
}

}  // namespace

CLI::App* addBenchCommand(CLI::App& app, BenchOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "bench", "Sweep solver settings: worst error of each canonical case and break run time");
  cmd->add_option("--repeats", options.repeats, "Timed breaks per setting (median reported)")
      ->check(CLI::Range(1, 1000));
  cmd->add_flag("--quick", options.quick, "Measure the default setting only");
  cmd->add_option("--csv", options.csv_path, "Also write the table as CSV to this file");
  return cmd;
}

int runBench(const BenchOptions& options, std::ostream& out, std::ostream& err) {
  std::vector<Row> rows;
  for (const StepParams& s : settings(options.quick)) rows.push_back(measure(s, options.repeats));

  std::ostringstream csv;
  csv << "contacts,scale,hz,break_sim_s,break_steps,break_wall_ms_median";
  for (const CaseError& e : rows.front().errors)
    csv << ',' << e.name << '_' << (e.unit == "%" ? "pct" : e.unit);
  csv << '\n';
  out << "contacts  scale     hz  break: sim s  steps  wall ms |";
  for (const CaseError& e : rows.front().errors) out << ' ' << e.name << " (" << e.unit << ")";
  out << '\n';
  for (const Row& r : rows) {
    csv << contactModelName(r.step.contacts) << ',' << r.step.scale << ',' << r.step.hz << ','
        << r.timing.sim_time << ',' << r.timing.steps << ',' << r.timing.wall_ms;
    char head[128];
    std::snprintf(head, sizeof head, "%-8s %6.0f %6.0f  %12.2f %6ld %8.2f |",
                  contactModelName(r.step.contacts), r.step.scale, r.step.hz, r.timing.sim_time,
                  r.timing.steps, r.timing.wall_ms);
    out << head;
    for (const CaseError& e : r.errors) {
      csv << ',' << e.worst;
      out << ' ' << scientific(e.worst);
    }
    csv << '\n';
    out << '\n';
  }
  // Spin against the paper's cloth, interleaved so that both see the same machine load.
  {
    PhysicsParams no_spin = PhysicsParams::real();
    no_spin.cloth = ClothModel::Friction;
    std::vector<double> with, without, with_ms, without_ms;
    BreakTiming spin_run, plain_run;
    for (int i = 0; i < std::max(options.repeats, 5); ++i) {
      spin_run = timeBreak(StepParams{});
      plain_run = timeBreak(StepParams{}, no_spin);
      with.push_back(spin_run.wall_ms / static_cast<double>(spin_run.steps));
      without.push_back(plain_run.wall_ms / static_cast<double>(plain_run.steps));
      with_ms.push_back(spin_run.wall_ms);
      without_ms.push_back(plain_run.wall_ms);
    }
    for (auto* v : {&with_ms, &without_ms}) std::sort(v->begin(), v->end());
    std::sort(with.begin(), with.end());
    std::sort(without.begin(), without.end());
    const double a = with[with.size() / 2] * 1000.0, b = without[without.size() / 2] * 1000.0;
    const double ma = with_ms[with_ms.size() / 2], mb = without_ms[without_ms.size() / 2];
    char line[512];
    std::snprintf(line, sizeof line,
                  "\nspin cost (default settings, medians of %zu runs): with spin %.2f us/step, "
                  "break %.2f ms (%.2f s simulated); without %.2f us/step, break %.2f ms "
                  "(%.2f s simulated); ratio per step %.2f, per break %.2f\n",
                  with.size(), a, ma, spin_run.sim_time, b, mb, plain_run.sim_time, a / b, ma / mb);
    out << line;
  }
  out << "\ncue ball after the break (vx / break speed at 0.3 s), by rack gap:\n";
  for (ContactModel contacts : {ContactModel::Pairwise, ContactModel::Box2D}) {
    StepParams s;
    s.contacts = contacts;
    out << "  " << contactModelName(contacts) << ':';
    for (double gap : {0.0, 1e-4, 5e-4}) {
      char cell[64];
      std::snprintf(cell, sizeof cell, "  gap %.1f mm %+.3f", gap * 1000.0,
                    breakCueRebound(s, gap));
      out << cell;
    }
    out << '\n';
  }
  if (!options.csv_path.empty()) {
    // Written whole or not at all: to a temporary name, then renamed.
    const std::string tmp = options.csv_path + ".tmp";
    {
      std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
      f << csv.str();
      if (!f.flush()) {
        err << "nineball bench: cannot write " << options.csv_path << '\n';
        std::remove(tmp.c_str());
        return kExitBadInput;
      }
    }
    if (std::rename(tmp.c_str(), options.csv_path.c_str()) != 0) {
      err << "nineball bench: cannot write " << options.csv_path << '\n';
      std::remove(tmp.c_str());
      return kExitBadInput;
    }
  }
  return out ? kExitOk : kExitInternal;
}

}  // namespace nineball::app
