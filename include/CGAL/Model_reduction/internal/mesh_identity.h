// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_INTERNAL_MESH_IDENTITY_H
#define CGAL_MODEL_REDUCTION_INTERNAL_MESH_IDENTITY_H

// The pieces of a result file's `Mesh_identity` (binary_file.h) that do not depend on a
// package's mesh representation: a connectivity hash that reads every face from a canonical
// corner, the geometry signature from the area and the edge lengths, and both for a triangle
// mesh given as stacked positions and index triples.

#include <CGAL/Model_reduction/internal/binary_file.h>

#include <array>
#include <vector>

namespace CGAL {
namespace Model_reduction {
namespace internal {

/// FNV-1a hash of the counts and of every face's corners (and edges, if `face_edges` is not
/// empty), each face read from its corner of smallest vertex index in its own orientation:
/// the hash depends on the connectivity only, not on where a representation starts a face
/// (a rotation chosen from the geometry, e.g. at the longest edge, would make a deformed mesh
/// look like another connectivity).
std::uint64_t connectivity_fingerprint(std::int64_t number_of_vertices, std::int64_t number_of_edges,
                                       const std::vector<std::array<int, 3>>& faces,
                                       const std::vector<std::array<int, 3>>& face_edges = {});

/// The total area and four pseudo-randomly weighted sums of the edge lengths (in the given
/// edge order): equal to ~1e-12 relative only for the same intrinsic geometry.
std::array<double, 5> geometry_signature(double total_area, const std::vector<double>& edge_lengths);

/// The identity of a triangle mesh given as stacked positions `(x0, y0, z0, x1, ...)` and
/// index triples: its connectivity, and the geometry signature with the edges in the order of
/// their sorted vertex pairs (intrinsic: a rigid motion keeps it).
Mesh_identity triangle_mesh_identity(const Eigen::VectorXd& positions, const std::vector<std::array<int, 3>>& triangles);

/// Three pseudo-randomly weighted sums of the coordinates (x, y and z) and the sum of their
/// absolute values: unlike `triangle_mesh_identity`, they change when the mesh is moved or turned.
std::array<double, 4> position_signature(const Eigen::VectorXd& positions);

} // namespace internal
} // namespace Model_reduction
} // namespace CGAL

#endif
