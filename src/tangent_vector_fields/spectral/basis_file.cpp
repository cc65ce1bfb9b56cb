// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/internal/basis_file.h>
#include <CGAL/Model_reduction/internal/mesh_identity.h>

#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

namespace {

std::array<double, 5> geometry_signature(const Intrinsic_mesh& mesh)
{
  double area = 0;
  for(int f = 0; f < mesh.number_of_faces(); ++f) area += mesh.face_area(f);
  std::vector<double> lengths(mesh.number_of_edges());
  for(int e = 0; e < mesh.number_of_edges(); ++e) lengths[e] = mesh.edge_length(e);
  return Model_reduction::internal::geometry_signature(area, lengths);
}

} // namespace

Model_reduction::internal::Mesh_identity mesh_identity(const Intrinsic_mesh& mesh)
{
  std::vector<std::array<int, 3>> faces(mesh.number_of_faces()), edges(mesh.number_of_faces());
  for(int f = 0; f < mesh.number_of_faces(); ++f)
  {
    faces[f] = mesh.face_vertices(f);
    edges[f] = mesh.face_edges(f);
  }
  Model_reduction::internal::Mesh_identity id;
  id.connectivity = Model_reduction::internal::connectivity_fingerprint(mesh.number_of_vertices(), mesh.number_of_edges(),
                                                                        faces, edges);
  id.geometry = geometry_signature(mesh);
  return id;
}

Model_reduction::internal::Mesh_identity legacy_mesh_identity(const Intrinsic_mesh& mesh)
{
  Model_reduction::internal::Hasher h;
  h.add(mesh.number_of_vertices());
  h.add(mesh.number_of_edges());
  h.add(mesh.number_of_faces());
  for(int f = 0; f < mesh.number_of_faces(); ++f)
  {
    h.add(mesh.face_vertices(f));
    h.add(mesh.face_edges(f));
  }
  Model_reduction::internal::Mesh_identity id;
  id.connectivity = h.h;
  id.geometry = geometry_signature(mesh);
  return id;
}

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL
