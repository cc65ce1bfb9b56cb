// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_INTERNAL_LANCZOS_WINDOW_H
#define CGAL_MODEL_REDUCTION_INTERNAL_LANCZOS_WINDOW_H

/// \file Lanczos_window.h
/// One window of spectrum slicing: a block shift-and-invert Lanczos run, thick-restarted
/// (`Eigensolver_options::restart_per_pair`), that finds exactly the pairs an inertia count
/// says lie in the window.

#include <CGAL/Model_reduction/Sparse_ldlt_solver.h>
#include <CGAL/Model_reduction/internal/Column_store.h>
#include <CGAL/Model_reduction/internal/Standard_eigenproblem.h>
#include <CGAL/Model_reduction/internal/huge_pages.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <complex>
#include <functional>
#include <memory>
#include <random>
#include <utility>
#include <vector>

namespace CGAL {
namespace Model_reduction {
namespace internal {

/// A converged pair with its true residual and the tolerance it met.
template <class Scalar>
struct Basic_ritz_pair
{
  typedef typename Float32_of<Scalar>::type Float32;
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, 1> Vector;
  double value;
  Scalar* data;      ///< a column of a `Column_store<Scalar>`: the standard form (`D^1/2 x`), unit length
  Eigen::Index size; ///< of the vector
  double residual, tolerance;
  /// Once no window needs the vector in double (`Eigensolver_options::float32_vectors`): a
  /// column of a `Column_store<Float32>`, the original variables (`x`) rounded; `data` is then null.
  Float32* rounded = nullptr;
  Eigen::Map<Vector> vector() const { return Eigen::Map<Vector>(data, size); }
};
template <class Scalar>
using Basic_ritz_set = std::vector<Basic_ritz_pair<Scalar>>;
typedef Basic_ritz_pair<double> Ritz_pair;
typedef Basic_ritz_set<double> Ritz_set;

// Krylov basis and projected matrix, kept from window to window of a chain: allocating
// them per window made page faults a fifth of the run.  Sized to the largest basis a window
// may reach: the restart limit when restarting, the unrestarted limit otherwise.
template <class Scalar>
struct Lanczos_workspace
{
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> Q, H;
  void reserve(Eigen::Index n, int columns)
  {
    if(Q.rows() != n || Q.cols() < columns) resize_in_huge_pages(Q, n, columns);
    if(H.rows() < columns) H.resize(columns, columns);
    H.topLeftCorner(columns, columns).setZero();
  }
};

struct Window
{
  double lo, hi;
  int wanted;      // pairs to find in (lo, hi]: the inertia count less the carried ones
  double carry_hi; // pairs converged in (hi, carry_hi) are kept for the next window
  double sigma;    // shift of the run
  bool refine = false; // one step of iterative refinement per solve with an indefinite factor
};

/// Thrown by `lanczos_window` when, without refinement, a window's pairs converged by the
/// Lanczos estimate but missed their tolerance on the true residual, and polishing the few
/// that missed (a solve shifted next to them, Rayleigh-Ritz on `A`) did not bring them
/// there: the unrefined solves of an indefinite factor are too inaccurate for this window.
struct Inaccurate_solves
{
};

/// Block classical Gram-Schmidt step: `C = Q_J^H Z`, then `Z -= Q_J C`, for the columns
/// `J = first .. first + count - 1` of `Q`; returns `C`.
Eigen::MatrixXd project_out_of_columns(const Eigen::Ref<const Eigen::MatrixXd>& Q, Eigen::Index first,
                                       Eigen::Index count, Eigen::MatrixXd& Z);
Eigen::MatrixXcd project_out_of_columns(const Eigen::Ref<const Eigen::MatrixXcd>& Q, Eigen::Index first,
                                        Eigen::Index count, Eigen::MatrixXcd& Z);

/// Converged vectors a window is kept orthogonal to, read where they are kept (columns of
/// `Column_store` blocks), as runs of adjacent columns: a copy into one matrix cost the
/// memory of ~50 vectors per chain (208 MB at the armadillo's 519k edges) and a pass over
/// them per window.
template <class Scalar>
class Locked_columns
{
public:
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> Matrix;
  Locked_columns(const std::vector<const Scalar*>& columns, Eigen::Index rows);
  Eigen::Index count() const { return count_; }
  /// `Z -= V (V^H Z)` for the locked vectors `V` (orthonormal), one Gram-Schmidt step.
  void project_out(Matrix& Z) const;

private:
  std::vector<std::pair<const Scalar*, Eigen::Index>> runs_; // first column, columns
  Eigen::Index rows_ = 0, count_ = 0;
};
extern template class Locked_columns<double>;
extern template class Locked_columns<std::complex<double>>;

// One block Lanczos run at shift `w.sigma` on the complement of `locked` (and the
// kernel).  Collects the converged pairs with eigenvalue in (lo, hi] into `window`
// (exactly `wanted` of them) and those in (hi, carry_hi) into `carry`, their vectors
// in `store`.  `solver` holds the factor of `A - w.sigma D`; a polish overwrites it
// (shifted next to a Ritz value), so after a return or a throw it may hold another shift.
// \throws Inaccurate_solves (only without `w.refine`), Numerical_failure.
template <class Scalar>
void lanczos_window(const Basic_standard_eigenproblem<Scalar>& p, Basic_sparse_ldlt_solver<Scalar>& solver,
                    const Window& w, const Locked_columns<Scalar>& locked, const Eigensolver_options& options,
                    std::mt19937_64& generator, Lanczos_workspace<Scalar>& space, Basic_ritz_set<Scalar>& window,
                    Basic_ritz_set<Scalar>& carry, Column_store<Scalar>& store, int& applications, int& basis_used,
                    const std::function<void(int)>& report);

} // namespace internal
} // namespace Model_reduction
} // namespace CGAL

#endif
