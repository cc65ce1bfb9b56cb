// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "full_spline_truth.h"
#include "test_meshes.h"

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>
#include <CGAL/Tangent_vector_fields/Full_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Hodge_solver.h>
#include <CGAL/Tangent_vector_fields/N_field_operators.h>
#include <CGAL/Tangent_vector_fields/N_field_spline_solver.h>

#include <stdexcept>

namespace server_test {

namespace {

// The sphere's operators, made once per process.
std::shared_ptr<const TVF::Operator_matrices> sphere_matrices()
{
  static const std::shared_ptr<const TVF::Operator_matrices> matrices = [] {
    tvf_test::Mesh mesh;
    if(!tvf_test::read_mesh(sphere_path(), mesh)) throw std::runtime_error("cannot read " + sphere_path());
    return TVF::Discrete_operators<tvf_test::Mesh>(mesh).shared_matrices();
  }();
  return matrices;
}

TVF::Spline_options with_omega(double omega)
{
  TVF::Spline_options options;
  options.omega = omega;
  return options;
}

// Frame coordinates (2 per face) as 3D vectors.
std::vector<std::array<double, 3>> to_3d(const TVF::Intrinsic_mesh& mesh, const Eigen::VectorXd& x)
{
  std::vector<std::array<double, 3>> out;
  for(int f = 0; f < mesh.number_of_faces(); ++f)
  {
    const auto v = mesh.from_frame(f, x[2 * f], x[2 * f + 1]);
    out.push_back({{v[0], v[1], v[2]}});
  }
  return out;
}

std::vector<double> areas(const TVF::Intrinsic_mesh& mesh)
{
  std::vector<double> out;
  for(int f = 0; f < mesh.number_of_faces(); ++f) out.push_back(mesh.face_area(f));
  return out;
}

} // namespace

std::vector<std::uint32_t> library_sphere_triangles()
{
  const TVF::Intrinsic_mesh& mesh = sphere_matrices()->mesh();
  std::vector<std::uint32_t> out;
  for(int f = 0; f < mesh.number_of_faces(); ++f)
    for(int k = 0; k < 3; ++k) out.push_back(std::uint32_t(mesh.face_vertices(f)[k]));
  return out;
}

Truth full_spline(const std::vector<TVF::Field_constraint>& constraints, double omega)
{
  const auto matrices = sphere_matrices();
  TVF::Full_spline_solver solver(std::make_shared<TVF::Hodge_solver>(matrices), with_omega(omega));
  for(const TVF::Field_constraint& c : constraints) solver.add(c);
  return {{to_3d(matrices->mesh(), solver.field())}, areas(matrices->mesh())};
}

Truth full_n_field_spline(int n, int order, const std::vector<TVF::N_field_constraint>& constraints, double omega)
{
  const auto matrices = sphere_matrices();
  const auto operators = std::make_shared<const TVF::N_field_operators>(matrices, n);
  TVF::Full_n_field_spline_solver solver(operators, with_omega(omega), order);
  for(const TVF::N_field_constraint& c : constraints) solver.add(c);
  const Eigen::VectorXd z = solver.field();
  Truth truth;
  for(int j = 0; j < n; ++j) truth.vectors.push_back(to_3d(matrices->mesh(), operators->to_vectors(z, j)));
  truth.areas = areas(matrices->mesh());
  return truth;
}

} // namespace server_test
