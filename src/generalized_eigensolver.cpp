// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Dense products go to the BLAS (OpenBLAS on Debian when libopenblas0-pthread is
// installed): the orthogonalisation against the whole Krylov basis dominates.
#define EIGEN_USE_BLAS

#include <CGAL/Tangent_vector_fields/Generalized_eigensolver.h>
#include <CGAL/Tangent_vector_fields/Sparse_spd_solver.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <limits>
#include <cmath>
#include <random>
#include <sstream>

extern "C" void dsyevd_(const char* jobz, const char* uplo, const int* n, double* a, const int* lda, double* w,
                        double* work, const int* lwork, int* iwork, const int* liwork, int* info);

namespace CGAL {
namespace Tangent_vector_fields {

namespace {

typedef Eigen::SparseMatrix<double> Sparse_matrix;

// Eigenvalues (ascending) and eigenvectors of a dense symmetric matrix, by LAPACK's
// divide and conquer (several times faster than Eigen's QR iteration at m ~ 1000).
void symmetric_eigen(Eigen::MatrixXd& A, Eigen::VectorXd& values)
{
  const int n = static_cast<int>(A.rows());
  values.resize(n);
  if(n == 0) return;
  int info = 0, lwork = -1, liwork = -1, iwork_query = 0;
  double work_query = 0;
  dsyevd_("V", "L", &n, A.data(), &n, values.data(), &work_query, &lwork, &iwork_query, &liwork, &info);
  lwork = static_cast<int>(work_query);
  liwork = iwork_query;
  std::vector<double> work(lwork);
  std::vector<int> iwork(liwork);
  dsyevd_("V", "L", &n, A.data(), &n, values.data(), work.data(), &lwork, iwork.data(), &liwork, &info);
  if(info != 0) throw Numerical_failure("dense symmetric eigensolver (LAPACK dsyevd) failed, info " + std::to_string(info));
}

// Orthonormal basis of the columns of X (thin Householder QR).
Eigen::MatrixXd orthonormal_columns(const Eigen::MatrixXd& X)
{
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(X);
  return qr.householderQ() * Eigen::MatrixXd::Identity(X.rows(), X.cols());
}

struct Problem
{
  const Sparse_matrix& A;
  Eigen::VectorXd d, sqrt_d, inv_sqrt_d;
  Eigen::MatrixXd kernel; // orthonormal, standard form

  Problem(const Sparse_matrix& A_, const Eigen::VectorXd& d_, const Eigen::MatrixXd& kernel_original) : A(A_), d(d_)
  {
    sqrt_d = d.cwiseSqrt();
    inv_sqrt_d = sqrt_d.cwiseInverse();
    if(kernel_original.cols() > 0) kernel = orthonormal_columns(sqrt_d.asDiagonal() * kernel_original);
    else kernel.resize(d.size(), 0);
  }
  void deflate(Eigen::MatrixXd& Z) const
  {
    if(kernel.cols() > 0) Z -= kernel * (kernel.transpose() * Z);
  }
  // Relative residuals of pairs (values, vectors in original variables, D-normalised).
  Eigen::VectorXd residuals(const Eigen::VectorXd& values, const Eigen::MatrixXd& X) const
  {
    const Eigen::MatrixXd AX = A * X;
    Eigen::VectorXd r(values.size());
    for(Eigen::Index i = 0; i < values.size(); ++i)
    {
      const Eigen::VectorXd Dx = d.cwiseProduct(X.col(i));
      r[i] = (AX.col(i) - values[i] * Dx).norm() / (std::abs(values[i]) * Dx.norm());
    }
    return r;
  }
};

Eigenpairs dense_eigenpairs(const Problem& p, int count)
{
  const Eigen::Index n = p.sqrt_d.size(), c = p.kernel.cols();
  Eigen::MatrixXd B = p.inv_sqrt_d.asDiagonal() * Eigen::MatrixXd(p.A) * p.inv_sqrt_d.asDiagonal();
  // Restrict to the orthogonal complement of the kernel (when there is one).
  Eigen::MatrixXd basis;
  if(c > 0)
  {
    Eigen::HouseholderQR<Eigen::MatrixXd> qr(p.kernel);
    basis = Eigen::MatrixXd(qr.householderQ()).rightCols(n - c);
    B = basis.transpose() * B * basis;
  }
  B = (B + B.transpose()).eval() / 2;
  Eigen::VectorXd values;
  symmetric_eigen(B, values);
  Eigenpairs result;
  result.values = values.head(count);
  const Eigen::MatrixXd Y = c > 0 ? Eigen::MatrixXd(basis * B.leftCols(count)) : Eigen::MatrixXd(B.leftCols(count));
  result.vectors = p.inv_sqrt_d.asDiagonal() * Y;
  result.residuals = p.residuals(result.values, result.vectors);
  result.basis_size = static_cast<int>(n - c);
  return result;
}

// The `count` lowest pairs outside the kernel (dense for small problems, block
// shift-and-invert Lanczos otherwise); no completeness check.
Eigenpairs solve_lowest(const Sparse_matrix& A, const Problem& p, int count, const Eigensolver_options& options)
{
  const int n = static_cast<int>(A.rows());
  const int c = static_cast<int>(p.kernel.cols());
  const Eigen::VectorXd& d = p.d;
  const int b = std::max(1, options.block_size);
  if(options.allow_dense && (n <= 1500 || count + 3 * b > (n - c) / 3)) return dense_eigenpairs(p, count);

  // Shift-and-invert in standard form: op(Y) = D^1/2 (A - sigma D)^-1 D^1/2 Y.  The
  // problem is scaled so that the mean mass is 1/n (unit total mass); sigma sits just
  // below 0, so A - sigma D is positive definite and the lowest eigenvalues become the
  // largest and best separated ones of op.
  const double total_mass = d.sum();
  const double sigma = -1e-2 / total_mass; // eigenvalues of unit-area surfaces are O(10) and up
  Sparse_matrix K = A;
  K.diagonal() -= sigma * d; // needs the diagonal stored: true for the Laplacians here
  Sparse_spd_solver solver;
  solver.factor(K, "the shifted matrix of the eigenproblem");
  auto op = [&](const Eigen::MatrixXd& Y) -> Eigen::MatrixXd {
    Eigen::MatrixXd Z = p.sqrt_d.asDiagonal() * solver.solve(Eigen::MatrixXd(p.sqrt_d.asDiagonal() * Y));
    p.deflate(Z);
    return Z;
  };

  // Krylov basis limit: about 3 times the wanted count was needed on meshes (the
  // lowest eigenvalues of a surface are packed ever closer, lambda_k ~ k).
  const int max_basis = std::min(n - c, std::max(4 * count + 8 * b, count + 40 * b));
  Eigen::MatrixXd Q(n, max_basis + b);
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(max_basis + b, max_basis + b);
  std::mt19937_64 generator(options.seed);
  std::normal_distribution<double> normal;
  auto random_block = [&](int cols) {
    Eigen::MatrixXd X(n, cols);
    for(Eigen::Index j = 0; j < X.cols(); ++j)
      for(Eigen::Index i = 0; i < n; ++i) X(i, j) = normal(generator);
    return X;
  };
  {
    Eigen::MatrixXd X = random_block(b);
    p.deflate(X);
    Q.leftCols(b) = orthonormal_columns(X);
  }
  int m = b;            // vectors in the basis
  int complete = 0;     // leading columns of H that are complete
  int next_check = std::min(max_basis, count + 2 * b);
  int applications = 0;
  Eigenpairs result;
  while(true)
  {
    // Expand with op(last block), orthogonalised twice against the whole basis.
    const int j0 = m - b;
    Eigen::MatrixXd Z = op(Q.middleCols(j0, b));
    applications += b;
    // Lanczos' local step first (the last two blocks hold nearly all of op(Q_j)),
    // then one pass against the whole basis, and a second one only where a column
    // lost more than half its norm in that pass ("twice is enough", Kahan-Parlett).
    {
      const int l0 = std::max(0, j0 - b);
      const Eigen::MatrixXd C = Q.middleCols(l0, m - l0).transpose() * Z;
      Z.noalias() -= Q.middleCols(l0, m - l0) * C;
      H.block(l0, j0, m - l0, b) += C;
    }
    for(int pass = 0; pass < 2; ++pass)
    {
      const Eigen::VectorXd before = Z.colwise().norm();
      const Eigen::MatrixXd C = Q.leftCols(m).transpose() * Z;
      Z.noalias() -= Q.leftCols(m) * C;
      H.block(0, j0, m, b) += C;
      const Eigen::VectorXd after = Z.colwise().norm();
      if(((after.array() / before.array().max(1e-300)) > 0.5).all()) break;
    }
    p.deflate(Z);
    Eigen::HouseholderQR<Eigen::MatrixXd> qr(Z);
    Eigen::MatrixXd R = qr.matrixQR().topRows(b).triangularView<Eigen::Upper>();
    Eigen::MatrixXd next = qr.householderQ() * Eigen::MatrixXd::Identity(n, b);
    // Breakdown (an invariant subspace was found): continue with fresh random
    // directions; the coupling R is then zero where the rank was lost.
    const double scale = R.cwiseAbs().maxCoeff();
    for(int i = 0; i < b; ++i)
      if(std::abs(R(i, i)) <= 1e-10 * std::max(scale, 1e-300))
      {
        Eigen::MatrixXd x = random_block(1);
        p.deflate(x);
        for(int pass = 0; pass < 2; ++pass)
        {
          x -= Q.leftCols(m) * (Q.leftCols(m).transpose() * x);
          x -= next * (next.transpose() * x);
        }
        next.col(i) = x / x.norm();
        R.row(i).setZero();
      }
    H.block(m, j0, b, b) = R;
    Q.middleCols(m, b) = next;
    complete = m;
    m += b;

    if(complete < next_check && m <= max_basis) continue;

    // Rayleigh-Ritz on the complete part.
    Eigen::MatrixXd T = H.topLeftCorner(complete, complete);
    T = (T + T.transpose()).eval() / 2;
    Eigen::VectorXd theta;
    symmetric_eigen(T, theta); // ascending: the wanted ones are at the end
    const int wanted = std::min(count, complete);
    const Eigen::MatrixXd coupling = H.block(complete, complete - b, b, b) * T.bottomRows(b);
    int converged = 0;
    for(int i = 0; i < wanted; ++i)
    {
      const int k = complete - 1 - i;
      if(coupling.col(k).norm() <= 1e-2 * options.tolerance * std::abs(theta[k])) ++converged;
      else break;
    }
    if(options.progress) options.progress({converged, count, complete});
    const bool exhausted = m > max_basis || complete >= n - c;
    if(converged == count || exhausted)
    {
      // Ritz pairs, checked on the true residual of A x = lambda D x.
      Eigen::MatrixXd S = T.rightCols(wanted).rowwise().reverse();
      Eigen::VectorXd values(wanted);
      for(int i = 0; i < wanted; ++i) values[i] = sigma + 1 / theta[complete - 1 - i];
      Eigen::MatrixXd X = p.inv_sqrt_d.asDiagonal() * (Q.leftCols(complete) * S);
      const Eigen::VectorXd residuals = p.residuals(values, X);
      if(wanted == count && residuals.maxCoeff() <= options.tolerance)
      {
        result.values = values;
        result.vectors = std::move(X);
        result.residuals = residuals;
        break;
      }
      if(exhausted)
      {
        std::ostringstream msg;
        msg << "the eigensolver did not converge: " << converged << " of " << count
            << " pairs within the Krylov basis limit " << max_basis << " (largest residual "
            << (wanted ? residuals.maxCoeff() : 0.) << ", tolerance " << options.tolerance << ")";
        throw Numerical_failure(msg.str());
      }
    }
    next_check = std::min(max_basis, complete + std::max(2 * b, count / 4));
  }
  result.basis_size = complete;
  result.operator_applications = applications;
  return result;
}

} // namespace

Completeness_check check_completeness(const Sparse_matrix& A, const Eigen::VectorXd& d, const Eigen::VectorXd& values,
                                      int kernel_dimension, int first_gap)
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
  check.inertia = count_eigenvalues_below(A, d, check.shift);
  return check;
}

Eigenpairs lowest_eigenpairs(const Sparse_matrix& A, const Eigen::VectorXd& d, int count, const Eigen::MatrixXd& kernel,
                             const Eigensolver_options& options)
{
  const int n = static_cast<int>(A.rows());
  const int c = static_cast<int>(kernel.cols());
  if(A.cols() != n || d.size() != n || (c > 0 && kernel.rows() != n))
    throw Invalid_input("eigenproblem: matrix, masses and kernel sizes differ");
  if(count < 0 || count > n - c)
    throw Invalid_input("asked for " + std::to_string(count) + " eigenpairs but the space has dimension " +
                        std::to_string(n - c));
  if(n > 0 && !(d.minCoeff() > 0)) throw Invalid_input("eigenproblem: the masses must be positive");
  const Problem p(A, d, kernel);
  if(count == 0)
  {
    Eigenpairs empty;
    empty.vectors.resize(n, 0);
    empty.complete_below = n - c > 0 ? 0. : std::numeric_limits<double>::infinity();
    return empty;
  }
  if(!options.verify_completeness || count == n - c)
  {
    Eigenpairs result = solve_lowest(A, p, count, options);
    result.complete_below = count == n - c ? std::numeric_limits<double>::infinity() : result.values[count - 1];
    return result;
  }
  // A margin of pairs beyond `count` gives the completeness check a gap to work in.
  int extra = std::min(n - c - count, std::max(4, count / 16));
  Eigensolver_options attempt = options;
  for(int round = 0;; ++round)
  {
    Eigenpairs all = solve_lowest(A, p, count + extra, attempt);
    const Completeness_check check = check_completeness(A, d, all.values, c, count);
    if(check.passed())
    {
      Eigenpairs result;
      result.values = all.values.head(count);
      result.vectors = all.vectors.leftCols(count);
      result.residuals = all.residuals.head(count);
      result.basis_size = all.basis_size;
      result.operator_applications = all.operator_applications;
      result.completeness = check;
      // Nothing was skipped below the shift: the first value not returned is the
      // next computed one if it lies below the shift, and at least the shift otherwise.
      const bool whole_space = count + extra == n - c;
      result.complete_below = whole_space || check.expected - c > count ? all.values[count] : check.shift;
      return result;
    }
    if(round == 1)
    {
      std::ostringstream msg;
      msg << "the eigensolver missed eigenvalues: " << check.inertia << " eigenvalues lie below " << check.shift
          << " but " << check.expected << " were found (kernel included); the problem may have multiplicities "
          << "larger than the block size " << options.block_size;
      throw Numerical_failure(msg.str());
    }
    // Retry with a wider margin, a larger block and a different start.
    extra = std::min(n - c - count, extra + std::abs(check.inertia - check.expected) + options.block_size);
    attempt.seed = options.seed + 0x9e3779b97f4a7c15ull;
    attempt.block_size = 2 * options.block_size;
  }
}

int count_eigenvalues_below(const Sparse_matrix& A, const Eigen::VectorXd& d, double tau)
{
  Sparse_matrix K = A;
  K.diagonal() -= tau * d;
  // LDL^T without pivoting: fine for these shifted Laplacians unless tau hits an
  // eigenvalue, which the caller avoids by placing tau in a spectral gap.
  Eigen::SimplicialLDLT<Sparse_matrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt(K);
  if(ldlt.info() != Eigen::Success) throw Numerical_failure("inertia count: the LDL^T factorisation failed");
  const Eigen::VectorXd& D = ldlt.vectorD();
  if(!D.allFinite()) throw Numerical_failure("inertia count: non-finite pivots (the shift is too close to an eigenvalue)");
  return static_cast<int>((D.array() < 0).count());
}

} // namespace Tangent_vector_fields
} // namespace CGAL
