// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// SLEPc runs on the package's scalar eigenproblems `A x = l diag(d) x`, for
// bench_spectral --against-slepc: spectrum slicing and Krylov-Schur shift-and-invert in
// this process (1 rank), and spectrum slicing in child processes under mpirun.  Only
// this file's .cpp sees PETSc; built when TVF_WITH_SLEPC is on.

#ifndef TVF_BENCH_SLEPC_RUNS_H
#define TVF_BENCH_SLEPC_RUNS_H

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <string>
#include <vector>

namespace tvf_bench {

enum class Slepc_method { slicing, krylov_schur };

struct Slepc_settings
{
  Slepc_method method = Slepc_method::slicing;
  double lower = 0, upper = 0; ///< slicing: the interval
  int nev = 0;                 ///< Krylov-Schur: pairs wanted (target -1)
  int partitions = 1;          ///< slicing: sub-intervals solved in parallel (one per rank)
  std::string extra_options;   ///< appended to the options database (--slepc-options)
};

/// SLEPc's answer: eigenvalues ascending, each with the package's relative residual
/// `|D^-1/2 (A x - l D x)| / (l |D^1/2 x|)` of its returned vector.
struct Slepc_outcome
{
  bool ok = false;
  std::string error;
  double seconds = 0;        ///< set-up (factorisations) + solve + eigenvectors; no file I/O
  double launch_seconds = 0; ///< mpirun runs: the whole child run, start-up and files included
  /// Resident memory the run added at its peak over what its process held at the start
  /// (the matrices loaded), summed over the ranks; -1 if unknown.
  double peak_bytes = -1;
  Eigen::VectorXd values, residuals;
};

/// The options database of a run (also printed by the bench, to repeat it by hand).
std::string slepc_options(const Slepc_settings& settings);

/// SLEPc initialised for the lifetime of the object (one at a time).  The environment is
/// saved before MPI starts: a singleton MPI_Init adds variables that would make the
/// children's mpirun join this process instead of starting its own job.
class Slepc_session
{
public:
  Slepc_session();
  ~Slepc_session();
  Slepc_session(const Slepc_session&) = delete;
  Slepc_session& operator=(const Slepc_session&) = delete;

  /// In this process, on one rank.  `kernel`'s columns are deflated (Krylov-Schur).
  Slepc_outcome solve(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& d, const Eigen::MatrixXd& kernel,
                      const Slepc_settings& settings) const;

  /// Spectrum slicing in `ranks` processes: `mpirun` (a command, words split at spaces)
  /// starts this executable with --slepc-child on the matrices written to a temporary
  /// folder, with one BLAS thread per rank.
  Slepc_outcome solve_with_mpirun(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& d,
                                  const Slepc_settings& settings, int ranks, const std::string& mpirun) const;

private:
  std::vector<std::string> environment_;
};

/// The child side of `solve_with_mpirun` (bench_spectral --slepc-child DIR): reads DIR,
/// solves, writes DIR/result.txt on rank 0.  Returns the exit code.
int slepc_child_main(const std::string& dir);

} // namespace tvf_bench

#endif
