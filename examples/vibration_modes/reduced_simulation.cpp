// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Linearised reduced simulation: a shell standing on its pinned feet falls under gravity
// from rest and swings, simulated in the span of its k lowest vibration modes and, as the
// yardstick, at full resolution; prints both run times and the reduced trajectory's relative
// error, and writes the reduced frames as OBJ files.
//
//   reduced_simulation [mesh.off] [output prefix] [k] [frames]

#include "example_mesh.h"

#include <CGAL/Vibration_modes/linear_simulation.h>
#include <CGAL/Vibration_modes/vibration_modes.h>

#include <chrono>
#include <cstdio>

namespace VM = CGAL::Vibration_modes;

int main(int argc, char** argv)
{
  const std::string path = argc > 1 ? argv[1] : VM_DEFAULT_MESH;
  const std::string prefix = argc > 2 ? argv[2] : "reduced_simulation";
  const int k = argc > 3 ? std::stoi(argv[3]) : 30;
  const int frames = argc > 4 ? std::stoi(argv[4]) : 20;
  Mesh mesh;
  if(!read_unit_area_mesh(path, mesh)) return 1;
  try
  {
    const std::vector<Vertex_index> feet = lowest_vertices(mesh, 0.05);
    const auto np = VM::parameters::bending_stiffness(1e-3).pinned_vertices(feet);
    const VM::Mode_problem problem = VM::mesh_mode_problem(mesh, np);
    const VM::Modes modes = VM::vibration_modes(mesh, k, np);
    std::cout << num_vertices(mesh) << " vertices, " << feet.size() << " pinned, " << k << " modes (lowest eigenvalue "
              << modes.energies[0] << ")\n";

    // Gravity -g y on the lumped masses, g set so the static sag along the slowest mode is
    // a few percent of the model's size (unit area); four periods of that mode, 20 steps each.
    const double lambda = modes.energies[0], period = 2 * M_PI / std::sqrt(lambda);
    VM::Linear_simulation_options o;
    o.time_step = period / 20;
    o.steps = 80;
    o.output_every = std::max(1, o.steps / frames);
    o.rayleigh_mass = 0.02 * std::sqrt(lambda); // light damping
    o.force = Eigen::VectorXd::Zero(problem.full_size);
    for(std::size_t i = 0; i < problem.free_unknowns.size(); ++i)
      if(problem.free_unknowns[i] % 3 == 1) o.force[problem.free_unknowns[i]] = -0.3 * lambda * problem.mass[Eigen::Index(i)];

    auto seconds = [](auto start) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    auto t0 = std::chrono::steady_clock::now();
    const VM::Linear_trajectory reduced = VM::reduced_linear_simulation(problem, modes, k, o);
    const double reduced_time = seconds(t0);
    t0 = std::chrono::steady_clock::now();
    const VM::Linear_trajectory full = VM::full_linear_simulation(problem, o);
    const double full_time = seconds(t0);
    std::printf("reduced simulation: %d steps in %.1f ms; full: %.1f ms; relative error of the reduced trajectory %.3g\n",
                o.steps, 1e3 * reduced_time, 1e3 * full_time, VM::relative_trajectory_error(problem, reduced, full));

    // Each frame as a per-vertex displacement map, added to a copy of the mesh.
    auto u = mesh.add_property_map<Vertex_index, Kernel::Vector_3>("v:displacement").first;
    for(Eigen::Index f = 0; f < reduced.displacements.cols(); ++f)
    {
      VM::copy_displacement_to_vertex_map(mesh, reduced.displacements.col(f), u);
      Mesh frame = mesh;
      for(auto v : vertices(frame)) frame.point(v) = mesh.point(v) + u[v];
      char name[32];
      std::snprintf(name, sizeof(name), "_%03d.obj", int(f));
      if(!CGAL::IO::write_polygon_mesh(prefix + name, frame, CGAL::parameters::stream_precision(10))) return 1;
    }
    std::cout << "wrote " << reduced.displacements.cols() << " frames " << prefix << "_000.obj ...\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
