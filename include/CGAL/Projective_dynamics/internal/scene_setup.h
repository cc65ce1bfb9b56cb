// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PROJECTIVE_DYNAMICS_INTERNAL_SCENE_SETUP_H
#define CGAL_PROJECTIVE_DYNAMICS_INTERNAL_SCENE_SETUP_H

/// \file scene_setup.h
/// What `tvf simulate` and the viewer's `simulation` session share to make a scene of a
/// surface mesh: the body (a shell of the surface, or a solid of tetrahedra with the surface
/// embedded), the floor of a drop, and reduction sizes capped to what a mesh allows.
/// Needs the `projective_dynamics_meshing` library (Mesh_3) for solids.

#include <CGAL/Projective_dynamics/Elastic_model.h>
#include <CGAL/Projective_dynamics/Reduced_simulator.h>
#include <CGAL/Projective_dynamics/make_models.h>
#include <CGAL/Projective_dynamics/tetrahedralize.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace CGAL {
namespace Projective_dynamics {
namespace internal {

/// A simulated body and the surface its frames show.
struct Simulated_body
{
  Simulated_body(Elastic_model m, std::vector<Triangle> s, bool is_solid, int element_count)
    : model(std::move(m)), surface(std::move(s)), solid(is_solid), elements(element_count)
  {}
  Elastic_model model;
  std::vector<Triangle> surface; ///< what the frames show
  bool solid;
  int elements;
  /// A surface mesh filled with tetrahedra: its vertices in them (the frames show the surface).
  bool embedded = false;
  Surface_embedding embedding;
  Tet_mesh tetrahedra; ///< of an embedded surface
  double largest_outside_distance = 0; ///< of the embedded surface, relative to the diagonal
  /// The frames' vertices for the simulator's positions.
  Positions drawn(const Positions& q) const { return embedded ? embedding.embed(q) : q; }
};

/// Material of a body made of a surface (per volume for solids, per area for shells).
struct Body_material
{
  double stiffness = 1e7;
  double density = 1e3;
  double bending = 0; ///< shells only
};

/// A shell of the surface, or (`solid`) the solid it bounds, tetrahedralized by Mesh_3 with
/// the surface's vertices embedded.  \throws as `tetrahedralize` and the model makers.
inline Simulated_body body_of_surface(const std::vector<Point>& points, const std::vector<Triangle>& triangles,
                                      bool solid, const Body_material& material,
                                      const Tetrahedralization_options& tets = Tetrahedralization_options())
{
  if(!solid)
    return Simulated_body(make_shell_model(points, triangles,
                                           parameters::strain_stiffness(material.stiffness)
                                               .density(material.density)
                                               .bending_stiffness(material.bending)),
                          triangles, false, int(triangles.size()));
  Tetrahedralized_surface t = tetrahedralize(points, triangles, tets);
  Simulated_body body(make_solid_model(t.mesh, parameters::strain_stiffness(material.stiffness).density(material.density)),
                      triangles, true, int(t.mesh.tetrahedra.size()));
  body.embedded = true;
  body.embedding = std::move(t.surface);
  body.largest_outside_distance = t.largest_outside_distance;
  body.tetrahedra = std::move(t.mesh);
  return body;
}

/// The vertices a floor must hold so that nothing drawn goes below it: every vertex of a shell;
/// of a solid, the boundary vertices of its tetrahedra (of an embedded surface, those of the
/// tetrahedra around it: the drawn vertices are their convex combinations).
/// `n`: the model's vertex count (the model itself may have moved into a simulator).
inline std::vector<int> collision_vertices(const Simulated_body& body, int n)
{
  std::vector<char> on(std::size_t(n), 0);
  if(!body.solid)
    std::fill(on.begin(), on.end(), 1);
  else
    for(const Triangle& t : body.embedded ? boundary_triangles(body.tetrahedra.points, body.tetrahedra.tetrahedra) : body.surface)
      for(int v : t) on[std::size_t(v)] = 1;
  std::vector<int> vertices;
  for(int v = 0; v < n; ++v)
    if(on[std::size_t(v)]) vertices.push_back(v);
  return vertices;
}

/// The floor of a drop: a quarter of the body's height below it (of its largest side if it is flat).
inline double drop_floor_height(const Positions& rest)
{
  const Eigen::RowVector3d lo = rest.colwise().minCoeff(), hi = rest.colwise().maxCoeff();
  const Eigen::RowVector3d extent = hi - lo;
  return lo[2] - 0.25 * std::max(extent[2], 0.1 * extent.maxCoeff());
}

/// Reduction sizes for a model of `n` vertices: `samples` position samples, but unless
/// `samples_given` at most one per 16 vertices (a sample's support must hold enough vertices
/// to span its affine maps); constraint samples at most `n`, `l` at most 4 per constraint
/// sample, `s` at least `l + 20`.
inline Reduction_options capped_reduction_options(int n, int samples, bool samples_given, int projection_columns,
                                                  int sampled_elements,
                                                  Reduction_options r = Reduction_options())
{
  r.samples = samples_given ? std::min(samples, n) : std::min(samples, std::max(1, n / 16));
  r.constraint_samples = std::min(r.constraint_samples, n);
  r.projection_columns = std::min(projection_columns, 4 * r.constraint_samples);
  r.sampled_elements = std::max(sampled_elements, r.projection_columns + 20);
  return r;
}

} // namespace internal
} // namespace Projective_dynamics
} // namespace CGAL

#endif
