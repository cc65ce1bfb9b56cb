// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Random rotations and matrices for the tests of Projective_dynamics.

#ifndef PD_TEST_SUPPORT_H
#define PD_TEST_SUPPORT_H

#include <Eigen/Core>
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

} // namespace pd_test

#endif
