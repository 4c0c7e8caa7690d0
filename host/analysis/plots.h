// Plots written directly as SVG (no plotting dependency): log-log error against time, one line per series.
#pragma once
#include <string>
#include <vector>

namespace vkmc {

struct PlotSeries {
  std::string label;
  std::vector<double> x, y;  // positive values
};

// A complete SVG document: log-log axes with decade ticks and labels, one polyline per series, a legend.
std::string logLogSvg(const std::vector<PlotSeries>& series, const std::string& title, const std::string& xLabel,
                      const std::string& yLabel);

// Least-squares slope and intercept of log y against log x.
struct LogFit {
  double slope = 0.0, intercept = 0.0;
  double at(double x) const;       // y at x
  double inverse(double y) const;  // x at y
};
LogFit fitLogLog(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace vkmc
