// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_FACE_FIELD_IO_H
#define CGAL_TANGENT_VECTOR_FIELDS_FACE_FIELD_IO_H

/// \file face_field_io.h
/// Reading and writing per-face vector fields.
///
/// **Text format** (`.tvf`), one vector per face in the order of the face index map:
/// \verbatim
/// TVF_FACE_FIELD 1
/// faces <number of faces>
/// <x> <y> <z>
/// ...
/// \endverbatim
/// Lines starting with `#` after the first line are comments.  Numbers are written
/// with 17 significant digits, so a round trip is exact.
///
/// **PLY**: for a `CGAL::Surface_mesh`, a field named `name` is stored as three
/// `double` face properties `name_x`, `name_y`, `name_z`, which `CGAL::IO::write_PLY`
/// writes and `CGAL::IO::read_PLY` reads back as `f:name_x`, ... property maps.

#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/named_function_parameters.h>

#include <CGAL/Surface_mesh/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <istream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

namespace internal {
// Faces in the order of the face index map.
template <class TriangleMesh, class NamedParameters>
std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>
faces_in_index_order(const TriangleMesh& mesh, const NamedParameters& np)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  auto fim = CGAL::get_initialized_face_index_map(mesh, np);
  std::vector<face_descriptor> faces(CGAL::num_faces(mesh));
  for(face_descriptor f : CGAL::faces(mesh))
  {
    const std::size_t i = static_cast<std::size_t>(get(fim, f));
    if(i >= faces.size()) throw Invalid_input("face indices are not 0..n-1 (call collect_garbage() first)");
    faces[i] = f;
  }
  return faces;
}
} // namespace internal

/// Writes `field` in the text format.  \throws Invalid_input if the stream fails.
template <class TriangleMesh, class FaceVectorMap, class NamedParameters = parameters::Default_named_parameters>
void write_face_field(std::ostream& out, const TriangleMesh& mesh, const FaceVectorMap& field,
                      const NamedParameters& np = parameters::default_values())
{
  const auto faces = internal::faces_in_index_order(mesh, np);
  out << "TVF_FACE_FIELD 1\nfaces " << faces.size() << '\n' << std::setprecision(17);
  for(const auto& f : faces)
  {
    const auto& w = get(field, f);
    out << CGAL::to_double(w.x()) << ' ' << CGAL::to_double(w.y()) << ' ' << CGAL::to_double(w.z()) << '\n';
  }
  if(!out) throw Invalid_input("writing the face field failed");
}

namespace internal {
// Comment lines (starting with '#') and white space.
inline void skip_face_field_comments(std::istream& in)
{
  in >> std::ws;
  while(in.peek() == '#')
  {
    std::string line;
    std::getline(in, line);
    in >> std::ws;
  }
}

// Reads the header of the text format; returns the announced number of vectors.
inline std::size_t read_face_field_header(std::istream& in)
{
  std::string magic, word;
  int version = 0;
  long long count = -1;
  if(!(in >> magic >> version) || magic != "TVF_FACE_FIELD" || version != 1)
    throw Invalid_input("not a face field file (expected the header 'TVF_FACE_FIELD 1')");
  skip_face_field_comments(in);
  if(!(in >> word >> count) || word != "faces" || count < 0)
    throw Invalid_input("face field file: expected 'faces <count>' after the header");
  return static_cast<std::size_t>(count);
}

// Reads `count` vectors after the header.
inline std::vector<std::array<double, 3>> read_face_field_vectors(std::istream& in, std::size_t count)
{
  std::vector<std::array<double, 3>> values;
  for(std::size_t i = 0; i < count; ++i)
  {
    skip_face_field_comments(in);
    std::array<double, 3> v;
    for(double& c : v)
    {
      if(!(in >> c)) throw Invalid_input("face field file: vector " + std::to_string(i) + " is missing or unreadable");
      if(!std::isfinite(c)) throw Invalid_input("face field file: vector " + std::to_string(i) + " is not finite");
    }
    values.push_back(v);
  }
  return values;
}
} // namespace internal

/// Reads a field in the text format into `field`.  The map is written only after the
/// whole input has been read and checked.
/// \throws Invalid_input for a wrong header, a face count that differs from the
///         mesh's, missing or non-finite numbers.
template <class TriangleMesh, class FaceVectorMap, class NamedParameters = parameters::Default_named_parameters>
void read_face_field(std::istream& in, const TriangleMesh& mesh, FaceVectorMap field,
                     const NamedParameters& np = parameters::default_values())
{
  typedef typename boost::property_traits<FaceVectorMap>::value_type Vector_3;
  const auto faces = internal::faces_in_index_order(mesh, np);
  const std::size_t count = internal::read_face_field_header(in);
  if(count != faces.size())
    throw Invalid_input("face field file has " + std::to_string(count) + " vectors but the mesh has " +
                        std::to_string(faces.size()) + " faces");
  const std::vector<std::array<double, 3>> values = internal::read_face_field_vectors(in, count);
  for(std::size_t i = 0; i < faces.size(); ++i) put(field, faces[i], Vector_3(values[i][0], values[i][1], values[i][2]));
}

/// Reads the vectors of a file in the text format without a mesh: one per face, in the
/// file's order (for a field given per polygon of a file that `Model_reduction::polygon_soup_to_mesh`
/// repaired, and mapped to the faces with its `face_to_polygon_map`).
/// \throws Invalid_input for a wrong header, missing or non-finite numbers.
inline std::vector<std::array<double, 3>> read_face_vectors(std::istream& in)
{
  return internal::read_face_field_vectors(in, internal::read_face_field_header(in));
}

/// File-name versions of `write_face_field` and `read_face_field`.
template <class TriangleMesh, class FaceVectorMap, class NamedParameters = parameters::Default_named_parameters>
void write_face_field(const std::string& filename, const TriangleMesh& mesh, const FaceVectorMap& field,
                      const NamedParameters& np = parameters::default_values())
{
  std::ofstream out(filename);
  if(!out) throw Invalid_input("cannot open '" + filename + "' for writing");
  write_face_field(out, mesh, field, np);
}

template <class TriangleMesh, class FaceVectorMap, class NamedParameters = parameters::Default_named_parameters>
void read_face_field(const std::string& filename, const TriangleMesh& mesh, FaceVectorMap field,
                     const NamedParameters& np = parameters::default_values())
{
  std::ifstream in(filename);
  if(!in) throw Invalid_input("cannot open '" + filename + "'");
  read_face_field(in, mesh, field, np);
}

/// Stores `field` as the face properties `name_x`, `name_y`, `name_z` of `mesh`,
/// ready for `CGAL::IO::write_PLY`.
template <class Point, class FaceVectorMap>
void add_face_field_properties(Surface_mesh<Point>& mesh, const std::string& name, const FaceVectorMap& field)
{
  typedef typename Surface_mesh<Point>::Face_index Face_index;
  const char* axes[3] = {"_x", "_y", "_z"};
  for(int k = 0; k < 3; ++k)
  {
    auto map = mesh.template add_property_map<Face_index, double>("f:" + name + axes[k], 0.).first;
    for(Face_index f : mesh.faces())
    {
      const auto& w = get(field, f);
      map[f] = CGAL::to_double(k == 0 ? w.x() : (k == 1 ? w.y() : w.z()));
    }
  }
}

/// Reads the face properties `name_x`, `name_y`, `name_z` (as created by
/// `CGAL::IO::read_PLY`) into `field`.  Returns false if any of them is missing.
template <class Point, class FaceVectorMap>
bool face_field_from_properties(const Surface_mesh<Point>& mesh, const std::string& name, FaceVectorMap field)
{
  typedef typename Surface_mesh<Point>::Face_index Face_index;
  typedef typename boost::property_traits<FaceVectorMap>::value_type Vector_3;
  auto x = mesh.template property_map<Face_index, double>("f:" + name + "_x");
  auto y = mesh.template property_map<Face_index, double>("f:" + name + "_y");
  auto z = mesh.template property_map<Face_index, double>("f:" + name + "_z");
  if(!x.second || !y.second || !z.second) return false;
  for(Face_index f : mesh.faces()) put(field, f, Vector_3(x.first[f], y.first[f], z.first[f]));
  return true;
}

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
