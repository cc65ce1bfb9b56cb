// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "slepc_side_by_side.h"
#include "peak_memory.h"

#include <CGAL/Model_reduction/Generalized_eigensolver.h>
#include <CGAL/Tangent_vector_fields/internal/scalar_eigenproblem.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace tvf_bench {

namespace {

namespace TVF = CGAL::Tangent_vector_fields;
namespace MR = CGAL::Model_reduction;
typedef Eigen::SparseMatrix<double> Sparse_matrix;

// The package asks for this many pairs beyond the requested count, to place the
// slicing interval's upper end in a gap of its spectrum.
constexpr int extra_pairs = 4;
// A gap between consecutive eigenvalues narrower than this (relative) is taken for a
// repeated eigenvalue: no interval end is put there.
constexpr double smallest_gap = 1e-6;

// The package's residual, |D^-1/2 (A x - l D x)| / (l |D^1/2 x|), one column at a time.
double relative_residual(const Sparse_matrix& A, const Eigen::VectorXd& d, double lambda, const Eigen::VectorXd& x)
{
  const Eigen::VectorXd r = A * x - lambda * d.cwiseProduct(x);
  return r.cwiseQuotient(d.cwiseSqrt()).norm() / (std::abs(lambda) * d.cwiseSqrt().cwiseProduct(x).norm());
}

// One method's answer on one problem, as the table shows it.
struct Row
{
  std::string method;
  Slepc_outcome outcome; // the package's answer is put in the same form
  std::string note;
  bool slicing = false; // must find exactly the interval's eigenvalues (the others at least as many)
};

Row run_package(const TVF::internal::Scalar_eigenproblem& p, int count, const TVF::Basis_options& settings)
{
  Row row{"package Model_reduction::lowest_eigenpairs", {}, {}};
  try
  {
    reset_peak_memory();
    const double resident = resident_bytes();
    const auto start = std::chrono::steady_clock::now();
    const MR::Eigenpairs pairs = MR::lowest_eigenpairs(p.A, p.d, count, p.kernel,
                                                         TVF::internal::eigensolver_options(settings));
    row.outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if(resident >= 0) row.outcome.peak_bytes = peak_memory_bytes() - resident;
    row.outcome.values = pairs.values;
    row.outcome.residuals.resize(pairs.values.size());
    for(Eigen::Index i = 0; i < pairs.values.size(); ++i)
      row.outcome.residuals[i] = relative_residual(p.A, p.d, pairs.values[i], pairs.vectors.col(i));
    row.outcome.ok = true;
  }
  catch(const std::exception& e)
  {
    row.outcome.error = e.what();
  }
  return row;
}

// Both problems of a mesh in one `Model_reduction::lowest_eigenpairs_of_each` call, as the spectral basis
// solves them: one pool of threads for the two.  The outcome holds the seconds and the peak
// of the call; `values` and `residuals` those of the problems one after the other.  With
// `float32`, the vectors are returned rounded, as for a basis stored in float32 (`residuals`
// then holds the largest relative distance of their Rayleigh quotients to the eigenvalues).
Slepc_outcome run_package_joint(const TVF::internal::Scalar_eigenproblem& exact, int exact_count,
                                const TVF::internal::Scalar_eigenproblem& coexact, int coexact_count, bool float32,
                                const TVF::Basis_options& settings, std::vector<Eigen::VectorXd>& values)
{
  Slepc_outcome outcome;
  try
  {
    reset_peak_memory();
    const double resident = resident_bytes();
    MR::Eigensolver_options options = TVF::internal::eigensolver_options(settings);
    options.float32_vectors = float32;
    const auto start = std::chrono::steady_clock::now();
    const std::vector<MR::Eigenpairs> pairs = MR::lowest_eigenpairs_of_each(
        {{exact.A, exact.d, exact_count, exact.kernel}, {coexact.A, coexact.d, coexact_count, coexact.kernel}}, options);
    outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if(resident >= 0) outcome.peak_bytes = peak_memory_bytes() - resident;
    const TVF::internal::Scalar_eigenproblem* problem[] = {&exact, &coexact};
    double residual = 0;
    for(std::size_t k = 0; k < 2; ++k)
    {
      const MR::Eigenpairs& e = pairs[k];
      values.push_back(e.values);
      for(Eigen::Index i = 0; i < e.values.size(); ++i)
        if(float32) // the rounded vector's Rayleigh quotient: its residual says nothing (amplified rounding)
        {
          const Eigen::VectorXd x = e.vectors_float32.col(i).cast<double>();
          const double quotient = x.dot(problem[k]->A * x) / x.dot(problem[k]->d.cwiseProduct(x));
          residual = std::max(residual, std::abs(quotient - e.values[i]) / e.values[i]);
        }
        else
          residual = std::max(residual, relative_residual(problem[k]->A, problem[k]->d, e.values[i], e.vectors.col(i)));
    }
    outcome.residuals = Eigen::VectorXd::Constant(1, residual);
    outcome.ok = true;
  }
  catch(const std::exception& e)
  {
    outcome.error = e.what();
  }
  return outcome;
}

// (lambda_1 / 2, upper) and how many eigenvalues it holds: the upper end halfway into
// the first gap at or after the `wanted`-th eigenvalue of the package's (ascending) values.
struct Interval
{
  double lower = 0, upper = 0;
  int count = 0;
};

Interval slicing_interval(const Eigen::VectorXd& values, int wanted)
{
  Interval interval;
  const int n = static_cast<int>(values.size());
  interval.lower = values[0] / 2;
  int m = wanted;
  while(m < n && values[m] - values[m - 1] <= smallest_gap * values[m - 1]) ++m;
  if(m < n)
    interval.upper = (values[m - 1] + values[m]) / 2;
  else // the package returned the whole spectrum, or no gap among its extra pairs
  {
    m = n;
    interval.upper = values[n - 1] * (1 + 1e-3);
  }
  interval.count = m;
  return interval;
}

struct Comparison
{
  int compared = 0;
  double residual = 0, difference = 0;
};

// The first `count` pairs of `outcome` against the package's.
Comparison compare(const Slepc_outcome& outcome, const Eigen::VectorXd& reference, int count)
{
  Comparison c;
  c.compared = std::min<int>(count, static_cast<int>(outcome.values.size()));
  for(int i = 0; i < c.compared; ++i)
  {
    c.residual = std::max(c.residual, outcome.residuals[i]);
    c.difference = std::max(c.difference, std::abs(outcome.values[i] - reference[i]) / reference[i]);
  }
  return c;
}

// Seconds of each method over the problems so far (a failure voids the method's total) and
// its largest peak memory.
struct Totals
{
  std::vector<std::string> methods;
  std::vector<double> seconds, peaks;
  bool complete = true; // false once the package failed on a problem (no rows to add)
  double joint_seconds = 0, joint_peak = -1; // both problems in one call (NaN: it failed)
  double float32_seconds = 0, float32_peak = -1; // the same, vectors returned in float32

  void add(const std::vector<Row>& rows)
  {
    if(methods.empty())
      for(const Row& r : rows)
      {
        methods.push_back(r.method);
        seconds.push_back(0);
        peaks.push_back(-1);
      }
    for(std::size_t i = 0; i < rows.size(); ++i)
    {
      seconds[i] = rows[i].outcome.ok ? seconds[i] + rows[i].outcome.seconds : std::numeric_limits<double>::quiet_NaN();
      peaks[i] = std::max(peaks[i], rows[i].outcome.peak_bytes);
    }
  }
};

// Index of the fastest SLEPc method (rows after the package's), -1 if all failed.
int best_slepc(const std::vector<double>& seconds)
{
  int best = -1;
  for(int i = 1; i < static_cast<int>(seconds.size()); ++i)
    if(!std::isnan(seconds[i]) && (best < 0 || seconds[i] < seconds[best])) best = i;
  return best;
}

void print_totals(const std::string& title, const Totals& totals)
{
  if(!totals.complete)
  {
    std::printf("%s: no totals (the package failed on a problem)\n", title.c_str());
    return;
  }
  if(totals.methods.empty()) return;
  std::printf("%s:", title.c_str());
  for(std::size_t i = 0; i < totals.methods.size(); ++i)
    if(std::isnan(totals.seconds[i])) std::printf("%s %s failed", i ? ";" : "", totals.methods[i].c_str());
    else std::printf("%s %s %.2f s (peak %.2f GB)", i ? ";" : "", totals.methods[i].c_str(), totals.seconds[i],
                     totals.peaks[i] / 1e9);
  if(std::isnan(totals.joint_seconds)) std::printf("; package, both problems in one call, failed");
  else std::printf("; package, both problems in one call %.2f s (peak %.2f GB)", totals.joint_seconds, totals.joint_peak / 1e9);
  const int best = best_slepc(totals.seconds);
  if(best > 0 && !std::isnan(totals.seconds[0]))
  {
    std::printf("\n  => SLEPc best (%s) / package = %.2f", totals.methods[best].c_str(),
                totals.seconds[best] / totals.seconds[0]);
    if(!std::isnan(totals.joint_seconds))
      std::printf("; / package in one call = %.2f (the spectral basis's way)", totals.seconds[best] / totals.joint_seconds);
    std::printf("\n  => peak memory, SLEPc best / package in one call = %.2f", totals.peaks[best] / totals.joint_peak);
    if(!std::isnan(totals.float32_seconds))
      std::printf("; / package in one call, vectors in float32 = %.2f (%.2f s, peak %.2f GB)",
                  totals.peaks[best] / totals.float32_peak, totals.float32_seconds, totals.float32_peak / 1e9);
    std::printf("\n");
  }
  else
    std::printf("\n  => no ratio (the package or every SLEPc run failed)\n");
}

// Solves one problem every way, prints its table, returns false if a run failed or
// found a different number of eigenvalues than the package.
bool compare_on(const Slepc_session& slepc, const Side_by_side_request& request, const std::string& mesh_name,
                const TVF::internal::Scalar_eigenproblem& p, const std::string& title, int wanted, Totals& totals,
                Eigen::VectorXd& package_values)
{
  wanted = std::min(wanted, p.available());
  std::printf("\n%s, %s: n = %ld, %d pairs\n", mesh_name.c_str(), title.c_str(), static_cast<long>(p.A.rows()), wanted);
  if(wanted <= 0) return true;
  std::vector<Row> rows;
  rows.push_back(run_package(p, std::min(wanted + extra_pairs, p.available()), request.package));
  const Slepc_outcome package = rows[0].outcome; // a copy: rows grows below
  package_values = package.values;
  if(!package.ok)
  {
    std::printf("  package failed: %s\n", package.error.c_str());
    totals.complete = false;
    return false;
  }
  const Interval interval = slicing_interval(package.values, wanted);
  std::printf("  (package asked for %ld pairs; slicing interval (%.6g, %.6g) of the unit-area problem holds %d)\n",
              static_cast<long>(package.values.size()), interval.lower, interval.upper, interval.count);

  Slepc_settings slicing;
  slicing.lower = interval.lower;
  slicing.upper = interval.upper;
  slicing.extra_options = request.extra_options;
  rows.push_back({"SLEPc slicing, 1 rank", slepc.solve(p.A, p.d, p.kernel, slicing), {}, true});

  Slepc_settings parallel = slicing;
  parallel.partitions = request.ranks;
  const std::string mpirun_name = "SLEPc slicing, mpirun -np " + std::to_string(request.ranks);
  rows.push_back({mpirun_name, slepc.solve_with_mpirun(p.A, p.d, parallel, request.ranks, request.mpirun), {}, true});
  if(rows.back().outcome.ok)
  {
    char note[80];
    std::snprintf(note, sizeof note, "(%.2f s with start-up and files)", rows.back().outcome.launch_seconds);
    rows.back().note = note;
  }

  if(request.krylov_schur)
  {
    Slepc_settings krylov_schur;
    krylov_schur.method = Slepc_method::krylov_schur;
    krylov_schur.nev = wanted + 10;
    krylov_schur.extra_options = request.extra_options;
    rows.push_back({"SLEPc Krylov-Schur, 1 rank", slepc.solve(p.A, p.d, p.kernel, krylov_schur), {}});
  }

  bool all_right = true;
  std::printf("  %-30s %8s %9s %8s %9s %6s %10s %10s\n", "method", "seconds", "/package", "peak GB", "/package",
              "found", "residual", "eig. diff");
  for(std::size_t i = 0; i < rows.size(); ++i)
  {
    const Row& row = rows[i];
    if(!row.outcome.ok)
    {
      std::printf("  %-30s FAILED: %s\n", row.method.c_str(), row.outcome.error.c_str());
      all_right = false;
      continue;
    }
    const Comparison c = compare(row.outcome, package.values, interval.count);
    std::string note = row.note;
    const bool exact_count = row.slicing ? static_cast<int>(row.outcome.values.size()) == interval.count
                                                           : c.compared == interval.count;
    if(!exact_count)
    {
      note += std::string(note.empty() ? "" : " ") + "(" + std::to_string(row.outcome.values.size()) + " found, " +
              std::to_string(interval.count) + " expected)";
      all_right = false;
    }
    char difference[16] = "-";
    if(i > 0) std::snprintf(difference, sizeof difference, "%.1e", c.difference);
    std::printf("  %-30s %8.2f %9.2f %8.3f %9.2f %6ld %10.1e %10s%s%s\n", row.method.c_str(), row.outcome.seconds,
                row.outcome.seconds / package.seconds, row.outcome.peak_bytes / 1e9,
                row.outcome.peak_bytes / package.peak_bytes, static_cast<long>(row.outcome.values.size()), c.residual,
                difference, note.empty() ? "" : " ", note.c_str());
  }
  std::vector<double> seconds;
  for(const Row& row : rows) seconds.push_back(row.outcome.ok ? row.outcome.seconds : std::numeric_limits<double>::quiet_NaN());
  const int best = best_slepc(seconds);
  if(best > 0)
    std::printf("  SLEPc best / package: %.2f (%s)\n", seconds[best] / package.seconds, rows[best].method.c_str());
  totals.add(rows);
  std::fflush(stdout);
  return all_right;
}

int run_all(const Side_by_side_request& request)
{
  const Slepc_session slepc; // first: it saves the environment before MPI adds to it
  const char* threads = std::getenv("OPENBLAS_NUM_THREADS");
  Slepc_settings slicing, parallel, krylov_schur;
  slicing.extra_options = parallel.extra_options = krylov_schur.extra_options = request.extra_options;
  parallel.partitions = request.ranks;
  krylov_schur.method = Slepc_method::krylov_schur;
  krylov_schur.nev = 0; // printed as N+10
  std::printf(
    "Package eigensolver against SLEPc on the same matrices: the basis' exact (W, vertex masses) and coexact\n"
    "(W*, interior-edge masses) problems scaled to unit area, %d + %d lowest pairs.  seconds: set-up\n"
    "(factorisations) + solve + eigenvectors; residual: largest |D^-1/2 (A x - l D x)| / (l |D^1/2 x|) of the\n"
    "returned vectors, computed by the bench; peak GB: resident memory the run added at its peak (summed over\n"
    "the ranks; the matrices already loaded); eig. diff: largest relative difference to the package's\n"
    "eigenvalues; found: pairs returned (the package asks for %d extra to place the interval's end).\n"
    "Residual and difference are over the pairs in the slicing interval.  BLAS threads: OPENBLAS_NUM_THREADS=%s\n"
    "for the package and the 1-rank runs, 1 per rank under mpirun.  Package: Krylov basis restarted at %g\n"
    "vectors per pair (0: never).  SLEPc options:\n"
    "  slicing, interval (lambda_1/2, gap after lambda_N): %s\n"
    "  slicing, mpirun -np %d:                             %s\n"
    "  Krylov-Schur, target -1, constants deflated:       %s\n",
    request.exact, request.coexact, extra_pairs, threads ? threads : "unset", request.package.restart_per_pair,
    slepc_options(slicing).c_str(),
    request.ranks, slepc_options(parallel).c_str(),
    request.krylov_schur ? slepc_options(krylov_schur).c_str() : "(left out: --no-krylov-schur)");

  bool all_right = true;
  Totals all;
  for(const Side_by_side_mesh& mesh : request.meshes)
  {
    const auto solver = mesh.load();
    if(!solver)
    {
      all_right = false;
      continue;
    }
    const TVF::Operator_matrices& ops = solver->operators();
    const double area = ops.face_areas().sum();
    const std::string name = mesh.name + " (" + std::to_string(ops.mesh().number_of_faces()) + " faces)";
    Totals totals;
    const auto exact = TVF::internal::scalar_eigenproblem(ops, TVF::Eigenfield_type::exact, area);
    Eigen::VectorXd one_call[2];
    all_right &= compare_on(slepc, request, name, exact, "exact, W phi = lambda M phi", request.exact, totals, one_call[0]);
    const auto coexact = TVF::internal::scalar_eigenproblem(ops, TVF::Eigenfield_type::coexact, area);
    all_right &= compare_on(slepc, request, name, coexact, "coexact, W* psi = mu M* psi", request.coexact, totals,
                            one_call[1]);
    // The same counts as the one-problem runs above (with their extra pairs).
    const int exact_count = std::min(std::min(request.exact, exact.available()) + extra_pairs, exact.available());
    const int coexact_count = std::min(std::min(request.coexact, coexact.available()) + extra_pairs, coexact.available());
    std::vector<Eigen::VectorXd> joint_values;
    const Slepc_outcome joint = run_package_joint(exact, exact_count, coexact, coexact_count, false, request.package, joint_values);
    if(joint.ok)
    {
      // Against the one-problem runs' eigenvalues (other random starts, other cuts).
      double difference = 0;
      for(int k = 0; k < 2; ++k)
        for(Eigen::Index i = 0; i < std::min(joint_values[k].size(), one_call[k].size()); ++i)
          difference = std::max(difference, std::abs(joint_values[k][i] - one_call[k][i]) / one_call[k][i]);
      std::printf("\n%s, both problems in one call (Model_reduction::lowest_eigenpairs_of_each): %.2f s, peak %.3f GB, residual %.1e, "
                  "eig. diff to the one-problem runs %.1e\n",
                  name.c_str(), joint.seconds, joint.peak_bytes / 1e9, joint.residuals[0], difference);
      totals.joint_seconds = joint.seconds;
      totals.joint_peak = joint.peak_bytes;
      std::vector<Eigen::VectorXd> rounded_values;
      const Slepc_outcome rounded = run_package_joint(exact, exact_count, coexact, coexact_count, true, request.package, rounded_values);
      if(rounded.ok)
        std::printf("%s, the same with the vectors returned in float32: %.2f s, peak %.3f GB, Rayleigh quotients of "
                    "the rounded vectors within %.1e of the eigenvalues\n",
                    name.c_str(), rounded.seconds, rounded.peak_bytes / 1e9, rounded.residuals[0]);
      else
        std::printf("%s, the same with the vectors returned in float32 FAILED: %s\n", name.c_str(), rounded.error.c_str());
      totals.float32_seconds = rounded.ok ? rounded.seconds : std::numeric_limits<double>::quiet_NaN();
      totals.float32_peak = rounded.peak_bytes;
      all_right &= rounded.ok;
    }
    else
    {
      std::printf("\n%s, both problems in one call FAILED: %s\n", name.c_str(), joint.error.c_str());
      totals.joint_seconds = std::numeric_limits<double>::quiet_NaN();
      all_right = false;
    }
    std::printf("\n");
    print_totals(mesh.name + ", exact + coexact", totals);
    all.complete &= totals.complete;
    for(std::size_t i = 0; i < totals.methods.size(); ++i)
    {
      if(all.methods.size() <= i)
      {
        all.methods.push_back(totals.methods[i]);
        all.seconds.push_back(0);
        all.peaks.push_back(-1);
      }
      all.seconds[i] += totals.seconds[i];
      all.peaks[i] = std::max(all.peaks[i], totals.peaks[i]);
    }
    all.joint_seconds += totals.joint_seconds;
    all.joint_peak = std::max(all.joint_peak, totals.joint_peak);
    all.float32_seconds += totals.float32_seconds;
    all.float32_peak = std::max(all.float32_peak, totals.float32_peak);
  }
  if(request.meshes.size() > 1) print_totals("\nall meshes, exact + coexact", all);
  return all_right ? 0 : 1;
}

} // namespace

int run_against_slepc(const Side_by_side_request& request)
{
  if(request.meshes.empty())
  {
    std::fprintf(stderr, "no mesh selected (--meshes takes rocker, bunny, armadillo)\n");
    return 1;
  }
  if(request.ranks < 1)
  {
    std::fprintf(stderr, "--ranks must be at least 1\n");
    return 1;
  }
  try
  {
    return run_all(request);
  }
  catch(const std::exception& e) // SLEPc's start, a mesh's operators
  {
    std::fprintf(stderr, "bench_spectral --against-slepc: %s\n", e.what());
    return 1;
  }
}

} // namespace tvf_bench
