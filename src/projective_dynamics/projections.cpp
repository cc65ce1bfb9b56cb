// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The local step: the closest point of each element's value in its constraint set.

#include <CGAL/Projective_dynamics/projections.h>

#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>

namespace CGAL {
namespace Projective_dynamics {

Eigen::Vector3d project_spring(const Eigen::Vector3d& d, double min_length, double max_length,
                               const Eigen::Vector3d& fallback)
{
  const double n = d.norm();
  if(!(n > 0))
  {
    const double f = fallback.norm();
    return f > 0 ? Eigen::Vector3d(fallback * (min_length / f)) : Eigen::Vector3d(min_length, 0, 0);
  }
  return d * (std::clamp(n, min_length, max_length) / n);
}

// GCC 12 warns that the fixed-size 3x2 JacobiSVD's singular values "may be used
// uninitialized" inside Eigen (a false positive on its SSE copies): silenced here alone.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
Eigen::Matrix<double, 3, 2> project_triangle_strain(const Eigen::Matrix<double, 3, 2>& F, double smin, double smax)
{
  // Fixed-size JacobiSVD computes the full U (3x3); its first two columns are the thin U.
  const Eigen::JacobiSVD<Eigen::Matrix<double, 3, 2>> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector2d s = svd.singularValues().cwiseMax(smin).cwiseMin(smax);
  return svd.matrixU().leftCols<2>() * s.asDiagonal() * svd.matrixV().transpose();
}
#pragma GCC diagnostic pop

Eigen::Matrix3d project_tet_strain(const Eigen::Matrix3d& F, double smin, double smax)
{
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d U = svd.matrixU();
  Eigen::Vector3d s = svd.singularValues(); // decreasing, non-negative
  if(U.determinant() * svd.matrixV().determinant() < 0)
  {
    // Inverted (or reflected) element: the closest proper map flips the smallest stretch.
    U.col(2) = -U.col(2);
    s[2] = -s[2];
  }
  s = s.cwiseMax(smin).cwiseMin(smax);
  return U * s.asDiagonal() * svd.matrixV().transpose();
}

Eigen::Vector3d project_bending(const Eigen::Vector3d& h, double rest_norm, const Eigen::Vector3d& fallback)
{
  const double n = h.norm();
  if(!(n > 0)) return fallback;
  return h * (rest_norm / n);
}

} // namespace Projective_dynamics
} // namespace CGAL
