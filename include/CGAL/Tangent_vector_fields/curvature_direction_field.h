// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_CURVATURE_DIRECTION_FIELD_H
#define CGAL_TANGENT_VECTOR_FIELDS_CURVATURE_DIRECTION_FIELD_H

/// \file curvature_direction_field.h
/// A guide for n-field design: the principal curvature direction per face, from CGAL's
/// jet fitting (`Monge_via_jet_fitting`, a degree-2 jet on each vertex's 2-ring), weighted by
/// how well the surface defines it.

#include <CGAL/Tangent_vector_fields/Intrinsic_mesh.h>
#include <CGAL/Tangent_vector_fields/internal/Mesh_adapter.h>
#include <CGAL/Tangent_vector_fields/named_function_parameters.h>

#include <Eigen/Core>

namespace CGAL {
namespace Tangent_vector_fields {

/// What `curvature_directions` measured besides the field.
struct Curvature_direction_report
{
  int fitted_vertices = 0;   ///< vertices with a jet (enough neighbours, finite result)
  int unfitted_vertices = 0; ///< vertices in faces without one (too few neighbours, or a degenerate fit): weight 0
  /// Area-weighted root mean square of `|k1| + |k2|` over the faces (1 / length): the unit of the lengths.
  double curvature_scale = 0;
};

/// Per face (frame coordinates, `2nf`, the vector-field layout): the principal direction of
/// larger `|curvature|`, as a line (its sign is arbitrary).  At each vertex a degree-2 jet is
/// fitted to the vertex's 2-ring (grown to the 3-ring where the 2-ring has fewer than 10
/// points); the three corner directions of a face are projected onto it and averaged as
/// lines (doubled angles), each weighted by its `|k1 - k2|`.  The length is that average
/// divided by the root mean square of `|k1| + |k2|` over the mesh: dimensionless (the same at
/// every scale), 1 on a cylinder, near 0 where the direction is not defined (umbilic and flat
/// regions; a sphere's is at the level of its discretisation), all 0 on a plane.  As the guide of a cross field (n = 4) the
/// minimal direction gives the same cross; for a line field (n = 2) turn it by 90 degrees in
/// each face to follow the minimal direction.  At saddles with `k1 = -k2` the larger of the
/// two is a toss-up: prefer n = 4 there.
Eigen::VectorXd curvature_directions(const Intrinsic_mesh& mesh, Curvature_direction_report* report = nullptr);

/// \brief Writes the principal curvature direction field of `mesh` (see
/// `curvature_directions`) into a face map of `Vector_3`, ready for `alignment_field_map`.
/// \param np `vertex_point_map` and index maps, as for `Discrete_operators`
template <class TriangleMesh, class FaceVectorMap, class NamedParameters = parameters::Default_named_parameters>
Curvature_direction_report curvature_direction_field(const TriangleMesh& mesh, FaceVectorMap field,
                                                     const NamedParameters& np = parameters::default_values())
{
  internal::Mesh_adapter<TriangleMesh> adapter(mesh, np);
  Curvature_direction_report report;
  adapter.write_field(curvature_directions(*adapter.intrinsic_mesh(), &report), field);
  return report;
}

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
