// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_N_FIELD_CONSTRAINT_H
#define CGAL_TANGENT_VECTOR_FIELDS_N_FIELD_CONSTRAINT_H

/// \file N_field_constraint.h
/// What a user asks of a designed n-field (SPEC 10): a vector (direction and length) or a
/// direction in a face, given by any one of the n vectors, or a singularity of index k/n at
/// a vertex, and the linear rows on the power representation that express it.

#include <CGAL/Tangent_vector_fields/Field_constraint.h>
#include <CGAL/Tangent_vector_fields/N_field_operators.h>

#include <array>
#include <string>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

enum class N_field_constraint_kind {
  vector,      ///< the n-field's vectors in a face: direction and length (2 rows)
  direction,   ///< the n-field's direction in a face, length free (1 row; see `direction_in_face`)
  singularity  ///< index `k / n` at an interior vertex (2 rows per face of its one-ring, less 2; 2 more if anchored)
};

/// \brief One constraint on an n-field, on the index-based mesh.
struct N_field_constraint
{
  N_field_constraint_kind kind = N_field_constraint_kind::vector;
  int face = -1;   ///< vector, direction; the anchor face of a singularity (-1: none)
  int vertex = -1; ///< singularity
  std::array<double, 3> vector = {{0, 0, 0}}; ///< any one of the n vectors (3D, projected onto the face)
  int index = 0;   ///< singularity: `k`, the field turns by `2 pi k / n` around the vertex
  /// Vector, direction: the point of `face` (barycentric, in the order of the face's
  /// vertices) where the field is constrained; the centroid (default) constrains the face's
  /// own value.  Elsewhere the constraint acts on the field interpolated at the point (see
  /// `vector_at_point`).
  std::array<double, 3> barycentric = {{1. / 3, 1. / 3, 1. / 3}};

  /// The n vectors of face `face` are `v` (projected onto the face) and its turns by `2 pi j / n`.
  static N_field_constraint vector_in_face(int face, const std::array<double, 3>& v)
  {
    N_field_constraint c;
    c.face = face;
    c.vector = v;
    return c;
  }
  /// `Im(conj(w) z_f) = 0` with `w` the power of `d`: the field's power is a real multiple of
  /// `w`.  For n = 1 that is the direction up to sign; for n > 1 a negative multiple is the
  /// n-field turned by `pi / n` (a cross at 45 degrees to `d`): where that matters, constrain
  /// the vector (direction and length) instead.
  static N_field_constraint direction_in_face(int face, const std::array<double, 3>& d)
  {
    N_field_constraint c = vector_in_face(face, d);
    c.kind = N_field_constraint_kind::direction;
    return c;
  }
  /// The n-field at a point of `face` (barycentric coordinates, see
  /// `barycentric_coordinates` for a 3D point): its value there is the face's own plus, per
  /// interior edge, `(1/3 - b_k) (rho^n z_g - z_f)` with `b_k` the coordinate of the corner
  /// opposite the edge and `z_g` the neighbour across it, carried into `f` by the surface's
  /// transport.  That is the Crouzeix-Raviart interpolant (edge midpoints take the mean of
  /// their two faces) moved so that the centroid keeps the face's value; it reproduces
  /// fields that are linear in the plane wherever neighbouring triangles are point
  /// reflections of each other (regular grids), and a point constraint touches at most 4 faces.
  static N_field_constraint vector_at_point(int face, const std::array<double, 3>& barycentric,
                                            const std::array<double, 3>& v)
  {
    N_field_constraint c = vector_in_face(face, v);
    c.barycentric = barycentric;
    return c;
  }
  /// `direction_in_face` at a point of `face` (interpolated as in `vector_at_point`).
  static N_field_constraint direction_at_point(int face, const std::array<double, 3>& barycentric,
                                               const std::array<double, 3>& d)
  {
    N_field_constraint c = direction_in_face(face, d);
    c.barycentric = barycentric;
    return c;
  }
  /// True unless the constraint is at the centroid of its face (vector, direction).
  bool is_at_point() const
  {
    return kind != N_field_constraint_kind::singularity &&
           !(barycentric[0] == 1. / 3 && barycentric[1] == 1. / 3 && barycentric[2] == 1. / 3);
  }
  /// A singularity of index `k / n` at interior vertex `vertex`.  Formulation (one-ring
  /// relations, SPEC 10 (a)): with faces `f_0 .. f_{m-1}` counter-clockwise around the vertex,
  /// `z_{i+1} = e^{i phi} rho_i^n z_i` for `i = 0 .. m-2`, `phi = (2 pi k - n K_v) / m`: the field
  /// turns by the same angle between neighbouring faces, `2 pi k` in total, so the index is
  /// exactly k.  `|phi| < pi` is required.
  ///
  /// Unanchored, the relations are homogeneous: the field may shrink on the one-ring and
  /// screen the singularity with opposite ones on the neighbouring vertices (measured on a
  /// torus: a prescribed -1/4 came with +1/4 on 3 of its neighbours).  Anchored by
  /// `singularity_at_vertex(vertex, k, face, v)`, one face of the one-ring also gets the
  /// n-field vector `v` (2 more rows): the one-ring keeps the length |v| and the pattern's
  /// orientation, and no neighbour can screen it.
  static N_field_constraint singularity_at_vertex(int vertex, int k)
  {
    N_field_constraint c;
    c.kind = N_field_constraint_kind::singularity;
    c.vertex = vertex;
    c.index = k;
    return c;
  }
  /// A singularity anchored by the vector `v` in `face`, a face of the vertex's one-ring.
  static N_field_constraint singularity_at_vertex(int vertex, int k, int face, const std::array<double, 3>& v)
  {
    N_field_constraint c = singularity_at_vertex(vertex, k);
    c.face = face;
    c.vector = v;
    return c;
  }
  bool is_anchored() const { return kind == N_field_constraint_kind::singularity && face >= 0; }

  /// Same kind and place (vectors of the same face, singularities of the same vertex, index
  /// and anchor face): replacing one by the other only changes values.
  bool same_rows_as(const N_field_constraint& other) const;
  /// One line such as "singularity 1/4 at vertex 12", for messages (`n` for the fraction).
  std::string describe() const;
};

/// The rows of `constraint` on the power representation (`2nf` unknowns).
/// \throws Invalid_input for an index out of range, non-finite numbers, barycentric
///         coordinates that are negative or do not sum to 1 (1e-9), a zero direction (a zero
///         vector is valid: the field vanishes there), one normal to its face, a singularity at a boundary or isolated
///         vertex, or one whose turning per face `|phi|` is `pi` or more.
std::vector<Constraint_row> constraint_rows(const N_field_operators& operators, const N_field_constraint& constraint);

/// The values of the rows of `constraint` without building them (value edits).
std::vector<double> constraint_values(const N_field_operators& operators, const N_field_constraint& constraint);

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
