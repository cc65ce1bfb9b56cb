// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Benchmark of the spectral basis (issue 3): set-up time of 500 exact + 500 coexact
// eigenfields next to the thesis' Table 1 (Java + MUMPS, 2012 laptop) and this
// machine's targets, each time with its error: the largest relative eigenpair
// residual and the Sylvester completeness check of both eigenproblems.  Then a sweep
// of the basis size on the first mesh, and compression rate against relative L2(MX)
// error on the rocker arm.
//
// Usage: bench_spectral [data-dir] [--meshes rocker,bunny,armadillo] [--exact N] [--coexact N]
//                       [--no-sweep] [--no-compression] [--compression-size D]
//                       [--threads T]  (eigensolver threads; 0: one per core)
//                       [--restart-per-pair R]  (Krylov vectors per pair before a window restarts; 0: never)
//                       [--float32]  (the set-up stores the eigenfunctions in float32, rounding them
//                                     while it solves)
//                       [--default-allocator]  (without Model_reduction::keep_freed_memory(), which the tvf tool calls)
//        bench_spectral --against-slepc [data-dir] [--meshes ...] [--exact N] [--coexact N]
//                       [--ranks R] [--mpirun CMD] [--slepc-options "..."] [--no-krylov-schur]
// --against-slepc: the package's eigensolver next to SLEPc on the same matrices
// (bench/tangent_vector_fields/slepc_side_by_side.cpp; needs a build with -DTVF_WITH_SLEPC=ON).

#include "bench_meshes.h"
#include "peak_memory.h"
#ifdef TVF_HAS_SLEPC
#include "slepc_side_by_side.h"
#endif

#include <CGAL/Model_reduction/keep_freed_memory.h>
#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <random>
#include <sstream>

namespace TVF = CGAL::Tangent_vector_fields;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

struct Source
{
  std::string key, file;
  int subdivisions;
  double thesis_seconds, target_seconds;
};

std::shared_ptr<TVF::Hodge_solver> load(const std::string& dir, const Source& s, int& faces)
{
  return tvf_bench::load_mesh(dir, s.file, s.subdivisions, faces);
}

double peak_memory_gb() { return tvf_bench::peak_memory_bytes() / (1024. * 1024. * 1024.); }

std::string completeness(const TVF::Basis_report& r)
{
  std::ostringstream s;
  s << r.exact_inertia << "/" << r.exact_expected << " " << r.coexact_inertia << "/" << r.coexact_expected
    << ((r.exact_inertia == r.exact_expected && r.coexact_inertia == r.coexact_expected) ? " ok" : " MISSED");
  return s.str();
}

// Fields to compress: smooth ones of several kinds and noise.
std::vector<std::pair<std::string, Eigen::VectorXd>> test_fields(const TVF::Operator_matrices& ops)
{
  const TVF::Intrinsic_mesh& m = ops.mesh();
  const int nf = m.number_of_faces();
  // Bounding box scale, for functions of position.
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for(int v = 0; v < m.number_of_vertices(); ++v)
    for(int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], m.position(v)[k]);
      hi[k] = std::max(hi[k], m.position(v)[k]);
    }
  const double size = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  auto u = [&](const std::array<double, 3>& p, int k) { return (p[k] - lo[k]) / size; };
  std::vector<std::pair<std::string, Eigen::VectorXd>> fields;
  {
    Eigen::VectorXd x(2 * nf);
    for(int f = 0; f < nf; ++f)
    {
      const auto ab = m.to_frame(f, {1.0, 0.5, 0.25});
      x[2 * f] = ab[0];
      x[2 * f + 1] = ab[1];
    }
    fields.push_back({"constant 3D vector, projected", x});
  }
  {
    Eigen::VectorXd f(m.number_of_vertices()), g = Eigen::VectorXd::Zero(m.number_of_edges());
    for(int v = 0; v < m.number_of_vertices(); ++v)
      f[v] = std::sin(6 * u(m.position(v), 0)) * std::cos(4 * u(m.position(v), 1));
    for(int e = 0; e < m.number_of_edges(); ++e)
    {
      const auto& p = m.position(m.edge_vertices(e)[0]);
      const auto& q = m.position(m.edge_vertices(e)[1]);
      const std::array<double, 3> mid = {(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2};
      if(!m.is_boundary_edge(e)) g[e] = std::cos(5 * u(mid, 2)) * u(mid, 0);
    }
    const Eigen::VectorXd x = ops.G() * f + ops.rotate(ops.G_star() * g);
    fields.push_back({"smooth G f + J G* g", x});
  }
  {
    std::mt19937 rng(3);
    std::normal_distribution<double> normal;
    Eigen::VectorXd x(2 * nf);
    for(int i = 0; i < 2 * nf; ++i) x[i] = normal(rng);
    fields.push_back({"white noise", x});
  }
  return fields;
}

} // namespace

int main(int argc, char** argv)
{
#ifdef TVF_HAS_SLEPC
  // A rank of the mpirun run that --against-slepc starts: nothing else to do.
  if(argc == 3 && !std::strcmp(argv[1], "--slepc-child")) return tvf_bench::slepc_child_main(argv[2]);
#endif
  bool against_slepc = false;
  int ranks = 2;
  std::string mpirun = "mpirun", slepc_options;
  std::string dir = TVF_SHARED_DATA_DIR;
  std::string which = "rocker,bunny,armadillo";
  int exact = 500, coexact = 500, compression_size = 2000, threads = 0;
  double restart_per_pair = TVF::Basis_options().restart_per_pair;
  bool sweep = true, compression = true, default_allocator = false, krylov_schur = true;
  TVF::Eigenfunction_precision precision = TVF::Eigenfunction_precision::float64;
  for(int i = 1; i < argc; ++i)
  {
    if(!std::strcmp(argv[i], "--meshes") && i + 1 < argc) which = argv[++i];
    else if(!std::strcmp(argv[i], "--exact") && i + 1 < argc) exact = std::atoi(argv[++i]);
    else if(!std::strcmp(argv[i], "--coexact") && i + 1 < argc) coexact = std::atoi(argv[++i]);
    else if(!std::strcmp(argv[i], "--compression-size") && i + 1 < argc) compression_size = std::atoi(argv[++i]);
    else if(!std::strcmp(argv[i], "--threads") && i + 1 < argc) threads = std::atoi(argv[++i]);
    else if(!std::strcmp(argv[i], "--restart-per-pair") && i + 1 < argc) restart_per_pair = std::atof(argv[++i]);
    else if(!std::strcmp(argv[i], "--no-sweep")) sweep = false;
    else if(!std::strcmp(argv[i], "--float32")) precision = TVF::Eigenfunction_precision::float32;
    else if(!std::strcmp(argv[i], "--default-allocator")) default_allocator = true;
    else if(!std::strcmp(argv[i], "--no-compression")) compression = false;
    else if(!std::strcmp(argv[i], "--against-slepc")) against_slepc = true;
    else if(!std::strcmp(argv[i], "--ranks") && i + 1 < argc) ranks = std::atoi(argv[++i]);
    else if(!std::strcmp(argv[i], "--mpirun") && i + 1 < argc) mpirun = argv[++i];
    else if(!std::strcmp(argv[i], "--slepc-options") && i + 1 < argc) slepc_options = argv[++i];
    else if(!std::strcmp(argv[i], "--no-krylov-schur")) krylov_schur = false;
    else dir = argv[i];
  }
  // As the tvf tool does (Model_reduction::keep_freed_memory.h).
  if(!default_allocator) CGAL::Model_reduction::keep_freed_memory();
  const std::vector<Source> sources = {{"rocker", "rocker-arm.obj", 0, 43, 4},
                                       {"bunny", "stanford-bunny.obj", 0, 184, 18},
                                       {"armadillo", "armadillo.obj", 1, 1246, 120}};
  if(against_slepc)
  {
#ifdef TVF_HAS_SLEPC
    tvf_bench::Side_by_side_request slepc_request;
    for(const Source& s : sources)
      if(which.find(s.key) != std::string::npos)
        slepc_request.meshes.push_back({s.key, [&dir, s]() -> std::shared_ptr<const TVF::Hodge_solver> {
                                          int faces = 0;
                                          return load(dir, s, faces);
                                        }});
    slepc_request.exact = exact;
    slepc_request.coexact = coexact;
    slepc_request.ranks = ranks;
    slepc_request.mpirun = mpirun;
    slepc_request.extra_options = slepc_options;
    slepc_request.krylov_schur = krylov_schur;
    slepc_request.package.threads = threads;
    slepc_request.package.restart_per_pair = restart_per_pair;
    return tvf_bench::run_against_slepc(slepc_request);
#else
    (void)ranks;
    (void)krylov_schur;
    std::fprintf(stderr, "bench_spectral was built without SLEPc: --against-slepc needs cmake -DTVF_WITH_SLEPC=ON "
                         "and libslepc-real-dev\n");
    return 2;
#endif
  }

  std::printf("Spectral basis benchmark: %d exact + %d coexact eigenfields (+ harmonic), one run each, seconds.\n"
              "set-up = operators + both eigenproblems + harmonic fields; exact, coexact = their shares of the\n"
              "eigenproblems' wall time (solved together on one pool of threads; shared out by thread time);\n"
              "residual = largest "
              "|D^-1/2 (A x - l D x)| / (l |D^1/2 x|);\ncomplete = inertia/expected of the exact and the coexact\n"
              "problem at the last window boundary (Sylvester: eigenvalues below it / pairs found + kernel);\n"
              "peak = largest resident memory of the process during the set-up (GB, the mesh loaded before it\n"
              "included); basis = eigenfunctions and harmonic fields kept (GB); eigenfunctions stored in %s;\n"
              "Krylov bases restarted at %g vectors per pair (0: never)\n\n",
              exact, coexact, precision == TVF::Eigenfunction_precision::float32 ? "float32" : "double", restart_per_pair);
  std::printf("%-10s %8s %4s | %7s %7s %7s %7s %8s | %6s %6s | %7s %7s %7s | %9s %s\n", "mesh", "faces", "dimH", "ops",
              "exact", "coexact", "harm.", "set-up", "peak", "basis", "thesis", "target", "speedup", "residual",
              "complete");
  for(const Source& s : sources)
  {
    if(which.find(s.key) == std::string::npos) continue;
    int faces = 0;
    auto solver = load(dir, s, faces);
    if(!solver) continue;
    tvf_bench::reset_peak_memory();
    const auto start = std::chrono::steady_clock::now();
    const auto& ops = solver->operators();
    ops.G(), ops.G_star_interior(), ops.W(), ops.W_star(), ops.field_masses();
    const double ops_seconds = seconds_since(start);
    TVF::Basis_options basis_options;
    basis_options.threads = threads;
    basis_options.restart_per_pair = restart_per_pair;
    TVF::Basis_request request = TVF::Basis_request::per_type(exact, coexact);
    request.precision = precision;
    TVF::Eigenfield_basis basis(solver, request, basis_options);
    const double total = seconds_since(start);
    const double peak = peak_memory_gb();
    const TVF::Basis_report& r = basis.report();
    std::printf("%-10s %8d %4d | %7.2f %7.2f %7.2f %7.2f %8.2f | %6.2f %6.2f | %7.0f %7.0f %7.1fx | %9.1e %s%s\n",
                s.key.c_str(), faces, basis.number_of_harmonic(), ops_seconds, r.exact_seconds, r.coexact_seconds,
                r.harmonic_seconds, total, peak, basis.memory_bytes() / 1e9, s.thesis_seconds, s.target_seconds,
                s.thesis_seconds / total,
                r.max_residual, completeness(r).c_str(), total <= s.target_seconds ? "" : "  (target missed)");
    std::fflush(stdout);
  }

  const Source& rocker = sources[0];
  if(sweep)
  {
    std::printf("\nBasis size sweep on %s (lowest d, merged): time, peak memory and basis memory (GB), residual,\n"
                "completeness, and agreement of the first 50 eigenvalues with the largest basis\n",
                rocker.file.c_str());
    std::printf("%6s %8s %6s %6s %9s %14s %12s\n", "d", "seconds", "peak", "basis", "residual", "complete", "eig. diff");
    int faces = 0;
    Eigen::VectorXd reference;
    for(int d : {2000, 1000, 500, 200, 100})
    {
      auto solver = load(dir, rocker, faces);
      if(!solver) break;
      tvf_bench::reset_peak_memory();
      const auto start = std::chrono::steady_clock::now();
      TVF::Basis_options sweep_options;
      sweep_options.restart_per_pair = restart_per_pair;
      TVF::Eigenfield_basis basis(solver, TVF::Basis_request::lowest(d), sweep_options);
      const double t = seconds_since(start), peak = peak_memory_gb();
      if(reference.size() == 0) reference = basis.eigenvalues().head(50);
      const Eigen::VectorXd head = basis.eigenvalues().head(50);
      double diff = 0;
      for(int k = 0; k < 50; ++k)
        if(reference[k] > 0) diff = std::max(diff, std::abs(head[k] - reference[k]) / reference[k]);
      std::printf("%6d %8.2f %6.2f %6.2f %9.1e %14s %12.1e\n", d, t, peak, basis.memory_bytes() / 1e9,
                  basis.report().max_residual, completeness(basis.report()).c_str(), diff);
      std::fflush(stdout);
    }
  }

  if(compression)
  {
    int faces = 0;
    auto solver = load(dir, rocker, faces);
    if(!solver) return 1;
    const auto start = std::chrono::steady_clock::now();
    TVF::Eigenfield_basis basis(solver, TVF::Basis_request::lowest(compression_size));
    const double t = seconds_since(start);
    std::printf("\nCompression on %s (%d faces, 2 doubles per face): basis of %d lowest eigenfields in %.1f s\n"
                "ratio = 2 nf / k; error = relative L2(MX) error of the field rebuilt from its k lowest coefficients\n",
                rocker.file.c_str(), faces, compression_size, t);
    const auto fields = test_fields(solver->operators());
    std::printf("%6s %8s %8s", "k", "ratio", "bits/f");
    for(const auto& f : fields) std::printf(" | %-30s", f.first.c_str());
    std::printf("\n");
    Eigen::MatrixXd X(fields[0].second.size(), static_cast<Eigen::Index>(fields.size()));
    for(std::size_t j = 0; j < fields.size(); ++j) X.col(static_cast<Eigen::Index>(j)) = fields[j].second;
    for(int k : {25, 50, 100, 200, 500, 1000, 1100, 1500, 2000})
    {
      if(k > basis.size()) break;
      const TVF::Compressed_fields c = basis.compress(X, k);
      std::printf("%6d %8.1f %8.2f", k, c.ratio, c.bits_per_face);
      for(Eigen::Index j = 0; j < c.relative_errors.size(); ++j) std::printf(" | %-30.2e", c.relative_errors[j]);
      std::printf("\n");
    }
  }
  return 0;
}
