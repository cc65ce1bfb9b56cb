// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fields and streamlines as VTK PolyData, OBJ and PLY polylines, Directional raw fields.

#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/field_files.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <istream>
#include <iterator>
#include <limits>
#include <locale>
#include <map>
#include <ostream>
#include <sstream>

namespace CGAL {
namespace Tangent_vector_fields {

Vtk_polydata face_fields_polydata(const std::vector<std::array<double, 3>>& points,
                                  const std::vector<std::array<int, 3>>& triangles,
                                  const std::vector<std::pair<std::string, std::vector<std::array<double, 3>>>>& fields)
{
  Vtk_polydata data;
  data.points = points;
  data.polygons.reserve(triangles.size());
  for(const auto& t : triangles) data.polygons.push_back({t[0], t[1], t[2]});
  for(const auto& field : fields)
  {
    if(field.second.size() != triangles.size())
      throw Invalid_input("field '" + field.first + "' has " + std::to_string(field.second.size()) +
                          " vectors for " + std::to_string(triangles.size()) + " faces");
    Vtk_polydata::Array a{field.first, 3, {}};
    a.values.reserve(3 * field.second.size());
    for(const auto& v : field.second) a.values.insert(a.values.end(), v.begin(), v.end());
    data.cell_data.push_back(std::move(a));
  }
  return data;
}

Vtk_polydata streamlines_polydata(const std::vector<Streamline>& lines)
{
  Vtk_polydata data;
  Vtk_polydata::Array face{"face", 1, {}}, closed{"closed", 1, {}}, length{"length", 1, {}};
  for(const Streamline& s : lines)
  {
    std::vector<int> cell;
    for(std::size_t i = 0; i < s.points.size(); ++i)
    {
      cell.push_back(static_cast<int>(data.points.size()));
      data.points.push_back(s.points[i]);
      face.values.push_back(s.faces[i]);
    }
    if(s.closed && !cell.empty()) cell.push_back(cell.front());
    data.lines.push_back(std::move(cell));
    closed.values.push_back(s.closed ? 1 : 0);
    length.values.push_back(s.length());
  }
  data.point_data.push_back(std::move(face));
  data.cell_data.push_back(std::move(closed));
  data.cell_data.push_back(std::move(length));
  return data;
}

void write_streamlines_obj(std::ostream& out, const std::vector<Streamline>& lines)
{
  Model_reduction::internal::prepare_exact_output(out);
  out << "# streamlines: " << lines.size() << " polylines\n";
  for(const Streamline& s : lines)
    for(const auto& p : s.points) out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  std::size_t base = 1;
  for(const Streamline& s : lines)
  {
    if(s.points.size() >= 2)
    {
      out << 'l';
      for(std::size_t i = 0; i < s.points.size(); ++i) out << ' ' << base + i;
      if(s.closed) out << ' ' << base;
      out << '\n';
    }
    base += s.points.size();
  }
  Model_reduction::internal::check_written(out, "OBJ file");
}

void write_streamlines_ply(std::ostream& out, const std::vector<Streamline>& lines)
{
  Model_reduction::internal::prepare_exact_output(out);
  std::size_t vertices = 0, edges = 0;
  for(const Streamline& s : lines)
  {
    vertices += s.points.size();
    edges += s.number_of_segments() + (s.closed && s.points.size() >= 2 ? 1 : 0);
  }
  out << "ply\nformat ascii 1.0\ncomment streamlines of a tangent vector field\n"
      << "element vertex " << vertices << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "property int face\nproperty int streamline\n"
      << "element edge " << edges << "\nproperty int vertex1\nproperty int vertex2\nend_header\n";
  for(std::size_t l = 0; l < lines.size(); ++l)
    for(std::size_t i = 0; i < lines[l].points.size(); ++i)
    {
      const auto& p = lines[l].points[i];
      out << p[0] << ' ' << p[1] << ' ' << p[2] << ' ' << lines[l].faces[i] << ' ' << l << '\n';
    }
  std::size_t base = 0;
  for(const Streamline& s : lines)
  {
    for(std::size_t i = 0; i + 1 < s.points.size(); ++i) out << base + i << ' ' << base + i + 1 << '\n';
    if(s.closed && s.points.size() >= 2) out << base + s.points.size() - 1 << ' ' << base << '\n';
    base += s.points.size();
  }
  Model_reduction::internal::check_written(out, "PLY file");
}

void write_raw_field(std::ostream& out, const Raw_field& field)
{
  if(field.degree <= 0) throw Invalid_input("raw field: the degree must be positive");
  if(field.vectors.size() % field.degree != 0)
    throw Invalid_input("raw field: the number of vectors is not a multiple of the degree");
  Model_reduction::internal::prepare_exact_output(out);
  out << field.degree << ' ' << field.number_of_faces() << '\n';
  for(std::size_t f = 0; f < field.number_of_faces(); ++f)
  {
    for(int k = 0; k < field.degree; ++k)
    {
      const auto& v = field.vectors[f * field.degree + k];
      out << (k ? " " : "") << v[0] << ' ' << v[1] << ' ' << v[2];
    }
    out << '\n';
  }
  Model_reduction::internal::check_written(out, "raw field");
}

Raw_field read_raw_field(std::istream& in)
{
  in.imbue(std::locale::classic());
  Raw_field field;
  long long faces = -1;
  if(!(in >> field.degree >> faces) || field.degree <= 0 || faces < 0)
    throw Invalid_input("raw field: expected '<degree> <number of faces>' on the first line");
  // Vectors as they are read, not the announced count allocated up front: a corrupt count
  // is refused where the numbers end instead of asking for terabytes.
  for(long long f = 0; f < faces; ++f)
    for(int k = 0; k < field.degree; ++k)
    {
      std::array<double, 3> v;
      for(double& c : v)
      {
        if(!(in >> c)) throw Invalid_input("raw field: face " + std::to_string(f) + " is missing or unreadable");
        if(!std::isfinite(c)) throw Invalid_input("raw field: face " + std::to_string(f) + " is not finite");
      }
      field.vectors.push_back(v);
    }
  std::string rest;
  if(in >> rest) throw Invalid_input("raw field: more numbers than " + std::to_string(faces) + " faces");
  return field;
}

} // namespace Tangent_vector_fields
} // namespace CGAL
