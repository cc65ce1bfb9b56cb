// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_MESH_ADAPTER_H
#define CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_MESH_ADAPTER_H

// Bridges a BGL `TriangleMesh` and the index-based `Intrinsic_mesh`: extracts the
// connectivity and points through the mesh's index maps, and moves values between
// property maps and Eigen vectors.

#include <CGAL/Tangent_vector_fields/Intrinsic_mesh.h>
#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/named_function_parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <Eigen/Core>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

template <class NamedParameters>
Intrinsic_mesh_options intrinsic_mesh_options(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Intrinsic_mesh_options options;
  options.use_intrinsic_mollification =
      choose_parameter(get_parameter(np, internal_np::use_intrinsic_mollification), false);
  options.mollification_epsilon =
      choose_parameter(get_parameter(np, internal_np::mollification_epsilon), options.mollification_epsilon);
  options.degeneracy_tolerance =
      choose_parameter(get_parameter(np, internal_np::degeneracy_tolerance), options.degeneracy_tolerance);
  return options;
}

/// The coordinates of a CGAL point or vector as doubles.
template <class T>
std::array<double, 3> to_array(const T& v)
{
  return {{CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z())}};
}

/// The mesh's elements in the order of their indices, and the intrinsic mesh built from them.
// The graph's ranges, found by argument-dependent lookup when the template is instantiated
// (so that this header compiles before the mesh's graph traits are included).
template <class Graph>
auto graph_vertices(const Graph& g) { return vertices(g); }
template <class Graph>
auto graph_edges(const Graph& g) { return edges(g); }
template <class Graph>
auto graph_faces(const Graph& g) { return faces(g); }

template <class TriangleMesh>
class Mesh_adapter
{
public:
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  template <class NamedParameters>
  Mesh_adapter(const TriangleMesh& mesh, const NamedParameters& np) : mesh_(mesh)
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, mesh));
    auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
    auto eim = CGAL::get_initialized_edge_index_map(mesh, np);
    auto fim = CGAL::get_initialized_face_index_map(mesh, np);

    place(vertices_, graph_vertices(mesh), vim, "vertex");
    place(edges_, graph_edges(mesh), eim, "edge");
    place(faces_, graph_faces(mesh), fim, "face");

    std::vector<Intrinsic_mesh::Point> points(vertices_.size());
    for(std::size_t i = 0; i < vertices_.size(); ++i)
    {
      const auto& p = get(vpm, vertices_[i]);
      points[i] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    }
    std::vector<std::array<int, 3>> face_vertices(faces_.size()), face_edges(faces_.size());
    for(std::size_t f = 0; f < faces_.size(); ++f)
    {
      const halfedge_descriptor h = halfedge(faces_[f], mesh);
      halfedge_descriptor g = h;
      int k = 0;
      do
      {
        if(k < 3)
        {
          face_vertices[f][k] = static_cast<int>(get(vim, source(g, mesh)));
          face_edges[f][k] = static_cast<int>(get(eim, edge(g, mesh)));
        }
        ++k;
        g = next(g, mesh);
      } while(g != h);
      if(k != 3)
        throw Invalid_mesh(Mesh_defect::non_triangle_face,
                           "face " + std::to_string(f) + " has " + std::to_string(k) + " vertices");
    }
    mesh_data_ = std::make_shared<const Intrinsic_mesh>(std::move(points), face_vertices, face_edges,
                                                        static_cast<int>(edges_.size()), intrinsic_mesh_options(np));
  }

  const TriangleMesh& mesh() const { return mesh_; }
  std::shared_ptr<const Intrinsic_mesh> intrinsic_mesh() const { return mesh_data_; }
  const std::vector<vertex_descriptor>& vertices() const { return vertices_; }
  const std::vector<edge_descriptor>& edges() const { return edges_; }
  const std::vector<face_descriptor>& faces() const { return faces_; }

  /// Frame coordinates (`2nf`) of a face map of 3D vectors (projected on the faces).
  template <class FaceVectorMap>
  Eigen::VectorXd read_field(const FaceVectorMap& field) const
  {
    Eigen::VectorXd x(2 * faces_.size());
    for(std::size_t f = 0; f < faces_.size(); ++f)
    {
      const auto& w = get(field, faces_[f]);
      const auto ab = mesh_data_->to_frame(
          static_cast<int>(f), {CGAL::to_double(w.x()), CGAL::to_double(w.y()), CGAL::to_double(w.z())});
      x[2 * f] = ab[0];
      x[2 * f + 1] = ab[1];
    }
    return x;
  }

  /// Writes frame coordinates as 3D vectors into a face map.
  template <class FaceVectorMap>
  void write_field(const Eigen::VectorXd& x, FaceVectorMap field) const
  {
    typedef typename boost::property_traits<FaceVectorMap>::value_type Vector_3;
    for(std::size_t f = 0; f < faces_.size(); ++f)
    {
      const auto w = mesh_data_->from_frame(static_cast<int>(f), x[2 * f], x[2 * f + 1]);
      put(field, faces_[f], Vector_3(w[0], w[1], w[2]));
    }
  }

  /// Values of a scalar property map over `elements` (vertices, edges or faces).
  template <class Descriptor, class ScalarMap>
  static Eigen::VectorXd read_values(const std::vector<Descriptor>& elements, const ScalarMap& map)
  {
    Eigen::VectorXd x(elements.size());
    for(std::size_t i = 0; i < elements.size(); ++i) x[i] = CGAL::to_double(get(map, elements[i]));
    return x;
  }

  template <class Descriptor, class ScalarMap>
  static void write_values(const std::vector<Descriptor>& elements, const Eigen::VectorXd& x, ScalarMap map)
  {
    typedef typename boost::property_traits<ScalarMap>::value_type FT;
    for(std::size_t i = 0; i < elements.size(); ++i) put(map, elements[i], FT(x[i]));
  }

private:
  // Puts each element at the position its index map gives, checking that the
  // indices are exactly 0..n-1.
  template <class Range, class IndexMap, class Descriptor>
  static void place(std::vector<Descriptor>& out, const Range& range, const IndexMap& index, const char* what)
  {
    const std::size_t n = static_cast<std::size_t>(std::distance(range.begin(), range.end()));
    out.assign(n, Descriptor());
    std::vector<char> seen(n, 0);
    for(const Descriptor& d : range)
    {
      const std::size_t i = static_cast<std::size_t>(get(index, d));
      if(i >= n || seen[i])
        throw Invalid_mesh(Mesh_defect::garbage,
                           std::string("the ") + what + " indices are not 0.." + std::to_string(n) +
                               "-1 (a Surface_mesh with removed elements: call collect_garbage() first)");
      seen[i] = 1;
      out[i] = d;
    }
  }

  const TriangleMesh& mesh_;
  std::vector<vertex_descriptor> vertices_;
  std::vector<edge_descriptor> edges_;
  std::vector<face_descriptor> faces_;
  std::shared_ptr<const Intrinsic_mesh> mesh_data_;
};

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
