// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The local step: the closest point of each element's value in its constraint set.

#include <CGAL/Projective_dynamics/projections.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>

// GCC 12 warns that the fixed-size JacobiSVDs' singular values "may be used uninitialized"
// inside Eigen (a false positive on its SSE copies): silenced for this file's functions.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

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

namespace {

// SVD of a small F (3 x C, C = 2 or 3) with rotations U and V and the last singular value signed
// (for C = 3, negative iff det F < 0), by the eigenvectors of F^T F in closed form
// (`computeDirect`): about 3x faster than a Jacobi SVD (0.4 against 1.2 us for 3x3 here).  The
// closed form loses accuracy for nearly repeated eigenvalues and rank-deficient F, so the
// result is checked: it is used only if V is orthonormal to 1e-14 and U S V^T reproduces F to
// 1e-13 of its largest entry (a few units of rounding for entries of size ~1); otherwise the
// caller falls back to Jacobi (about 1 in 10^4 random matrices, never near rest).
template <int C>
bool closed_form_svd(const Eigen::Matrix<double, 3, C>& F, Eigen::Matrix<double, 3, C>& U,
                     Eigen::Matrix<double, C, 1>& s, Eigen::Matrix<double, C, C>& V)
{
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, C, C>> eig;
  eig.computeDirect(F.transpose() * F);
  V = eig.eigenvectors().rowwise().reverse(); // decreasing eigenvalues
  if(V.determinant() < 0) V.col(C - 1) = -V.col(C - 1);
  const Eigen::Matrix<double, 3, C> FV = F * V;
  Eigen::Vector3d u1 = FV.col(0), u2 = FV.col(1);
  const double n1 = u1.norm();
  if(!(n1 > 0)) return false;
  u1 /= n1;
  u2 -= u1.dot(u2) * u1;
  const double n2 = u2.norm();
  if(!(n2 > 1e-6 * n1)) return false; // (nearly) rank one: u2 would be noise
  u2 /= n2;
  U.col(0) = u1;
  U.col(1) = u2;
  s[0] = n1;
  s[1] = u2.dot(FV.col(1));
  if constexpr(C == 3)
  {
    U.col(2) = u1.cross(u2);
    s[2] = U.col(2).dot(FV.col(2));
  }
  const double scale = F.cwiseAbs().maxCoeff();
  return (V.transpose() * V - Eigen::Matrix<double, C, C>::Identity()).cwiseAbs().maxCoeff() <= 1e-14 &&
         (U * s.asDiagonal() * V.transpose() - F).cwiseAbs().maxCoeff() <= 1e-13 * scale;
}

} // namespace

Eigen::Matrix<double, 3, 2> project_triangle_strain(const Eigen::Matrix<double, 3, 2>& F, double smin, double smax)
{
  Eigen::Matrix<double, 3, 2> U;
  Eigen::Vector2d s;
  Eigen::Matrix2d V;
  if(!closed_form_svd<2>(F, U, s, V))
  {
    // Fixed-size JacobiSVD computes the full U (3x3); its first two columns are the thin U.
    const Eigen::JacobiSVD<Eigen::Matrix<double, 3, 2>> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
    U = svd.matrixU().leftCols<2>();
    s = svd.singularValues();
    V = svd.matrixV();
  }
  // For a 3x2 F both singular values are non-negative already (U is any 3x2 with orthonormal columns).
  s = s.cwiseMax(smin).cwiseMin(smax);
  return U * s.asDiagonal() * V.transpose();
}

Eigen::Matrix3d project_tet_strain(const Eigen::Matrix3d& F, double smin, double smax)
{
  Eigen::Matrix3d U, V;
  Eigen::Vector3d s;
  if(!closed_form_svd<3>(F, U, s, V))
  {
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
    U = svd.matrixU();
    V = svd.matrixV();
    s = svd.singularValues(); // decreasing, non-negative
    if(U.determinant() * V.determinant() < 0)
    {
      // Inverted (or reflected) element: the closest proper map flips the smallest stretch.
      U.col(2) = -U.col(2);
      s[2] = -s[2];
    }
  }
  // Either way F = U diag(s) V^T with det U det V = 1, and s[2] < 0 iff det F < 0.
  s = s.cwiseMax(smin).cwiseMin(smax);
  return U * s.asDiagonal() * V.transpose();
}

Eigen::Vector3d project_bending(const Eigen::Vector3d& h, double rest_norm, const Eigen::Vector3d& fallback)
{
  const double n = h.norm();
  if(!(n > 0)) return fallback;
  return h * (rest_norm / n);
}

} // namespace Projective_dynamics
} // namespace CGAL

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
