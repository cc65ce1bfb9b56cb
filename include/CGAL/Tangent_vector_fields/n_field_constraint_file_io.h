// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_N_FIELD_CONSTRAINT_FILE_IO_H
#define CGAL_TANGENT_VECTOR_FIELDS_N_FIELD_CONSTRAINT_FILE_IO_H

/// \file n_field_constraint_file_io.h
/// n-field design constraints as JSON (the vector-field files' conventions, `constraint_file_io.h`).
///
/// \verbatim
/// {
///   "n": 4,                                   required: the symmetry
///   "omega": 0.0,                             optional: tension
///   "order": 2,                               optional: m of the energy E_m (2: E_B, 1: first order)
///   "singularities": [                        optional: prescribed in the connection (exact index, no screening)
///     {"vertex": 5, "index": 1}               index k: the field's index is k/n
///   ],
///   "constraints": [
///     {"type": "vector",      "face": 12, "vector": [1, 0, 0]},        any one of the n vectors, with its length
///     {"type": "direction",   "face": 3,  "direction": [0, 1, 0]},
///     {"type": "vector", "face": 7, "point": [0.1, 0.2, 0.3], "vector": [1, 0, 0]},   at a point of the face
///     {"type": "vector", "face": 7, "vertices": [4, 8, 2], "barycentric": [0.2, 0.3, 0.5], "vector": [1, 0, 0]},
///     {"type": "singularity", "vertex": 9, "index": -1},               one-ring relations (editable in real time)
///     {"type": "singularity", "vertex": 9, "index": -1, "face": 20, "vector": [0, 1, 0]}   anchored
///   ]
/// }
/// \endverbatim

#include <CGAL/Tangent_vector_fields/N_field_constraint.h>
#include <CGAL/Tangent_vector_fields/Operator_matrices.h>

#include <iosfwd>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

/// The contents of an n-field constraint file.
struct N_field_constraint_file
{
  int n = 0;
  double omega = 0;
  int order = 2;
  /// Prescribed in the connection: `(vertex, k)`.
  std::vector<std::pair<int, int>> singularities;
  std::vector<N_field_constraint> constraints;
};

/// Reads and checks a file for the mesh of `operators`: every constraint as `constraint_rows`
/// checks it, every prescribed singularity as `N_field_operators` does.
/// \throws Invalid_input with a one-line reason naming the entry (JSON syntax with its line).
N_field_constraint_file read_n_field_constraint_file(std::istream& in, std::shared_ptr<const Operator_matrices> operators);
N_field_constraint_file read_n_field_constraint_file(const std::string& path,
                                                     std::shared_ptr<const Operator_matrices> operators);

/// Writes a file `read_n_field_constraint_file` reads back exactly (17 digits); points as
/// `"vertices"` and `"barycentric"` of `mesh`.
void write_n_field_constraint_file(std::ostream& out, const N_field_constraint_file& file, const Intrinsic_mesh& mesh);

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
