// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// tvf fit: the fewest-knot spline of curves (Chapter 6) from a CSV table, an OBJ polyline, the
// subpaths of an SVG file or a glyph of a font, written as JSON (the B-splines), OBJ (the fitted
// curves), SVG or PNG (data, fit and knots), with a chart of the error against the knot count.

#include "spline_curves.h"
#include "spline_pictures.h"
#include "tool.h"

#include <CGAL/Model_reduction/Vtk_polydata.h>
#include <CGAL/Spline_approximation/Glyph_outline.h>
#include <CGAL/Spline_approximation/Spline_fit.h>
#include <CGAL/Spline_approximation/Svg_paths.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <locale>
#include <map>
#include <sstream>

namespace tvf_tool {

namespace SA = CGAL::Spline_approximation;

namespace {

std::ofstream open_output(const std::string& path)
{
  std::ofstream out(path);
  if(!out) throw Tool_error("cannot open '" + path + "' for writing: " + std::strerror(errno));
  CGAL::Model_reduction::internal::prepare_exact_output(out);
  return out;
}

void finish_output(std::ofstream& out, const std::string& path)
{
  out.close();
  if(!out) throw Tool_error("writing '" + path + "' failed");
}

void write_json_fit(std::ostream& out, const SA::Spline_fit& fit)
{
  const SA::B_spline& s = fit.spline;
  out << "{\"degree\": " << s.degree << ", \"closed\": " << (s.closed ? "true" : "false") << ",\n \"knots\": [";
  for(Eigen::Index i = 0; i < s.knots.size(); ++i) out << (i ? ", " : "") << s.knots[i];
  out << "],\n \"control_points\": [";
  for(Eigen::Index i = 0; i < s.control_points.rows(); ++i)
  {
    out << (i ? ",\n   [" : "[");
    for(Eigen::Index j = 0; j < s.control_points.cols(); ++j) out << (j ? ", " : "") << s.control_points(i, j);
    out << "]";
  }
  out << "],\n \"max_error\": " << fit.max_error << ", \"rms_error\": " << fit.rms_error << ", \"algorithm\": \""
      << SA::algorithm_name(fit.algorithm) << "\"}";
}

// One curve: the B-spline object as before; several: {"curves": [...]}.
void write_json(const std::string& path, const std::vector<SA::Spline_fit>& fits)
{
  std::ofstream out = open_output(path);
  if(fits.size() == 1) write_json_fit(out, fits.front());
  else
  {
    out << "{\"curves\": [\n";
    for(std::size_t i = 0; i < fits.size(); ++i)
    {
      if(i) out << ",\n";
      write_json_fit(out, fits[i]);
    }
    out << "\n]}";
  }
  out << "\n";
  finish_output(out, path);
}

// Every fitted curve as one `l` element.
void write_obj(const std::string& path, const std::vector<Fit_picture_curve>& curves)
{
  std::ofstream out = open_output(path);
  for(const Fit_picture_curve& c : curves)
    for(Eigen::Index i = 0; i < c.fit.rows(); ++i)
    {
      out << "v";
      for(Eigen::Index k = 0; k < 3; ++k) out << " " << (k < c.fit.cols() ? c.fit(i, k) : 0.);
      out << "\n";
    }
  long first = 1;
  for(const Fit_picture_curve& c : curves)
  {
    out << "l";
    for(Eigen::Index i = 0; i < c.fit.rows(); ++i) out << " " << first + i;
    if(c.closed) out << " " << first;
    out << "\n";
    first += long(c.fit.rows());
  }
  finish_output(out, path);
}

std::string extension_of(const std::string& path)
{
  const std::size_t dot = path.find_last_of('.');
  std::string e = dot == std::string::npos || path.find('/', dot) != std::string::npos ? "" : path.substr(dot);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return e;
}

// The fits of every curve, with the totals.
struct Fits
{
  std::vector<SA::Spline_fit> fits;
  std::size_t knots = 0, control_points = 0;
  double max_error = 0, rms_error = 0, seconds = 0;
  bool within_bound = true;
};

Fits fit_all(const std::vector<Curve_to_fit>& curves, SA::Fit_options options, const std::string& source)
{
  Fits out;
  double squared = 0;
  Eigen::Index samples = 0;
  for(const Curve_to_fit& c : curves)
  {
    options.closed_curve = c.closed;
    try
    {
      out.fits.push_back(c.parameters.size() > 0 ? SA::fit_spline(c.samples, c.parameters, options)
                                                 : SA::fit_spline(c.samples, options));
    }
    catch(const SA::Invalid_input& e)
    {
      throw Tool_error("'" + source + "'" + (curves.size() > 1 ? " (" + c.name + ")" : std::string()) + ": " +
                       one_line(e.what()));
    }
    const SA::Spline_fit& f = out.fits.back();
    out.knots += f.number_of_knots();
    out.control_points += std::size_t(f.spline.control_points.rows());
    out.max_error = std::max(out.max_error, f.max_error);
    squared += f.squared_error;
    samples += c.samples.rows();
    out.seconds += f.seconds;
    out.within_bound = out.within_bound && f.within_bound;
  }
  out.rms_error = std::sqrt(squared / double(std::max<Eigen::Index>(1, samples)));
  return out;
}

// The fitted curves densely sampled, with their knots' points, for pictures and OBJ.
std::vector<Fit_picture_curve> picture_curves(const std::vector<Curve_to_fit>& curves, const Fits& fits)
{
  std::vector<Fit_picture_curve> out;
  for(std::size_t i = 0; i < curves.size(); ++i)
  {
    const SA::Spline_fit& fit = fits.fits[i];
    const Eigen::Index count = std::max<Eigen::Index>(1000, 8 * curves[i].samples.rows());
    const Eigen::VectorXd t = fit.closed() ? Eigen::VectorXd(Eigen::VectorXd::LinSpaced(count + 1, 0, 1).head(count))
                                           : Eigen::VectorXd::LinSpaced(count, 0, 1);
    Fit_picture_curve c;
    c.samples = curves[i].samples;
    c.fit = fit.spline.evaluate(t);
    c.knots = fit.spline.evaluate(fit.spline.interior_knots());
    c.closed = fit.closed();
    out.push_back(std::move(c));
  }
  return out;
}

// The error (max and RMS) against the knot count, over a sweep of error bounds from 1e-4 to
// 0.3 times the data's extent (max bounds; RMS bounds for the exact algorithm, which takes no
// max bound), with the fit asked for marked.
CGAL::Model_reduction::Line_chart error_chart(const std::vector<Curve_to_fit>& curves, SA::Fit_options options,
                                               const Fits& asked, const std::string& source)
{
  double extent = 0;
  for(const Curve_to_fit& c : curves)
    extent = std::max(extent, (c.samples.colwise().maxCoeff() - c.samples.colwise().minCoeff()).maxCoeff());
  const bool rms = options.algorithm == SA::Fit_algorithm::dynamic_programming || bool(options.rms_error);
  options.penalty.reset();
  options.max_error.reset();
  options.rms_error.reset();
  CGAL::Model_reduction::Line_chart chart;
  chart.title = "fit error against knot count (degree " + std::to_string(options.degree) + ", " +
                SA::algorithm_name(options.algorithm) + ", sweep of " + (rms ? "RMS" : "max") + " error bounds)";
  chart.x_label = "knots";
  chart.y_label = "error";
  chart.log_x = false;
  CGAL::Model_reduction::Chart_series max_series{"max error", {}, {}}, rms_series{"RMS error", {}, {}},
      marked{"this fit (max error)", {double(asked.knots)}, {asked.max_error}};
  const int steps = 12;
  for(int i = 0; i < steps; ++i)
  {
    const double bound = extent * std::pow(10.0, -4 + 3.5 * double(i) / double(steps - 1));
    (rms ? options.rms_error : options.max_error) = bound;
    const Fits f = fit_all(curves, options, source);
    max_series.x.push_back(double(f.knots));
    max_series.y.push_back(f.max_error);
    rms_series.x.push_back(double(f.knots));
    rms_series.y.push_back(f.rms_error);
  }
  chart.series = {max_series, rms_series, marked};
  return chart;
}

// Every contour cut at its kinks (SA::split_at_kinks), the pieces in order.
std::vector<SA::Bezier_contour> split_all(const std::vector<SA::Bezier_contour>& contours)
{
  std::vector<SA::Bezier_contour> out;
  for(const SA::Bezier_contour& c : contours)
    for(SA::Bezier_contour& piece : SA::split_at_kinks(c)) out.push_back(std::move(piece));
  return out;
}

} // namespace

int fit_command(const Arguments& args)
{
  Command_line command(
      "tvf fit (<curve.csv|curve.obj|drawing.svg> | --glyph C [--font F]) (--max-error E | --rms-error E | --lambda L)\n"
      "        [--degree K] [--closed] -o OUT [--chart CHART.svg]",
      "Fits the spline with the fewest knots to curves (Chapter 6, SPEC 14): the samples are the rows of a\n"
      "CSV table (any number of columns; comma or space separated, '#' comments, an optional header row), the\n"
      "vertices of an OBJ polyline, the subpaths of the <path> elements and the basic shapes an SVG file draws\n"
      "(one fit each; closed by Z or by the shape; <use>, transforms and the viewBox applied: viewport px), or\n"
      "the contours of a glyph of a font (--glyph, read by FreeType; closed).\n"
      "SVG paths and glyphs are sampled densely from their exact Bezier segments.  With --max-error or\n"
      "--rms-error the fewest knots within that distance; with --lambda the best trade of squared error\n"
      "against lambda per knot.  Prints the knots kept and the errors.  Outputs by extension: .json (the\n"
      "B-splines: degree, knots, control points), .obj (the fitted curves as polylines), .svg or .png (data\n"
      "grey, fit blue, knots red; PNG needs Cairo).  --chart: the error against the knot count (SVG).");
  command.positional("curve", "the samples (.csv, .txt, .obj or .svg)");
  command.group("fit").add_options()
    ("max-error", po::value<double>()->value_name("E"), "every sample within this distance of the fit")
    ("rms-error", po::value<double>()->value_name("E"), "root-mean-square distance within this")
    ("lambda", po::value<double>()->value_name("L"), "penalty per knot, in squared data units")
    ("degree", po::value<int>()->value_name("K")->default_value(3), "1 (polyline) to 3 (cubic)")
    ("closed", "tables and OBJ: a closed curve (the last sample joins the first; do not repeat it)")
    ("algorithm", po::value<std::string>()->value_name("A")->default_value("greedy"),
     "greedy (knot removal), penalty (penalty decomposition), exact (degree 1: dynamic programming)")
    ("output,o", po::value<std::vector<std::string>>()->value_name("FILE"), "output file(s): .json, .obj, .svg or .png")
    ("chart", po::value<std::string>()->value_name("FILE.svg"), "chart of the error (max, RMS) against the knot count");
  command.group("SVG paths and glyphs").add_options()
    ("glyph", po::value<std::string>()->value_name("C"), "fit the outline of this character (UTF-8) of a font")
    ("font", po::value<std::string>()->value_name("F")->default_value(SA::default_glyph_font), "the font file of --glyph")
    ("em-size", po::value<double>()->value_name("S")->default_value(1000), "--glyph: the em square's size in output units")
    ("samples-per-segment", po::value<int>()->value_name("N")->default_value(16), "samples of each Bezier segment")
    ("parameters", po::value<std::string>()->value_name("P")->default_value("chord"),
     "chord (chord length) or bezier (affine on every Bezier segment: exact segments are then recovered exactly)")
    ("split-kinks", "fit the pieces between the joints that are not C^1 in the Bezier parameter (corners) separately:\n"
     "a spline of degree >= 2 with simple knots cannot turn a corner");
  if(!command.parse(args)) return 0; // --help
  const int bounds = int(command.has("max-error")) + int(command.has("rms-error")) + int(command.has("lambda"));
  if(bounds != 1) throw Usage_error("give exactly one of '--max-error', '--rms-error' and '--lambda'");
  if(command.has("glyph") && command.has("curve"))
    throw Usage_error("give a curve file or '--glyph', not both");
  const std::string parameters = command.get<std::string>("parameters");
  if(parameters != "chord" && parameters != "bezier")
    throw Usage_error("'--parameters' must be chord or bezier, not '" + parameters + "'");
  const int per_segment = command.get<int>("samples-per-segment");
  if(per_segment < 1 || per_segment > 100000) throw Usage_error("'--samples-per-segment' must be 1 to 100000");

  // The curves.
  const bool split = command.has("split-kinks");
  std::vector<Curve_to_fit> curves;
  std::string source;
  bool y_down = false, from_contours = true;
  if(command.has("glyph"))
  {
#ifdef TVF_HAS_FREETYPE
    source = command.get<std::string>("font");
    SA::Glyph_outline glyph;
    try
    {
      glyph = SA::read_glyph_outline(source, SA::first_code_point(command.get<std::string>("glyph")),
                                     command.get<double>("em-size"));
    }
    catch(const SA::Invalid_input& e)
    {
      throw Tool_error(one_line(e.what()));
    }
    curves = sample_contours(split ? split_all(glyph.contours) : glyph.contours, per_segment, parameters == "bezier",
                             split ? "piece" : "contour");
    say("glyph '%s' of %s (%s, %d units per em): %zu contours\n", command.get<std::string>("glyph").c_str(),
        source.c_str(), glyph.font_format.c_str(), glyph.units_per_em, glyph.contours.size());
#else
    throw Tool_error("'--glyph': this tvf was built without FreeType (TVF_USE_FREETYPE; Debian: libfreetype-dev)");
#endif
  }
  else
  {
    source = command.positional_value();
    const std::string extension = extension_of(source);
    if(extension == ".svg")
    {
      SA::Svg_paths svg;
      try
      {
        svg = SA::read_svg_paths(source);
      }
      catch(const SA::Invalid_input& e)
      {
        throw Tool_error(one_line(e.what()));
      }
      curves = sample_contours(split ? split_all(svg.contours) : svg.contours, per_segment, parameters == "bezier",
                               split ? "piece" : "subpath");
      y_down = true;
    }
    else
    {
      from_contours = false;
      Curve_to_fit c;
      c.samples = extension == ".obj" ? read_obj_polyline(source) : read_table(source);
      c.closed = command.has("closed");
      curves.push_back(std::move(c));
    }
  }
  if(from_contours && command.has("closed"))
    throw Usage_error("'--closed' is for tables and OBJ polylines: SVG subpaths are closed by Z, glyph contours always");
  if(!from_contours && split)
    throw Usage_error("'--split-kinks' is for SVG paths and glyphs (tables and OBJ polylines have no Bezier segments)");
  if(!from_contours && parameters == "bezier")
    throw Usage_error("'--parameters bezier' is for SVG paths and glyphs (tables and OBJ polylines have no Bezier segments)");
  if(curves.empty()) throw Tool_error("'" + source + "' has no curve to fit");

  SA::Fit_options options;
  options.degree = command.get<int>("degree");
  if(command.has("max-error")) options.max_error = command.get<double>("max-error");
  if(command.has("rms-error")) options.rms_error = command.get<double>("rms-error");
  if(command.has("lambda")) options.penalty = command.get<double>("lambda");
  const std::map<std::string, SA::Fit_algorithm> algorithms = {
      {"greedy", SA::Fit_algorithm::greedy_removal},
      {"penalty", SA::Fit_algorithm::penalty_decomposition},
      {"exact", SA::Fit_algorithm::dynamic_programming}};
  const auto algorithm = algorithms.find(command.get<std::string>("algorithm"));
  if(algorithm == algorithms.end())
    throw Usage_error("'--algorithm' must be greedy, penalty or exact, not '" + command.get<std::string>("algorithm") + "'");
  options.algorithm = algorithm->second;

  const Fits fits = fit_all(curves, options, source);
  if(!from_contours)
  {
    say("curve: %s, %ld samples in %ld dimensions%s\n", source.c_str(), long(curves[0].samples.rows()),
        long(curves[0].samples.cols()), curves[0].closed ? ", closed" : "");
  }
  else
  {
    std::size_t closed = 0;
    long samples = 0;
    for(const Curve_to_fit& c : curves)
    {
      closed += std::size_t(c.closed);
      samples += long(c.samples.rows());
    }
    say("curves: %s, %zu curves (%zu closed), %ld samples in 2 dimensions, %s parameters\n", source.c_str(),
        curves.size(), closed, samples, parameters.c_str());
    for(std::size_t i = 0; i < curves.size(); ++i)
      say("  %s: %ld samples%s, %zu knots, max error %.6g\n", curves[i].name.c_str(), long(curves[i].samples.rows()),
          curves[i].closed ? ", closed" : "", fits.fits[i].number_of_knots(), fits.fits[i].max_error);
  }
  say("fit: degree %d, %s: %zu knots, %zu control points; max error %.6g, rms error %.6g%s; %.3f s\n", options.degree,
      SA::algorithm_name(options.algorithm), fits.knots, fits.control_points, fits.max_error, fits.rms_error,
      fits.within_bound ? "" : " (the bound was not met: the best fit found)", fits.seconds);
  if(!fits.within_bound) warn("'" + source + "': the error bound was not met; the best fit found is written");

  const std::vector<Fit_picture_curve> pictured = picture_curves(curves, fits);
  std::vector<std::string> outputs;
  if(command.has("output")) outputs = command.get<std::vector<std::string>>("output");
  for(const std::string& out : outputs) // every extension checked before anything is written
  {
    const std::string ext = extension_of(out);
    if(ext != ".json" && ext != ".obj" && ext != ".svg" && ext != ".png")
      throw Usage_error("'" + out + "': the output format is chosen by the extension: .json, .obj, .svg or .png");
  }
  for(const std::string& out : outputs)
  {
    const std::string ext = extension_of(out);
    if(ext == ".json") write_json(out, fits.fits);
    else if(ext == ".obj") write_obj(out, pictured);
    else if(ext == ".svg") write_fit_svg(out, pictured, y_down);
    else write_fit_png(out, pictured, y_down);
    say("wrote %s\n", out.c_str());
  }
  if(command.has("chart"))
  {
    const std::string path = command.get<std::string>("chart");
    write_error_chart(path, error_chart(curves, options, fits, source));
    say("wrote %s\n", path.c_str());
  }
  if(outputs.empty() && !command.has("chart")) say("(no --output given: nothing written)\n");
  return 0;
}

} // namespace tvf_tool
