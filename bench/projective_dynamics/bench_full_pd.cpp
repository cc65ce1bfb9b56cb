// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Full-space Projective Dynamics: time per step against the mesh size.
//
//   bench_full_pd [--threads N] [--iterations 10] [--steps 8] [--max-tets 110000]
//
// Scene: a box of tetrahedra (a grid, six tets per cube) pinned on its face x = 0, sagging under
// gravity (1e6 Pa, 1000 kg/m^3, h = 1/60 s).  Per size: tetrahedra, vertices, factorisation
// time, and the median over the steps (after two warm-up steps) of the milliseconds per step,
// split into the local step (projections) and the global step (right-hand sides and solves).

#include <CGAL/Model_reduction/Sparse_spd_solver.h>
#include <CGAL/Projective_dynamics/Simulator.h>
#include <CGAL/Projective_dynamics/make_models.h>
#include <CGAL/Projective_dynamics/mesh_generators.h>

#include "peak_memory.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace PD = CGAL::Projective_dynamics;

namespace {
double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
} // namespace

int main(int argc, char** argv)
{
  int threads = 0, iterations = 10, steps = 8, max_tets = 110000;
  for(int i = 1; i + 1 < argc; i += 2)
  {
    const std::string a = argv[i];
    const int v = std::atoi(argv[i + 1]);
    if(a == "--threads") threads = v;
    else if(a == "--iterations") iterations = v;
    else if(a == "--steps") steps = v;
    else if(a == "--max-tets") max_tets = v;
    else
    {
      std::fprintf(stderr, "usage: %s [--threads N] [--iterations 10] [--steps 8] [--max-tets 110000]\n", argv[0]);
      return 2;
    }
  }
  std::printf("full-space Projective Dynamics, %d iterations per step, %d threads (of %u cores), %s\n", iterations,
              threads == 0 ? int(std::max(1u, std::thread::hardware_concurrency())) : threads,
              std::max(1u, std::thread::hardware_concurrency()), CGAL::Model_reduction::Sparse_spd_solver::backend_name());
  std::printf("%9s %9s %12s %12s %12s %12s %10s\n", "tets", "vertices", "factor (ms)", "local (ms)", "global (ms)",
              "step (ms)", "peak (MB)");
  const int grids[][3] = {{5, 5, 7}, {10, 10, 10}, {16, 16, 16}, {20, 20, 20}, {26, 26, 25}, {34, 34, 34}};
  for(const auto& g : grids)
  {
    if(6 * g[0] * g[1] * g[2] > max_tets) break;
    const PD::Tet_mesh mesh = PD::make_tet_box(g[0], g[1], g[2], {0, 0, 0}, {1.0 * g[0] / g[2], 1.0 * g[1] / g[2], 1.0});
    PD::Simulator sim(PD::make_solid_model(mesh, PD::parameters::strain_stiffness(1e6).density(1e3)),
                      PD::parameters::time_step(1.0 / 60).number_of_iterations(iterations).number_of_threads(threads));
    std::vector<int> pinned;
    for(std::size_t v = 0; v < mesh.points.size(); ++v)
      if(mesh.points[v][0] == 0) pinned.push_back(int(v));
    sim.set_pinned_vertices(pinned);
    std::vector<double> local, global, total;
    for(int s = 0; s < steps + 2; ++s)
    {
      sim.step();
      if(s < 2) continue;
      local.push_back(1e3 * sim.last_step_timings().local);
      global.push_back(1e3 * sim.last_step_timings().global);
      total.push_back(1e3 * sim.last_step_timings().total);
    }
    std::printf("%9zu %9zu %12.1f %12.2f %12.2f %12.2f %10.0f\n", mesh.tetrahedra.size(), mesh.points.size(),
                1e3 * sim.last_step_timings().factorization, median(local), median(global), median(total),
                tvf_bench::peak_memory_bytes() / 1e6);
    std::fflush(stdout);
  }
  return 0;
}
