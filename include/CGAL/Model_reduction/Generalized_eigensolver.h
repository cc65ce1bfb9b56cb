// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_GENERALIZED_EIGENSOLVER_H
#define CGAL_MODEL_REDUCTION_GENERALIZED_EIGENSOLVER_H

/// \file Generalized_eigensolver.h
/// Lowest eigenpairs of `A x = lambda D x` with `A` sparse symmetric positive
/// semi-definite and `D` diagonal positive, by spectrum slicing: windows of the
/// spectrum, each with an `LDL^T` whose inertia counts its eigenvalues and a short
/// block shift-and-invert Lanczos run that must find exactly that many; a known kernel
/// deflated, every returned pair checked on its true residual.
///
/// `A` may also be complex Hermitian (`D` still real): an operator that commutes with a
/// complex structure (the n-field energy, `z -> i z` per face) has every eigenvalue twice in
/// its real form, which the complex form has once, with half the unknowns -- half the
/// vectors to find and orthogonalise, a quarter of the matrix entries to factor.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <complex>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace CGAL {
namespace Model_reduction {

/// Reported to the progress callback while the solver runs.
struct Eigensolver_progress
{
  int converged = 0;  ///< wanted pairs converged so far (estimate)
  int wanted = 0;     ///< pairs asked for
  int basis_size = 0; ///< Krylov basis size
};

struct Eigensolver_options
{
  /// Vectors per block.  With spectrum slicing, 4 needed the fewest solves and the
  /// least time (rocker arm, 520 Crouzeix-Raviart pairs: block 16 9.0 s, 8 6.6 s,
  /// 4 5.6 s, 2 6.0 s); must exceed the largest multiplicity to be found in one run.
  int block_size = 4;
  /// Spectrum slicing: about this many eigenvalues per window (each window one
  /// short Lanczos run and two `LDL^T` factorisations; completeness is proved per
  /// window by the inertia).  The Krylov basis of a window grows to about 3x its
  /// count, so the orthogonalisation per pair grows with the window.  Measured with
  /// two chains (500 Crouzeix-Raviart pairs, medians of 4 runs in turn): rocker arm,
  /// 50 took 0.91x the time of 100 and 35 took 1.05x that of 50; bunny, 50 and 100
  /// equally fast.
  int slice_size = 50;
  /// Spectrum slicing: a window's Krylov basis is restarted (thick restart: cut to its Ritz
  /// vectors nearest the shift, about 1.1 per wanted pair, and grown again) once it holds
  /// this many vectors per wanted pair, plus 8 blocks; values below 1 count as 1; 0 never
  /// restarts.  Unrestarted, a window's basis grows to about 3.7 vectors per pair, and the
  /// two running windows' bases are the largest part of the solve's working set.  Measured
  /// with 1.3 against 0 (500 + 500 pairs, two threads, runs alternated): bunny (104k
  /// Crouzeix-Raviart unknowns alone), peaks 638-651 MB against 752-756 MB, in the same
  /// time; armadillo (both problems, 519k edges, three pairs), peaks 3.19-3.28 GB against
  /// 3.62-3.76 GB, 168, 212 and 234 s against 185, 238 and 194 s (614 s against 617 s).
  double restart_per_pair = 1.3;
  /// Required relative residual of every returned pair, in the mass-weighted norms:
  /// `|D^-1/2 (A x - l D x)| / (l |D^1/2 x|)`.  This is the residual of the symmetric
  /// standard form `D^-1/2 A D^-1/2`, so it bounds the relative error of the
  /// eigenvalue; unlike the plain Euclidean ratio it does not depend on how uneven
  /// the masses are.  Where double precision cannot reach it -- the floor is about
  /// `64 eps lambda_max / l`, with `lambda_max` bounded by Gershgorin, which matters for the
  /// lowest eigenvalues of meshes with 100k+ vertices -- the floor is required instead.
  double tolerance = 1e-10;
  std::uint64_t seed = 1;
  /// Spectrum slicing: requests of at least two windows are cut, at an inertia-counted
  /// shift, into this many chains of windows solved at once (0: one per hardware
  /// thread), each with one BLAS thread (OpenBLAS's count is restored afterwards).
  /// The progress callback is still called on the caller's thread only.  A thread that
  /// runs out of chains cuts the top off the running chain with the most work left, at an
  /// inertia-counted shift, and runs it: where the cuts fall then depends on timing, so
  /// with several threads the signs of the vectors and the bases chosen in the spaces of
  /// repeated eigenvalues may differ between runs (the values, the spaces and the checks do
  /// not).  One thread gives the same pairs for the same `seed`.
  int threads = 0;
  /// Small problems (up to `dense_size` unknowns, or asking for a third of the
  /// space) are solved densely (LAPACK) unless this is false.
  bool allow_dense = true;
  int dense_size = 1500;
  /// Return the vectors rounded to float32 (`Eigenpairs::vectors_float32`; `vectors` is
  /// then empty), for a basis stored in float32: half the memory of the vectors, during
  /// the solve as well as after it.  Spectrum slicing rounds each converged vector as soon
  /// as no later window is kept orthogonal to it and no join between chains needs it;
  /// the vectors a window works with stay double, so the values, residuals and checks are
  /// those of the double solve (the residuals reported are the double vectors', before
  /// rounding).  The dense path rounds at the end.
  bool float32_vectors = false;
  /// Called after every Rayleigh-Ritz step.
  std::function<void(const Eigensolver_progress&)> progress;
};

/// Outcome of a completeness check (see `check_completeness`).
struct Completeness_check
{
  double shift = 0;        ///< `tau`, placed in a gap of the checked spectrum
  int expected = 0;        ///< kernel dimension + checked eigenvalues below `tau`
  int inertia = 0;         ///< eigenvalues below `tau` by Sylvester's law of inertia
  bool passed() const { return expected == inertia; }
};

namespace internal {
/// The scalar a vector of `Scalar`s is rounded to for `Eigensolver_options::float32_vectors`.
template <class Scalar>
struct Float32_of
{
  typedef float type;
};
template <>
struct Float32_of<std::complex<double>>
{
  typedef std::complex<float> type;
};
} // namespace internal

/// Eigenpairs in ascending order (the values real); `vectors` are `D`-orthonormal (in the
/// Hermitian inner product `x^H D y` when `Scalar` is `std::complex<double>`).
template <class Scalar>
struct Basic_eigenpairs
{
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> Matrix; ///< of the vectors
  /// Of the vectors rounded to float32 (`std::complex<float>` for complex ones).
  typedef Eigen::Matrix<typename internal::Float32_of<Scalar>::type, Eigen::Dynamic, Eigen::Dynamic> Float32_matrix;

  Eigen::VectorXd values;
  Matrix vectors;
  /// With `Eigensolver_options::float32_vectors`: the vectors, each entry (each part of a
  /// complex one) rounded to float32.
  Float32_matrix vectors_float32;
  Eigen::VectorXd residuals;    ///< relative residual of each pair
  int basis_size = 0;           ///< Krylov vectors used
  int operator_applications = 0; ///< columns passed through the shift-invert solve
  /// Time the solver's threads spent on this problem, summed over the threads (with
  /// `lowest_eigenpairs_of_each`, the share of the joint run that was this problem's).
  double thread_seconds = 0;
  /// Every eigenvalue that was not returned is at least this (infinity when the whole
  /// space was returned).  Established by the completeness check when it ran.
  double complete_below = 0;
  /// The inertia check behind `complete_below` (`shift == 0`, `inertia == 0` if it did not run).
  Completeness_check completeness;
};

/// Eigenpairs of a real symmetric problem.
typedef Basic_eigenpairs<double> Eigenpairs;
/// Eigenpairs of a complex Hermitian problem: real values, complex vectors.
typedef Basic_eigenpairs<std::complex<double>> Complex_eigenpairs;

/// The `count` smallest eigenvalues of `A x = lambda D x` on the `D`-orthogonal
/// complement of `kernel` (columns: a basis of the null space of `A`, may be empty).
/// \throws Numerical_failure if a window does not converge to `tolerance` (after one
///         retry with wider blocks) or its pairs disagree with the inertia count.
Eigenpairs lowest_eigenpairs(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& D, int count,
                             const Eigen::MatrixXd& kernel, const Eigensolver_options& options = {});

/// The same for `A` complex Hermitian positive semi-definite (both triangles stored) and `D`
/// real: for operators with a complex structure, whose real form has every eigenvalue twice
/// (`(x, J x)`); each complex pair `(lambda, z)` stands for the real pairs of `z` and `i z`.
/// The options keep their meaning, counted in complex vectors (`block_size` complex vectors a
/// block: as the multiplicities are halved too, it finds what twice as many real ones would).
/// The kernel's columns are complex (one per pair of the real form's kernel).
Complex_eigenpairs lowest_eigenpairs(const Eigen::SparseMatrix<std::complex<double>>& A, const Eigen::VectorXd& D,
                                     int count, const Eigen::MatrixXcd& kernel, const Eigensolver_options& options = {});

/// One eigenproblem of `lowest_eigenpairs_of_each`: `A x = lambda D x` outside `kernel`,
/// its `count` lowest pairs (complex ones are solved one at a time, by `lowest_eigenpairs`).
template <class Scalar>
struct Basic_eigenproblem_request
{
  const Eigen::SparseMatrix<Scalar>& A;
  const Eigen::VectorXd& D;
  int count;
  const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& kernel;
};
/// A real symmetric problem of `lowest_eigenpairs_of_each`.
typedef Basic_eigenproblem_request<double> Eigenproblem_request;

/// `lowest_eigenpairs` of several problems at once: the windows of all of them are queued
/// for one pool of threads (`options.threads`), so that a thread that finishes its part of
/// one problem works on another's instead of waiting.  The same pairs, to the same
/// tolerance and with the same completeness check, as one call per problem; progress is
/// reported over all of them.
/// \throws Invalid_input for a bad request (checked before any work), as `lowest_eigenpairs`.
std::vector<Eigenpairs> lowest_eigenpairs_of_each(const std::vector<Eigenproblem_request>& problems,
                                                  const Eigensolver_options& options = {});

/// Checks that `values` (ascending, computed eigenvalues of `A x = lambda D x` outside a
/// kernel of dimension `kernel_dimension`, starting at the lowest) contain every
/// eigenvalue below a shift placed in the widest relative gap among
/// `values[first_gap ..]` (default: the last gap).
Completeness_check check_completeness(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& D,
                                      const Eigen::VectorXd& values, int kernel_dimension, int first_gap = -1);
/// The same for `A` complex Hermitian (each eigenvalue of the complex form counted once).
Completeness_check check_completeness(const Eigen::SparseMatrix<std::complex<double>>& A, const Eigen::VectorXd& D,
                                      const Eigen::VectorXd& values, int kernel_dimension, int first_gap = -1);

/// Number of eigenvalues of `A x = lambda D x` below `tau` (Sylvester's law of inertia:
/// the negative pivots of an `LDL^T` factorisation of `A - tau D`).
int count_eigenvalues_below(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& D, double tau);
/// The same for `A` complex Hermitian (`LDL^H`, `D` real): each eigenvalue of the complex form
/// counted once, half the count of its real form.
int count_eigenvalues_below(const Eigen::SparseMatrix<std::complex<double>>& A, const Eigen::VectorXd& D, double tau);

} // namespace Model_reduction
} // namespace CGAL

#endif
