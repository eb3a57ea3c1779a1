#include "app/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace nineball::app {
namespace {

constexpr double kWidth = 900.0, kHeight = 560.0;
constexpr double kLeft = 80.0, kRight = 250.0, kTop = 50.0, kBottom = 60.0;
// Errors of exactly zero still need a place on a log axis.
constexpr double kErrorFloor = 1e-7;

std::string axisNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') {
      out += "&lt;";
    } else if (c == '>') {
      out += "&gt;";
    } else if (c == '&') {
      out += "&amp;";
    } else {
      out += c;
    }
  }
  return out;
}

struct LogAxis {
  double lo, hi;  // decades
  double span;
  double at(double v) const { return (std::log10(v) - lo) / (hi - lo) * span; }
};

}  // namespace

std::string errorTimePlot(const std::vector<PlotPoint>& points, const std::string& title,
                          const std::optional<ReferenceMark>& reference) {
  double tmin = 1e300, tmax = 0.0, emin = 1e300, emax = 0.0;
  for (const PlotPoint& p : points) {
    tmin = std::min(tmin, p.time_ms);
    tmax = std::max(tmax, p.time_ms);
    emin = std::min(emin, std::max(p.error, kErrorFloor));
    emax = std::max(emax, std::max(p.error, kErrorFloor));
  }
  if (reference) {
    tmin = std::min(tmin, reference->time_ms);
    tmax = std::max(tmax, reference->time_ms);
  }
  emax = std::max(emax, 1.0);
  const double plot_w = kWidth - kLeft - kRight, plot_h = kHeight - kTop - kBottom;
  const LogAxis x{std::floor(std::log10(tmin)), std::ceil(std::log10(tmax)), plot_w};
  // A point near the bottom decade line gets a decade below it, not a seat on the axis.
  const LogAxis y{std::floor(std::log10(emin) - 0.3), std::ceil(std::log10(emax)), plot_h};
  auto px = [&](double t) { return kLeft + x.at(t); };
  auto py = [&](double e) { return kTop + plot_h - y.at(std::max(e, kErrorFloor)); };

  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << kHeight
      << "\" font-family=\"DejaVu Sans, sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << kLeft << "\" y=\"28\" font-size=\"16\">" << escape(title) << "</text>\n";
  for (double d = x.lo; d <= x.hi; d += 1.0) {
    const double xp = px(std::pow(10.0, d));
    svg << "<line x1=\"" << axisNumber(xp) << "\" y1=\"" << kTop << "\" x2=\"" << axisNumber(xp)
        << "\" y2=\"" << kTop + plot_h << "\" stroke=\"#ddd\"/>\n<text x=\"" << axisNumber(xp)
        << "\" y=\"" << kTop + plot_h + 18 << "\" text-anchor=\"middle\">" << std::pow(10.0, d)
        << "</text>\n";
  }
  for (double d = y.lo; d <= y.hi; d += 1.0) {
    const double yp = py(std::pow(10.0, d));
    svg << "<line x1=\"" << kLeft << "\" y1=\"" << axisNumber(yp) << "\" x2=\"" << kLeft + plot_w
        << "\" y2=\"" << axisNumber(yp) << "\" stroke=\"#ddd\"/>\n<text x=\"" << kLeft - 8
        << "\" y=\"" << axisNumber(yp + 4) << "\" text-anchor=\"end\">1e" << d << "</text>\n";
  }
  svg << "<line x1=\"" << kLeft << "\" y1=\"" << axisNumber(py(1.0)) << "\" x2=\"" << kLeft + plot_w
      << "\" y2=\"" << axisNumber(py(1.0)) << "\" stroke=\"#c00\" stroke-dasharray=\"6,4\"/>\n"
      << "<text x=\"" << kLeft + plot_w - 4 << "\" y=\"" << axisNumber(py(1.0) - 6)
      << "\" text-anchor=\"end\" fill=\"#c00\">every case at its target</text>\n"
      << "<text x=\"" << kLeft + plot_w / 2 << "\" y=\"" << kHeight - 15
      << "\" text-anchor=\"middle\">median wall time of a break to rest (ms, log)</text>\n"
      << "<text transform=\"translate(20," << kTop + plot_h / 2
      << ") rotate(-90)\" text-anchor=\"middle\">worst error / its target (log)</text>\n";

  std::vector<const PlotPoint*> front;
  for (const PlotPoint& p : points) {
    if (p.on_front) front.push_back(&p);
  }
  std::sort(front.begin(), front.end(),
            [](const PlotPoint* a, const PlotPoint* b) { return a->time_ms < b->time_ms; });
  if (front.size() > 1) {
    svg << "<polyline fill=\"none\" stroke=\"#1a7f37\" stroke-width=\"2\" points=\"";
    for (const PlotPoint* p : front)
      svg << axisNumber(px(p->time_ms)) << ',' << axisNumber(py(p->error)) << ' ';
    svg << "\"/>\n";
  }
  for (const PlotPoint& p : points) {
    const std::string colour = p.chosen ? "#d4a000" : p.on_front ? "#1a7f37" : "#888";
    svg << "<circle cx=\"" << axisNumber(px(p.time_ms)) << "\" cy=\"" << axisNumber(py(p.error))
        << "\" r=\"" << (p.chosen ? 7 : 4) << "\" fill=\"" << colour << "\"><title>"
        << escape(p.label) << "</title></circle>\n";
  }
  if (reference) {
    // Error 0 has no place on a log axis: a line at its run time, the marker at the bottom.
    const double xp = px(reference->time_ms), bottom = kTop + plot_h;
    svg << "<line x1=\"" << axisNumber(xp) << "\" y1=\"" << kTop << "\" x2=\"" << axisNumber(xp)
        << "\" y2=\"" << bottom
        << "\" stroke=\"#2457a6\" stroke-width=\"1.5\" stroke-dasharray=\"2,3\"/>\n"
        << "<path d=\"M" << axisNumber(xp) << ',' << axisNumber(bottom - 12)
        << " l7,12 l-14,0 z\" fill=\"#2457a6\">"
        << "<title>" << escape(reference->label) << "</title></path>\n"
        << "<text x=\"" << axisNumber(xp + 5) << "\" y=\"" << axisNumber(kTop + 14)
        << "\" fill=\"#2457a6\">" << escape(reference->label) << "</text>\n"
        << "<text x=\"" << axisNumber(xp + 5) << "\" y=\"" << axisNumber(kTop + 28)
        << "\" fill=\"#2457a6\">(error 0 by definition)</text>\n";
  }
  // The front's settings, listed beside the plot.
  double ly = kTop + 10;
  svg << "<text x=\"" << kWidth - kRight + 15 << "\" y=\"" << ly << "\" fill=\"#1a7f37\">"
      << "Pareto front:</text>\n";
  for (const PlotPoint* p : front) {
    ly += 16;
    svg << "<text x=\"" << kWidth - kRight + 15 << "\" y=\"" << ly << "\""
        << (p->chosen ? " font-weight=\"bold\"" : "") << ">" << escape(p->label)
        << (p->chosen ? " (default)" : "") << "</text>\n";
  }
  svg << "<text x=\"" << kWidth - kRight + 15 << "\" y=\"" << ly + 26
      << "\" fill=\"#888\">grey: dominated</text>\n</svg>\n";
  return svg.str();
}

}  // namespace nineball::app
