// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PROJECTIVE_DYNAMICS_TET_MESH_H
#define CGAL_PROJECTIVE_DYNAMICS_TET_MESH_H

/// \file Tet_mesh.h
/// A tetrahedral mesh as plain arrays (no CGAL mesh type, so that the simulator's translation
/// units compile fast), its checks, and what is derived from it: the boundary triangles and
/// the unique edges.

#include <array>
#include <vector>

namespace CGAL {
namespace Projective_dynamics {

typedef std::array<double, 3> Point;
typedef std::array<int, 2> Edge;
typedef std::array<int, 3> Triangle;
typedef std::array<int, 4> Tetrahedron;

/// Positions, tetrahedra and (optionally) surface triangles, all indices 0-based.
/// A tetrahedron `(a, b, c, d)` is positively oriented when `(b - a) x (c - a) . (d - a) > 0`;
/// the checks accept both orientations (the simulator's strain does not depend on it).
struct Tet_mesh
{
  std::vector<Point> points;
  std::vector<Tetrahedron> tetrahedra;
  /// Surface triangles, e.g. for drawing; may be empty (`boundary_triangles` makes them).
  std::vector<Triangle> triangles;
};

/// Checks `mesh` for what the simulator refuses.
/// \throws Invalid_mesh: `empty` (no points or no tetrahedra), `invalid_index` (an index out
///         of range or repeated within an element, naming the element), `non_finite_coordinate`
///         (naming the vertex), `degenerate_face` (a tetrahedron of (nearly) zero volume, naming
///         it: `|volume| <= 1e-12 * (longest edge)^3`).
void check_tet_mesh(const Tet_mesh& mesh);

/// Signed volume of tetrahedron `t`: `(b - a) x (c - a) . (d - a) / 6`.
double signed_volume(const std::vector<Point>& points, const Tetrahedron& t);

/// The faces used by exactly one tetrahedron, oriented with their normal pointing out of it.
std::vector<Triangle> boundary_triangles(const std::vector<Point>& points, const std::vector<Tetrahedron>& tets);

/// Every edge of the tetrahedra once, as `(smaller, larger)` index pairs, sorted.
std::vector<Edge> unique_edges(const std::vector<Tetrahedron>& tets);
/// Every edge of the triangles once, as `(smaller, larger)` index pairs, sorted.
std::vector<Edge> unique_edges(const std::vector<Triangle>& triangles);

} // namespace Projective_dynamics
} // namespace CGAL

#endif
