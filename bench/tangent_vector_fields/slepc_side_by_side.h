// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// bench_spectral --against-slepc (issue 15): the package's eigensolver and SLEPc on the
// same matrices in the same run.  Built when TVF_WITH_SLEPC is on.

#ifndef TVF_BENCH_SLEPC_SIDE_BY_SIDE_H
#define TVF_BENCH_SLEPC_SIDE_BY_SIDE_H

#include "slepc_runs.h"

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Hodge_solver.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace tvf_bench {

struct Side_by_side_mesh
{
  std::string name;
  /// The mesh's operators (null if it cannot be read); loaded when its turn comes.
  std::function<std::shared_ptr<const CGAL::Tangent_vector_fields::Hodge_solver>()> load;
};

struct Side_by_side_request
{
  std::vector<Side_by_side_mesh> meshes;
  int exact = 500, coexact = 500; ///< pairs per problem
  int ranks = 2;                  ///< of the mpirun slicing run
  std::string mpirun = "mpirun";  ///< command (words split at spaces)
  std::string extra_options;      ///< appended to every SLEPc run's options database
  /// Also SLEPc's Krylov-Schur (the slowest: 246 s on the bunny against 96 s for slicing
  /// under mpirun); `--no-krylov-schur` leaves it out on meshes where it would take an hour.
  bool krylov_schur = true;
  /// The package's settings (its eigensolver's are taken from them, as the basis does).
  CGAL::Tangent_vector_fields::Basis_options package;
};

/// Prints one table per mesh and problem and the totals; returns the exit code
/// (non-zero if a run failed or disagreed in its count).
int run_against_slepc(const Side_by_side_request& request);

} // namespace tvf_bench

#endif
