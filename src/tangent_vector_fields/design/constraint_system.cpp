// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/internal/Constraint_system.h>

#include <Eigen/Householder>
#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

Constraint_system::Constraint_system(int harmonic_dimension, double harmonic_scale, double harmonic_penalty)
  : nh_(harmonic_dimension), harmonic_scale_(harmonic_scale), harmonic_penalty_(harmonic_penalty),
    determination_(std::numeric_limits<double>::infinity())
{
  undetermined_ = nh_;
}

double Constraint_system::independence(const Eigen::VectorXd& k, double kappa) const
{
  if(!(kappa > 0)) return 0;
  double rest = kappa;
  if(n_ > 0)
  {
    const Eigen::VectorXd r = R_.topLeftCorner(n_, n_).transpose().triangularView<Eigen::Lower>().solve(k);
    rest -= r.squaredNorm();
  }
  return std::max(rest, 0.) / kappa;
}

void Constraint_system::append(const Eigen::VectorXd& k, double kappa, const Eigen::VectorXd& h)
{
  if(n_ + 1 > R_.rows())
  {
    const int capacity = std::max(8, 2 * (n_ + 1));
    Eigen::MatrixXd R = Eigen::MatrixXd::Zero(capacity, capacity);
    R.topLeftCorner(n_, n_) = R_.topLeftCorner(n_, n_);
    R_.swap(R);
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(capacity, nh_);
    C.topRows(n_) = Ch_.topRows(n_);
    Ch_.swap(C);
  }
  Eigen::VectorXd r = Eigen::VectorXd::Zero(n_);
  if(n_ > 0) r = R_.topLeftCorner(n_, n_).transpose().triangularView<Eigen::Lower>().solve(k);
  R_.col(n_).head(n_) = r;
  R_(n_, n_) = std::sqrt(std::max(kappa - r.squaredNorm(), 0.));
  Ch_.row(n_) = h.transpose();
  ++n_;
  update_harmonic();
}

void Constraint_system::remove(int first, int count)
{
  const int n = n_ - count;
  // Drop the columns; the block below the diagonal from `first` on is then upper
  // Hessenberg-like with `count` sub-diagonals: a QR of that block re-triangularises it.
  Eigen::MatrixXd kept(n_, n);
  kept.leftCols(first) = R_.topLeftCorner(n_, first);
  kept.rightCols(n - first) = R_.block(0, first + count, n_, n - first);
  const int tail = n_ - first;
  Eigen::MatrixXd block = kept.bottomRightCorner(tail, n - first);
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(block);
  Eigen::MatrixXd T = qr.matrixQR().topRows(n - first).triangularView<Eigen::Upper>();
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(R_.rows(), R_.cols());
  R.topLeftCorner(first, n) = kept.topRows(first);
  R.block(first, first, n - first, n - first) = T;
  R_.swap(R);
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(Ch_.rows(), nh_);
  C.topRows(first) = Ch_.topRows(first);
  C.middleRows(first, n - first) = Ch_.middleRows(first + count, n - first);
  Ch_.swap(C);
  n_ = n;
  update_harmonic();
}

Eigen::VectorXd Constraint_system::solve_K(const Eigen::VectorXd& b) const
{
  if(n_ == 0) return Eigen::VectorXd(0);
  const auto R = R_.topLeftCorner(n_, n_);
  const Eigen::VectorXd g = R.transpose().triangularView<Eigen::Lower>().solve(b);
  return R.triangularView<Eigen::Upper>().solve(g);
}

void Constraint_system::solve(const Eigen::VectorXd& c, Eigen::VectorXd& mu, Eigen::VectorXd& z) const
{
  z = Eigen::VectorXd::Zero(nh_);
  if(n_ == 0)
  {
    mu.resize(0);
    return;
  }
  const auto R = R_.topLeftCorner(n_, n_);
  Eigen::VectorXd g = R.transpose().triangularView<Eigen::Lower>().solve(c);
  if(nh_ > 0)
  {
    z = V_pinv_ * g;
    g -= V_ * z;
  }
  mu = R.triangularView<Eigen::Upper>().solve(g);
}

double Constraint_system::smallest_independence() const
{
  double s = 1;
  for(int j = 0; j < n_; ++j)
  {
    const double column = R_.col(j).head(j + 1).squaredNorm();
    if(column > 0) s = std::min(s, R_(j, j) * R_(j, j) / column);
  }
  return s;
}

void Constraint_system::update_harmonic()
{
  determination_ = std::numeric_limits<double>::infinity();
  undetermined_ = nh_;
  if(nh_ == 0) return;
  V_pinv_ = Eigen::MatrixXd::Zero(nh_, n_);
  if(n_ == 0)
  {
    V_.resize(0, nh_);
    return;
  }
  V_ = R_.topLeftCorner(n_, n_).transpose().triangularView<Eigen::Lower>().solve(Ch_.topRows(n_));
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(V_, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& s = svd.singularValues();
  undetermined_ = nh_ - static_cast<int>(s.size());
  for(int j = 0; j < s.size(); ++j)
  {
    const double ratio = s[j] * s[j] / harmonic_scale_;
    if(!(ratio > undetermined_harmonic_threshold))
    {
      ++undetermined_;
      continue;
    }
    determination_ = std::min(determination_, ratio);
    // Free harmonic part: pseudo-inverse; with an energy kappa |z|^2: ridge, s / (s^2 + kappa).
    V_pinv_ += svd.matrixV().col(j) * (svd.matrixU().col(j).transpose() * (s[j] / (s[j] * s[j] + harmonic_penalty_)));
  }
}

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL
