// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Random rotations, matrices and positions for the tests of Projective_dynamics, and the
// distance to the rotations computed independently of the package.

#ifndef PD_TEST_SUPPORT_H
#define PD_TEST_SUPPORT_H

#include <CGAL/Projective_dynamics/Elastic_model.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <random>

namespace pd_test {

/// A rotation uniform on SO(3): a unit quaternion from four normal deviates.
inline Eigen::Matrix3d random_rotation(std::mt19937& rng)
{
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  return q.normalized().toRotationMatrix();
}

template <int R, int C>
Eigen::Matrix<double, R, C> random_matrix(std::mt19937& rng, double scale = 1)
{
  std::uniform_real_distribution<double> u(-scale, scale);
  Eigen::Matrix<double, R, C> m;
  for(int i = 0; i < R; ++i)
    for(int j = 0; j < C; ++j) m(i, j) = u(rng);
  return m;
}

/// Every coordinate of `x` moved by a uniform deviate in [-amount, amount].
inline CGAL::Projective_dynamics::Positions jittered(const CGAL::Projective_dynamics::Positions& x, double amount,
                                                     std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(-amount, amount);
  CGAL::Projective_dynamics::Positions y = x;
  for(Eigen::Index i = 0; i < y.size(); ++i) y.data()[i] += u(rng);
  return y;
}

/// Squared distance of F to SO(3) from the signed singular values, these from the eigenvalues
/// of F^T F (not the package's SVD): min_R |F - R|^2 = sum (s_i - 1)^2, the smallest s_i
/// carrying the sign of det F.
inline double squared_distance_to_rotations(const Eigen::Matrix3d& F)
{
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(F.transpose() * F);
  Eigen::Vector3d s = eig.eigenvalues().cwiseMax(0).cwiseSqrt(); // increasing
  if(F.determinant() < 0) s[0] = -s[0];
  return (s - Eigen::Vector3d::Ones()).squaredNorm();
}

} // namespace pd_test

#endif
