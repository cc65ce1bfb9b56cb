// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Two scenes of full-space Projective Dynamics, each frame's surface written as an OBJ file:
//   projective_dynamics_scenes drop <output folder> [frames]        a soft box dropped on a floor
//   projective_dynamics_scenes cantilever <output folder> [frames]  a rod pinned at one end, sagging

#include <CGAL/Projective_dynamics/Simulator.h>
#include <CGAL/Projective_dynamics/make_models.h>
#include <CGAL/Projective_dynamics/mesh_generators.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

namespace PD = CGAL::Projective_dynamics;

namespace {

void write_obj(const std::string& path, const PD::Positions& q, const std::vector<PD::Triangle>& triangles)
{
  std::ofstream out(path);
  out.precision(9);
  for(Eigen::Index i = 0; i < q.rows(); ++i) out << "v " << q(i, 0) << ' ' << q(i, 1) << ' ' << q(i, 2) << '\n';
  for(const PD::Triangle& f : triangles) out << "f " << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << '\n';
  if(!out) throw std::runtime_error("cannot write " + path);
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 3 || (std::string(argv[1]) != "drop" && std::string(argv[1]) != "cantilever"))
  {
    std::cerr << "usage: " << argv[0] << " drop|cantilever <output folder> [frames]\n";
    return 2;
  }
  const std::string scene = argv[1], folder = argv[2];
  const int frames = argc > 3 ? std::stoi(argv[3]) : 120;
  std::filesystem::create_directories(folder);
  try
  {
    const bool drop = scene == "drop";
    // SI units: a 0.4 m box of rubber-like material (1e5 Pa, 1000 kg/m^3) falling from 0.3 m,
    // or a 1 m x 0.1 m rod (1e7 Pa) pinned at x = 0.
    const PD::Tet_mesh mesh = drop ? PD::make_tet_box(6, 6, 6, {-0.2, -0.2, 0.3}, {0.2, 0.2, 0.7})
                                   : PD::make_tet_rod(20, 2, 1.0, 0.1);
    PD::Simulator sim(PD::make_solid_model(mesh, PD::parameters::strain_stiffness(drop ? 1e5 : 1e7).density(1e3)),
                      PD::parameters::time_step(1.0 / 60).number_of_iterations(10).friction(0.8));
    std::vector<int> pinned;
    if(drop)
      sim.add_floor({0, 0, 0}, {0, 0, 1});
    else
    {
      for(std::size_t v = 0; v < mesh.points.size(); ++v)
        if(mesh.points[v][0] == 0) pinned.push_back(int(v));
      sim.set_pinned_vertices(pinned);
    }
    std::cout << scene << ": " << mesh.tetrahedra.size() << " tetrahedra, " << mesh.points.size() << " vertices";
    if(!drop) std::cout << ", " << pinned.size() << " pinned";
    std::cout << '\n';
    double lowest = 1e300, local = 0, global = 0;
    for(int f = 0; f < frames; ++f)
    {
      sim.step();
      lowest = std::min(lowest, sim.positions().col(2).minCoeff());
      local += sim.last_step_timings().local;
      global += sim.last_step_timings().global;
      char name[32];
      std::snprintf(name, sizeof name, "frame_%04d.obj", f);
      write_obj((std::filesystem::path(folder) / name).string(), sim.positions(), mesh.triangles);
    }
    const PD::Positions& q = sim.positions();
    if(drop)
      std::cout << "lowest vertex over all frames: z = " << lowest << " (floor at 0); at the end the box spans z in ["
                << q.col(2).minCoeff() << ", " << q.col(2).maxCoeff() << "], speed " << sim.velocities().rowwise().norm().maxCoeff()
                << " m/s\n";
    else
    {
      // The free end's centre line: vertices at x = 1.
      double tip = 0;
      int n = 0;
      for(std::size_t v = 0; v < mesh.points.size(); ++v)
        if(mesh.points[v][0] == 1.0) tip += q(Eigen::Index(v), 2) - mesh.points[v][2], ++n;
      std::cout << "tip deflection " << tip / n << " m after " << frames << " frames\n";
    }
    std::cout << "time per step: local " << 1e3 * local / frames << " ms, global " << 1e3 * global / frames
              << " ms; factorisation " << 1e3 * sim.last_step_timings().factorization << " ms\n";
    std::cout << "wrote " << frames << " OBJ frames to " << folder << '\n';
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
