#pragma once

#include <string>
#include <vector>

namespace nineball::app {

/// One measured solver setting on the plot.
struct PlotPoint {
  double time_ms;  ///< x: median run time
  double error;    ///< y: worst error as a multiple of its target
  std::string label;
  bool on_front;  ///< on the Pareto front
  bool chosen;    ///< the default setting
};

/// An SVG scatter of error against run time, both axes logarithmic, the Pareto front joined
/// and marked, the target (error 1) drawn as a line.
std::string errorTimePlot(const std::vector<PlotPoint>& points, const std::string& title);

}  // namespace nineball::app
