// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Model_reduction/internal/Lanczos_window.h>
#include <CGAL/Model_reduction/errors.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace CGAL {
namespace Model_reduction {
namespace internal {

namespace {

template <class Scalar>
using Dense = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;

// A random number of the normal distribution; complex: real and imaginary parts each.
double random_entry(std::normal_distribution<double>& normal, std::mt19937_64& generator, double)
{
  return normal(generator);
}
std::complex<double> random_entry(std::normal_distribution<double>& normal, std::mt19937_64& generator,
                                  std::complex<double>)
{
  const double re = normal(generator);
  return {re, normal(generator)};
}

// The first `S.cols()` columns of `Q` become `Q.leftCols(complete) * S`, in place, a band of
// rows at a time: no n x S.cols() temporary.
template <class Scalar>
void turn_in_place(Dense<Scalar>& Q, int complete, const Dense<Scalar>& S)
{
  const Eigen::Index n = Q.rows(), band = 1024;
  Dense<Scalar> rows;
  for(Eigen::Index r0 = 0; r0 < n; r0 += band)
  {
    const Eigen::Index h = std::min(band, n - r0);
    rows.noalias() = Q.block(r0, 0, h, complete) * S;
    Q.block(r0, 0, h, S.cols()) = rows;
  }
}

// The pairs of an unrefined run that converged by the Lanczos estimate but missed their
// tolerance on the true residual are few and close to it, at the far end of the window
// from the shift (bunny, Crouzeix-Raviart: 1 to 3 of 50, 1.5e-10 .. 2.4e-10 against
// 1e-10).  One refined solve with a shift at the worst of them, then Rayleigh-Ritz on A
// itself over the window's Ritz vectors and these images, usually brings them there for
// a fraction of a rerun of the window.  (Images of all the Ritz vectors at the window's
// shift add directions from all over the spectrum, whose combinations made spurious
// Ritz values inside the window: 62 for 47.)
constexpr int most_polished = 8;

// The window's pairs and the carried ones are the first `k` columns of `Q`, whose other
// columns are free; `deflate` removes the kernel and the locked vectors.  Everything
// happens in `Q`: the images go next to the Ritz vectors, and the new Ritz vectors are
// formed in place of them (`turn_in_place`).  Collecting them next to the basis made the
// peak of the armadillo's set-up: 50-60 new vectors (0.25 GB at 519k edges) next to a
// basis of 100 while the other chain's basis was at its largest.  The factor `solver` is
// the window's, overwritten (a factor of its own was the largest transient at the bunny's
// 104k edges).  Returns how many of the pairs accepted are the window's (0: the polish did
// not succeed); `accepted` lists their columns of `Q`, the window's first, and `values`,
// `residuals` and `tolerances` those of the first columns of `Q`, accepted or not.
template <class Scalar, class Deflate>
Eigen::Index polish(const Basic_standard_eigenproblem<Scalar>& p, const Window& w, Dense<Scalar>& Q, Eigen::Index k,
                    Eigen::VectorXd& values, Eigen::VectorXd& residuals, Eigen::VectorXd& tolerances,
                    const Deflate& deflate, Basic_sparse_ldlt_solver<Scalar>& solver, double tolerance,
                    std::vector<Eigen::Index>& accepted, int& applications)
{
  typedef Dense<Scalar> Matrix;
  const Eigen::Index n = Q.rows();
  std::vector<Eigen::Index> failed;
  Eigen::Index worst = 0;
  for(Eigen::Index i = 0; i < w.wanted; ++i)
    if(!(residuals[i] <= tolerances[i]))
    {
      failed.push_back(i);
      if(residuals[i] / tolerances[i] > residuals[worst] / tolerances[worst]) worst = i;
    }
  if(failed.empty() || failed.size() > most_polished || k + most_polished > Q.cols()) return 0;
  // The shift a thousandth of the mean eigenvalue spacing of the window away from the
  // Ritz value: exactly at it, the pivots come near zero (measured: 2.5e-15 relative).
  const double spacing = (w.hi - w.lo) / std::max(1, w.wanted);
  double shift = 0;
  for(double offset = 1e-3 * spacing;; offset *= 10)
  {
    shift = values[worst] + offset;
    solver.factor(p.shifted(shift), "the eigenproblem shifted next to a Ritz value");
    if(solver.smallest_relative_pivot() >= 1e-14) break;
    if(offset >= 0.1 * spacing) return 0;
  }
  const auto Y = Q.leftCols(k);
  Matrix rhs(n, static_cast<Eigen::Index>(failed.size()));
  for(std::size_t j = 0; j < failed.size(); ++j) rhs.col(static_cast<Eigen::Index>(j)) = p.sqrt_d.cwiseProduct(Y.col(failed[j]));
  Matrix X = solver.solve(rhs);
  X += solver.solve(Matrix(rhs - p.shifted_times(shift, X)));
  applications += static_cast<int>(2 * failed.size());
  Matrix Z = p.sqrt_d.asDiagonal() * X;
  deflate(Z);
  for(int pass = 0; pass < 2; ++pass) Z -= Y * (Y.adjoint() * Z);
  const Eigen::Index f = Z.cols(), m = k + f;
  Q.middleCols(k, f) = orthonormal_columns(Z);
  // G = [Y Z]^H D^-1/2 A D^-1/2 [Y Z], 8 columns at a time.
  Matrix G(m, m);
  for(Eigen::Index j0 = 0; j0 < m; j0 += 8)
  {
    const auto V = Q.middleCols(j0, std::min<Eigen::Index>(8, m - j0));
    const Matrix AV = p.inv_sqrt_d.asDiagonal() * (p.A * (p.inv_sqrt_d.asDiagonal() * V)).eval();
    G.middleCols(j0, V.cols()).noalias() = Q.leftCols(m).adjoint() * AV;
  }
  G = (G + G.adjoint()).eval() / 2;
  Eigen::VectorXd mu;
  symmetric_eigen(G, mu);
  std::vector<Eigen::Index> chosen;
  for(Eigen::Index i = 0; i < mu.size(); ++i)
    if(mu[i] > w.lo && mu[i] <= w.hi) chosen.push_back(i);
  // Rayleigh-Ritz may also make a value inside the window from images that still hold
  // parts of eigenvectors far below it (not locked out): its residual is large.  So the
  // window's Ritz values may be more than wanted, but exactly `wanted` must meet their
  // tolerance -- orthonormal vectors with those residuals, as many as the inertia counts.
  const Eigen::Index in_window = static_cast<Eigen::Index>(chosen.size());
  if(in_window < w.wanted) return 0;
  for(Eigen::Index i = 0; i < mu.size(); ++i)
    if(mu[i] > w.hi && mu[i] < w.carry_hi) chosen.push_back(i);
  const Eigen::Index c = static_cast<Eigen::Index>(chosen.size());
  Matrix S(m, c);
  values.resize(c);
  for(Eigen::Index j = 0; j < c; ++j)
  {
    S.col(j) = G.col(chosen[j]);
    values[j] = mu[chosen[j]];
  }
  turn_in_place(Q, static_cast<int>(m), S);
  p.residuals_of_standard(values, Q.leftCols(c), tolerance, residuals, &tolerances);
  accepted.clear();
  Eigen::Index accepted_in_window = 0;
  for(Eigen::Index j = 0; j < c; ++j)
    if(residuals[j] <= tolerances[j])
    {
      accepted.push_back(j);
      if(j < in_window) ++accepted_in_window;
    }
  return accepted_in_window == w.wanted ? accepted_in_window : 0;
}

// Moves the accepted pairs, the columns `accepted` of `Q` (the window's first, `in_window`
// of them), into `store` a column at a time, each column's pages given back as it goes, and
// then the pages of the basis' first `used` columns, written afresh by the next window: no
// block of new vectors next to the whole basis (at the end of the largest chain, with most
// pairs held, that block set the peak of the solve).
template <class Scalar>
void move_to_store(Dense<Scalar>& Q, Eigen::Index used, const std::vector<Eigen::Index>& accepted,
                   Eigen::Index in_window, const Eigen::VectorXd& values, const Eigen::VectorXd& residuals,
                   const Eigen::VectorXd& tolerances, Column_store<Scalar>& store, Basic_ritz_set<Scalar>& window,
                   Basic_ritz_set<Scalar>& carry)
{
  const Eigen::Index n = Q.rows();
  for(std::size_t i = 0; i < accepted.size(); ++i)
  {
    Scalar* column = store.add(Q.col(accepted[i]));
    discard_pages(Q.col(accepted[i]).data(), sizeof(Scalar) * static_cast<std::size_t>(n));
    (static_cast<Eigen::Index>(i) < in_window ? window : carry)
        .push_back({values[i], column, n, residuals[i], tolerances[i]});
  }
  discard_pages(Q.data(), sizeof(Scalar) * static_cast<std::size_t>(n) * static_cast<std::size_t>(used));
}

struct Restart_sizes
{
  int limit, keep;
};

// Columns of a window's Krylov basis: at most `limit`, where a restart keeps `keep` (about
// 1.1 per wanted pair, enough to hold the window's pairs and a margin next to them), unless
// the run needs no more than `max_basis` anyway.
Restart_sizes restart_sizes(int wanted, int b, int max_basis, double per_pair)
{
  if(!(per_pair > 0)) return {max_basis, max_basis};
  const int limit = static_cast<int>(std::ceil(std::max(1.0, per_pair) * wanted)) + 8 * b;
  if(limit >= max_basis) return {max_basis, max_basis};
  return {limit, std::min(wanted + wanted / 10 + 2 * b, limit - 2 * b)};
}

// The thick-restart form, once the first `S.cols()` columns of `Q` hold the Ritz vectors
// `Q.leftCols(complete) * S` (`turn_in_place`) of values `kept`: the next block moves next
// to them, and `H` becomes diagonal on them with the next block coupled to each.  Returns
// the new count of complete columns.
template <class Scalar>
int restart_on_formed(Dense<Scalar>& Q, Dense<Scalar>& H, const Dense<Scalar>& S, const Eigen::VectorXd& kept,
                      int complete, int b)
{
  const int keep = static_cast<int>(S.cols());
  const Dense<Scalar> coupling = H.block(complete, 0, b, complete) * S;
  Q.middleCols(keep, b) = Q.middleCols(complete, b).eval(); // they overlap if keep + b > complete
  H.topLeftCorner(complete + b, complete + b).setZero();
  H.diagonal().head(keep) = kept.cast<Scalar>();
  H.block(keep, 0, b, keep) = coupling;
  return keep;
}

// Cuts the Krylov basis `Q` (its first `complete` columns and the next block) to the `keep`
// Ritz vectors whose values `theta` (of shift-and-invert: 1 / (lambda - sigma)) are largest
// in magnitude, the eigenvectors of `T` giving them, followed by the next block: the
// thick-restart form, where `H` is diagonal on the kept vectors and the next block is
// coupled to each of them.  Returns the new count of complete columns (`keep`).
template <class Scalar>
int thick_restart(Dense<Scalar>& Q, Dense<Scalar>& H, const Dense<Scalar>& T, const Eigen::VectorXd& theta,
                  int complete, int keep, int b)
{
  std::vector<int> order(static_cast<std::size_t>(complete));
  for(int i = 0; i < complete; ++i) order[static_cast<std::size_t>(i)] = i;
  std::partial_sort(order.begin(), order.begin() + keep, order.end(),
                    [&](int x, int y) { return std::abs(theta[x]) > std::abs(theta[y]); });
  Dense<Scalar> S(complete, keep);
  Eigen::VectorXd kept(keep);
  for(int j = 0; j < keep; ++j)
  {
    S.col(j) = T.col(order[static_cast<std::size_t>(j)]);
    kept[j] = theta[order[static_cast<std::size_t>(j)]];
  }
  turn_in_place(Q, complete, S);
  return restart_on_formed(Q, H, S, kept, complete, b);
}

} // namespace

// One block Lanczos run at shift `w.sigma` on the complement of `locked` (and the
// kernel).  Collects the converged pairs with eigenvalue in (lo, hi] into `window`
// (exactly `wanted` of them) and those in (hi, carry_hi) into `carry`.
template <class Scalar>
void lanczos_window(const Basic_standard_eigenproblem<Scalar>& p, Basic_sparse_ldlt_solver<Scalar>& solver,
                    const Window& w, const Locked_columns<Scalar>& locked, const Eigensolver_options& options,
                    std::mt19937_64& generator, Lanczos_workspace<Scalar>& space, Basic_ritz_set<Scalar>& window,
                    Basic_ritz_set<Scalar>& carry, Column_store<Scalar>& store, int& applications, int& basis_used,
                    const std::function<void(int)>& report)
{
  typedef Dense<Scalar> Matrix;
  const Eigen::Index n = p.sqrt_d.size();
  const int c = static_cast<int>(p.kernel.cols());
  const int b = std::max(1, options.block_size);
  const int wanted = w.wanted;
  const int free_dimension = static_cast<int>(n) - c - static_cast<int>(locked.count());
  const int max_basis = std::min(free_dimension, std::max(6 * wanted + 8 * b, wanted + 40 * b));
  // Thick restart: past `basis_limit` columns, the Krylov basis is cut to the Ritz vectors
  // nearest the shift (`restart_keep` of them) and grown again from its last block.
  const Restart_sizes sizes = restart_sizes(wanted, b, max_basis, options.restart_per_pair);
  const int basis_limit = sizes.limit, restart_keep = sizes.keep;
  const bool restarts = basis_limit < max_basis;
  long budget = restarts ? 3L * max_basis : max_basis; // columns generated, restarts included
  long generated = b;
  auto deflate = [&](Matrix& Z) {
    p.deflate(Z);
    locked.project_out(Z);
  };
  // LDL^T without pivoting of an indefinite matrix loses digits: relative solve
  // residuals of 1e-12 to 1e-10 (rocker arm), up to 3e-9 on other meshes.  A pair's true
  // residual cannot fall much below the solve residual times |lambda - sigma| / lambda,
  // which most windows tolerate; one step of iterative refinement restores the digits
  // at the price of a second solve, and is asked for by the caller where needed.
  const bool indefinite = solver.negative_pivots() > 0;
  const bool refine = w.refine && indefinite;
  auto op = [&](const Matrix& Y) -> Matrix {
    const Matrix rhs = p.sqrt_d.asDiagonal() * Y;
    Matrix X = solver.solve(rhs);
    if(refine) X += solver.solve(Matrix(rhs - p.shifted_times(w.sigma, X)));
    Matrix Z = p.sqrt_d.asDiagonal() * X;
    deflate(Z);
    return Z;
  };
  std::normal_distribution<double> normal;
  auto random_block = [&](int cols) {
    Matrix X(n, cols);
    for(Eigen::Index j = 0; j < X.cols(); ++j)
      for(Eigen::Index i = 0; i < n; ++i) X(i, j) = random_entry(normal, generator, Scalar());
    deflate(X);
    deflate(X);
    return X;
  };

  space.reserve(n, basis_limit + b + most_polished); // room for a polish's images
  Matrix& Q = space.Q;
  Matrix& H = space.H;
  // The start block through the operator twice: a random vector has parts of size
  // 1/sqrt(n) on every entry, and the Ritz vectors keep roundoff of that size.  Where the
  // standard form has huge entries (tiny masses: a component a million times smaller,
  // needle triangles) it is amplified far beyond the roundoff of the vectors' own entries
  // (camel.off: true residuals stuck at 1e-10 .. 1e-8 however long the basis grew).
  // Shift-and-invert scales every entry by the square root of its mass per application.
  Q.leftCols(b) = orthonormal_columns(op(orthonormal_columns(op(random_block(b)))));
  int m = b, complete = 0;
  int next_check = std::min(max_basis, std::max(2 * b, wanted + wanted / 2));
  double estimate_factor = 0.5; // standard-form residual <= factor * tol (the estimate is exact up to roundoff)
  while(true)
  {
    const int j0 = m - b;
    Matrix Z = op(Q.middleCols(j0, b));
    applications += b;
    {
      const int l0 = std::max(0, j0 - b);
      H.block(l0, j0, m - l0, b) += project_out_of_columns(Q, l0, m - l0, Z);
    }
    for(int pass = 0; pass < 2; ++pass)
    {
      const Eigen::VectorXd before = Z.colwise().norm();
      H.block(0, j0, m, b) += project_out_of_columns(Q, 0, m, Z);
      const Eigen::VectorXd after = Z.colwise().norm();
      if(((after.array() / before.array().max(1e-300)) > 0.5).all()) break;
    }
    Matrix R, next;
    block_qr(Z, next, R);
    const double scale = R.cwiseAbs().maxCoeff();
    for(int i = 0; i < b; ++i)
      if(std::abs(R(i, i)) <= 1e-10 * std::max(scale, 1e-300))
      {
        Matrix x = op(orthonormal_columns(op(random_block(1)))); // as the start block
        for(int pass = 0; pass < 2; ++pass)
        {
          x -= Q.leftCols(m) * (Q.leftCols(m).adjoint() * x);
          x -= next * (next.adjoint() * x);
        }
        next.col(i) = x / x.norm();
        R.row(i).setZero();
      }
    H.block(m, j0, b, b) = R;
    Q.middleCols(m, b) = next;
    complete = m;
    m += b;
    generated += b;
    const bool exhausted = generated > budget || complete >= free_dimension;
    const bool full = m > basis_limit;
    if(complete < next_check && !exhausted && !full) continue;

    // Rayleigh-Ritz; theta = 1 / (lambda - sigma).  T is Hermitian, theta real.
    Matrix T = H.topLeftCorner(complete, complete);
    T = (T + T.adjoint()).eval() / 2;
    Eigen::VectorXd theta;
    symmetric_eigen(T, theta);
    // The next block is coupled to the last block only, or after a restart to every kept
    // Ritz vector (until a block is added).
    const Matrix coupling = H.block(complete, 0, b, complete) * T;
    // If op y = theta y + r with r = Q_next c, then in standard form
    // (D^-1/2 A D^-1/2 - lambda) y = -(1/theta) D^-1/2 K D^-1/2 r: the residual of every
    // Ritz pair from one small Gram matrix, P^H P with P = D^-1/2 K D^-1/2 Q_next.
    const Matrix P = p.inv_sqrt_d.asDiagonal() *
                     p.shifted_times(w.sigma, Matrix(p.inv_sqrt_d.asDiagonal() * Q.middleCols(complete, b)));
    const Matrix gram = P.adjoint() * P;
    std::vector<int> in_window, in_carry;
    for(int k = 0; k < complete; ++k)
    {
      if(theta[k] == 0) continue;
      const double lambda = w.sigma + 1 / theta[k];
      const double residual = std::sqrt(std::max(0., std::real(coupling.col(k).dot(gram * coupling.col(k))))) /
                              std::abs(theta[k] * lambda);
      const bool converged = residual <= estimate_factor * p.tolerance_for(lambda, options.tolerance);
      if(!converged) continue;
      if(lambda > w.lo && lambda <= w.hi) in_window.push_back(k);
      else if(lambda > w.hi && lambda < w.carry_hi) in_carry.push_back(k);
    }
    report(static_cast<int>(in_window.size()));
    if(static_cast<int>(in_window.size()) > wanted)
      throw Numerical_failure("spectrum slicing: more converged eigenvalues in (" + std::to_string(w.lo) + ", " +
                              std::to_string(w.hi) + "] than the inertia count " + std::to_string(wanted));
    if(static_cast<int>(in_window.size()) == wanted)
    {
      // Accept on the true residual of A x = lambda D x.  The Ritz vectors are formed in
      // place of the basis' first columns.
      std::vector<int> all = in_window;
      all.insert(all.end(), in_carry.begin(), in_carry.end());
      const Eigen::Index count = static_cast<Eigen::Index>(all.size());
      Matrix S(complete, count);
      Eigen::VectorXd values(count), formed_theta(count), residuals, tolerances;
      for(Eigen::Index i = 0; i < count; ++i)
      {
        S.col(i) = T.col(all[i]);
        formed_theta[i] = theta[all[i]];
        values[i] = w.sigma + 1 / formed_theta[i];
      }
      turn_in_place(Q, complete, S);
      p.residuals_of_standard(values, Q.leftCols(count), options.tolerance, residuals, &tolerances);
      const Eigen::Index in_count = static_cast<Eigen::Index>(in_window.size());
      std::vector<Eigen::Index> accepted; // the window's pairs if all are accurate, the carried ones that are
      for(Eigen::Index i = 0; i < count; ++i)
        if(residuals[i] <= tolerances[i]) accepted.push_back(i);
      if(static_cast<Eigen::Index>(std::count_if(accepted.begin(), accepted.end(),
                                                 [&](Eigen::Index i) { return i < in_count; })) == in_count)
      {
        move_to_store(Q, m, accepted, in_count, values(accepted), residuals(accepted), tolerances(accepted), store,
                      window, carry);
        basis_used = std::max(basis_used, complete);
        return;
      }
      if(indefinite && !refine)
      {
        // Polishing works on the window's vectors in the basis, whose work is done.  The
        // estimate holds for the inexact operator only.
        const Eigen::Index polished = polish(p, w, Q, count, values, residuals, tolerances, deflate, solver,
                                             options.tolerance, accepted, applications);
        if(polished > 0)
        {
          move_to_store(Q, Q.cols(), accepted, polished, values(accepted), residuals(accepted), tolerances(accepted),
                        store, window, carry);
          basis_used = std::max(basis_used, complete);
          return;
        }
        throw Inaccurate_solves();
      }
      // The estimate was optimistic: ask for more, going on from the Ritz vectors formed
      // (a thick restart that keeps them; the columns dropped may be generated again, as
      // long as the estimate can still be made stricter).
      const bool stricter = estimate_factor > 1e-6;
      estimate_factor = std::max(estimate_factor * 1e-2, 1e-6);
      if(!exhausted) // else the failure below
      {
        if(stricter) budget += complete - count;
        complete = restart_on_formed(Q, H, S, formed_theta, complete, b);
        m = complete + b;
        next_check = std::min(max_basis, complete + 2 * b);
        continue;
      }
    }
    if(exhausted)
    {
      std::ostringstream msg;
      msg << "spectrum slicing: " << in_window.size() << " of " << wanted << " eigenvalues in (" << w.lo << ", "
          << w.hi << "] converged within " << (restarts ? "the operator applications allowed, " : "the Krylov basis limit ")
          << budget;
      throw Numerical_failure(msg.str());
    }
    if(full)
    {
      complete = thick_restart(Q, H, T, theta, complete, restart_keep, b);
      m = complete + b;
    }
    next_check = std::min(max_basis, complete + std::max(2 * b, (wanted - static_cast<int>(in_window.size())) / 2 + b));
  }
}

template void lanczos_window<double>(const Standard_eigenproblem&, Sparse_ldlt_solver&, const Window&,
                                     const Locked_columns<double>&, const Eigensolver_options&, std::mt19937_64&,
                                     Lanczos_workspace<double>&, Ritz_set&, Ritz_set&, Vector_store&, int&, int&,
                                     const std::function<void(int)>&);
template void lanczos_window<std::complex<double>>(
    const Basic_standard_eigenproblem<std::complex<double>>&, Hermitian_ldlt_solver&, const Window&,
    const Locked_columns<std::complex<double>>&, const Eigensolver_options&, std::mt19937_64&,
    Lanczos_workspace<std::complex<double>>&, Basic_ritz_set<std::complex<double>>&,
    Basic_ritz_set<std::complex<double>>&, Column_store<std::complex<double>>&, int&, int&,
    const std::function<void(int)>&);

} // namespace internal
} // namespace Model_reduction
} // namespace CGAL
