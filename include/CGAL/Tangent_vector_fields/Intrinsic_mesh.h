// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_INTRINSIC_MESH_H
#define CGAL_TANGENT_VECTOR_FIELDS_INTRINSIC_MESH_H

/// \file Intrinsic_mesh.h
/// The validated, index-based view of a triangle mesh that all numerics work on:
/// connectivity, edge lengths (optionally mollified), the 2D layout of every face,
/// face frames in 3D, and the topology.  It does not depend on the mesh type, so
/// the heavy numerics compile once in `src/`.

#include <CGAL/Tangent_vector_fields/Mesh_topology.h>

#include <array>
#include <string>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

/// Options for building the intrinsic geometry.
struct Intrinsic_mesh_options
{
  /// Add the smallest constant to every edge length so that each triangle
  /// inequality holds with margin `mollification_epsilon` times the mean edge
  /// length (Sharp and Crane 2020).  Makes degenerate faces usable.
  bool use_intrinsic_mollification = false;
  /// Margin of mollification, relative to the mean edge length.
  double mollification_epsilon = 1e-6;
  /// A face whose smallest triangle-inequality margin `l_i + l_j - l_k` is at most
  /// this times its longest edge is degenerate: its cotangents exceed ~1/tolerance
  /// and all accuracy would be lost, so it is refused (unless mollified).
  double degeneracy_tolerance = 1e-10;
};

/// Index-based triangle mesh with intrinsic geometry.
///
/// Local numbering of a face: corners 0, 1, 2 in positive orientation, rotated so
/// that the edge from corner 0 to corner 1 is the longest one; the face frame `e1`
/// points along that edge and `e2 = n x e1`.  Local edge `k` is opposite corner `k`.
/// The 2D layout puts corner 0 at (0,0), corner 1 at (l_2, 0), corner 2 at (x, y),
/// y > 0: it is the face in its own frame coordinates.
class Intrinsic_mesh
{
public:
  typedef std::array<double, 3> Point;
  typedef std::array<double, 3> Vector;

  /// Validates and builds.  `faces` lists vertex indices in positive orientation.
  /// If `face_edges` is non-empty, entry `[f][k]` is the index (in `[0, number_of_edges)`)
  /// of the edge from corner `k` to corner `k+1` of face `f` as given; otherwise edges
  /// are numbered here in order of first appearance.
  /// \throws Invalid_mesh naming the first defect found.
  Intrinsic_mesh(std::vector<Point> positions,
                 const std::vector<std::array<int, 3>>& faces,
                 const std::vector<std::array<int, 3>>& face_edges = {},
                 int number_of_edges = 0,
                 const Intrinsic_mesh_options& options = Intrinsic_mesh_options());

  int number_of_vertices() const { return static_cast<int>(positions_.size()); }
  int number_of_edges() const { return static_cast<int>(edge_vertices_.size()); }
  int number_of_faces() const { return static_cast<int>(face_vertices_.size()); }
  int number_of_interior_edges() const { return static_cast<int>(interior_edges_.size()); }

  /// Corners of face `f` in local order.
  const std::array<int, 3>& face_vertices(int f) const { return face_vertices_[f]; }
  /// Edge opposite local corner `k` of face `f`.
  const std::array<int, 3>& face_edges(int f) const { return face_edges_[f]; }
  const std::array<int, 2>& edge_vertices(int e) const { return edge_vertices_[e]; }
  /// The one or two faces at edge `e`; the second is -1 on the boundary.
  const std::array<int, 2>& edge_faces(int e) const { return edge_faces_[e]; }
  bool is_boundary_edge(int e) const { return edge_faces_[e][1] < 0; }
  /// Position of `e` among interior edges, or -1 for a boundary edge.
  int interior_edge_index(int e) const { return interior_index_[e]; }
  const std::vector<int>& interior_edges() const { return interior_edges_; }

  const Point& position(int v) const { return positions_[v]; }
  /// Intrinsic length (after mollification) of edge `e`.
  double edge_length(int e) const { return edge_lengths_[e]; }
  /// Length of local edge `k` (opposite corner `k`) of face `f`.
  double face_edge_length(int f, int k) const { return edge_lengths_[face_edges_[f][k]]; }
  double face_area(int f) const { return face_areas_[f]; }
  /// Area of face `f` divided by the square of its longest edge: its shape, free of the
  /// mesh's scale (representable where the area itself under- or overflows).
  double face_shape_area(int f) const { return shape_areas_[f]; }
  /// Layout of corner 2 of face `f` (corner 0 at the origin, corner 1 at (l_2, 0)).
  const std::array<double, 2>& corner2_layout(int f) const { return corner2_[f]; }
  /// Cotangent of the angle at local corner `k` of face `f`.
  double cotangent(int f, int k) const;

  /// Orthonormal frame of face `f` in 3D: `e1`, `e2` and the unit normal.
  const Vector& frame_e1(int f) const { return frames_[f][0]; }
  const Vector& frame_e2(int f) const { return frames_[f][1]; }
  const Vector& normal(int f) const { return frames_[f][2]; }
  /// Frame coordinates of the projection of `w` onto the plane of face `f`.
  std::array<double, 2> to_frame(int f, const Vector& w) const;
  /// The 3D vector with frame coordinates `(a, b)` in face `f`.
  Vector from_frame(int f, double a, double b) const;

  /// Component of vertex `v`, or -1 for a vertex in no face.
  int vertex_component(int v) const { return vertex_component_[v]; }
  int edge_component(int e) const { return vertex_component_[edge_vertices_[e][0]]; }
  int face_component(int f) const { return vertex_component_[face_vertices_[f][0]]; }
  bool is_isolated_vertex(int v) const { return vertex_component_[v] < 0; }
  const Mesh_topology& topology() const { return topology_; }

  /// The constant added to all edge lengths by mollification (0 without it).
  double mollification_delta() const { return mollification_delta_; }
  double mean_edge_length() const { return mean_edge_length_; }
  /// The power of two nearest below the mean edge length.  Dividing lengths by it (and
  /// areas by its square) is exact and brings them near 1: solvers use it to keep
  /// products of lengths, areas and their inverses far from under- and overflow.
  double length_unit() const { return length_unit_; }
  /// Non-fatal findings, e.g. vertices referenced by no face.
  const std::vector<std::string>& warnings() const { return warnings_; }

private:
  void build_edges(const std::vector<std::array<int, 3>>& faces,
                   const std::vector<std::array<int, 3>>& face_edges, int number_of_edges);
  void check_vertex_manifoldness() const;
  void compute_lengths(const Intrinsic_mesh_options& options);
  void compute_layout_and_frames();
  void compute_topology();

  std::vector<Point> positions_;
  std::vector<std::array<int, 3>> face_vertices_;
  std::vector<std::array<int, 3>> face_edges_;
  std::vector<std::array<int, 2>> edge_vertices_;
  std::vector<std::array<int, 2>> edge_faces_;
  std::vector<int> interior_index_;
  std::vector<int> interior_edges_;
  std::vector<double> edge_lengths_;
  std::vector<double> face_areas_;
  std::vector<double> shape_areas_;
  std::vector<std::array<double, 2>> corner2_;
  std::vector<std::array<Vector, 3>> frames_;
  std::vector<int> vertex_component_;
  Mesh_topology topology_;
  double mollification_delta_ = 0;
  double mean_edge_length_ = 0;
  double length_unit_ = 1;
  std::vector<std::string> warnings_;
};

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
