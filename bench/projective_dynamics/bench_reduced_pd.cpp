// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reduced and hyper-reduced Projective Dynamics against full PD: error against run time.
//
//   bench_reduced_pd [--cells 40] [--across 10] [--frames 200] [--threads N] [--iterations 10] [--modes all|reduced|hyper]
//
// (`--modes` runs only the reduced or only the hyper-reduced rows, after full PD, to keep a run short.)
//
// Scene: a cantilever of tetrahedra (cells x across x across cubes, six tets each; 2 m x 0.5 m x
// 0.5 m; 1e5 Pa, 1000 kg/m^3, h = 1/60 s, 10 iterations) pinned on its face x = 0 (hard pins in
// full PD, soft pins in the subspace), sagging and swinging under gravity for `frames` frames.
// Per configuration: the subspace sizes (k = 4 m columns, l projection columns and s sampled
// elements per group), the precomputation time, the median milliseconds per step split into
// local (positions of the used vertices, projections, fits), global (right-hand side and the
// k x k solves), and the full-position update U a (once per frame, timed apart), and the
// relative M-norm error sqrt(sum_t |q_t - q*_t|_M^2 / sum_t |q*_t - x|_M^2) against full PD over
// the frames (q* full PD, x rest).  Under each configuration: the precomputation saved to a
// file (`Reduced_simulator::save`) and loaded back (`Reduced_simulator::load`): the file's size,
// the save and load times against the precomputation's, and whether the loaded simulator's
// first step equals the original's bit for bit.

#include <CGAL/Projective_dynamics/Reduced_simulator.h>
#include <CGAL/Projective_dynamics/Simulator.h>
#include <CGAL/Projective_dynamics/make_models.h>
#include <CGAL/Projective_dynamics/mesh_generators.h>

#include "peak_memory.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

namespace PD = CGAL::Projective_dynamics;

namespace {
double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}
double m_norm2(const PD::Positions& d, const Eigen::VectorXd& m)
{
  double s = 0;
  for(Eigen::Index i = 0; i < d.rows(); ++i) s += m[i] * d.row(i).squaredNorm();
  return s;
}
typedef std::chrono::steady_clock Clock;
} // namespace

int main(int argc, char** argv)
{
  int cells = 40, across = 10, frames = 200, threads = 0, iterations = 10;
  std::string modes = "all";
  for(int i = 1; i + 1 < argc; i += 2)
  {
    const std::string a = argv[i];
    const int v = std::atoi(argv[i + 1]);
    if(a == "--modes") modes = argv[i + 1];
    else if(a == "--cells") cells = v;
    else if(a == "--across") across = v;
    else if(a == "--frames") frames = v;
    else if(a == "--threads") threads = v;
    else if(a == "--iterations") iterations = v;
    else
    {
      std::fprintf(stderr, "usage: %s [--cells 40] [--across 10] [--frames 200] [--threads N] [--iterations 10] [--modes all|reduced|hyper]\n", argv[0]);
      return 2;
    }
  }
  const PD::Tet_mesh mesh = PD::make_tet_rod(cells, across, 2.0, 2.0 * across / cells);
  const PD::Elastic_model model = PD::make_solid_model(mesh, PD::parameters::strain_stiffness(1e5).density(1e3));
  std::vector<int> pinned;
  for(std::size_t v = 0; v < mesh.points.size(); ++v)
    if(mesh.points[v][0] == 0) pinned.push_back(int(v));
  PD::Simulator_options o;
  o.time_step = 1.0 / 60;
  o.iterations = iterations;
  o.threads = threads;
  std::printf("cantilever: %zu tets, %zu vertices, %d frames, %d iterations, %d threads (of %u cores)\n",
              mesh.tetrahedra.size(), mesh.points.size(), frames, iterations,
              threads == 0 ? int(std::max(1u, std::thread::hardware_concurrency())) : threads,
              std::max(1u, std::thread::hardware_concurrency()));

  // Full PD: the truth.
  std::vector<PD::Positions> truth;
  std::vector<double> full_ms;
  double full_factor = 0;
  {
    PD::Simulator full(model, o);
    full.set_pinned_vertices(pinned);
    for(int t = 0; t < frames; ++t)
    {
      full.step();
      if(t == 0) full_factor = full.last_step_timings().factorization;
      else full_ms.push_back(1e3 * full.last_step_timings().total);
      truth.push_back(full.positions());
    }
  }
  const Eigen::VectorXd& m = model.masses();
  double motion = 0;
  for(const auto& q : truth) motion += m_norm2(q - model.rest_positions(), m);

  std::printf("%-14s %5s %5s %5s %10s %9s %9s %9s %9s %9s %8s\n", "mode", "k", "l", "s", "precomp(s)", "local", "global",
              "U a (ms)", "step(ms)", "frame(ms)", "error");
  std::printf("%-14s %5s %5s %5s %10.2f %9s %9s %9s %9.2f %9.2f %8s\n", "full PD", "-", "-", "-", full_factor, "", "", "",
              median(full_ms), median(full_ms), "0");
  std::fflush(stdout);

  struct Config
  {
    bool hyper;
    int samples, l, s;
  };
  const Config configs[] = {{false, 25, 0, 0},      {false, 50, 0, 0},       {false, 100, 0, 0},     {false, 150, 0, 0},
                            {true, 25, 60, 300},    {true, 50, 120, 1000},   {true, 100, 120, 1000}, {true, 150, 120, 1000},
                            {true, 150, 200, 2000}, {true, 150, 120, 3000}};
  for(const Config& c : configs)
  {
    if((modes == "reduced" && c.hyper) || (modes == "hyper" && !c.hyper)) continue;
    PD::Reduction_options r;
    r.samples = c.samples;
    r.hyper_reduction = c.hyper;
    if(c.hyper) r.projection_columns = c.l, r.sampled_elements = c.s, r.constraint_samples = std::max(60, c.l / 3 + 10); // tets: 3 independent candidates per sample
    PD::Reduced_simulator sim(model, o, r);
    const double precomputation = sim.last_step_timings().precomputation;
    // Saved and loaded: what a second run of the same scene pays instead of the precomputation.
    const std::string file = (std::filesystem::temp_directory_path() / "bench_reduced_pd.pdr").string();
    const auto save_start = Clock::now();
    sim.save(file);
    const double save_time = std::chrono::duration<double>(Clock::now() - save_start).count();
    const auto load_start = Clock::now();
    PD::Reduced_simulator loaded = PD::Reduced_simulator::load(model, file, o, r);
    const double load_time = std::chrono::duration<double>(Clock::now() - load_start).count();
    const double megabytes = double(std::filesystem::file_size(file)) / 1e6;
    std::filesystem::remove(file);
    sim.set_pinned_vertices(pinned);
    loaded.set_pinned_vertices(pinned);
    loaded.step();
    std::vector<double> local, global, update, total;
    double error = 0;
    PD::Positions first_step;
    for(int t = 0; t < frames; ++t)
    {
      sim.step();
      const auto start = Clock::now();
      const PD::Positions q = sim.positions();
      if(t == 0) first_step = q;
      const double u = 1e3 * std::chrono::duration<double>(Clock::now() - start).count();
      if(t > 0)
      {
        local.push_back(1e3 * sim.last_step_timings().local);
        global.push_back(1e3 * sim.last_step_timings().global);
        total.push_back(1e3 * sim.last_step_timings().total);
        update.push_back(u);
      }
      error += m_norm2(q - truth[std::size_t(t)], m);
    }
    std::printf("%-14s %5d %5s %5s %10.2f %9.2f %9.2f %9.2f %9.2f %9.2f %8.4f\n", c.hyper ? "hyper-reduced" : "reduced",
                4 * c.samples, c.hyper ? std::to_string(c.l).c_str() : "-",
                c.hyper ? std::to_string(std::min<std::size_t>(std::size_t(c.s), mesh.tetrahedra.size())).c_str() : "-",
                precomputation, median(local), median(global), median(update), median(total),
                median(total) + median(update), std::sqrt(error / motion));
    std::printf("  %-12s file %.1f MB, saved in %.3f s, loaded in %.3f s (precomputation %.2f s: %.0fx), first step %s\n", "saved:",
                megabytes, save_time, load_time, precomputation, precomputation / std::max(load_time, 1e-9),
                truth.empty() || frames < 1 ? "-" : (first_step == loaded.positions() ? "equal" : "DIFFERENT"));
    std::fflush(stdout);
  }
  std::printf("peak memory %.0f MB\n", tvf_bench::peak_memory_bytes() / 1e6);
  return 0;
}
