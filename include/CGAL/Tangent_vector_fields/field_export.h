// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_FIELD_EXPORT_H
#define CGAL_TANGENT_VECTOR_FIELDS_FIELD_EXPORT_H

/// \file field_export.h
/// Face fields of a `TriangleMesh` to and from files that other programs read:
/// VTK XML PolyData (`.vtp`: the mesh with one cell vector array per field, for
/// ParaView) and Directional's `.rawfield`; streamlines as `.obj`, `.ply` or `.vtp`.
/// The formats themselves are in `field_files.h`.
///
/// Vertices and faces are written in the order of the vertex and face index maps
/// (named parameters `vertex_index_map`, `face_index_map`; points from
/// `vertex_point_map`).  Numbers have 17 significant digits: a round trip is exact.

#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/field_files.h>
#include <CGAL/Tangent_vector_fields/named_function_parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

namespace internal {

// Points (vertex index order), triangles (face index order) and faces by index.
template <class TriangleMesh, class NamedParameters>
struct Indexed_triangles
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<face_descriptor> faces;

  Indexed_triangles(const TriangleMesh& mesh, const NamedParameters& np)
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                get_const_property_map(CGAL::vertex_point, mesh));
    auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
    auto fim = CGAL::get_initialized_face_index_map(mesh, np);
    const std::size_t nv = static_cast<std::size_t>(num_vertices(mesh));
    const std::size_t nf = static_cast<std::size_t>(num_faces(mesh));
    points.resize(nv);
    for(auto v : vertices(mesh))
    {
      const std::size_t i = static_cast<std::size_t>(get(vim, v));
      if(i >= nv) throw Invalid_input("vertex indices are not 0..n-1 (call collect_garbage() first)");
      const auto& p = get(vpm, v);
      points[i] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    }
    triangles.resize(nf);
    faces.resize(nf);
    for(auto f : CGAL::faces(mesh))
    {
      const std::size_t i = static_cast<std::size_t>(get(fim, f));
      if(i >= nf) throw Invalid_input("face indices are not 0..n-1 (call collect_garbage() first)");
      faces[i] = f;
      int k = 0;
      for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
      {
        if(k == 3) throw Invalid_input("face " + std::to_string(i) + " is not a triangle");
        triangles[i][k++] = static_cast<int>(get(vim, v));
      }
      if(k != 3) throw Invalid_input("face " + std::to_string(i) + " is not a triangle");
    }
  }

  template <class FaceVectorMap>
  std::vector<std::array<double, 3>> read(const FaceVectorMap& field) const
  {
    std::vector<std::array<double, 3>> values(faces.size());
    for(std::size_t i = 0; i < faces.size(); ++i)
    {
      const auto& w = get(field, faces[i]);
      values[i] = {CGAL::to_double(w.x()), CGAL::to_double(w.y()), CGAL::to_double(w.z())};
    }
    return values;
  }

  template <class FaceVectorMap>
  void write(const std::vector<std::array<double, 3>>& values, FaceVectorMap field, std::size_t stride = 1) const
  {
    typedef typename boost::property_traits<FaceVectorMap>::value_type Vector_3;
    for(std::size_t i = 0; i < faces.size(); ++i)
    {
      const auto& w = values[i * stride];
      put(field, faces[i], Vector_3(w[0], w[1], w[2]));
    }
  }
};

inline std::ofstream open_for_writing(const std::string& filename)
{
  std::ofstream out(filename);
  if(!out) throw Invalid_input("cannot open '" + filename + "' for writing");
  return out;
}

inline std::ifstream open_for_reading(const std::string& filename)
{
  std::ifstream in(filename);
  if(!in) throw Invalid_input("cannot open '" + filename + "'");
  return in;
}

} // namespace internal

/// \brief Writes the mesh and face fields as a VTK XML PolyData file (`.vtp`).
///
/// Each field becomes a 3-component cell array named after it; the first is the
/// active vector array, so ParaView's *Glyph* filter shows it directly.
/// \param fields pairs of a name and a face map with `Vector_3` values.
template <class TriangleMesh, class FaceVectorMap, class NamedParameters = parameters::Default_named_parameters>
void write_vtp(const std::string& filename, const TriangleMesh& mesh,
               const std::vector<std::pair<std::string, FaceVectorMap>>& fields,
               const NamedParameters& np = parameters::default_values())
{
  internal::Indexed_triangles<TriangleMesh, NamedParameters> soup(mesh, np);
  std::vector<std::pair<std::string, std::vector<std::array<double, 3>>>> arrays;
  for(const auto& f : fields) arrays.emplace_back(f.first, soup.read(f.second));
  std::ofstream out = internal::open_for_writing(filename);
  write_vtk_polydata(out, face_fields_polydata(soup.points, soup.triangles, arrays));
}

/// One field: `write_vtp(filename, mesh, {{name, field}}, np)`.
template <class TriangleMesh, class FaceVectorMap, class NamedParameters = parameters::Default_named_parameters>
void write_vtp(const std::string& filename, const TriangleMesh& mesh, const FaceVectorMap& field,
               const std::string& name, const NamedParameters& np = parameters::default_values())
{
  write_vtp(filename, mesh, std::vector<std::pair<std::string, FaceVectorMap>>{{name, field}}, np);
}

/// \brief Reads the 3-component cell array `name` of a `.vtp` file into `field`.
///
/// The file must have one polygon per face of the mesh (in face index order), as
/// `write_vtp` writes it.  The map is written only after the whole file was read.
/// \throws Invalid_input if the file is unreadable, has no such array, or does not
///         match the mesh's face count.
template <class TriangleMesh, class FaceVectorMap, class NamedParameters = parameters::Default_named_parameters>
void read_vtp(const std::string& filename, const TriangleMesh& mesh, const std::string& name, FaceVectorMap field,
              const NamedParameters& np = parameters::default_values())
{
  std::ifstream in = internal::open_for_reading(filename);
  const Vtk_polydata data = read_vtk_polydata(in);
  internal::Indexed_triangles<TriangleMesh, NamedParameters> soup(mesh, np);
  if(data.polygons.size() != soup.faces.size() || !data.lines.empty())
    throw Invalid_input("'" + filename + "' has " + std::to_string(data.polygons.size()) + " polygons, the mesh " +
                        std::to_string(soup.faces.size()) + " faces");
  const Vtk_polydata::Array* a = data.find_cell_array(name);
  if(!a || a->components != 3) throw Invalid_input("'" + filename + "' has no 3-component cell array '" + name + "'");
  std::vector<std::array<double, 3>> values(soup.faces.size());
  for(std::size_t i = 0; i < values.size(); ++i) values[i] = {a->values[3 * i], a->values[3 * i + 1], a->values[3 * i + 2]};
  soup.write(values, field);
}

/// \brief Writes `field` in Directional's raw format (degree 1), faces in index order.
template <class TriangleMesh, class FaceVectorMap, class NamedParameters = parameters::Default_named_parameters>
void write_raw_field(const std::string& filename, const TriangleMesh& mesh, const FaceVectorMap& field,
                     const NamedParameters& np = parameters::default_values())
{
  internal::Indexed_triangles<TriangleMesh, NamedParameters> soup(mesh, np);
  Raw_field raw;
  raw.vectors = soup.read(field);
  std::ofstream out = internal::open_for_writing(filename);
  write_raw_field(out, raw);
}

/// \brief Reads a raw field into `field`.  For a field of degree `N > 1` (N vectors
/// per face, e.g. an N-RoSy field), `direction` (0..N-1) picks which vector per face.
/// \throws Invalid_input for a malformed file, a face count different from the mesh's,
///         or a `direction` outside `[0, N)`; the map is then untouched.
template <class TriangleMesh, class FaceVectorMap, class NamedParameters = parameters::Default_named_parameters>
void read_raw_field(const std::string& filename, const TriangleMesh& mesh, FaceVectorMap field, int direction = 0,
                    const NamedParameters& np = parameters::default_values())
{
  std::ifstream in = internal::open_for_reading(filename);
  const Raw_field raw = read_raw_field(in);
  internal::Indexed_triangles<TriangleMesh, NamedParameters> soup(mesh, np);
  if(raw.number_of_faces() != soup.faces.size())
    throw Invalid_input("'" + filename + "' has " + std::to_string(raw.number_of_faces()) + " faces, the mesh " +
                        std::to_string(soup.faces.size()));
  if(direction < 0 || direction >= raw.degree)
    throw Invalid_input("'" + filename + "' has " + std::to_string(raw.degree) + " vectors per face; direction " +
                        std::to_string(direction) + " does not exist");
  std::vector<std::array<double, 3>> picked(raw.vectors.begin() + direction, raw.vectors.end());
  soup.write(picked, field, static_cast<std::size_t>(raw.degree));
}

/// Streamlines as OBJ polylines (`write_streamlines_obj`).
inline void write_streamlines_obj(const std::string& filename, const std::vector<Streamline>& lines)
{
  std::ofstream out = internal::open_for_writing(filename);
  write_streamlines_obj(out, lines);
}

/// Streamlines as a PLY file with edge elements (`write_streamlines_ply`).
inline void write_streamlines_ply(const std::string& filename, const std::vector<Streamline>& lines)
{
  std::ofstream out = internal::open_for_writing(filename);
  write_streamlines_ply(out, lines);
}

/// Streamlines as VTK polylines (`streamlines_polydata`).
inline void write_streamlines_vtp(const std::string& filename, const std::vector<Streamline>& lines)
{
  std::ofstream out = internal::open_for_writing(filename);
  write_vtk_polydata(out, streamlines_polydata(lines));
}

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
