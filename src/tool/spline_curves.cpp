// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The curves of tvf fit: tables, OBJ polylines, and sampled Bezier contours (SVG paths, glyphs).

#include "spline_curves.h"
#include "tool.h"

#include <CGAL/Spline_approximation/errors.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <locale>
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

} // namespace

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

std::vector<Curve_to_fit> sample_contours(const std::vector<SA::Bezier_contour>& contours, int samples_per_segment,
                                          bool bezier_parameters, const std::string& kind)
{
  std::vector<Curve_to_fit> out;
  for(std::size_t i = 0; i < contours.size(); ++i)
  {
    Curve_to_fit c;
    c.name = kind + " " + std::to_string(i + 1);
    SA::Sampled_contour s;
    try
    {
      s = SA::sample_contour(contours[i], samples_per_segment);
    }
    catch(const SA::Invalid_input& e)
    {
      warn(c.name + " skipped: " + one_line(e.what()));
      continue;
    }
    c.samples = s.points;
    c.closed = s.closed;
    if(bezier_parameters) c.parameters = s.parameters;
    out.push_back(std::move(c));
  }
  return out;
}

} // namespace tvf_tool
