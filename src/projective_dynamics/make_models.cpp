// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Lumped masses and the elastic models of solids, shells and spring networks.

#include <CGAL/Projective_dynamics/errors.h>
#include <CGAL/Projective_dynamics/make_models.h>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>
#include <string>

namespace CGAL {
namespace Projective_dynamics {

Positions to_positions(const std::vector<Point>& points)
{
  Positions q(Eigen::Index(points.size()), 3);
  for(std::size_t v = 0; v < points.size(); ++v) q.row(Eigen::Index(v)) << points[v][0], points[v][1], points[v][2];
  return q;
}

namespace {
void check_density(double density)
{
  if(!(density > 0) || !std::isfinite(density))
    throw Invalid_input("the density " + std::to_string(density) + " must be positive and finite");
}

template <std::size_t N>
Eigen::VectorXd lumped(const std::vector<Point>& points, const std::vector<std::array<int, N>>& cells, double density,
                       const char* kind)
{
  check_density(density);
  const Positions x = to_positions(points);
  Eigen::VectorXd m = Eigen::VectorXd::Zero(x.rows());
  for(std::size_t c = 0; c < cells.size(); ++c)
  {
    for(int v : cells[c])
      if(v < 0 || v >= x.rows())
        throw Invalid_mesh(Mesh_defect::invalid_index, std::string(kind) + " " + std::to_string(c) + " has vertex index " +
                                                           std::to_string(v) + " outside [0, " + std::to_string(x.rows()) + ")");
    const auto& k = cells[c];
    double measure;
    if constexpr(N == 4)
    {
      Eigen::Matrix3d D;
      for(int i = 0; i < 3; ++i) D.col(i) = (x.row(k[i + 1]) - x.row(k[0])).transpose();
      measure = std::abs(D.determinant()) / 6;
    }
    else if constexpr(N == 3)
      measure = (x.row(k[1]) - x.row(k[0])).cross(x.row(k[2]) - x.row(k[0])).norm() / 2;
    else
      measure = (x.row(k[1]) - x.row(k[0])).norm();
    for(int v : k) m[v] += density * measure / double(N);
  }
  return m;
}
} // namespace

Eigen::VectorXd lumped_masses(const std::vector<Point>& points, const std::vector<Tetrahedron>& tets, double density)
{
  return lumped(points, tets, density, "tetrahedron");
}
Eigen::VectorXd lumped_masses(const std::vector<Point>& points, const std::vector<Triangle>& triangles, double density)
{
  return lumped(points, triangles, density, "triangle");
}
Eigen::VectorXd lumped_masses(const std::vector<Point>& points, const std::vector<Edge>& edges, double density)
{
  return lumped(points, edges, density, "edge");
}

namespace internal {

Elastic_model make_solid_model(const Tet_mesh& mesh, const Model_parameters& p)
{
  check_tet_mesh(mesh);
  Elastic_model model(to_positions(mesh.points), lumped_masses(mesh.points, mesh.tetrahedra, p.density));
  model.add_tet_strain(mesh.tetrahedra, p.strain_stiffness, p.strain_limits.first, p.strain_limits.second);
  if(p.has_springs)
    model.add_springs(unique_edges(mesh.tetrahedra), p.spring_stiffness, p.strain_limits.first, p.strain_limits.second);
  return model;
}

Elastic_model make_shell_model(const std::vector<Point>& points, const std::vector<Triangle>& triangles,
                               const Model_parameters& p)
{
  if(points.empty() || triangles.empty())
    throw Invalid_mesh(Mesh_defect::empty, "the shell is empty (" + std::to_string(points.size()) + " vertices, " +
                                               std::to_string(triangles.size()) + " triangles)");
  Elastic_model model(to_positions(points), lumped_masses(points, triangles, p.density));
  model.add_triangle_strain(triangles, p.strain_stiffness, p.strain_limits.first, p.strain_limits.second);
  model.add_bending(triangles, p.bending_stiffness);
  if(p.has_springs)
    model.add_springs(unique_edges(triangles), p.spring_stiffness, p.strain_limits.first, p.strain_limits.second);
  return model;
}

Elastic_model make_spring_model(const std::vector<Point>& points, const std::vector<Edge>& edges, const Model_parameters& p)
{
  if(points.empty() || edges.empty())
    throw Invalid_mesh(Mesh_defect::empty, "the spring network is empty (" + std::to_string(points.size()) + " vertices, " +
                                               std::to_string(edges.size()) + " edges)");
  Elastic_model model(to_positions(points), lumped_masses(points, edges, p.density));
  model.add_springs(edges, p.spring_stiffness, p.strain_limits.first, p.strain_limits.second);
  return model;
}

} // namespace internal
} // namespace Projective_dynamics
} // namespace CGAL
