// SVG plots and log-log fits.
#include "analysis/plots.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace vkmc {
namespace {

std::string escapeXml(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

const char* kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                         "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};

}  // namespace

double LogFit::at(double x) const { return std::exp(intercept + slope * std::log(x)); }
double LogFit::inverse(double y) const { return slope != 0.0 ? std::exp((std::log(y) - intercept) / slope) : 0.0; }

LogFit fitLogLog(const std::vector<double>& x, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
    if (!(x[i] > 0.0) || !(y[i] > 0.0)) continue;
    double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
    ++n;
  }
  LogFit f;
  double den = n * sxx - sx * sx;
  if (n >= 2 && den != 0.0) {
    f.slope = (n * sxy - sx * sy) / den;
    f.intercept = (sy - f.slope * sx) / n;
  } else if (n == 1) {
    f.intercept = sy;
  }
  return f;
}

std::string logLogSvg(const std::vector<PlotSeries>& series, const std::string& title, const std::string& xLabel,
                      const std::string& yLabel) {
  const double width = 720, height = 480, left = 80, right = 220, top = 40, bottom = 60;
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  for (const auto& s : series)
    for (size_t i = 0; i < s.x.size(); ++i) {
      if (!(s.x[i] > 0) || !(s.y[i] > 0)) continue;
      xmin = std::min(xmin, s.x[i]), xmax = std::max(xmax, s.x[i]);
      ymin = std::min(ymin, s.y[i]), ymax = std::max(ymax, s.y[i]);
    }
  if (xmin > xmax) xmin = 0.1, xmax = 10, ymin = 0.1, ymax = 10;
  double lx0 = std::floor(std::log10(xmin)), lx1 = std::ceil(std::log10(xmax));
  double ly0 = std::floor(std::log10(ymin)), ly1 = std::ceil(std::log10(ymax));
  if (lx1 == lx0) lx1 += 1;
  if (ly1 == ly0) ly1 += 1;
  double pw = width - left - right, ph = height - top - bottom;
  auto px = [&](double x) { return left + (std::log10(x) - lx0) / (lx1 - lx0) * pw; };
  auto py = [&](double y) { return top + ph - (std::log10(y) - ly0) / (ly1 - ly0) * ph; };
  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height << "\" viewBox=\"0 0 " << width
    << " " << height << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  o << "<rect x=\"0\" y=\"0\" width=\"" << width << "\" height=\"" << height << "\" fill=\"white\"/>\n";
  o << "<text x=\"" << left + pw / 2 << "\" y=\"24\" text-anchor=\"middle\" font-size=\"15\">" << escapeXml(title) << "</text>\n";
  for (double e = lx0; e <= lx1; e += 1) {
    double x = left + (e - lx0) / (lx1 - lx0) * pw;
    o << "<line x1=\"" << x << "\" y1=\"" << top << "\" x2=\"" << x << "\" y2=\"" << top + ph << "\" stroke=\"#ddd\"/>\n";
    o << "<text x=\"" << x << "\" y=\"" << top + ph + 18 << "\" text-anchor=\"middle\">1e" << int(e) << "</text>\n";
  }
  for (double e = ly0; e <= ly1; e += 1) {
    double y = top + ph - (e - ly0) / (ly1 - ly0) * ph;
    o << "<line x1=\"" << left << "\" y1=\"" << y << "\" x2=\"" << left + pw << "\" y2=\"" << y << "\" stroke=\"#ddd\"/>\n";
    o << "<text x=\"" << left - 8 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">1e" << int(e) << "</text>\n";
  }
  o << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
    << "\" fill=\"none\" stroke=\"black\"/>\n";
  o << "<text x=\"" << left + pw / 2 << "\" y=\"" << height - 16 << "\" text-anchor=\"middle\">" << escapeXml(xLabel)
    << "</text>\n";
  o << "<text x=\"20\" y=\"" << top + ph / 2 << "\" text-anchor=\"middle\" transform=\"rotate(-90 20 " << top + ph / 2 << ")\">"
    << escapeXml(yLabel) << "</text>\n";
  for (size_t k = 0; k < series.size(); ++k) {
    const PlotSeries& s = series[k];
    const char* color = kColors[k % 10];
    o << "<polyline fill=\"none\" stroke=\"" << color << "\" stroke-width=\"2\" points=\"";
    for (size_t i = 0; i < s.x.size(); ++i)
      if (s.x[i] > 0 && s.y[i] > 0) o << px(s.x[i]) << "," << py(s.y[i]) << " ";
    o << "\"><title>" << escapeXml(s.label) << "</title></polyline>\n";
    for (size_t i = 0; i < s.x.size(); ++i)
      if (s.x[i] > 0 && s.y[i] > 0)
        o << "<circle cx=\"" << px(s.x[i]) << "\" cy=\"" << py(s.y[i]) << "\" r=\"3\" fill=\"" << color << "\"/>\n";
    double ly = top + 10 + 20 * k;
    o << "<line x1=\"" << left + pw + 15 << "\" y1=\"" << ly << "\" x2=\"" << left + pw + 40 << "\" y2=\"" << ly << "\" stroke=\""
      << color << "\" stroke-width=\"2\"/>\n";
    o << "<text x=\"" << left + pw + 46 << "\" y=\"" << ly + 4 << "\">" << escapeXml(s.label) << "</text>\n";
  }
  o << "</svg>\n";
  return o.str();
}

}  // namespace vkmc
