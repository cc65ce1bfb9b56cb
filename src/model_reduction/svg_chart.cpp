// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// SVG line charts written as text.

#include <CGAL/Model_reduction/errors.h>
#include <CGAL/Model_reduction/svg_chart.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <locale>
#include <ostream>

namespace CGAL {
namespace Model_reduction {

namespace {

const char* const palette[] = {"#1f5fa8", "#d9541e", "#2a9d4b", "#8e44ad", "#c0392b", "#16a5a5", "#b8860b", "#555555"};

std::string escaped(const std::string& text)
{
  std::string out;
  for(char c : text)
  {
    switch(c)
    {
    case '&': out += "&amp;"; break;
    case '<': out += "&lt;"; break;
    case '>': out += "&gt;"; break;
    case '"': out += "&quot;"; break;
    default: out += c;
    }
  }
  return out;
}

std::string number(double x, const char* format = "%g")
{
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, format, x);
  return buffer;
}

// One axis: value -> transformed coordinate, range and ticks.
struct Axis
{
  bool log = false;
  double lo = 0, hi = 1; // transformed
  std::vector<double> ticks; // transformed positions
  std::vector<std::string> labels;

  static bool usable(double v, bool log) { return std::isfinite(v) && (!log || v > 0); }
  double transform(double v) const { return log ? std::log10(v) : v; }

  void fit(double min, double max)
  {
    if(log)
    {
      lo = std::floor(std::log10(min) + 1e-9);
      hi = std::ceil(std::log10(max) - 1e-9);
      if(hi <= lo) hi = lo + 1;
      const bool fine = hi - lo < 3;
      for(int k = static_cast<int>(lo); k <= static_cast<int>(hi); ++k)
      {
        ticks.push_back(k);
        labels.push_back("10^" + std::to_string(k));
        if(fine && k < hi)
          for(double m : {2., 5.})
          {
            ticks.push_back(k + std::log10(m));
            labels.push_back(number(m * std::pow(10., k)));
          }
      }
      return;
    }
    if(!(max > min))
    {
      const double pad = std::max(std::abs(min) * 0.1, 1.);
      min -= pad;
      max += pad;
    }
    const double raw = (max - min) / 5;
    const double magnitude = std::pow(10., std::floor(std::log10(raw)));
    double step = magnitude;
    for(double m : {1., 2., 5., 10.})
      if(m * magnitude >= raw)
      {
        step = m * magnitude;
        break;
      }
    lo = std::floor(min / step) * step;
    hi = std::ceil(max / step) * step;
    for(double t = lo; t <= hi + 0.5 * step; t += step)
    {
      ticks.push_back(std::abs(t) < 1e-12 * step ? 0 : t);
      labels.push_back(number(ticks.back()));
    }
  }
};

// A label "10^k" as SVG text with a superscript, other labels as they are.
std::string label_text(const std::string& label)
{
  if(label.compare(0, 3, "10^") == 0)
    return "10<tspan dy=\"-6\" font-size=\"9\">" + escaped(label.substr(3)) + "</tspan>";
  return escaped(label);
}

} // namespace

void write_svg_line_chart(std::ostream& out, const Line_chart& chart)
{
  if(chart.width < 200 || chart.height < 150) throw Invalid_input("chart: at least 200 x 150 pixels");
  double xmin = HUGE_VAL, xmax = -HUGE_VAL, ymin = HUGE_VAL, ymax = -HUGE_VAL;
  for(const Chart_series& s : chart.series)
  {
    if(s.x.size() != s.y.size())
      throw Invalid_input("chart: series '" + s.name + "' has " + std::to_string(s.x.size()) + " x and " +
                          std::to_string(s.y.size()) + " y values");
    for(std::size_t i = 0; i < s.x.size(); ++i)
      if(Axis::usable(s.x[i], chart.log_x) && Axis::usable(s.y[i], chart.log_y))
      {
        xmin = std::min(xmin, s.x[i]);
        xmax = std::max(xmax, s.x[i]);
        ymin = std::min(ymin, s.y[i]);
        ymax = std::max(ymax, s.y[i]);
      }
  }
  if(!(xmin <= xmax)) throw Invalid_input("chart: no point can be drawn");
  Axis ax, ay;
  ax.log = chart.log_x;
  ay.log = chart.log_y;
  ax.fit(xmin, xmax);
  ay.fit(ymin, ymax);

  const double left = 78, right = 170, top = chart.title.empty() ? 24 : 46, bottom = 58;
  const double pw = chart.width - left - right, ph = chart.height - top - bottom;
  auto px = [&](double v) { return left + (ax.transform(v) - ax.lo) / (ax.hi - ax.lo) * pw; };
  auto py = [&](double v) { return top + ph - (ay.transform(v) - ay.lo) / (ay.hi - ay.lo) * ph; };
  auto tx = [&](double t) { return left + (t - ax.lo) / (ax.hi - ax.lo) * pw; };
  auto ty = [&](double t) { return top + ph - (t - ay.lo) / (ay.hi - ay.lo) * ph; };

  out.imbue(std::locale::classic());
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << chart.width << "\" height=\"" << chart.height
      << "\" viewBox=\"0 0 " << chart.width << ' ' << chart.height
      << "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  if(!chart.title.empty())
    out << "<text x=\"" << left + pw / 2 << "\" y=\"28\" text-anchor=\"middle\" font-size=\"15\">"
        << escaped(chart.title) << "</text>\n";
  // Grid and ticks.
  out << "<g stroke=\"#dddddd\" stroke-width=\"1\">\n";
  for(double t : ax.ticks) out << "<line x1=\"" << tx(t) << "\" y1=\"" << top << "\" x2=\"" << tx(t) << "\" y2=\"" << top + ph << "\"/>\n";
  for(double t : ay.ticks) out << "<line x1=\"" << left << "\" y1=\"" << ty(t) << "\" x2=\"" << left + pw << "\" y2=\"" << ty(t) << "\"/>\n";
  out << "</g>\n<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
      << "\" fill=\"none\" stroke=\"#333333\"/>\n";
  for(std::size_t i = 0; i < ax.ticks.size(); ++i)
    out << "<text class=\"x-tick\" x=\"" << tx(ax.ticks[i]) << "\" y=\"" << top + ph + 18
        << "\" text-anchor=\"middle\">" << label_text(ax.labels[i]) << "</text>\n";
  for(std::size_t i = 0; i < ay.ticks.size(); ++i)
    out << "<text class=\"y-tick\" x=\"" << left - 8 << "\" y=\"" << ty(ay.ticks[i]) + 4
        << "\" text-anchor=\"end\">" << label_text(ay.labels[i]) << "</text>\n";
  out << "<text x=\"" << left + pw / 2 << "\" y=\"" << chart.height - 14 << "\" text-anchor=\"middle\">"
      << escaped(chart.x_label) << "</text>\n"
      << "<text x=\"18\" y=\"" << top + ph / 2 << "\" text-anchor=\"middle\" transform=\"rotate(-90 18 "
      << top + ph / 2 << ")\">" << escaped(chart.y_label) << "</text>\n";
  // Series and legend.
  for(std::size_t k = 0; k < chart.series.size(); ++k)
  {
    const Chart_series& s = chart.series[k];
    const char* colour = palette[k % (sizeof palette / sizeof palette[0])];
    out << "<g class=\"series\" stroke=\"" << colour << "\" fill=\"" << colour << "\">\n<polyline fill=\"none\" stroke-width=\"2\" points=\"";
    std::string markers;
    bool first = true;
    for(std::size_t i = 0; i < s.x.size(); ++i)
    {
      if(!Axis::usable(s.x[i], chart.log_x) || !Axis::usable(s.y[i], chart.log_y)) continue;
      const std::string x = number(px(s.x[i]), "%.2f"), y = number(py(s.y[i]), "%.2f");
      out << (first ? "" : " ") << x << ',' << y;
      first = false;
      markers += "<circle cx=\"" + x + "\" cy=\"" + y + "\" r=\"3\"/>\n";
    }
    out << "\"/>\n" << markers << "</g>\n";
    const double ly = top + 10 + 20 * k;
    out << "<line x1=\"" << left + pw + 14 << "\" y1=\"" << ly << "\" x2=\"" << left + pw + 38 << "\" y2=\"" << ly
        << "\" stroke=\"" << colour << "\" stroke-width=\"2\"/>\n<text x=\"" << left + pw + 44 << "\" y=\"" << ly + 4
        << "\">" << escaped(s.name) << "</text>\n";
  }
  out << "</svg>\n";
  if(!out) throw Invalid_input("writing the chart failed");
}

void write_svg_line_chart(const std::string& filename, const Line_chart& chart)
{
  std::ofstream out(filename);
  if(!out) throw Invalid_input("cannot open '" + filename + "' for writing");
  write_svg_line_chart(out, chart);
}

} // namespace Model_reduction
} // namespace CGAL
