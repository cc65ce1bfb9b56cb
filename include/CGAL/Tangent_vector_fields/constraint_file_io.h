// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_CONSTRAINT_FILE_IO_H
#define CGAL_TANGENT_VECTOR_FIELDS_CONSTRAINT_FILE_IO_H

/// \file constraint_file_io.h
/// Field-design constraints as JSON, for the command line and the editor.
///
/// \verbatim
/// {
///   "omega": 0.0,                       optional: tension (splines) or biharmonic weight (soft)
///   "constraints": [
///     {"type": "vector",     "face": 12, "vector": [1, 0, 0]},
///     {"type": "vector",     "face": 12, "vector": [1, 0, 0], "weight": 5},   weight: soft design only
///     {"type": "direction",  "face": 3,  "direction": [0, 1, 0]},
///     {"type": "divergence", "vertex": 5, "value": 1.0},
///     {"type": "divergence", "face": 7, "point": [0.1, 0.2, 0.3], "value": -1},
///     {"type": "curl",       "edge": 9, "value": 1},
///     {"type": "curl",       "face": 7, "vertices": [4, 9, 2], "barycentric": [0.2, 0.3, 0.5], "value": 1},
///     {"type": "boundary_alignment", "edge": 3}
///   ]
/// }
/// \endverbatim
/// Indices are those of the mesh's index maps (for a `Surface_mesh` read from a file:
/// the order of the file).  A point in a face is a 3D `point` (projected onto the
/// face) or `barycentric` coordinates for the listed `vertices`.  Errors name the
/// constraint (its position in the list) and what is wrong.

#include <CGAL/Tangent_vector_fields/Field_constraint.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

/// The contents of a constraint file.
struct Constraint_file
{
  double omega = 0;
  bool has_omega = false;
  std::vector<Field_constraint> constraints;
  std::vector<double> weights; ///< one per constraint (1 where not given)
};

/// Reads constraints for the mesh of `operators` (and checks them as `constraint_rows` does).
/// \throws Invalid_input with a one-line reason (JSON syntax with its line, unknown
///         type, missing or malformed member, index out of range).
Constraint_file read_constraint_file(std::istream& in, const Operator_matrices& operators);
Constraint_file read_constraint_file(const std::string& path, const Operator_matrices& operators);

/// Writes constraints in the format `read_constraint_file` reads (points as
/// barycentric coordinates with their vertices, numbers with 17 digits).
void write_constraint_file(std::ostream& out, const Constraint_file& file, const Intrinsic_mesh& mesh);

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
