#pragma once

#include <optional>
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

/// A run time with no error by definition (the reference engine, the yardstick of the errors):
/// drawn as a labelled vertical line, its marker on the bottom of the error axis, which a log
/// axis cannot take to zero. Not part of the Pareto front.
struct ReferenceMark {
  double time_ms;
  std::string label;
};

/// An SVG scatter of error against run time, both axes logarithmic, the Pareto front joined
/// and marked, the target (error 1) drawn as a line, and the reference's run time if given.
std::string errorTimePlot(const std::vector<PlotPoint>& points, const std::string& title,
                          const std::optional<ReferenceMark>& reference = std::nullopt);

}  // namespace nineball::app
