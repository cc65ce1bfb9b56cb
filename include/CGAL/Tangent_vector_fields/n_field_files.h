// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_N_FIELD_FILES_H
#define CGAL_TANGENT_VECTOR_FIELDS_N_FIELD_FILES_H

/// \file n_field_files.h
/// n-direction fields in the files other programs read: Directional's `.rawfield` (all n
/// vectors per face) and `.sing` (singular vertices), and VTK PolyData (`.vtp`: the n vectors
/// as cell arrays, the index of every vertex as a point array, for ParaView's glyphs).

#include <CGAL/Tangent_vector_fields/N_field_operators.h>
#include <CGAL/Tangent_vector_fields/field_files.h>

#include <Eigen/Core>

#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

/// The n vectors of every face of the n-field `z` (power representation), in 3D, counter-
/// clockwise from the first (`N_field_operators::to_vectors`): Directional's `.rawfield`
/// layout, degree n.
Raw_field n_field_to_raw_field(const N_field_operators& operators, const Eigen::VectorXd& z);

/// The n-field (power representation) of a raw field of degree n.  Each face's n vectors must
/// be one vector and its turns by `2 pi j / n`, counter-clockwise: `|u_j - e^{2 pi i j / n} u_0|`
/// at most `tolerance` times the longest of them (after projection onto the face).  The
/// default, 1e-4, accepts files written with 6 significant digits (Directional's default
/// precision: measured 5e-7 on its elephant cross field) and still refuses anything that is
/// not an n-field; all zero is a zero face.
/// \throws Invalid_input naming the face and what is wrong: another degree than n, another
///         number of faces, vectors that are not an n-field (e.g. clockwise, or a frame field).
Eigen::VectorXd n_field_from_raw_field(const N_field_operators& operators, const Raw_field& raw,
                                       double tolerance = 1e-4);

/// Singular vertices in Directional's `.sing` format: a line `N count`, then one line
/// `vertex k` per singularity (the index is `k / N`).
struct Singularity_file
{
  int n = 0;
  std::vector<std::pair<int, int>> singularities; ///< `(vertex, k)`
};

/// \throws Invalid_input if `n < 1` or the stream fails.
void write_singularity_file(std::ostream& out, const Singularity_file& file);
/// \throws Invalid_input for a bad header, missing or non-integer numbers, a negative vertex,
///         extra text, or a vertex listed twice.
Singularity_file read_singularity_file(std::istream& in);

/// The singular vertices of `z` as a `.sing` file's contents.
Singularity_file n_field_singularity_file(const N_field_operators& operators, const Eigen::VectorXd& z);

/// The mesh with the n-field `z`: cell arrays `name_0 ... name_{n-1}` (the n vectors, 3D) and
/// the point array `name_index` (the index `k / n` of every vertex; 0 at regular ones), for
/// `write_vtk_polydata`.
Vtk_polydata n_field_polydata(const N_field_operators& operators, const Eigen::VectorXd& z, const std::string& name);

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
