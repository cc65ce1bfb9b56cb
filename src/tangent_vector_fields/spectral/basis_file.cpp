// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/internal/basis_file.h>

#include <cmath>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

namespace {

std::uint64_t mesh_fingerprint(const Intrinsic_mesh& mesh)
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
  return h.h;
}

std::array<double, 5> geometry_signature(const Intrinsic_mesh& mesh)
{
  std::array<double, 5> s{};
  for(int f = 0; f < mesh.number_of_faces(); ++f) s[0] += mesh.face_area(f);
  std::uint64_t state = 0x243f6a8885a308d3ull;
  for(int e = 0; e < mesh.number_of_edges(); ++e)
    for(int k = 1; k < 5; ++k)
    {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      const double weight = 0.5 + double(state >> 11) / double(1ull << 53);
      s[k] += weight * mesh.edge_length(e);
    }
  return s;
}

} // namespace

Model_reduction::internal::Mesh_identity mesh_identity(const Intrinsic_mesh& mesh)
{
  Model_reduction::internal::Mesh_identity id;
  id.connectivity = mesh_fingerprint(mesh);
  id.geometry = geometry_signature(mesh);
  return id;
}

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL
