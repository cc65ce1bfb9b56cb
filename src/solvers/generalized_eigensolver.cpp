// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Dense products go to the BLAS (OpenBLAS on Debian when libopenblas0-pthread is
// installed): the orthogonalisation against the whole Krylov basis dominates.
#define EIGEN_USE_BLAS

#include <CGAL/Tangent_vector_fields/Generalized_eigensolver.h>
#include <CGAL/Tangent_vector_fields/Sparse_ldlt_solver.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <Eigen/Dense>

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

// Z = next R with orthonormal `next` (n x b) and upper triangular R: Cholesky QR
// twice (two small Gram matrices through the BLAS; Householder's rank-one updates
// were 11% of the run), Householder when the block is (nearly) rank deficient.
void block_qr(const Eigen::MatrixXd& Z, Eigen::MatrixXd& next, Eigen::MatrixXd& R)
{
  const Eigen::Index b = Z.cols();
  Eigen::MatrixXd Y = Z;
  R = Eigen::MatrixXd::Identity(b, b);
  for(int pass = 0; pass < 2; ++pass)
  {
    const Eigen::MatrixXd gram = Y.transpose() * Y;
    Eigen::LLT<Eigen::MatrixXd> llt(gram);
    const Eigen::MatrixXd U = llt.matrixU();
    const double ratio = U.diagonal().minCoeff() / std::max(U.diagonal().maxCoeff(), 1e-300);
    if(llt.info() != Eigen::Success || !(ratio > 1e-6))
    {
      Eigen::HouseholderQR<Eigen::MatrixXd> qr(Z);
      R = qr.matrixQR().topRows(b).triangularView<Eigen::Upper>();
      next = qr.householderQ() * Eigen::MatrixXd::Identity(Z.rows(), b);
      return;
    }
    Y = U.triangularView<Eigen::Upper>().solve<Eigen::OnTheRight>(Y);
    R = (U * R).eval();
  }
  next = std::move(Y);
}

struct Problem
{
  const Sparse_matrix& A;
  Eigen::VectorXd d, sqrt_d, inv_sqrt_d;
  Eigen::MatrixXd kernel; // orthonormal, standard form

  // Gershgorin bound of the largest eigenvalue of the standard form D^-1/2 A D^-1/2.
  double largest_eigenvalue_bound = 0;
  Sparse_matrix abs_A; // |A|, for the roundoff of A x

  Problem(const Sparse_matrix& A_, const Eigen::VectorXd& d_, const Eigen::MatrixXd& kernel_original) : A(A_), d(d_)
  {
    Eigen::VectorXd row_sums = Eigen::VectorXd::Zero(A.rows());
    for(Eigen::Index j = 0; j < A.outerSize(); ++j)
      for(Sparse_matrix::InnerIterator it(A, j); it; ++it)
        row_sums[it.row()] += std::abs(it.value()) / std::sqrt(d[it.row()] * d[j]);
    largest_eigenvalue_bound = row_sums.size() ? row_sums.maxCoeff() : 0.;
    abs_A = A.cwiseAbs();
    sqrt_d = d.cwiseSqrt();
    inv_sqrt_d = sqrt_d.cwiseInverse();
    if(kernel_original.cols() > 0) kernel = orthonormal_columns(sqrt_d.asDiagonal() * kernel_original);
    else kernel.resize(d.size(), 0);
  }
  // The residual a pair can reach in double precision: the eigenvector carries
  // roundoff of relative size ~eps in every direction, which A amplifies by up to
  // its largest eigenvalue, so |A x - l D x| / (l |D x|) cannot go much below
  // eps * lambda_max / l.  A margin of 64 covers the accumulation over the run.
  double tolerance_for(double lambda, double tolerance) const
  {
    return std::max(tolerance, 64 * std::numeric_limits<double>::epsilon() * largest_eigenvalue_bound / std::abs(lambda));
  }
  // The same bound for each pair from its own vector: the roundoff of computing A x is
  // eps |A| |x| entry by entry, in the norm of `residuals`.  Where A's large entries sit
  // away from the vector -- a component of the mesh a million times smaller than the one
  // the vector lives on -- it is far below `tolerance_for`, which would accept a pair that
  // has only a few correct digits.  Vectors with roundoff on such entries (from a dense
  // eigensolver) have a residual above this bound.
  Eigen::VectorXd tolerances_for(const Eigen::VectorXd& values, const Eigen::MatrixXd& X, double tolerance) const
  {
    const Eigen::MatrixXd AX = abs_A * X.cwiseAbs();
    Eigen::VectorXd t(values.size());
    for(Eigen::Index i = 0; i < values.size(); ++i)
      t[i] = std::max(tolerance, 64 * std::numeric_limits<double>::epsilon() * inv_sqrt_d.cwiseProduct(AX.col(i)).norm() /
                                     (std::abs(values[i]) * sqrt_d.cwiseProduct(X.col(i)).norm()));
    return t;
  }
  void deflate(Eigen::MatrixXd& Z) const
  {
    if(kernel.cols() > 0) Z -= kernel * (kernel.transpose() * Z);
  }
  // Relative residuals of pairs (values, vectors in original variables) in the
  // mass-weighted norms, |D^-1/2 (A x - l D x)| / (|l| |D^1/2 x|): the residual of
  // the symmetric standard form, which bounds the relative eigenvalue error.
  Eigen::VectorXd residuals(const Eigen::VectorXd& values, const Eigen::MatrixXd& X) const
  {
    const Eigen::MatrixXd AX = A * X;
    Eigen::VectorXd r(values.size());
    for(Eigen::Index i = 0; i < values.size(); ++i)
      r[i] = (inv_sqrt_d.cwiseProduct(AX.col(i) - values[i] * d.cwiseProduct(X.col(i)))).norm() /
             (std::abs(values[i]) * sqrt_d.cwiseProduct(X.col(i)).norm());
    return r;
  }
};

// `subspace`, if given, receives the standard-form vectors of all the values returned.
Eigenpairs dense_eigenpairs(const Problem& p, int count, Eigen::MatrixXd* subspace = nullptr)
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
  // A few values beyond `count` (for the completeness check's gap), trimmed by the caller.
  const Eigen::Index shown = std::min<Eigen::Index>(values.size(), count + 16);
  result.values = values.head(shown);
  result.complete_below = count < values.size() ? values[count] : std::numeric_limits<double>::infinity();
  const Eigen::MatrixXd Y = c > 0 ? Eigen::MatrixXd(basis * B.leftCols(count)) : Eigen::MatrixXd(B.leftCols(count));
  result.vectors = p.inv_sqrt_d.asDiagonal() * Y;
  result.residuals = p.residuals(result.values.head(count), result.vectors);
  result.basis_size = static_cast<int>(n - c);
  if(subspace) *subspace = c > 0 ? Eigen::MatrixXd(basis * B.leftCols(shown)) : Eigen::MatrixXd(B.leftCols(shown));
  return result;
}

// Subspace inverse iteration with Rayleigh-Ritz on the dense pairs (all `vectors` columns,
// a few more than `count`), until the `count` lowest meet `accurate`.  The dense solver's
// roundoff on the entries of the largest eigenvalues (a component far smaller than the
// others) is damped by lambda / lambda_max per step, and the sparse products and solves do
// not spread it back over the entries; the wanted pairs converge at the ratio of their
// eigenvalue to that of the first pair beyond the subspace.
template <class Accurate>
void purify(const Sparse_matrix& A, const Problem& p, Eigenpairs& result, int count, const Accurate& accurate)
{
  // Below the spectrum (A is semi-definite, D positive), near its bottom.
  const double shift = std::max(1e-3 * std::abs(result.values[0]), std::numeric_limits<double>::min());
  Sparse_matrix K = A;
  K.diagonal() += shift * p.d;
  Sparse_ldlt_solver solver;
  solver.analyze(K);
  solver.factor(K, "the eigenproblem shifted below its spectrum");
  Eigen::MatrixXd X = result.vectors;
  for(int step = 0; step < 60; ++step)
  {
    Eigen::MatrixXd Z = p.sqrt_d.asDiagonal() * solver.solve(Eigen::MatrixXd(p.d.asDiagonal() * X));
    p.deflate(Z);
    X = p.inv_sqrt_d.asDiagonal() * orthonormal_columns(Z);
    Eigen::MatrixXd a = X.transpose() * (A * X), m = X.transpose() * p.d.asDiagonal() * X;
    a = (a + a.transpose()).eval() / 2;
    m = (m + m.transpose()).eval() / 2;
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> small(a, m);
    if(small.info() != Eigen::Success) throw Numerical_failure("eigenproblem: the Rayleigh-Ritz step failed");
    X = X * small.eigenvectors();
    result.values.head(X.cols()) = small.eigenvalues();
    result.vectors = X.leftCols(count);
    result.residuals = p.residuals(result.values.head(count), result.vectors);
    if(step >= 1 && accurate()) return;
  }
}

// ---------------------------------------------------------------------------
// Spectrum slicing.  The wanted part of the spectrum is cut into windows (lo, hi].
// An LDL^T factorisation of A - hi D gives, by Sylvester's law, the exact number of
// eigenvalues below hi, so each window's count is known before its run starts; a
// second factorisation, at the window middle, drives a short block shift-and-invert
// Lanczos run that stops once it has found exactly that many: completeness is proved
// window by window.  Orthogonalisation is against the run's own basis (about 3-4x
// the window count with blocks of 4) and the converged vectors next to the window,
// instead of against everything found so far.

struct Ritz_set
{
  std::vector<double> values;
  std::vector<Eigen::VectorXd> vectors; // standard form (D^1/2 x), orthonormal
};

// One block Lanczos run at shift `sigma` on the complement of `locked` (and the
// kernel).  Collects the converged pairs with eigenvalue in (lo, hi] into `window`
// (exactly `wanted` of them) and those in (hi, carry_hi) into `carry`.
void lanczos_window(const Problem& p, const Sparse_matrix& K, const Sparse_ldlt_solver& solver, double sigma, const Eigen::MatrixXd& locked,
                    double lo, double hi, int wanted, double carry_hi, const Eigensolver_options& options,
                    std::mt19937_64& generator, Ritz_set& window, Ritz_set& carry, int& applications, int& basis_used,
                    int progress_offset, int progress_total)
{
  const Eigen::Index n = p.sqrt_d.size();
  const int c = static_cast<int>(p.kernel.cols());
  const int b = std::max(1, options.block_size);
  const int free_dimension = static_cast<int>(n) - c - static_cast<int>(locked.cols());
  const int max_basis = std::min(free_dimension, std::max(6 * wanted + 8 * b, wanted + 40 * b));
  auto deflate = [&](Eigen::MatrixXd& Z) {
    p.deflate(Z);
    if(locked.cols() > 0) Z -= locked * (locked.transpose() * Z);
  };
  // LDL^T without pivoting of an indefinite matrix loses digits (solve residuals up
  // to 3e-9 measured); one step of iterative refinement restores them.
  const bool refine = solver.negative_pivots() > 0;
  auto op = [&](const Eigen::MatrixXd& Y) -> Eigen::MatrixXd {
    const Eigen::MatrixXd rhs = p.sqrt_d.asDiagonal() * Y;
    Eigen::MatrixXd X = solver.solve(rhs);
    if(refine) X += solver.solve(Eigen::MatrixXd(rhs - K * X));
    Eigen::MatrixXd Z = p.sqrt_d.asDiagonal() * X;
    deflate(Z);
    return Z;
  };
  std::normal_distribution<double> normal;
  auto random_block = [&](int cols) {
    Eigen::MatrixXd X(n, cols);
    for(Eigen::Index j = 0; j < X.cols(); ++j)
      for(Eigen::Index i = 0; i < n; ++i) X(i, j) = normal(generator);
    deflate(X);
    deflate(X);
    return X;
  };

  Eigen::MatrixXd Q(n, max_basis + b);
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(max_basis + b, max_basis + b);
  Q.leftCols(b) = orthonormal_columns(random_block(b));
  int m = b, complete = 0;
  int next_check = std::min(max_basis, std::max(2 * b, wanted + wanted / 2));
  double estimate_factor = 0.5; // standard-form residual <= factor * tol (the estimate is exact up to roundoff)
  while(true)
  {
    const int j0 = m - b;
    Eigen::MatrixXd Z = op(Q.middleCols(j0, b));
    applications += b;
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
    Eigen::MatrixXd R, next;
    block_qr(Z, next, R);
    const double scale = R.cwiseAbs().maxCoeff();
    for(int i = 0; i < b; ++i)
      if(std::abs(R(i, i)) <= 1e-10 * std::max(scale, 1e-300))
      {
        Eigen::MatrixXd x = random_block(1);
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
    const bool exhausted = m > max_basis || complete >= free_dimension;
    if(complete < next_check && !exhausted) continue;

    // Rayleigh-Ritz; theta = 1 / (lambda - sigma).
    Eigen::MatrixXd T = H.topLeftCorner(complete, complete);
    T = (T + T.transpose()).eval() / 2;
    Eigen::VectorXd theta;
    symmetric_eigen(T, theta);
    const Eigen::MatrixXd coupling = H.block(complete, complete - b, b, b) * T.bottomRows(b);
    // If op y = theta y + r with r = Q_next c, then in standard form
    // (D^-1/2 A D^-1/2 - lambda) y = -(1/theta) D^-1/2 K D^-1/2 r: the residual of every
    // Ritz pair from one small Gram matrix, P^T P with P = D^-1/2 K D^-1/2 Q_next.
    const Eigen::MatrixXd P =
        p.inv_sqrt_d.asDiagonal() * (K * (p.inv_sqrt_d.asDiagonal() * Q.middleCols(complete, b)).eval());
    const Eigen::MatrixXd gram = P.transpose() * P;
    std::vector<int> in_window, in_carry;
    for(int k = 0; k < complete; ++k)
    {
      if(theta[k] == 0) continue;
      const double lambda = sigma + 1 / theta[k];
      const double residual =
          std::sqrt(std::max(0., coupling.col(k).dot(gram * coupling.col(k)))) / std::abs(theta[k] * lambda);
      const bool converged = residual <= estimate_factor * p.tolerance_for(lambda, options.tolerance);
      if(!converged) continue;
      if(lambda > lo && lambda <= hi) in_window.push_back(k);
      else if(lambda > hi && lambda < carry_hi) in_carry.push_back(k);
    }
    if(options.progress)
      options.progress({std::min(progress_total, progress_offset + static_cast<int>(in_window.size())), progress_total,
                        complete});
    if(static_cast<int>(in_window.size()) > wanted)
      throw Numerical_failure("spectrum slicing: more converged eigenvalues in (" + std::to_string(lo) + ", " +
                              std::to_string(hi) + "] than the inertia count " + std::to_string(wanted));
    if(static_cast<int>(in_window.size()) == wanted)
    {
      // Accept on the true residual of A x = lambda D x.
      std::vector<int> all = in_window;
      all.insert(all.end(), in_carry.begin(), in_carry.end());
      Eigen::MatrixXd S(complete, all.size());
      Eigen::VectorXd values(all.size());
      for(std::size_t i = 0; i < all.size(); ++i)
      {
        S.col(i) = T.col(all[i]);
        values[i] = sigma + 1 / theta[all[i]];
      }
      const Eigen::MatrixXd Y = Q.leftCols(complete) * S;
      const Eigen::MatrixXd X = p.inv_sqrt_d.asDiagonal() * Y;
      const Eigen::VectorXd residuals = p.residuals(values, X);
      const Eigen::VectorXd tolerances = p.tolerances_for(values, X, options.tolerance);
      bool window_ok = true;
      for(std::size_t i = 0; i < in_window.size(); ++i) window_ok = window_ok && residuals[i] <= tolerances[i];
      if(window_ok)
      {
        for(std::size_t i = 0; i < all.size(); ++i)
        {
          if(i >= in_window.size() && !(residuals[i] <= tolerances[i]))
            continue; // carry only if accurate
          Ritz_set& target = i < in_window.size() ? window : carry;
          target.values.push_back(values[i]);
          target.vectors.push_back(Y.col(i));
        }
        basis_used = std::max(basis_used, complete);
        return;
      }
      estimate_factor *= 1e-2; // the estimate was optimistic: ask for more
    }
    if(exhausted)
    {
      std::ostringstream msg;
      msg << "spectrum slicing: " << in_window.size() << " of " << wanted << " eigenvalues in (" << lo << ", "
          << hi << "] converged within the Krylov basis limit " << max_basis;
      throw Numerical_failure(msg.str());
    }
    next_check = std::min(max_basis, complete + std::max(2 * b, (wanted - static_cast<int>(in_window.size())) / 2 + b));
  }
}

Eigenpairs sliced_eigenpairs(const Sparse_matrix& A, const Problem& p, int count, const Eigensolver_options& options)
{
  const Eigen::Index n = A.rows();
  const int c = static_cast<int>(p.kernel.cols());
  const double total_mass = p.d.sum();
  const int per_window = std::max(options.block_size, options.slice_size);
  // Weyl's law on a surface of area |D|: about |D| lambda / (4 pi) eigenvalues below lambda.
  double density = total_mass / (4 * M_PI);
  Sparse_matrix K = A;
  Sparse_ldlt_solver solver;
  auto factor_at = [&](double sigma) {
    K = A;
    K.diagonal() -= sigma * p.d;
    solver.factor(K, "the shifted matrix of the eigenproblem");
    return solver.negative_pivots();
  };
  solver.analyze(A);

  std::mt19937_64 generator(options.seed);
  Ritz_set found, carry;
  double lo = 0;   // every eigenvalue in (0, lo] is in `found`
  int below_lo = c; // eigenvalues (with the kernel) below or at lo
  int applications = 0, basis_used = 0;
  Completeness_check check;
  while(static_cast<int>(found.values.size()) < count)
  {
    const int remaining = count - static_cast<int>(found.values.size());
    const int step = remaining <= per_window + per_window / 2 ? remaining + std::max(2, remaining / 20) : per_window;
    // Upper end of the window: its inertia counts the eigenvalues in (lo, hi].
    double hi = lo + step / density;
    int below = 0;
    for(int attempt = 0;; ++attempt)
    {
      below = factor_at(hi);
      // A boundary on top of an eigenvalue makes a tiny pivot: move it a little.
      if(solver.smallest_relative_pivot() < 1e-14 && attempt < 3)
      {
        hi += 1e-6 * (hi - lo);
        continue;
      }
      const int in_window = below - below_lo;
      if(in_window > 2 * per_window && attempt < 6)
      {
        hi = lo + (hi - lo) * per_window / in_window; // density underestimated: shrink
        continue;
      }
      if(in_window == 0 && attempt < 6)
      {
        hi = lo + 2 * (hi - lo);
        continue;
      }
      break;
    }
    if(below > c) density = (below - c) / hi;
    // The shift of the run in the middle, so both ends of the window are equally
    // far -- except for the first window: the residual floor of a Ritz pair grows like
    // |lambda - sigma| / lambda, and the lowest eigenvalues need a shift next to them
    // (just below 0; measured: a shift at the middle of (0, hi] left them at 1e-10).
    double sigma = lo == 0 ? -1e-2 / total_mass : 0.5 * (lo + hi);
    // Lock the found vectors near the window (and the carried ones) out of the run.
    std::vector<const Eigen::VectorXd*> lock;
    const double reach = lo - 0.5 * (hi - lo);
    for(std::size_t i = 0; i < found.values.size(); ++i)
      if(found.values[i] > reach) lock.push_back(&found.vectors[i]);
    int carried_in_window = 0;
    for(std::size_t i = 0; i < carry.values.size(); ++i)
    {
      lock.push_back(&carry.vectors[i]);
      if(carry.values[i] <= hi) ++carried_in_window;
    }
    Eigen::MatrixXd locked(n, static_cast<Eigen::Index>(lock.size()));
    for(std::size_t i = 0; i < lock.size(); ++i) locked.col(static_cast<Eigen::Index>(i)) = *lock[i];
    // Ritz vectors of one run are orthonormal, of different runs orthogonal to the
    // accuracy of the pairs: no need to orthonormalise them again.
    const int wanted = below - below_lo - carried_in_window;
    if(wanted < 0)
      throw Numerical_failure("spectrum slicing: more eigenvalues carried into (" + std::to_string(lo) + ", " +
                              std::to_string(hi) + "] than the inertia count allows");
    Ritz_set window, new_carry;
    if(wanted > 0) // else the carried pairs fill the window: no run, no factorisation
    {
      factor_at(sigma);
      if(solver.smallest_relative_pivot() < 1e-14) factor_at(sigma += 1e-6 * (hi - lo));
      try
      {
        lanczos_window(p, K, solver, sigma, locked, lo, hi, wanted, hi + 0.5 * (hi - lo), options, generator, window,
                       new_carry, applications, basis_used, static_cast<int>(found.values.size()), count);
      }
      catch(const Numerical_failure&)
      {
        // A block Lanczos run finds at most `block_size` copies of a repeated
        // eigenvalue quickly (symmetric meshes have multiplicities up to 5 and more):
        // retry the window once with wider blocks.
        Eigensolver_options wider = options;
        wider.block_size = 4 * options.block_size;
        window = Ritz_set();
        new_carry = Ritz_set();
        lanczos_window(p, K, solver, sigma, locked, lo, hi, wanted, hi + 0.5 * (hi - lo), wider, generator, window,
                       new_carry, applications, basis_used, static_cast<int>(found.values.size()), count);
      }
    }
    // Move the carried pairs of this window to `found`; keep the others.
    Ritz_set still_carried;
    for(std::size_t i = 0; i < carry.values.size(); ++i)
    {
      Ritz_set& target = carry.values[i] <= hi ? found : still_carried;
      target.values.push_back(carry.values[i]);
      target.vectors.push_back(std::move(carry.vectors[i]));
    }
    for(std::size_t i = 0; i < window.values.size(); ++i)
    {
      found.values.push_back(window.values[i]);
      found.vectors.push_back(std::move(window.vectors[i]));
    }
    for(std::size_t i = 0; i < new_carry.values.size(); ++i)
    {
      still_carried.values.push_back(new_carry.values[i]);
      still_carried.vectors.push_back(std::move(new_carry.vectors[i]));
    }
    carry = std::move(still_carried);
    lo = hi;
    below_lo = below;
    check.shift = hi;
    check.inertia = below;
    check.expected = c + static_cast<int>(found.values.size());
    if(options.progress)
      options.progress({std::min(count, static_cast<int>(found.values.size())), count, basis_used});
  }

  // Sort, keep the lowest `count`.
  std::vector<int> order(found.values.size());
  for(std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return found.values[a] < found.values[b]; });
  Eigenpairs result;
  result.values.resize(count);
  Eigen::MatrixXd Y(n, count);
  for(int i = 0; i < count; ++i)
  {
    result.values[i] = found.values[order[i]];
    Y.col(i) = found.vectors[order[i]];
  }
  result.vectors = p.inv_sqrt_d.asDiagonal() * Y;
  result.residuals = p.residuals(result.values, result.vectors);
  result.basis_size = basis_used;
  result.operator_applications = applications;
  result.completeness = check;
  result.complete_below = static_cast<int>(found.values.size()) > count ? found.values[order[count]] : lo;
  const Eigen::VectorXd tolerances = p.tolerances_for(result.values, result.vectors, options.tolerance);
  for(int i = 0; i < count; ++i)
    if(!(result.residuals[i] <= tolerances[i]))
      throw Numerical_failure("spectrum slicing: an eigenpair misses the tolerance (residual " +
                              std::to_string(result.residuals[i]) + ")");
  return result;
}

} // namespace

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
  // A NaN tolerance would never be met: the eigensolver would fail after all its restarts
  // with a misleading "misses the tolerance"; 0 or less would ask for the impossible.
  if(!(options.tolerance > 0 && options.tolerance < 1))
    throw Invalid_input("eigenproblem: the tolerance must lie in (0, 1) (got " + std::to_string(options.tolerance) + ")");
  const Problem p(A, d, kernel);
  if(count == 0)
  {
    Eigenpairs empty;
    empty.vectors.resize(n, 0);
    empty.complete_below = n - c > 0 ? 0. : std::numeric_limits<double>::infinity();
    return empty;
  }
  const bool dense =
      options.allow_dense && (n <= options.dense_size || count + 3 * options.block_size > (n - c) / 3);
  if(!dense) return sliced_eigenpairs(A, p, count, options);
  Eigen::MatrixXd subspace;
  Eigenpairs result = dense_eigenpairs(p, count, &subspace);
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
    if(!accurate())
      throw Numerical_failure("eigenproblem: an eigenpair misses the tolerance after refinement (residual " +
                              std::to_string(result.residuals.maxCoeff()) + ")");
  }
  // Complete by construction; the inertia count is recorded all the same.
  if(count < n - c) result.completeness = check_completeness(A, d, result.values, c, count);
  result.values.conservativeResize(count);
  return result;
}

} // namespace Tangent_vector_fields
} // namespace CGAL
