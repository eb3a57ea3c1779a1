#include "app/bench_command.hpp"

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <sstream>
#include <vector>

#include "accuracy/accuracy.hpp"
#include "accuracy/whole_shots.hpp"
#include "app/exit_codes.hpp"
#include "app/svg_plot.hpp"
#include "common/atomic_file.hpp"

namespace nineball::app {
namespace {

struct Row {
  StepParams step;
  std::vector<CaseError> errors;
  BreakTiming timing;  // wall_ms holds the median
  bool on_front = false;
};

StepParams setting(ContactModel contacts, double scale, double hz, int iterations = 8) {
  StepParams s;
  s.box2d.contacts = contacts;
  s.box2d.scale = scale;
  s.hz = hz;
  s.box2d.velocity_iterations = iterations;
  return s;
}

std::vector<StepParams> settings(bool quick) {
  if (quick) return {StepParams{}, StepParams::plainBaseline()};
  std::vector<StepParams> out;
  for (double scale : {10.0, 50.0, 100.0, 200.0}) {
    for (double hz : {30.0, 60.0, 120.0, 250.0, 500.0, 1000.0, 2000.0}) {
      out.push_back(setting(ContactModel::Pairwise, scale, hz));
    }
  }
  for (int iterations : {1, 3}) {
    for (double hz : {60.0, 250.0})
      out.push_back(setting(ContactModel::Pairwise, 100.0, hz, iterations));
  }
  for (double scale : {50.0, 100.0, 200.0}) {
    for (double hz : {60.0, 250.0, 1000.0}) out.push_back(setting(ContactModel::Box2D, scale, hz));
  }
  out.push_back(StepParams::plainBaseline());
  return out;
}

std::string label(const StepParams& s) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s%s k=%g %gHz vi=%d", s.baseline ? "baseline " : "",
                contactModelName(s.box2d.contacts), s.box2d.scale, s.hz,
                s.box2d.velocity_iterations);
  return buf;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

Row measure(const StepParams& step, int repeats) {
  Row row;
  row.step = step;
  row.errors = runAccuracyCases(step);
  // Whole shots, strike to rest, against the reference engine: the worst final position.
  row.errors.push_back({"whole-shot", "mm", compareWholeShots(step).worst_position_mm,
                        kWholeShotPositionToleranceMm});
  std::vector<double> times;
  for (int i = 0; i < repeats; ++i) {
    row.timing = timeBreak(step);
    times.push_back(row.timing.wall_ms);
  }
  row.timing.wall_ms = median(times);
  return row;
}

bool isDefault(const StepParams& s) {
  const StepParams d;
  return !s.baseline && s.box2d.contacts == d.box2d.contacts && s.box2d.scale == d.box2d.scale &&
         s.hz == d.hz && s.box2d.velocity_iterations == d.box2d.velocity_iterations;
}

std::string sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, " %9.2e", v);
  return buf;
}

// Default against baseline, and spin against the paper's cloth, each pair interleaved so that
// both sides see the same machine load.
void compareInterleaved(std::ostream& out, int repeats) {
  std::vector<double> fast, slow;
  BreakTiming f{}, b{};
  for (int i = 0; i < repeats; ++i) {
    f = timeBreak(StepParams{});
    b = timeBreak(StepParams::plainBaseline());
    fast.push_back(f.wall_ms);
    slow.push_back(b.wall_ms);
  }
  const double mf = median(fast), mb = median(slow);
  char line[512];
  std::snprintf(line, sizeof line,
                "\nbreak to rest, medians of %d interleaved runs: default %.2f ms (%ld steps, "
                "%.2f s simulated); baseline %.2f ms (%ld steps, %.2f s simulated); "
                "%.1f times faster\n",
                repeats, mf, f.steps, f.sim_time, mb, b.steps, b.sim_time, mb / mf);
  out << line;

  PhysicsParams no_spin = PhysicsParams::real();
  no_spin.cloth = ClothModel::Friction;
  std::vector<double> with_step, without_step, with_ms, without_ms;
  BreakTiming s{}, p{};
  for (int i = 0; i < repeats; ++i) {
    s = timeBreak(StepParams{});
    p = timeBreak(StepParams{}, no_spin);
    with_step.push_back(s.wall_ms / static_cast<double>(s.steps) * 1000.0);
    without_step.push_back(p.wall_ms / static_cast<double>(p.steps) * 1000.0);
    with_ms.push_back(s.wall_ms);
    without_ms.push_back(p.wall_ms);
  }
  const double ws = median(with_step), wo = median(without_step);
  const double wm = median(with_ms), om = median(without_ms);
  std::snprintf(line, sizeof line,
                "spin cost, medians of %d interleaved runs: with spin %.2f us/step, break %.2f ms "
                "(%.2f s simulated); without %.2f us/step, break %.2f ms (%.2f s simulated); "
                "ratio per step %.2f, per break %.2f\n",
                repeats, ws, wm, s.sim_time, wo, om, p.sim_time, ws / wo, wm / om);
  out << line;
}

StepParams referenceStep() {
  StepParams s;
  s.engine = EngineKind::named("reference");
  return s;
}

// The reference engine's own break to rest, interleaved with the default's. Returns its median.
double referenceTiming(std::ostream& out, int repeats) {
  std::vector<double> reference, box2d;
  BreakTiming r{}, d{};
  for (int i = 0; i < repeats; ++i) {
    r = timeBreak(referenceStep());
    d = timeBreak(StepParams{});
    reference.push_back(r.wall_ms);
    box2d.push_back(d.wall_ms);
  }
  const double mr = median(reference), md = median(box2d);
  char line[320];
  std::snprintf(line, sizeof line,
                "reference engine (exact, event-based; error 0 by definition), break to rest, "
                "medians of %d interleaved runs: %.2f ms (%.2f s simulated); default %.2f ms; "
                "ratio default / reference %.2f\n",
                repeats, mr, r.sim_time, md, md / mr);
  out << line;
  return mr;
}

void rackGaps(std::ostream& out) {
  out << "\ncue ball after the break (vx / break speed at 0.3 s), by rack gap:\n";
  for (ContactModel contacts : {ContactModel::Pairwise, ContactModel::Box2D}) {
    StepParams s;
    s.box2d.contacts = contacts;
    out << "  " << contactModelName(contacts) << ':';
    for (double gap : {0.0, 1e-4, 5e-4}) {
      char cell[64];
      std::snprintf(cell, sizeof cell, "  gap %.1f mm %+.3f", gap * 1000.0,
                    breakCueRebound(s, gap));
      out << cell;
    }
    out << '\n';
  }
}

}  // namespace

CLI::App* addBenchCommand(CLI::App& app, BenchOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "bench", "Sweep solver settings: worst error of each canonical case against break run time");
  cmd->add_option("--repeats", options.repeats, "Timed breaks per setting (median reported)")
      ->check(CLI::Range(1, 1000));
  cmd->add_flag("--quick", options.quick, "Measure the default setting and the baseline only");
  cmd->add_option("--csv", options.csv_path, "Also write the table as CSV to this file");
  cmd->add_option("--svg", options.svg_path, "Also plot error against run time (SVG)");
  return cmd;
}

int runBench(const BenchOptions& options, std::ostream& out, std::ostream& err) {
  // A destination that cannot be written is refused before minutes of measuring, not after.
  for (const std::string* path : {&options.csv_path, &options.svg_path}) {
    std::string why;
    if (!path->empty() && !canWriteFile(*path, why)) {
      err << "nineball bench: " << why << '\n';
      return kExitBadInput;
    }
  }
  std::vector<Row> rows;
  for (const StepParams& s : settings(options.quick)) rows.push_back(measure(s, options.repeats));
  std::vector<std::pair<double, double>> points;
  for (const Row& r : rows) points.emplace_back(r.timing.wall_ms, worstScore(r.errors));
  const std::vector<bool> front = paretoFront(points);
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i].on_front = front[i];

  std::ostringstream csv;
  csv << "setting,contacts,scale,hz,velocity_iterations,baseline,break_sim_s,break_steps,"
         "break_wall_ms_median,worst_over_target,pareto";
  out << "setting                          sim s  steps  wall ms  worst/target front |";
  for (const CaseError& e : rows.front().errors) {
    csv << ',' << e.name << '_' << (e.unit == "%" ? "pct" : e.unit);
    out << ' ' << e.name << " (" << e.unit << ")";
  }
  csv << '\n';
  out << '\n';
  std::vector<PlotPoint> plot;
  for (const Row& r : rows) {
    const double score = worstScore(r.errors);
    csv << label(r.step) << ',' << contactModelName(r.step.box2d.contacts) << ','
        << r.step.box2d.scale << ',' << r.step.hz << ',' << r.step.box2d.velocity_iterations << ','
        << r.step.baseline << ',' << r.timing.sim_time << ',' << r.timing.steps << ','
        << r.timing.wall_ms << ',' << score << ',' << r.on_front;
    char head[160];
    std::snprintf(head, sizeof head, "%-30s %7.2f %6ld %8.2f %12.2e %5s |", label(r.step).c_str(),
                  r.timing.sim_time, r.timing.steps, r.timing.wall_ms, score,
                  r.on_front ? "*" : "");
    out << head;
    for (const CaseError& e : r.errors) {
      csv << ',' << e.worst;
      out << sci(e.worst);
    }
    csv << '\n';
    out << '\n';
    plot.push_back({r.timing.wall_ms, score, label(r.step), r.on_front, isDefault(r.step)});
  }
  compareInterleaved(out, std::max(options.repeats, 5));
  const double reference_ms = referenceTiming(out, std::max(options.repeats, 5));
  rackGaps(out);

  std::string why;
  if (!options.csv_path.empty() && !writeFileAtomically(options.csv_path, csv.str(), why)) {
    err << "nineball bench: " << why << '\n';
    return kExitBadInput;
  }
  if (!options.svg_path.empty() &&
      !writeFileAtomically(options.svg_path,
                           errorTimePlot(plot,
                                         "nineball: error against run time per solver "
                                         "setting (break to rest)",
                                         ReferenceMark{reference_ms, "reference engine"}),
                           why)) {
    err << "nineball bench: " << why << '\n';
    return kExitBadInput;
  }
  return out ? kExitOk : kExitInternal;
}

}  // namespace nineball::app
