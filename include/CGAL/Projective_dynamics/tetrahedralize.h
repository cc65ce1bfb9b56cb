// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PROJECTIVE_DYNAMICS_TETRAHEDRALIZE_H
#define CGAL_PROJECTIVE_DYNAMICS_TETRAHEDRALIZE_H

/// \file tetrahedralize.h
/// A closed triangle surface filled with tetrahedra by CGAL's Mesh_3 (sharp edges kept as
/// features), with the surface's own vertices embedded in the tetrahedra, so that a solid
/// simulated on the tetrahedra moves the user's surface:
/// \code
/// namespace PD = CGAL::Projective_dynamics;
/// PD::Tetrahedralized_surface t = PD::tetrahedralize(surface_mesh, PD::parameters::cell_size(0.03));
/// PD::Simulator sim(PD::make_solid_model(t.mesh));
/// sim.step();
/// PD::Positions drawn = t.surface.embed(sim.positions()); // the surface mesh's vertices, moved
/// \endcode
/// Built in its own library (`projective_dynamics_meshing`): Mesh_3 is a heavy compile that the
/// simulators do not need.

#include <CGAL/Projective_dynamics/Elastic_model.h>
#include <CGAL/Projective_dynamics/Tet_mesh.h>
#include <CGAL/Projective_dynamics/errors.h>
#include <CGAL/Projective_dynamics/named_function_parameters.h>

#include <boost/graph/graph_traits.hpp>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <vector>

namespace CGAL {
namespace Projective_dynamics {

/// Sizes of `tetrahedralize`, relative to the diagonal of the surface's bounding box.
struct Tetrahedralization_options
{
  double cell_size = 0.05;       ///< largest circumradius of a tetrahedron (and of a boundary facet and feature edge)
  double facet_distance = 0.002; ///< largest distance between a boundary facet and the surface
  double feature_angle = 60;     ///< edges whose faces' normals differ by more than this (degrees) stay sharp; 0: none
};

/// Points given by barycentric coordinates in tetrahedra: point `i` is
/// `sum_k weights[i][k] * x[mesh.tetrahedra[tetrahedra[i]][k]]`.  A point just outside the
/// tetrahedra (the surface lies within `facet_distance` of them) has coordinates in the
/// tetrahedron of the nearest boundary facet, one of them slightly negative: the tetrahedron's
/// affine map carries it along.
struct Surface_embedding
{
  std::vector<int> tetrahedra;
  std::vector<std::array<double, 4>> weights;
  std::vector<Tetrahedron> corners; ///< the vertices of `tetrahedra[i]`
  /// The points' positions for tetrahedron-mesh positions `x` (n x 3).
  /// \throws Invalid_input if `x` has fewer rows than a corner index.
  Positions embed(const Positions& x) const;
};

/// The tetrahedra and where the surface's vertices are in them.
struct Tetrahedralized_surface
{
  Tet_mesh mesh; ///< its `triangles` are the boundary facets of the tetrahedra
  Surface_embedding surface;
  /// Largest distance from a surface vertex to the tetrahedra (0 inside), relative to the
  /// bounding box diagonal: how far the tetrahedra's boundary is from the surface.
  double largest_outside_distance = 0;
};

/// Fills the closed surface given by `points` and `triangles` (indices into `points`).
/// \throws Invalid_input, with the reason, for an empty surface, a non-finite coordinate, an
///         index out of range, a surface that is not an oriented 2-manifold, that is open
///         (naming its border edges), that intersects itself, or sizes that are not positive;
///         Numerical_failure if Mesh_3 makes no tetrahedron.
Tetrahedralized_surface tetrahedralize(const std::vector<Point>& points, const std::vector<Triangle>& triangles,
                                       const Tetrahedralization_options& options = Tetrahedralization_options());

/// The same for a triangle mesh (a model of `FaceListGraph`, e.g. `CGAL::Surface_mesh`): the
/// embedding's point `i` is the vertex of index `i`.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{cell_size} relative to the bounding box diagonal; `double`; default 0.05 \cgalParamNEnd
///   \cgalParamNBegin{facet_distance} relative to the diagonal; `double`; default 0.002 \cgalParamNEnd
///   \cgalParamNBegin{feature_angle} degrees; `double`; default 60 \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map, vertex_index_map} as in CGAL \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
Tetrahedralized_surface tetrahedralize(const TriangleMesh& mesh,
                                       const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Tetrahedralization_options o;
  o.cell_size = choose_parameter(get_parameter(np, internal_np::cell_size), o.cell_size);
  o.facet_distance = choose_parameter(get_parameter(np, internal_np::facet_distance), o.facet_distance);
  o.feature_angle = choose_parameter(get_parameter(np, internal_np::feature_angle), o.feature_angle);
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
  std::vector<Point> points(num_vertices(mesh));
  for(auto v : vertices(mesh))
  {
    const auto& p = get(vpm, v);
    points[get(vim, v)] = {double(p.x()), double(p.y()), double(p.z())};
  }
  std::vector<Triangle> triangles;
  for(auto f : faces(mesh))
  {
    Triangle t{};
    int k = 0;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
    {
      if(k == 3) throw Invalid_input("tetrahedralize: the surface has a face with more than three vertices");
      t[std::size_t(k++)] = int(get(vim, v));
    }
    if(k != 3) throw Invalid_input("tetrahedralize: the surface has a face with fewer than three vertices");
    triangles.push_back(t);
  }
  return tetrahedralize(points, triangles, o);
}

} // namespace Projective_dynamics
} // namespace CGAL

#endif
