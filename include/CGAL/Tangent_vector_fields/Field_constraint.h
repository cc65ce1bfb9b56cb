// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_FIELD_CONSTRAINT_H
#define CGAL_TANGENT_VECTOR_FIELDS_FIELD_CONSTRAINT_H

/// \file Field_constraint.h
/// What a user asks of a designed field (SPEC 7): a vector, a direction, a
/// divergence or a curl at a place on the mesh, and the linear rows `C~ x = c`
/// on frame coordinates that express it.

#include <CGAL/Tangent_vector_fields/Operator_matrices.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

/// The kinds of constraints on a designed field.
enum class Constraint_kind {
  vector,     ///< the field equals a vector in a face (2 rows)
  direction,  ///< the field is parallel to a direction in a face: its normal component is 0 (1 row)
  divergence, ///< `div_h` at a vertex, or interpolated at a point of a face (1 row)
  curl        ///< `curl*_h` at an edge, or interpolated at a point of a face (1 row)
};

/// \brief One constraint, on the index-based mesh (`Intrinsic_mesh` numbering).
///
/// Points of a face are given by barycentric coordinates with respect to
/// `Intrinsic_mesh::face_vertices(face)` (the generic `Vector_field_spline` accepts
/// them in the mesh's own vertex order and converts).  Vectors are 3D; they are
/// projected orthogonally onto the face plane.
///
/// Signs: a positive divergence makes a source, a positive curl a vortex turning
/// counter-clockwise seen from the side the face normals point to.
struct Field_constraint
{
  Constraint_kind kind = Constraint_kind::vector;
  int face = -1;   ///< vector, direction, and divergence or curl at a point
  int vertex = -1; ///< divergence at a vertex
  int edge = -1;   ///< curl at an edge
  std::array<double, 3> barycentric = {{1. / 3, 1. / 3, 1. / 3}}; ///< point in `face` (divergence, curl)
  std::array<double, 3> vector = {{0, 0, 0}}; ///< vector or direction
  double value = 0;                           ///< divergence or curl

  static Field_constraint vector_in_face(int face, const std::array<double, 3>& v)
  {
    Field_constraint c;
    c.face = face;
    c.vector = v;
    return c;
  }
  static Field_constraint direction_in_face(int face, const std::array<double, 3>& d)
  {
    Field_constraint c = vector_in_face(face, d);
    c.kind = Constraint_kind::direction;
    return c;
  }
  static Field_constraint divergence_at_vertex(int vertex, double value)
  {
    Field_constraint c;
    c.kind = Constraint_kind::divergence;
    c.vertex = vertex;
    c.value = value;
    return c;
  }
  static Field_constraint divergence_at_point(int face, const std::array<double, 3>& barycentric, double value)
  {
    Field_constraint c;
    c.kind = Constraint_kind::divergence;
    c.face = face;
    c.barycentric = barycentric;
    c.value = value;
    return c;
  }
  static Field_constraint curl_at_edge(int edge, double value)
  {
    Field_constraint c;
    c.kind = Constraint_kind::curl;
    c.edge = edge;
    c.value = value;
    return c;
  }
  static Field_constraint curl_at_point(int face, const std::array<double, 3>& barycentric, double value)
  {
    Field_constraint c = divergence_at_point(face, barycentric, value);
    c.kind = Constraint_kind::curl;
    return c;
  }
  /// The field is parallel to boundary edge `edge` in its face.
  static Field_constraint boundary_alignment(const Intrinsic_mesh& mesh, int edge);

  /// Whether `other` has the same rows as this constraint, so that replacing one by the
  /// other only changes values (same kind and place; never for directions).
  bool same_rows_as(const Field_constraint& other) const;
  /// Number of rows: 2 for a vector, 1 otherwise.
  int rows() const { return kind == Constraint_kind::vector ? 2 : 1; }
  /// One line such as "divergence 1.5 at vertex 12", for messages.
  std::string describe() const;
};

/// Barycentric coordinates (in the order of `mesh.face_vertices(face)`) of the
/// orthogonal projection of `point` onto the plane of `face`, clamped into the face.
/// \throws Invalid_input for a face out of range or a non-finite point.
std::array<double, 3> barycentric_coordinates(const Intrinsic_mesh& mesh, int face, const std::array<double, 3>& point);

/// True if `b` are the barycentric coordinates of a point of a (closed) face: finite,
/// non-negative and summing to 1, each up to 1e-9 (rounding of coordinates typed in or
/// computed by `barycentric_coordinates`).
bool is_point_of_face(const std::array<double, 3>& b);

/// Reorders barycentric `weights` given for the vertices `vertices` (any order of the
/// face's three vertices) into the order of `mesh.face_vertices(face)`.
/// \throws Invalid_input if `vertices` are not the vertices of `face`.
std::array<double, 3> barycentric_in_face_order(const Intrinsic_mesh& mesh, int face, const std::array<int, 3>& vertices,
                                                const std::array<double, 3>& weights);

/// A sparse row of `C~` (entries `(index in 0..2nf-1, coefficient)`) with its value.
struct Constraint_row
{
  std::vector<std::pair<int, double>> entries;
  double value = 0;
  /// Scale that makes the row dimensionless on the unit-area mesh: 1 for vectors and
  /// directions, `sqrt(area)` for divergence and curl (they carry one inverse length).
  double unit_area_scale = 1;

  double dot(const Eigen::VectorXd& field) const
  {
    double s = 0;
    for(const auto& e : entries) s += e.second * field[e.first];
    return s;
  }
};

/// The values `c` of the rows of `constraint`, checked as `constraint_rows` checks them
/// but without building the rows (for value edits).
std::vector<double> constraint_values(const Intrinsic_mesh& mesh, const Field_constraint& constraint);
inline std::vector<double> constraint_values(const Operator_matrices& operators, const Field_constraint& constraint)
{
  return constraint_values(operators.mesh(), constraint);
}

/// The rows of `constraint` (`rows()` of them).
/// \throws Invalid_input for an element index out of range, non-finite numbers,
///         barycentric coordinates that are negative or do not sum to 1 (1e-9), a
///         zero direction, a non-zero vector normal to its face, or a divergence at a
///         vertex in no face.
std::vector<Constraint_row> constraint_rows(const Operator_matrices& operators, const Field_constraint& constraint);

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
