// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_BASIS_FILE_H
#define CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_BASIS_FILE_H

// The binary basis files (vector-field `.tvfb`, n-field `.tvfn`) are the shared package's
// result files (<CGAL/Model_reduction/internal/binary_file.h>), tied to their mesh by the
// identity of its intrinsic geometry.

#include <CGAL/Model_reduction/internal/binary_file.h>
#include <CGAL/Tangent_vector_fields/Intrinsic_mesh.h>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

using Model_reduction::internal::Binary_reader;
using Model_reduction::internal::open_binary_file;
using Model_reduction::internal::write_header;
using Model_reduction::internal::write_matrix;
using Model_reduction::internal::write_value;

/// A hash of the connectivity (counts, face vertices and edges, each face read from its corner
/// of smallest index), the total area and four pseudo-randomly weighted sums of the edge
/// lengths: equal (the sums to ~1e-12 relative) only for the same mesh with the same intrinsic
/// geometry.  Written by `.tvfb` version 3 and `.tvfn` version 3 on.
Model_reduction::internal::Mesh_identity mesh_identity(const Intrinsic_mesh& mesh);
/// The identity earlier files hold (`.tvfb` versions 1-2, `.tvfn` version 2): its hash reads
/// each face from the corner `Intrinsic_mesh` starts it at, which depends on the edge lengths
/// (longest edge first), so a mesh whose vertices moved could look like other connectivity.
Model_reduction::internal::Mesh_identity legacy_mesh_identity(const Intrinsic_mesh& mesh);

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
