// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PROJECTIVE_DYNAMICS_MESH_GENERATORS_H
#define CGAL_PROJECTIVE_DYNAMICS_MESH_GENERATORS_H

/// \file mesh_generators.h
/// Meshes made in code, for tests, examples and benchmarks.

#include <CGAL/Projective_dynamics/Tet_mesh.h>

#include <vector>

namespace CGAL {
namespace Projective_dynamics {

/// The box `[min, max]` cut into `nx * ny * nz` cubes of `(nx+1)(ny+1)(nz+1)` grid vertices
/// (vertex `(i, j, k)` has index `i + (nx+1) (j + (ny+1) k)`), each cube into six positively
/// oriented tetrahedra around its main diagonal (conforming across cubes); the boundary
/// triangles are filled in.
/// \throws Invalid_input for a count below 1 or `min >= max` in a coordinate.
Tet_mesh make_tet_box(int nx, int ny, int nz, const Point& min, const Point& max);

/// A rod (cantilever) along x: `[0, length] x [0, width] x [0, width]`, `cells` cubes along its
/// length and `cells_across` across, so cubes are about `length / cells` long.
Tet_mesh make_tet_rod(int cells, int cells_across, double length, double width);

/// A chain of `springs` springs hanging from `top`: vertex `i` at `top - i * spacing * axis`,
/// edge `i` from vertex `i` to `i + 1`.
struct Spring_chain
{
  std::vector<Point> points;
  std::vector<Edge> edges;
};
/// \throws Invalid_input for `springs < 1` or `spacing <= 0`.
Spring_chain make_spring_chain(int springs, double spacing, const Point& top = {0, 0, 0},
                               const Point& axis = {0, 0, 1});

} // namespace Projective_dynamics
} // namespace CGAL

#endif
