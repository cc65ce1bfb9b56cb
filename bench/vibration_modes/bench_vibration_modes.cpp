// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Vibration modes and compressed modes: time, memory and quality per mode.
//
//   bench_vibration_modes --scalar MESH [--mu 0.1124] [--modes 10] [--kernel free|orthogonal] [--start lowest|random]
//     The scalar problem of compressed manifold modes (cotangent stiffness, lumped mass,
//     the mesh centred and divided by its coordinates' standard deviation), objective
//     sum_i phi_i^T K phi_i + mu sum_j m_j |phi_ij|: the anchors' measurements are in these units.
//     As there, modes need not be orthogonal to the constants (--kernel free), unless asked.
//   bench_vibration_modes --shell MESH [--modes 50] [--mu-scale 4] [--bending 1e-3] [--trace 1]
//                         [--first n] [--working-sets 0|1]
//     Compressed modes of the mesh as a shell (scaled to unit area), mu = mu-scale times the
//     last ordinary mode's eigenvalue over sqrt(area); --first n computes only the first n
//     of them (same mu), --working-sets 0 runs ICCM on the whole mesh throughout.
//   bench_vibration_modes --sizes MESH [--subdivisions 2]
//     Ordinary shell modes: time per mode against k and the mesh size (Loop subdivision).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <CGAL/Discrete_shells/make_shell_energy.h>
#include <CGAL/Vibration_modes/compressed_modes.h>
#include <CGAL/Vibration_modes/lowest_vibration_modes.h>

#include "peak_memory.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <string>

namespace DS = CGAL::Discrete_shells;
namespace VM = CGAL::Vibration_modes;
typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;
using tvf_bench::peak_memory_bytes;
using tvf_bench::reset_peak_memory;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

bool read(const std::string& path, Mesh& mesh, int subdivisions = 0)
{
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || mesh.is_empty())
  {
    std::cerr << "cannot read " << path << "\n";
    return false;
  }
  for(int i = 0; i < subdivisions; ++i) CGAL::Subdivision_method_3::Loop_subdivision(mesh);
  return true;
}

// Centred and divided by the standard deviation of all coordinates (as compressed manifold
// modes' scripts normalise their meshes).
Eigen::VectorXd normalised(Eigen::VectorXd x)
{
  const Eigen::Index n = x.size() / 3;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for(Eigen::Index v = 0; v < n; ++v) centre += x.segment<3>(3 * v);
  centre /= double(n);
  for(Eigen::Index v = 0; v < n; ++v) x.segment<3>(3 * v) -= centre;
  return x / std::sqrt(x.squaredNorm() / double(x.size()));
}

double max_orthogonality_error(const VM::Mode_problem& p, const Eigen::MatrixXd& full_modes, bool to_kernel)
{
  Eigen::MatrixXd U(p.H.rows(), full_modes.cols());
  for(Eigen::Index i = 0; i < U.rows(); ++i)
    U.row(i) = full_modes.row(p.free_unknowns.empty() ? i : p.free_unknowns[std::size_t(i)]);
  const Eigen::MatrixXd G = U.transpose() * p.mass.asDiagonal() * U;
  double e = (G - Eigen::MatrixXd::Identity(G.rows(), G.cols())).cwiseAbs().maxCoeff();
  if(to_kernel && p.kernel.cols() > 0) e = std::max(e, (p.kernel.transpose() * p.mass.asDiagonal() * U).cwiseAbs().maxCoeff());
  return e;
}

void print_modes(const VM::Mode_problem& p, const VM::Modes& modes, bool to_kernel = true)
{
  std::printf("| mode | objective | energy u^T H u | support | ICCM iterations | ADMM iterations |\n|---|---|---|---|---|---|\n");
  for(Eigen::Index i = 0; i < modes.objectives.size(); ++i)
    std::printf("| %ld | %.6g | %.6g | %.1f %% | %d | %d |\n", long(i + 1), modes.objectives[i], modes.energies[i],
                100 * modes.support_fractions[i], modes.outer_iterations[i], modes.inner_iterations[i]);
  std::printf("objective sum %.6g; max |U^T M U - I|%s = %.2e\n", modes.objectives.sum(),
              to_kernel ? ", |K^T M U|" : "", max_orthogonality_error(p, modes.vectors, to_kernel));
}

double step_tolerance = VM::Compressed_mode_options().step_tolerance;
double admm_tolerance = VM::Compressed_mode_options().admm_tolerance;
bool trace = false;    // --trace 1: every ICCM iteration to stderr
bool working_sets = true; // --working-sets 0: ICCM on the whole mesh throughout
int first_modes = 0;       // --first n: only the first n of the k compressed modes (mu from lambda_k)
double fixed_mu = 0;  // --shell: --mu overrides --mu-scale

int scalar(const std::string& path, double mu, int k, bool free, bool random)
{
  Mesh mesh;
  if(!read(path, mesh)) return 1;
  const VM::Mode_problem p = VM::laplacian_mode_problem(normalised(DS::stacked_positions(mesh)), DS::mesh_triangles(mesh));
  std::printf("scalar problem of %s: %ld vertices, mu %g, %d modes, %s\n", path.c_str(), long(p.H.rows()), mu, k,
              free ? "constants allowed in the modes (as compressed manifold modes)" : "modes orthogonal to the constants");
  reset_peak_memory();
  auto t0 = std::chrono::steady_clock::now();
  VM::Compressed_mode_options o;
  o.sparsity_weight = mu;
  o.orthogonal_to_kernel = !free;
  o.step_tolerance = step_tolerance;
  o.admm_tolerance = admm_tolerance;
  o.working_sets = working_sets;
  if(random) o.start = VM::Compressed_mode_start::random;
  const VM::Modes modes = VM::compressed_modes(p, k, o);
  const double total = seconds_since(t0);
  print_modes(p, modes, !free);
  std::printf("time %.2f s (the ordinary modes that start it included), peak memory %.0f MB\n", total,
              peak_memory_bytes() / 1e6);
  return 0;
}

int shell(const std::string& path, int k, double mu_scale, double bending)
{
  Mesh mesh;
  if(!read(path, mesh)) return 1;
  Eigen::VectorXd x = DS::stacked_positions(mesh);
  const auto triangles = DS::mesh_triangles(mesh);
  {
    const DS::Shell_energy unit(x, triangles, {1, 1, 0});
    x /= std::sqrt(unit.lumped_mass().sum() / 3); // unit area
  }
  reset_peak_memory();
  auto t0 = std::chrono::steady_clock::now();
  const DS::Shell_energy W(x, triangles, {1, 1, bending});
  const VM::Mode_problem p = VM::shell_mode_problem(W);
  const double t_assembly = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  const VM::Modes ordinary = VM::lowest_vibration_modes(p, k);
  const double t_ordinary = seconds_since(t0);
  std::fprintf(stderr, "assembly %.1f s, %d ordinary modes %.1f s\n", t_assembly, k, t_ordinary);
  const double mu = fixed_mu > 0 ? fixed_mu : mu_scale * ordinary.energies[k - 1]; // area 1: sqrt(area) = 1
  std::printf("shell %s: %ld vertices, k_b %g, mu %g (%g x lambda_%d), %d modes\n", path.c_str(),
              long(num_vertices(mesh)), bending, mu, mu_scale, k, k);
  t0 = std::chrono::steady_clock::now();
  VM::Compressed_mode_options o;
  o.sparsity_weight = mu;
  o.step_tolerance = step_tolerance;
  o.admm_tolerance = admm_tolerance;
  o.working_sets = working_sets;
  o.ordinary_modes = &ordinary; // computed above to choose mu: not again
  int last_mode = -1;
  o.progress = [&](const VM::Compressed_mode_progress& s) {
    if(s.mode != last_mode)
      std::fprintf(stderr, "mode %d of %d started at %.1f s\n", s.mode + 1, s.count, seconds_since(t0));
    if(trace)
      std::fprintf(stderr, "  ICCM %d: ADMM %d, objective %.8g, support %.1f %%, %.2f s\n", s.outer_iteration,
                   s.inner_iterations, s.objective, 100 * s.support_fraction, seconds_since(t0));
    last_mode = s.mode;
    return true;
  };
  const VM::Modes modes = VM::compressed_modes(p, first_modes > 0 ? std::min(first_modes, k) : k, o);
  const double t_compressed = seconds_since(t0);
  print_modes(p, modes);
  std::printf("assembly %.2f s, ordinary modes %.2f s, compressed modes %.2f s (given the ordinary modes), peak memory %.0f MB\n",
              t_assembly, t_ordinary, t_compressed, peak_memory_bytes() / 1e6);
  return 0;
}

int sizes(const std::string& path, int subdivisions)
{
  std::printf("| vertices | unknowns | k | time | per mode | max residual | peak memory |\n|---|---|---|---|---|---|---|\n");
  for(int s = 0; s <= subdivisions; ++s)
  {
    Mesh mesh;
    if(!read(path, mesh, s)) return 1;
    Eigen::VectorXd x = DS::stacked_positions(mesh);
    const auto triangles = DS::mesh_triangles(mesh);
    x /= std::sqrt(DS::Shell_energy(x, triangles, {1, 1, 0}).lumped_mass().sum() / 3);
    const VM::Mode_problem p = VM::shell_mode_problem(DS::Shell_energy(x, triangles, {1, 1, 1e-3}));
    for(int k : {10, 50, 200})
    {
      reset_peak_memory();
      auto t0 = std::chrono::steady_clock::now();
      const VM::Modes modes = VM::lowest_vibration_modes(p, k);
      const double t = seconds_since(t0);
      std::printf("| %ld | %ld | %d | %.2f s | %.1f ms | %.1e | %.0f MB |\n", long(num_vertices(mesh)), long(p.H.rows()), k, t,
                  1e3 * t / k, modes.residuals.maxCoeff(), peak_memory_bytes() / 1e6);
      std::fflush(stdout);
    }
  }
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  std::map<std::string, std::string> a;
  for(int i = 1; i + 1 < argc; i += 2) a[argv[i]] = argv[i + 1];
  auto get = [&](const std::string& key, const std::string& fallback) { return a.count(key) ? a[key] : fallback; };
  try
  {
    step_tolerance = std::stod(get("--step-tolerance", std::to_string(step_tolerance)));
    admm_tolerance = std::stod(get("--admm-tolerance", std::to_string(admm_tolerance)));
    trace = get("--trace", "0") == "1";
    working_sets = get("--working-sets", "1") == "1";
    first_modes = std::stoi(get("--first", "0"));
    if(a.count("--shell")) fixed_mu = std::stod(get("--mu", "0"));
    if(a.count("--scalar"))
      return scalar(a["--scalar"], std::stod(get("--mu", "0.1124")), std::stoi(get("--modes", "10")),
                    get("--kernel", "free") == "free", get("--start", "lowest") == "random");
    if(a.count("--shell"))
      return shell(a["--shell"], std::stoi(get("--modes", "50")), std::stod(get("--mu-scale", "4")),
                   std::stod(get("--bending", "1e-3")));
    if(a.count("--sizes")) return sizes(a["--sizes"], std::stoi(get("--subdivisions", "2")));
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  std::cerr << "usage: bench_vibration_modes --scalar MESH [--mu m] [--modes k] | --shell MESH [--modes k] "
               "[--mu-scale s] [--bending kb] [--first n] [--working-sets 0|1] | --sizes MESH [--subdivisions s]\n";
  return 2;
}
