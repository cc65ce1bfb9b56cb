// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef VIBRATION_MODES_TEST_SHELL_TEST_MESHES_H
#define VIBRATION_MODES_TEST_SHELL_TEST_MESHES_H

// Shells for the tests: the shared test meshes as (positions, triangles) arrays.

#include "test_meshes.h"

#include <CGAL/Discrete_shells/make_shell_energy.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <random>

namespace shell_test {

namespace DS = CGAL::Discrete_shells;
using namespace tvf_test;

inline std::vector<DS::Shell_energy::Triangle> triangles_of(const Mesh& mesh) { return DS::mesh_triangles(mesh); }

inline Eigen::VectorXd random_vector(Eigen::Index n, unsigned seed, double scale = 1)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-scale, scale);
  Eigen::VectorXd v(n);
  for(Eigen::Index i = 0; i < n; ++i) v[i] = u(rng);
  return v;
}

inline Eigen::Matrix3d rotation(const Eigen::Vector3d& axis, double angle)
{
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

/// p -> s R p + t on stacked positions.
inline Eigen::VectorXd moved(const Eigen::VectorXd& x, double s, const Eigen::Matrix3d& R, const Eigen::Vector3d& t)
{
  Eigen::VectorXd y(x.size());
  for(Eigen::Index v = 0; v < x.size() / 3; ++v) y.segment<3>(3 * v) = s * R * x.segment<3>(3 * v) + t;
  return y;
}

} // namespace shell_test

#endif
