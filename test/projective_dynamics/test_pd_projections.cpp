// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The local step's projections: rigid invariance P(R F) = R P(F) with random rotations, the
// tetrahedron's [1, 1] projection against an independent polar decomposition (Newton's
// iteration), inverted tetrahedra to proper rotations, and closest points against samples of
// the constraint set.

#include "pd_test_support.h"

#include <CGAL/Projective_dynamics/projections.h>

#include <Eigen/LU>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <gtest/gtest.h>

#include <random>

namespace PD = CGAL::Projective_dynamics;
using pd_test::random_matrix;
using pd_test::random_rotation;

namespace {

// The orthogonal polar factor by Newton's iteration R <- (R + R^-T) / 2 (Higham), independent
// of any SVD; quadratic convergence, 60 iterations are far more than enough from F.
Eigen::Matrix3d newton_polar(const Eigen::Matrix3d& F)
{
  Eigen::Matrix3d R = F;
  for(int i = 0; i < 60; ++i) R = (R + R.inverse().transpose()) / 2;
  return R;
}

// Rounding of a handful of 3x3 products and a Jacobi SVD of entries of size ~1: 1e-12.
constexpr double tolerance = 1e-12;

} // namespace

TEST(Projections, RigidInvarianceOfEveryProjection)
{
  std::mt19937 rng(7);
  for(int trial = 0; trial < 200; ++trial)
  {
    const Eigen::Matrix3d R = random_rotation(rng);
    const Eigen::Vector3d d = random_matrix<3, 1>(rng, 2), rest = random_matrix<3, 1>(rng);
    EXPECT_LT((PD::project_spring(R * d, 0.8, 1.2, rest) - R * PD::project_spring(d, 0.8, 1.2, rest)).norm(), tolerance);
    EXPECT_LT((PD::project_bending(R * d, 0.3, rest) - R * PD::project_bending(d, 0.3, rest)).norm(), tolerance);
    const Eigen::Matrix<double, 3, 2> F2 = random_matrix<3, 2>(rng, 2);
    for(auto [lo, hi] : {std::pair{1.0, 1.0}, std::pair{0.9, 1.1}, std::pair{0.0, 10.0}})
      EXPECT_LT((PD::project_triangle_strain(R * F2, lo, hi) - R * PD::project_triangle_strain(F2, lo, hi)).norm(), tolerance);
    const Eigen::Matrix3d F3 = random_matrix<3, 3>(rng, 2); // either sign of det
    for(auto [lo, hi] : {std::pair{1.0, 1.0}, std::pair{0.9, 1.1}, std::pair{0.5, 3.0}})
      EXPECT_LT((PD::project_tet_strain(R * F3, lo, hi) - R * PD::project_tet_strain(F3, lo, hi)).norm(), tolerance)
          << "det F " << F3.determinant();
  }
}

TEST(Projections, TetStrainIsThePolarRotation)
{
  std::mt19937 rng(11);
  int tested = 0;
  while(tested < 200)
  {
    const Eigen::Matrix3d F = random_matrix<3, 3>(rng, 2);
    if(F.determinant() < 0.05) continue; // non-inverted, away from singular (Newton's convergence)
    ++tested;
    const Eigen::Matrix3d P = PD::project_tet_strain(F, 1, 1);
    EXPECT_LT((P - newton_polar(F)).norm(), 1e-10); // Newton on cond(F) up to ~1e3: 1e-10
  }
}

TEST(Projections, InvertedTetGoesToTheClosestProperRotation)
{
  std::mt19937 rng(13);
  int tested = 0;
  while(tested < 100)
  {
    const Eigen::Matrix3d F = random_matrix<3, 3>(rng, 2);
    if(F.determinant() > -0.05) continue;
    ++tested;
    const Eigen::Matrix3d P = PD::project_tet_strain(F, 1, 1);
    EXPECT_NEAR(P.determinant(), 1, tolerance);
    EXPECT_LT((P.transpose() * P - Eigen::Matrix3d::Identity()).norm(), tolerance);
    // Closest: no random rotation, and no small rotation of P, is closer to F.
    const double d = (F - P).norm();
    for(int k = 0; k < 200; ++k)
      EXPECT_GE((F - random_rotation(rng)).norm(), d - tolerance);
    for(int k = 0; k < 50; ++k)
    {
      const Eigen::Vector3d a = random_matrix<3, 1>(rng, 1e-3);
      const Eigen::Matrix3d Q = Eigen::AngleAxisd(a.norm(), a.normalized()).toRotationMatrix() * P;
      EXPECT_GE((F - Q).norm(), d - tolerance);
    }
  }
}

TEST(Projections, ClampedStrainsStayInTheirSets)
{
  std::mt19937 rng(17);
  for(int trial = 0; trial < 200; ++trial)
  {
    const Eigen::Matrix3d F = random_matrix<3, 3>(rng, 2);
    const Eigen::Matrix3d P = PD::project_tet_strain(F, 0.8, 1.25);
    EXPECT_GT(P.determinant(), 0);
    const Eigen::Vector3d s = Eigen::JacobiSVD<Eigen::Matrix3d>(P).singularValues();
    EXPECT_LE(s.maxCoeff(), 1.25 + tolerance);
    EXPECT_GE(s.minCoeff(), 0.8 - tolerance);
    // A value already in the set is its own projection.
    const Eigen::Matrix3d inside = random_rotation(rng) * Eigen::Vector3d(0.9, 1.1, 1.2).asDiagonal() * random_rotation(rng);
    EXPECT_LT((PD::project_tet_strain(inside, 0.8, 1.25) - inside).norm(), tolerance);
    // Triangles: a 3x2 with orthonormal columns is an isometry, fixed by [1, 1].
    const Eigen::Matrix<double, 3, 2> iso = random_rotation(rng).leftCols<2>();
    EXPECT_LT((PD::project_triangle_strain(iso, 1, 1) - iso).norm(), tolerance);
  }
  const Eigen::Vector3d d(3, 4, 0); // length 5
  EXPECT_LT((PD::project_spring(d, 1, 2, d) - d * (2.0 / 5)).norm(), tolerance);
  EXPECT_LT((PD::project_spring(d, 6, 7, d) - d * (6.0 / 5)).norm(), tolerance);
  EXPECT_LT((PD::project_spring(d, 4, 6, d) - d).norm(), tolerance);
  EXPECT_LT((PD::project_spring(Eigen::Vector3d::Zero(), 1, 2, d) - d / 5).norm(), tolerance); // falls back to the rest edge
  EXPECT_LT(PD::project_bending(d, 0, Eigen::Vector3d::Zero()).norm(), tolerance); // flat rest: 0
}

TEST(Projections, TriangleStrainIsTheClosestPoint)
{
  // Against samples of the set {A : 3x2, singular values in [0.9, 1.1]}: none is closer.
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> s(0.9, 1.1);
  for(int trial = 0; trial < 30; ++trial)
  {
    const Eigen::Matrix<double, 3, 2> F = random_matrix<3, 2>(rng, 2);
    const Eigen::Matrix<double, 3, 2> P = PD::project_triangle_strain(F, 0.9, 1.1);
    const double d = (F - P).norm();
    for(int k = 0; k < 300; ++k)
    {
      const Eigen::Matrix<double, 3, 2> U = random_rotation(rng).leftCols<2>();
      const Eigen::Matrix2d V = random_rotation(rng).topLeftCorner<2, 2>().householderQr().householderQ();
      const Eigen::Matrix<double, 3, 2> A = U * Eigen::Vector2d(s(rng), s(rng)).asDiagonal() * V;
      EXPECT_GE((F - A).norm(), d - tolerance);
    }
  }
}

TEST(Projections, DegenerateAndExactStrainsProjectSafely)
{
  // The cases where a closed-form SVD loses accuracy (repeated singular values, rank deficiency)
  // and the projection falls back to Jacobi: results stay rotations, exact input stays put.
  std::mt19937 rng(23);
  for(int trial = 0; trial < 20; ++trial)
  {
    const Eigen::Matrix3d R = random_rotation(rng);
    const Eigen::Vector3d a = random_matrix<3, 1>(rng), b = random_matrix<3, 1>(rng);
    for(const Eigen::Matrix3d& F : {Eigen::Matrix3d(R), Eigen::Matrix3d(Eigen::Matrix3d::Zero()), Eigen::Matrix3d(a * b.transpose()),
                                    Eigen::Matrix3d(R * Eigen::Vector3d(1, 1, 1 + 1e-9).asDiagonal()),
                                    Eigen::Matrix3d(R * Eigen::Vector3d(2, 1e-9, 0).asDiagonal()),
                                    Eigen::Matrix3d(R * Eigen::Vector3d(1, 1, -1).asDiagonal())})
    {
      const Eigen::Matrix3d P = PD::project_tet_strain(F, 1, 1);
      ASSERT_TRUE(P.allFinite());
      EXPECT_LT((P.transpose() * P - Eigen::Matrix3d::Identity()).norm(), tolerance);
      EXPECT_NEAR(P.determinant(), 1, tolerance);
    }
    EXPECT_LT((PD::project_tet_strain(R, 1, 1) - R).norm(), tolerance);
    EXPECT_LT((PD::project_tet_strain(R, 0.5, 2) - R).norm(), tolerance);
    EXPECT_LT((PD::project_tet_strain(R * Eigen::Vector3d(1, 1, 1 + 1e-9).asDiagonal(), 1, 1) - R).norm(), 1e-9);
    const Eigen::Matrix<double, 3, 2> iso = R.leftCols<2>();
    for(const Eigen::Matrix<double, 3, 2>& F :
        {Eigen::Matrix<double, 3, 2>(iso), Eigen::Matrix<double, 3, 2>(Eigen::Matrix<double, 3, 2>::Zero()),
         Eigen::Matrix<double, 3, 2>(a * b.head<2>().transpose())})
    {
      const Eigen::Matrix<double, 3, 2> P = PD::project_triangle_strain(F, 1, 1);
      ASSERT_TRUE(P.allFinite());
      EXPECT_LT((P.transpose() * P - Eigen::Matrix2d::Identity()).norm(), tolerance);
    }
    EXPECT_LT((PD::project_triangle_strain(iso, 1, 1) - iso).norm(), tolerance);
  }
}

TEST(Projections, InvertedTetWithClampsFlipsBeforeClamping)
{
  // F = R1 diag(1.5, 1.2, -1) R2 is inverted; the closest map with positive determinant and
  // singular values in [0.5, 3] keeps R1 and R2 and clamps the signed -1 up to 0.5 (distance
  // 1.5); clamping |-1| = 1 instead would give an improper map or one 2 away.
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> s(0.5, 3);
  for(int trial = 0; trial < 20; ++trial)
  {
    const Eigen::Matrix3d R1 = random_rotation(rng), R2 = random_rotation(rng);
    const Eigen::Matrix3d F = R1 * Eigen::Vector3d(1.5, 1.2, -1).asDiagonal() * R2;
    const Eigen::Matrix3d expected = R1 * Eigen::Vector3d(1.5, 1.2, 0.5).asDiagonal() * R2;
    const Eigen::Matrix3d P = PD::project_tet_strain(F, 0.5, 3);
    EXPECT_LT((P - expected).norm(), tolerance);
    const double d = (F - P).norm();
    for(int k = 0; k < 200; ++k)
    {
      const Eigen::Matrix3d A = random_rotation(rng) * Eigen::Vector3d(s(rng), s(rng), s(rng)).asDiagonal() * random_rotation(rng);
      EXPECT_GE((F - A).norm(), d - tolerance);
    }
  }
}
