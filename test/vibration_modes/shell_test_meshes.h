// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef VIBRATION_MODES_TEST_SHELL_TEST_MESHES_H
#define VIBRATION_MODES_TEST_SHELL_TEST_MESHES_H

// Shells for the tests: the shared test meshes as (positions, triangles) arrays.

#include "test_meshes.h"

#include <CGAL/Discrete_shells/make_shell_energy.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>

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

/// Two spheres of radius 1 (centres at z = -c and z = c) joined by a cylindrical neck of
/// radius `neck`: a surface of revolution with `around` vertices per ring and `rings` rings
/// per sphere, closed by a vertex at each pole.
inline Mesh make_dumbbell(double c = 1.6, double neck = 0.25, int around = 16, int rings = 10, int neck_rings = 5)
{
  std::vector<std::pair<double, double>> profile; // (radius, z) from the bottom up
  const double theta_max = M_PI - std::asin(neck);
  for(int j = 1; j <= rings; ++j)
  {
    const double t = theta_max * j / rings;
    profile.emplace_back(std::sin(t), -c - std::cos(t));
  }
  const double z0 = -c - std::cos(theta_max);
  for(int j = 1; j < neck_rings; ++j) profile.emplace_back(neck, z0 + (-2 * z0) * j / neck_rings);
  for(int j = rings; j >= 1; --j)
  {
    const double t = theta_max * j / rings;
    profile.emplace_back(std::sin(t), c + std::cos(t));
  }
  std::vector<Point_3> points;
  points.emplace_back(0, 0, -c - 1);
  for(const auto& rz : profile)
    for(int k = 0; k < around; ++k)
    {
      const double phi = 2 * M_PI * (k + 0.5 * (points.size() / around % 2)) / around;
      points.emplace_back(rz.first * std::cos(phi), rz.first * std::sin(phi), rz.second);
    }
  points.emplace_back(0, 0, c + 1);
  const int top = int(points.size()) - 1, ring_count = int(profile.size());
  auto at = [&](int ring, int k) { return 1 + ring * around + (k % around); };
  std::vector<std::array<int, 3>> triangles;
  for(int k = 0; k < around; ++k)
  {
    triangles.push_back({0, at(0, k + 1), at(0, k)});
    triangles.push_back({top, at(ring_count - 1, k), at(ring_count - 1, k + 1)});
  }
  for(int i = 0; i + 1 < ring_count; ++i)
    for(int k = 0; k < around; ++k)
    {
      triangles.push_back({at(i, k), at(i, k + 1), at(i + 1, k + 1)});
      triangles.push_back({at(i, k), at(i + 1, k + 1), at(i + 1, k)});
    }
  return make_mesh(points, triangles);
}

/// A closed shell without symmetries (so that eigenvalues are simple).
inline Mesh lumpy_sphere(int levels = 2)
{
  Mesh mesh = make_icosphere(levels);
  jitter_vertices(mesh, 0.15, 21);
  return mesh;
}

/// sin of the largest principal angle between the column spans of A and B (of equal rank) in
/// the inner product of the diagonal mass m.
inline double largest_angle_sine(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::VectorXd& m)
{
  auto orthonormal = [&](const Eigen::MatrixXd& X) {
    const Eigen::MatrixXd G = X.transpose() * m.asDiagonal() * X;
    const Eigen::MatrixXd L = G.llt().matrixL();
    return Eigen::MatrixXd(X * L.transpose().inverse());
  };
  const Eigen::MatrixXd QA = orthonormal(A), QB = orthonormal(B);
  const Eigen::MatrixXd residual = QA - QB * (QB.transpose() * m.asDiagonal() * QA);
  return std::sqrt(std::max(0.0, Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(
                                         residual.transpose() * m.asDiagonal() * residual)
                                         .eigenvalues()
                                         .maxCoeff()));
}

} // namespace shell_test

#endif
