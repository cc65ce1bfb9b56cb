// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// tvf fit: the fewest-knot spline of a curve (Chapter 6) from a CSV table or an OBJ polyline,
// written as JSON (the B-spline), OBJ (the fitted curve) or SVG (data, fit and knots).

#include "tool.h"

#include <CGAL/Model_reduction/Vtk_polydata.h>
#include <CGAL/Spline_approximation/Spline_fit.h>

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

std::string location(const std::string& path, std::size_t line, std::size_t column = 0)
{
  return "'" + path + "' line " + std::to_string(line) + (column > 0 ? ", column " + std::to_string(column) : "");
}

// One number of a table cell, the whole cell (C locale).
bool parse_number(const std::string& cell, double& x)
{
  std::istringstream in(cell);
  in.imbue(std::locale::classic());
  in >> x;
  return !in.fail() && (in >> std::ws).eof();
}

// Rows of numbers separated by commas or white space; '#' starts a comment; a first row that is
// not numbers is a header.  Every row has the same count.
Eigen::MatrixXd read_table(const std::string& path)
{
  std::ifstream in(path);
  if(!in) throw Tool_error("cannot open curve file '" + path + "': " + std::strerror(errno));
  std::vector<std::vector<double>> rows;
  std::string line;
  std::size_t number = 0;
  bool content_seen = false; // a header may only be the first line with content
  while(std::getline(in, line))
  {
    ++number;
    line = line.substr(0, line.find('#'));
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream cells(line);
    std::vector<double> row;
    std::string cell;
    std::size_t column = 0;
    bool header = false;
    while(cells >> cell)
    {
      ++column;
      double x;
      if(!parse_number(cell, x))
      {
        if(!content_seen && row.empty()) header = true;
        if(header) break;
        throw Tool_error(location(path, number, column) + ": '" + cell + "' is not a number");
      }
      if(!std::isfinite(x)) throw Tool_error(location(path, number, column) + ": '" + cell + "' is not finite");
      row.push_back(x);
    }
    content_seen = content_seen || header || !row.empty();
    if(header || row.empty()) continue;
    if(!rows.empty() && row.size() != rows.front().size())
      throw Tool_error(location(path, number) + ": " + std::to_string(row.size()) + " numbers where the first row has " +
                       std::to_string(rows.front().size()));
    rows.push_back(row);
  }
  if(rows.empty()) throw Tool_error("'" + path + "' has no rows of numbers");
  Eigen::MatrixXd P(Eigen::Index(rows.size()), Eigen::Index(rows.front().size()));
  for(std::size_t i = 0; i < rows.size(); ++i)
    for(std::size_t j = 0; j < rows[i].size(); ++j) P(Eigen::Index(i), Eigen::Index(j)) = rows[i][j];
  return P;
}

// The vertices of an OBJ file along its polyline: the `l` elements joined end to start (the
// vertices in file order if there is none).
Eigen::MatrixXd read_obj_polyline(const std::string& path)
{
  std::ifstream in(path);
  if(!in) throw Tool_error("cannot open curve file '" + path + "': " + std::strerror(errno));
  std::vector<std::array<double, 3>> vertices;
  std::vector<long> order;
  std::string line;
  std::size_t number = 0;
  while(std::getline(in, line))
  {
    ++number;
    std::istringstream words(line.substr(0, line.find('#')));
    words.imbue(std::locale::classic());
    std::string tag;
    if(!(words >> tag)) continue;
    if(tag == "v")
    {
      std::array<double, 3> p;
      for(double& x : p)
        if(!(words >> x) || !std::isfinite(x))
          throw Tool_error(location(path, number) + ": a vertex needs three finite coordinates");
      vertices.push_back(p);
    }
    else if(tag == "l")
    {
      std::vector<long> element;
      std::string item;
      while(words >> item)
      {
        long index = 0;
        try
        {
          index = std::stol(item.substr(0, item.find('/')));
        }
        catch(const std::exception&)
        {
          throw Tool_error(location(path, number) + ": '" + item + "' is not a vertex index");
        }
        // OBJ indices count from 1; negative ones from the end of the vertices read so far.
        const long resolved = index > 0 ? index - 1 : long(vertices.size()) + index;
        if(index == 0 || resolved < 0 || resolved >= long(vertices.size()))
          throw Tool_error(location(path, number) + ": vertex index " + item + " is not one of the " +
                           std::to_string(vertices.size()) + " vertices before it");
        element.push_back(resolved);
      }
      if(element.size() < 2) throw Tool_error(location(path, number) + ": a polyline element needs two vertices");
      if(!order.empty() && element.front() != order.back())
        throw Tool_error(location(path, number) + ": this polyline does not start where the previous one ends (one curve "
                         "per file)");
      order.insert(order.end(), element.begin() + (order.empty() ? 0 : 1), element.end());
    }
  }
  if(order.empty())
    for(std::size_t i = 0; i < vertices.size(); ++i) order.push_back(long(i));
  if(order.empty()) throw Tool_error("'" + path + "' has no vertices");
  Eigen::MatrixXd P(Eigen::Index(order.size()), 3);
  for(std::size_t i = 0; i < order.size(); ++i)
    for(int k = 0; k < 3; ++k) P(Eigen::Index(i), k) = vertices[std::size_t(order[i])][std::size_t(k)];
  return P;
}

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

// The fitted curve at `count` parameters spread evenly over its range.
Eigen::MatrixXd sampled_fit(const SA::Spline_fit& fit, Eigen::Index count)
{
  const Eigen::VectorXd t =
      fit.closed() ? Eigen::VectorXd(Eigen::VectorXd::LinSpaced(count + 1, 0, 1).head(count)) : Eigen::VectorXd::LinSpaced(count, 0, 1);
  return fit.spline.evaluate(t);
}

void write_json(const std::string& path, const SA::Spline_fit& fit)
{
  std::ofstream out = open_output(path);
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
      << SA::algorithm_name(fit.algorithm) << "\"}\n";
  finish_output(out, path);
}

void write_obj(const std::string& path, const Eigen::MatrixXd& curve, bool closed)
{
  std::ofstream out = open_output(path);
  for(Eigen::Index i = 0; i < curve.rows(); ++i)
  {
    out << "v";
    for(Eigen::Index k = 0; k < 3; ++k) out << " " << (k < curve.cols() ? curve(i, k) : 0.);
    out << "\n";
  }
  out << "l";
  for(Eigen::Index i = 0; i < curve.rows(); ++i) out << " " << i + 1;
  if(closed) out << " 1";
  out << "\n";
  finish_output(out, path);
}

// Data (grey), fit (blue) and knots (red) seen along z: x and y at one scale.
void write_svg(const std::string& path, const Eigen::MatrixXd& samples, const Eigen::MatrixXd& curve,
               const Eigen::MatrixXd& knots, bool closed)
{
  auto coordinate = [](const Eigen::MatrixXd& P, Eigen::Index i, int k) { return k < P.cols() ? P(i, k) : 0.; };
  double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
  for(const Eigen::MatrixXd* P : {&samples, &curve})
    for(Eigen::Index i = 0; i < P->rows(); ++i)
      for(int k = 0; k < 2; ++k)
      {
        lo[k] = std::min(lo[k], coordinate(*P, i, k));
        hi[k] = std::max(hi[k], coordinate(*P, i, k));
      }
  const double size = 800, margin = 20;
  const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], 1e-300});
  const double scale = (size - 2 * margin) / extent;
  auto x = [&](const Eigen::MatrixXd& P, Eigen::Index i) { return margin + scale * (coordinate(P, i, 0) - lo[0]); };
  auto y = [&](const Eigen::MatrixXd& P, Eigen::Index i) { return size - margin - scale * (coordinate(P, i, 1) - lo[1]); };
  std::ofstream out = open_output(path);
  out.precision(8);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << size << "\" height=\"" << size << "\" viewBox=\"0 0 "
      << size << " " << size << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  auto polyline = [&](const Eigen::MatrixXd& P, const char* colour, double width) {
    out << (closed ? "<polygon" : "<polyline") << " fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"" << width
        << "\" points=\"";
    for(Eigen::Index i = 0; i < P.rows(); ++i) out << x(P, i) << "," << y(P, i) << " ";
    out << "\"/>\n";
  };
  polyline(samples, "#999999", 3);
  polyline(curve, "#1f5fbf", 1.5);
  for(Eigen::Index i = 0; i < knots.rows(); ++i)
    out << "<circle cx=\"" << x(knots, i) << "\" cy=\"" << y(knots, i) << "\" r=\"4\" fill=\"#d62728\"/>\n";
  out << "</svg>\n";
  finish_output(out, path);
}

} // namespace

int fit_command(const Arguments& args)
{
  Command_line command(
      "tvf fit <curve.csv|curve.obj> (--max-error E | --rms-error E | --lambda L) [--degree K] [--closed] -o OUT",
      "Fits the spline with the fewest knots to a curve (Chapter 6, SPEC 14): the samples are the rows of a\n"
      "CSV table (any number of columns; comma or space separated, '#' comments, an optional header row) or\n"
      "the vertices of an OBJ polyline, at chord-length parameters.  With --max-error or --rms-error the\n"
      "fewest knots within that distance; with --lambda the best trade of squared error against lambda per\n"
      "knot.  Prints the knots kept and the errors.  Outputs by extension: .json (the B-spline: degree,\n"
      "knots, control points), .obj (the fitted curve as a polyline), .svg (data, fit and knots along z).");
  command.positional("curve", "the samples (.csv, .txt or .obj)");
  command.group("fit").add_options()
    ("max-error", po::value<double>()->value_name("E"), "every sample within this distance of the fit")
    ("rms-error", po::value<double>()->value_name("E"), "root-mean-square distance within this")
    ("lambda", po::value<double>()->value_name("L"), "penalty per knot, in squared data units")
    ("degree", po::value<int>()->value_name("K")->default_value(3), "1 (polyline) to 3 (cubic)")
    ("closed", "a closed curve (the last sample joins the first; do not repeat it)")
    ("algorithm", po::value<std::string>()->value_name("A")->default_value("greedy"),
     "greedy (knot removal), penalty (penalty decomposition), exact (degree 1: dynamic programming)")
    ("output,o", po::value<std::vector<std::string>>()->value_name("FILE"), "output file(s): .json, .obj or .svg");
  if(!command.parse(args)) return 0; // --help
  const int bounds = int(command.has("max-error")) + int(command.has("rms-error")) + int(command.has("lambda"));
  if(bounds != 1) throw Usage_error("give exactly one of '--max-error', '--rms-error' and '--lambda'");
  const std::string path = command.positional_value();
  const std::string extension = path.substr(path.find_last_of('.') == std::string::npos ? path.size() : path.find_last_of('.'));
  const Eigen::MatrixXd samples = extension == ".obj" ? read_obj_polyline(path) : read_table(path);

  SA::Fit_options options;
  options.degree = command.get<int>("degree");
  options.closed_curve = command.has("closed");
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

  SA::Spline_fit fit;
  try
  {
    fit = SA::fit_spline(samples, options);
  }
  catch(const SA::Invalid_input& e)
  {
    throw Tool_error("'" + path + "': " + one_line(e.what()));
  }
  say("curve: %s, %ld samples in %ld dimensions%s\n", path.c_str(), long(samples.rows()), long(samples.cols()),
      options.closed_curve ? ", closed" : "");
  say("fit: degree %d, %s: %zu knots, %ld control points; max error %.6g, rms error %.6g%s; %.3f s\n",
      options.degree, SA::algorithm_name(fit.algorithm), fit.number_of_knots(), long(fit.spline.control_points.rows()),
      fit.max_error, fit.rms_error, fit.within_bound ? "" : " (the bound was not met: the best fit found)", fit.seconds);
  if(!fit.within_bound) warn("'" + path + "': the error bound was not met; the best fit found is written");

  const Eigen::MatrixXd curve = sampled_fit(fit, std::max<Eigen::Index>(1000, 8 * samples.rows()));
  const Eigen::MatrixXd knot_points = fit.spline.evaluate(fit.spline.interior_knots());
  std::vector<std::string> outputs;
  if(command.has("output")) outputs = command.get<std::vector<std::string>>("output");
  for(const std::string& out : outputs)
  {
    const std::string ext = out.substr(out.find_last_of('.') == std::string::npos ? out.size() : out.find_last_of('.'));
    if(ext == ".json") write_json(out, fit);
    else if(ext == ".obj") write_obj(out, curve, fit.closed());
    else if(ext == ".svg") write_svg(out, samples, curve, knot_points, fit.closed());
    else throw Usage_error("'" + out + "': the output format is chosen by the extension: .json, .obj or .svg");
    say("wrote %s\n", out.c_str());
  }
  if(outputs.empty()) say("(no --output given: nothing written)\n");
  return 0;
}

} // namespace tvf_tool
