// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Sylvester's inertia: how many eigenvalues of A x = lambda D x lie below a shift, and the
// completeness check of a list of computed eigenvalues built on it.

#include <CGAL/Model_reduction/Generalized_eigensolver.h>
#include <CGAL/Model_reduction/Sparse_ldlt_solver.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Model_reduction {

namespace {

template <class Scalar>
int count_below(const Eigen::SparseMatrix<Scalar>& A, const Eigen::VectorXd& d, double tau)
{
  Eigen::SparseMatrix<Scalar> K = A;
  K.diagonal() -= tau * d;
  // LDL^T without pivoting: fine for these shifted Laplacians unless tau hits an
  // eigenvalue, which the callers avoid by placing tau in a spectral gap.
  Basic_sparse_ldlt_solver<Scalar> ldlt;
  ldlt.factor(K, "the shifted matrix of the inertia count");
  return ldlt.negative_pivots();
}

template <class Scalar>
Completeness_check completeness(const Eigen::SparseMatrix<Scalar>& A, const Eigen::VectorXd& d,
                                const Eigen::VectorXd& values, int kernel_dimension, int first_gap)
{
  const Eigen::Index m = values.size();
  Completeness_check check;
  if(m == 0)
  {
    check.shift = 0;
    check.expected = check.inertia = 0;
    return check;
  }
  // The shift goes in the widest gap (relative to the eigenvalue) among the last
  // values, so that it is far from every eigenvalue and LDL^T without pivoting is
  // stable; after the last value when there is no gap to choose from.
  Eigen::Index below = m; // number of values below the shift
  double best = -1;
  for(Eigen::Index j = std::max<Eigen::Index>(first_gap < 0 ? m - 1 : first_gap, 1); j < m; ++j)
  {
    const double gap = (values[j] - values[j - 1]) / std::max(std::abs(values[j]), 1e-300);
    if(gap > best)
    {
      best = gap;
      below = j;
    }
  }
  if(below == m || best <= 1e-8)
  {
    below = m;
    check.shift = values[m - 1] * (1 + 1e-6) + 1e-12 * std::abs(values[0]);
  }
  else
    check.shift = 0.5 * (values[below - 1] + values[below]);
  check.expected = kernel_dimension + static_cast<int>(below);
  check.inertia = count_below(A, d, check.shift);
  return check;
}

} // namespace

Completeness_check check_completeness(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& d,
                                      const Eigen::VectorXd& values, int kernel_dimension, int first_gap)
{
  return completeness(A, d, values, kernel_dimension, first_gap);
}

Completeness_check check_completeness(const Eigen::SparseMatrix<std::complex<double>>& A, const Eigen::VectorXd& d,
                                      const Eigen::VectorXd& values, int kernel_dimension, int first_gap)
{
  return completeness(A, d, values, kernel_dimension, first_gap);
}

int count_eigenvalues_below(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& d, double tau)
{
  return count_below(A, d, tau);
}

int count_eigenvalues_below(const Eigen::SparseMatrix<std::complex<double>>& A, const Eigen::VectorXd& d, double tau)
{
  return count_below(A, d, tau);
}

} // namespace Model_reduction
} // namespace CGAL
