// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Moments of runs of samples about a span's end, for the degree-1 knot search: per sample, or
// for any run at once from sums over blocks of 8, 64, 512 and 4,096 samples.  A knot sliding over a
// span of 25,000 samples (a million samples, 40 knots) then costs a few hundred additions per
// place instead of one per sample.  Each block's sums are taken about its own first sample and
// shifted to the span's end in closed form, so, as with per-sample sums, no prefix sum over the
// whole curve cancels.

#ifndef CGAL_SPLINE_APPROXIMATION_SAMPLE_MOMENTS_H
#define CGAL_SPLINE_APPROXIMATION_SAMPLE_MOMENTS_H

#include <Eigen/Core>

#include <array>

namespace CGAL {
namespace Spline_approximation {
namespace internal {

// Sums over the samples of a span, about the span's end e: count, sum of d = |t - e|, of d^2,
// of P, of d P, of |P|^2.
struct Moments
{
  double n = 0, d1 = 0, d2 = 0, pp = 0;
  Eigen::RowVectorXd p, dp;
  explicit Moments(Eigen::Index D) : p(Eigen::RowVectorXd::Zero(D)), dp(Eigen::RowVectorXd::Zero(D)) {}
  // Adds (sign 1) or removes (-1) the sample at P (coordinates `stride` apart) at distance d.
  void add(double d, const double* P, Eigen::Index stride, double sign = 1)
  {
    n += sign;
    d1 += sign * d;
    d2 += sign * d * d;
    double squared = 0;
    for(Eigen::Index k = 0; k < p.size(); ++k) {
      const double x = P[k * stride];
      p[k] += sign * x;
      dp[k] += sign * d * x;
      squared += x * x;
    }
    pp += sign * squared;
  }
};

// The samples' moments in blocks, at two levels.
class Block_moments
{
public:
  Block_moments(const Eigen::VectorXd& t, const Eigen::MatrixXd& P) : t_(t), P_(P)
  {
    for(std::size_t l = 0; l < levels_.size(); ++l) build(l);
  }

  // Adds sign times the moments of the samples [j0, j1) (0 <= j0 <= j1 <= n), their parameters
  // shifted by `offset` (a closed curve's period), about e: d = t - e if about_start, e - t if not.
  void add(Moments& m, Eigen::Index j0, Eigen::Index j1, double offset, double e, bool about_start, double sign) const
  {
    const double direction = about_start ? 1.0 : -1.0;
    for(Eigen::Index j = j0; j < j1;) {
      std::size_t l = levels_.size();
      while(l > 0 && !(j % block_sizes[l - 1] == 0 && j + block_sizes[l - 1] <= j1)) --l;
      if(l == 0) { // a single sample
        m.add(direction * (t_[j] + offset - e), &P_(j, 0), P_.rows(), sign);
        ++j;
        continue;
      }
      const Level& L = levels_[l - 1];
      const Eigen::Index b = j / block_sizes[l - 1];
      // d = direction (u + delta) with u = t - (the block's first parameter): its sums follow
      // from the block's sums of u.
      const double delta = L.anchor[b] + offset - e, count = L.n[b];
      m.n += sign * count;
      m.d1 += sign * direction * (L.u1[b] + count * delta);
      m.d2 += sign * (L.u2[b] + 2 * delta * L.u1[b] + count * delta * delta);
      m.pp += sign * L.pp[b];
      m.p += sign * L.p.row(b);
      m.dp += (sign * direction) * (L.up.row(b) + delta * L.p.row(b));
      j += block_sizes[l - 1];
    }
  }

private:
  struct Level
  {
    Eigen::VectorXd anchor, n, u1, u2, pp;
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> p, up; // a block's coordinates side by side
  };
  // Each level's blocks join 8 of the level below: a run costs at most 7 samples and 7
  // blocks of each level at either end, and one block per 4,096 samples in between.
  static constexpr std::array<Eigen::Index, 4> block_sizes{{8, 64, 512, 4096}};

  void build(std::size_t l)
  {
    Level& L = levels_[l];
    const Eigen::Index size = block_sizes[l], blocks = t_.size() / size, D = P_.cols(); // whole blocks only
    L.anchor.resize(blocks);
    L.n = L.u1 = L.u2 = L.pp = Eigen::VectorXd::Zero(blocks);
    L.p.setZero(blocks, D);
    L.up.setZero(blocks, D);
    for(Eigen::Index b = 0; b < blocks; ++b) {
      L.anchor[b] = t_[b * size];
      if(l == 0) {
        for(Eigen::Index j = b * size; j < (b + 1) * size; ++j) {
          const double u = t_[j] - L.anchor[b];
          L.n[b] += 1;
          L.u1[b] += u;
          L.u2[b] += u * u;
          for(Eigen::Index c = 0; c < D; ++c) {
            const double x = P_(j, c);
            L.p(b, c) += x;
            L.up(b, c) += u * x;
            L.pp[b] += x * x;
          }
        }
        continue;
      }
      const Level& below = levels_[l - 1];
      const Eigen::Index ratio = size / block_sizes[l - 1];
      for(Eigen::Index i = b * ratio; i < (b + 1) * ratio; ++i) { // about this block's first parameter
        const double delta = below.anchor[i] - L.anchor[b];
        L.n[b] += below.n[i];
        L.u1[b] += below.u1[i] + below.n[i] * delta;
        L.u2[b] += below.u2[i] + 2 * delta * below.u1[i] + below.n[i] * delta * delta;
        L.pp[b] += below.pp[i];
        L.p.row(b) += below.p.row(i);
        L.up.row(b) += below.up.row(i) + delta * below.p.row(i);
      }
    }
  }

  const Eigen::VectorXd& t_;
  const Eigen::MatrixXd& P_;
  std::array<Level, 4> levels_;
};

} // namespace internal
} // namespace Spline_approximation
} // namespace CGAL

#endif // CGAL_SPLINE_APPROXIMATION_SAMPLE_MOMENTS_H
