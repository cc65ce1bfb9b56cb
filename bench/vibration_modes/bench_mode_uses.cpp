// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The uses of vibration modes: the reduced linear simulation's error against the full one
// and both run times as k grows, and the time of one drag in elastic modelling.
//
//   bench_mode_uses MESH [--ks 5,10,20,50,100,200] [--steps 200] [--drags 20000]
//     The mesh scaled to unit area, a shell (bending 1e-3) standing on its pinned lowest 5 %
//     along y, under gravity from rest (the load of examples/vibration_modes/reduced_simulation).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Vibration_modes/Elastic_deformer.h>
#include <CGAL/Vibration_modes/linear_simulation.h>
#include <CGAL/Vibration_modes/vibration_modes.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

namespace VM = CGAL::Vibration_modes;
typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex_index;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int run(const std::string& path, std::vector<int> ks, int steps, int drags)
{
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || mesh.is_empty())
  {
    std::cerr << "cannot read " << path << "\n";
    return 1;
  }
  const double area = CGAL::Polygon_mesh_processing::area(mesh);
  for(auto v : vertices(mesh)) mesh.point(v) = CGAL::ORIGIN + (mesh.point(v) - CGAL::ORIGIN) / std::sqrt(area);
  double low = 1e300, high = -1e300;
  for(auto v : vertices(mesh)) low = std::min(low, mesh.point(v).y()), high = std::max(high, mesh.point(v).y());
  std::vector<Vertex_index> feet;
  Vertex_index top = *vertices(mesh).begin();
  for(auto v : vertices(mesh))
  {
    if(mesh.point(v).y() <= low + 0.05 * (high - low)) feet.push_back(v);
    if(mesh.point(v).y() > mesh.point(top).y()) top = v;
  }
  const auto np = VM::parameters::bending_stiffness(1e-3).pinned_vertices(feet);
  const VM::Mode_problem p = VM::mesh_mode_problem(mesh, np);
  std::sort(ks.begin(), ks.end());
  auto t0 = std::chrono::steady_clock::now();
  const VM::Modes modes = VM::vibration_modes(mesh, ks.back(), np);
  std::printf("%s: %ld vertices, %zu pinned; %d modes in %.2f s\n\n", path.c_str(), long(num_vertices(mesh)), feet.size(),
              ks.back(), seconds_since(t0));

  const double lambda = modes.energies[0];
  VM::Linear_simulation_options o;
  o.time_step = 2 * M_PI / std::sqrt(lambda) / 20;
  o.steps = steps;
  o.output_every = 10;
  o.rayleigh_mass = 0.02 * std::sqrt(lambda);
  o.force = Eigen::VectorXd::Zero(p.full_size);
  for(std::size_t i = 0; i < p.free_unknowns.size(); ++i)
    if(p.free_unknowns[i] % 3 == 1) o.force[p.free_unknowns[i]] = -0.3 * lambda * p.mass[Eigen::Index(i)];
  VM::Linear_trajectory full;
  double t_full = 1e300;
  for(int run = 0; run < 3; ++run)
  {
    t0 = std::chrono::steady_clock::now();
    full = VM::full_linear_simulation(p, o);
    t_full = std::min(t_full, seconds_since(t0));
  }
  std::printf("Reduced linear simulation (%d steps of h = T1/20, a frame kept every 10 steps) against the full one "
              "(CHOLMOD, %.0f ms with its factorisation: %.2f ms per step); times are the fastest of three runs:\n\n",
              steps, 1e3 * t_full, 1e3 * t_full / steps);
  std::printf("| k | relative M-norm error | reduced time | set-up (B^T H B, B^T M B) | per step (frames expanded) | speed-up |\n"
              "|---|---|---|---|---|---|\n");
  VM::Linear_simulation_options setup_only = o;
  setup_only.steps = 0;
  for(int k : ks)
  {
    // The fastest of three runs (the machine is shared).
    VM::Linear_trajectory reduced;
    double t = 1e300, t_setup = 1e300;
    for(int run = 0; run < 3; ++run)
    {
      t0 = std::chrono::steady_clock::now();
      reduced = VM::reduced_linear_simulation(p, modes, k, o);
      t = std::min(t, seconds_since(t0));
      t0 = std::chrono::steady_clock::now();
      VM::reduced_linear_simulation(p, modes, k, setup_only);
      t_setup = std::min(t_setup, seconds_since(t0));
    }
    std::printf("| %d | %.3e | %.1f ms | %.1f ms | %.1f us | %.0fx |\n", k, VM::relative_trajectory_error(p, reduced, full),
                1e3 * t, 1e3 * t_setup, 1e6 * std::max(0.0, t - t_setup) / steps, t_full / t);
    std::fflush(stdout);
  }

  std::vector<std::vector<int>> one(1, std::vector<int>{int(top)});
  for(auto v : vertices_around_target(mesh.halfedge(top), mesh)) one[0].push_back(int(v));
  std::printf("\nElastic modelling: one drag (the basis coordinates q = G d), %d drags of a handle of %zu vertices at "
              "the top; setup = B^T H B and the KKT precomputation:\n\n",
              drags, one[0].size());
  std::printf("| k | setup | median drag | max drag | displacement B q (n x k) |\n|---|---|---|---|---|\n");
  for(int k : {10, 50, 100})
  {
    if(k > modes.vectors.cols()) continue;
    t0 = std::chrono::steady_clock::now();
    VM::Reduced_elastic_deformer deformer(p, modes.vectors.leftCols(k), one);
    const double setup = seconds_since(t0);
    std::vector<double> times;
    Eigen::MatrixXd target(3, 1);
    for(int d = 0; d < drags; ++d)
    {
      const double a = 2 * M_PI * d / drags;
      target << 0.1 * std::sin(a), 0.05 * (1 - std::cos(a)), 0.1 * std::sin(2 * a);
      t0 = std::chrono::steady_clock::now();
      deformer.drag(target);
      times.push_back(1e6 * seconds_since(t0));
    }
    std::sort(times.begin(), times.end());
    t0 = std::chrono::steady_clock::now();
    const Eigen::VectorXd u = deformer.displacement();
    const double expand = seconds_since(t0);
    std::printf("| %d | %.2f ms | %.2f us | %.1f us | %.2f ms |\n", k, 1e3 * setup, times[times.size() / 2], times.back(),
                1e3 * expand);
  }
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: bench_mode_uses MESH [--ks 5,10,20,50,100,200] [--steps 200] [--drags 20000]\n";
    return 2;
  }
  std::map<std::string, std::string> a;
  for(int i = 2; i + 1 < argc; i += 2) a[argv[i]] = argv[i + 1];
  auto get = [&](const std::string& key, const std::string& fallback) { return a.count(key) ? a[key] : fallback; };
  try
  {
    std::vector<int> ks;
    std::stringstream list(get("--ks", "5,10,20,50,100,200"));
    for(std::string item; std::getline(list, item, ',');) ks.push_back(std::stoi(item));
    return run(argv[1], ks, std::stoi(get("--steps", "200")), std::stoi(get("--drags", "20000")));
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
