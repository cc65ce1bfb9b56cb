// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Model_reduction/Generalized_eigensolver.h>
#include <CGAL/Model_reduction/Sparse_ldlt_solver.h>
#include <CGAL/Model_reduction/errors.h>
#include <CGAL/Model_reduction/internal/Standard_eigenproblem.h>

#include <Eigen/Dense>

#include <algorithm>
#include <limits>
#include <memory>
#include <cmath>
#include <random>
#include <sstream>


namespace CGAL {
namespace Model_reduction {

namespace {

using internal::orthonormal_columns;
using internal::symmetric_eigen;
template <class Scalar>
using Problem = internal::Basic_standard_eigenproblem<Scalar>;
template <class Scalar>
using Dense = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;

// `subspace`, if given, receives the standard-form vectors of all the values returned.
template <class Scalar>
Basic_eigenpairs<Scalar> dense_eigenpairs(const Problem<Scalar>& p, int count, Dense<Scalar>* subspace = nullptr)
{
  typedef Dense<Scalar> Matrix;
  const Eigen::Index n = p.sqrt_d.size(), c = p.kernel.cols();
  Matrix B = p.inv_sqrt_d.asDiagonal() * Matrix(p.A) * p.inv_sqrt_d.asDiagonal();
  // Restrict to the orthogonal complement of the kernel (when there is one).
  Matrix basis;
  if(c > 0)
  {
    Eigen::HouseholderQR<Matrix> qr(p.kernel);
    basis = Matrix(qr.householderQ()).rightCols(n - c);
    B = basis.adjoint() * B * basis;
  }
  B = (B + B.adjoint()).eval() / 2;
  Eigen::VectorXd values;
  symmetric_eigen(B, values);
  Basic_eigenpairs<Scalar> result;
  // A few values beyond `count` (for the completeness check's gap), trimmed by the caller.
  const Eigen::Index shown = std::min<Eigen::Index>(values.size(), count + 16);
  result.values = values.head(shown);
  result.complete_below = count < values.size() ? values[count] : std::numeric_limits<double>::infinity();
  const Matrix Y = c > 0 ? Matrix(basis * B.leftCols(count)) : Matrix(B.leftCols(count));
  result.vectors = p.inv_sqrt_d.asDiagonal() * Y;
  result.residuals = p.residuals(result.values.head(count), result.vectors);
  result.basis_size = static_cast<int>(n - c);
  if(subspace) *subspace = c > 0 ? Matrix(basis * B.leftCols(shown)) : Matrix(B.leftCols(shown));
  return result;
}

// Subspace inverse iteration with Rayleigh-Ritz on the dense pairs (all `vectors` columns,
// a few more than `count`), until the `count` lowest meet `accurate`.  The dense solver's
// roundoff on the entries of the largest eigenvalues (a component far smaller than the
// others) is damped by lambda / lambda_max per step, and the sparse products and solves do
// not spread it back over the entries; the wanted pairs converge at the ratio of their
// eigenvalue to that of the first pair beyond the subspace.
template <class Scalar, class Accurate>
void purify(const Eigen::SparseMatrix<Scalar>& A, const Problem<Scalar>& p, Basic_eigenpairs<Scalar>& result, int count,
            const Accurate& accurate)
{
  typedef Dense<Scalar> Matrix;
  // Below the spectrum (A is semi-definite, D positive), near its bottom.
  const double shift = std::max(1e-3 * std::abs(result.values[0]), std::numeric_limits<double>::min());
  Basic_sparse_ldlt_solver<Scalar> solver;
  const Eigen::SparseMatrix<Scalar> K = p.shifted(-shift);
  solver.analyze(K);
  solver.factor(K, "the eigenproblem shifted below its spectrum");
  Matrix X = result.vectors;
  for(int step = 0; step < 60; ++step)
  {
    Matrix Z = p.sqrt_d.asDiagonal() * solver.solve(Matrix(p.d.asDiagonal() * X));
    p.deflate(Z);
    X = p.inv_sqrt_d.asDiagonal() * orthonormal_columns(Z);
    Matrix a = X.adjoint() * (A * X), m = X.adjoint() * p.d.asDiagonal() * X;
    a = (a + a.adjoint()).eval() / 2;
    m = (m + m.adjoint()).eval() / 2;
    Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> small(a, m);
    if(small.info() != Eigen::Success) throw Numerical_failure("eigenproblem: the Rayleigh-Ritz step failed");
    X = X * small.eigenvectors();
    result.values.head(X.cols()) = small.eigenvalues();
    result.vectors = X.leftCols(count);
    result.residuals = p.residuals(result.values.head(count), result.vectors);
    if(step >= 1 && accurate()) return;
  }
}

} // namespace

namespace {

template <class Scalar>
void check_request(const Basic_eigenproblem_request<Scalar>& r, const Eigensolver_options& options)
{
  const Eigen::Index n = r.A.rows(), c = r.kernel.cols();
  if(r.A.cols() != n || r.D.size() != n || (c > 0 && r.kernel.rows() != n))
    throw Invalid_input("eigenproblem: matrix, masses and kernel sizes differ");
  if(r.count < 0 || r.count > n - c)
    throw Invalid_input("asked for " + std::to_string(r.count) + " eigenpairs but the space has dimension " +
                        std::to_string(n - c));
  if(n > 0 && !(r.D.minCoeff() > 0)) throw Invalid_input("eigenproblem: the masses must be positive");
  // A NaN tolerance would never be met: the eigensolver would fail after all its restarts
  // with a misleading "misses the tolerance"; 0 or less would ask for the impossible.
  if(!(options.tolerance > 0 && options.tolerance < 1))
    throw Invalid_input("eigenproblem: the tolerance must lie in (0, 1) (got " + std::to_string(options.tolerance) + ")");
}

// The pairs of a small problem (or one asking for a third of its space) by a dense
// eigensolver; false when they are not accurate enough and slicing must find them.
template <class Scalar>
bool dense_lowest(const Eigen::SparseMatrix<Scalar>& A, const Problem<Scalar>& p, int count,
                  const Eigensolver_options& options, Basic_eigenpairs<Scalar>& result)
{
  const int n = static_cast<int>(A.rows()), c = static_cast<int>(p.kernel.cols());
  Dense<Scalar> subspace;
  result = dense_eigenpairs(p, count, &subspace);
  // A dense eigensolver leaves roundoff of size eps |x| on every entry, which the largest
  // eigenvalues amplify: with a spectrum spread over many orders (components of very
  // different sizes) the low pairs keep only a few digits.  Inverse iteration cleans them.
  auto accurate = [&] {
    const Eigen::VectorXd tolerances = p.tolerances_for(result.values.head(count), result.vectors, options.tolerance);
    for(int i = 0; i < count; ++i)
      if(!(result.residuals[i] <= tolerances[i])) return false;
    return true;
  };
  if(!accurate())
  {
    result.vectors = p.inv_sqrt_d.asDiagonal() * subspace;
    purify(A, p, result, count, accurate);
    // Inverse iteration can stall above the tolerance where faces are extremely thin
    // (CGAL's ALSTOM_TEST4.off, angles of 0.02 degrees: residuals 5e-10 .. 1.4e-9 over 60
    // steps, against 1e-10), while Lanczos runs from a block the operator has smoothed
    // reach it; so do those.
    if(!accurate()) return false;
  }
  // Complete by construction; the inertia count is recorded all the same.
  if(count < n - c) result.completeness = check_completeness(A, p.d, result.values, c, count);
  result.values.conservativeResize(count);
  return true;
}

// `lowest_eigenpairs_of_each` for either scalar.
template <class Scalar>
std::vector<Basic_eigenpairs<Scalar>> solve_each(const std::vector<Basic_eigenproblem_request<Scalar>>& problems,
                                                 const Eigensolver_options& options)
{
  typedef typename Basic_eigenpairs<Scalar>::Float32_matrix::Scalar Float32;
  for(const Basic_eigenproblem_request<Scalar>& r : problems) check_request(r, options);
  std::vector<Basic_eigenpairs<Scalar>> result(problems.size());
  std::vector<std::unique_ptr<Problem<Scalar>>> standard;
  std::vector<internal::Sliced_request<Scalar>> sliced;
  std::vector<std::size_t> sliced_index;
  for(std::size_t i = 0; i < problems.size(); ++i)
  {
    const Basic_eigenproblem_request<Scalar>& r = problems[i];
    const int n = static_cast<int>(r.A.rows()), c = static_cast<int>(r.kernel.cols());
    if(r.count == 0)
    {
      if(options.float32_vectors) result[i].vectors_float32.resize(n, 0);
      else result[i].vectors.resize(n, 0);
      result[i].complete_below = n - c > 0 ? 0. : std::numeric_limits<double>::infinity();
      continue;
    }
    standard.push_back(std::make_unique<Problem<Scalar>>(r.A, r.D, r.kernel));
    const Problem<Scalar>& p = *standard.back();
    const bool dense =
        options.allow_dense && (n <= options.dense_size || r.count + 3 * options.block_size > (n - c) / 3);
    if(dense && dense_lowest(r.A, p, r.count, options, result[i]))
    {
      if(options.float32_vectors) // small problems: rounded at the end
      {
        result[i].vectors_float32 = result[i].vectors.template cast<Float32>();
        result[i].vectors.resize(0, 0);
      }
      continue;
    }
    sliced.push_back({p, r.count});
    sliced_index.push_back(i);
  }
  if(!sliced.empty())
  {
    std::vector<Basic_eigenpairs<Scalar>> solved = internal::sliced_eigenpairs(sliced, options);
    for(std::size_t k = 0; k < solved.size(); ++k) result[sliced_index[k]] = std::move(solved[k]);
  }
  return result;
}

} // namespace

std::vector<Eigenpairs> lowest_eigenpairs_of_each(const std::vector<Eigenproblem_request>& problems,
                                                  const Eigensolver_options& options)
{
  return solve_each(problems, options);
}

Eigenpairs lowest_eigenpairs(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& d, int count,
                             const Eigen::MatrixXd& kernel, const Eigensolver_options& options)
{
  return std::move(solve_each<double>({{A, d, count, kernel}}, options).front());
}

Complex_eigenpairs lowest_eigenpairs(const Eigen::SparseMatrix<std::complex<double>>& A, const Eigen::VectorXd& d,
                                     int count, const Eigen::MatrixXcd& kernel, const Eigensolver_options& options)
{
  return std::move(solve_each<std::complex<double>>({{A, d, count, kernel}}, options).front());
}

} // namespace Model_reduction
} // namespace CGAL
