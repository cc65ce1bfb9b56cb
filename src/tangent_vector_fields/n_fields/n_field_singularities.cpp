// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/N_field_singularities.h>
#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/internal/n_field_geometry.h>

#include <cmath>

namespace CGAL {
namespace Tangent_vector_fields {

namespace {

// Sum over the vertices of each one's turning, computed per edge once so that the two ends
// of an edge see exactly opposite numbers.
Eigen::VectorXd vertex_turning(const N_field_operators& ops, const Eigen::VectorXd& z)
{
  const Intrinsic_mesh& mesh = ops.mesh();
  const int n = ops.n();
  if(z.size() != 2 * mesh.number_of_faces())
    throw Invalid_input("n-field index: the field has " + std::to_string(z.size()) + " values, the mesh needs " +
                        std::to_string(2 * mesh.number_of_faces()));
  // A NaN angle would round to an arbitrary integer index.
  if(!z.allFinite()) throw Invalid_input("n-field index: the field has non-finite entries");
  std::vector<double> arg(mesh.number_of_faces());
  for(int f = 0; f < mesh.number_of_faces(); ++f) arg[f] = std::atan2(z[2 * f + 1], z[2 * f]);

  Eigen::VectorXd turning = n * ops.vertex_curvatures();
  const Eigen::VectorXd& t = ops.transport_angles();
  for(int f = 0; f < mesh.number_of_faces(); ++f)
  {
    const auto& corner = mesh.face_vertices(f);
    for(int k = 0; k < 3; ++k)
    {
      const int v = corner[k];
      // Counter-clockwise around v, f is followed by the face across edge (v, corner k+2),
      // local edge k+1, and preceded by the face across edge (v, corner k+1), local edge k+2.
      const int next_edge = mesh.face_edges(f)[(k + 1) % 3];
      const int previous_edge = mesh.face_edges(f)[(k + 2) % 3];
      if(!mesh.is_boundary_edge(next_edge))
      {
        // From f to g: wrap(arg z_g - arg(rho_gf^n z_f)).  Canonically per edge from its
        // second face into its first, delta = wrap(arg z_first - arg z_second - n t).
        const int i = mesh.interior_edge_index(next_edge);
        const auto& ff = mesh.edge_faces(next_edge);
        const double delta = internal::wrap_angle(arg[ff[0]] - arg[ff[1]] - n * t[i]);
        turning[v] += ff[0] == f ? -delta : delta;
      }
      else
      {
        // The boundary edge u -> v with u = corner k+2 (surface on its left): minus its beta.
        turning[v] -= internal::wrap_angle(arg[f] - n * internal::edge_angle(mesh, f, corner[(k + 2) % 3], v));
      }
      if(mesh.is_boundary_edge(previous_edge))
      {
        // The boundary edge v -> w with w = corner k+1: plus its beta.
        turning[v] += internal::wrap_angle(arg[f] - n * internal::edge_angle(mesh, f, v, corner[(k + 1) % 3]));
      }
    }
  }
  return turning;
}

} // namespace

std::vector<int> n_field_indices(const N_field_operators& operators, const Eigen::VectorXd& z)
{
  const Eigen::VectorXd turning = vertex_turning(operators, z);
  std::vector<int> k(turning.size());
  for(Eigen::Index v = 0; v < turning.size(); ++v)
    k[v] = static_cast<int>(std::lround(turning[v] / (2 * M_PI)));
  return k;
}

std::vector<N_field_singularity> n_field_singularities(const N_field_operators& operators, const Eigen::VectorXd& z)
{
  const std::vector<int> k = n_field_indices(operators, z);
  const std::vector<char>& on_boundary = operators.boundary_vertices();
  std::vector<N_field_singularity> result;
  for(int v = 0; v < static_cast<int>(k.size()); ++v)
    if(k[v] != 0) result.push_back({v, k[v], on_boundary[v] != 0});
  return result;
}

} // namespace Tangent_vector_fields
} // namespace CGAL
