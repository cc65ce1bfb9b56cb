// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Elastic modelling with a dragged handle: the shell stands on its pinned feet, a handle at
// its top is dragged along a circle, and every drag asks for the deformation of least
// linearised elastic energy in the span of k modes.  Prints the time per drag (the basis
// coordinates, what a viewer sends to the GPU with the modes), the handle's error, and the
// last pose against the full-resolution answer; writes the last pose.
//
//   elastic_modelling [mesh.off] [output.off] [k] [drags]

#include "example_mesh.h"

#include <CGAL/Vibration_modes/Elastic_deformer.h>
#include <CGAL/Vibration_modes/vibration_modes.h>

#include <chrono>
#include <cstdio>

namespace VM = CGAL::Vibration_modes;

int main(int argc, char** argv)
{
  const std::string path = argc > 1 ? argv[1] : VM_DEFAULT_MESH;
  const std::string output = argc > 2 ? argv[2] : "elastic_modelling.off";
  const int k = argc > 3 ? std::stoi(argv[3]) : 100;
  const int drags = argc > 4 ? std::stoi(argv[4]) : 1000;
  Mesh mesh;
  if(!read_unit_area_mesh(path, mesh)) return 1;
  try
  {
    const std::vector<Vertex_index> feet = lowest_vertices(mesh, 0.05);
    const auto np = VM::parameters::bending_stiffness(1e-3).pinned_vertices(feet);
    const VM::Mode_problem problem = VM::mesh_mode_problem(mesh, np);
    const VM::Modes modes = VM::vibration_modes(mesh, k, np);
    // The handle: the topmost vertex and its neighbours.
    Vertex_index top = *vertices(mesh).begin();
    for(auto v : vertices(mesh))
      if(mesh.point(v).y() > mesh.point(top).y()) top = v;
    std::vector<std::vector<int>> handles(1, std::vector<int>{int(top)});
    for(auto v : vertices_around_target(mesh.halfedge(top), mesh)) handles[0].push_back(int(v));

    auto now = [] { return std::chrono::steady_clock::now(); };
    auto t0 = now();
    VM::Reduced_elastic_deformer deformer(problem, modes.vectors, handles);
    const double setup = std::chrono::duration<double>(now() - t0).count();
    std::vector<double> times;
    Eigen::MatrixXd target(3, 1);
    for(int d = 0; d < drags; ++d)
    {
      const double a = 2 * M_PI * d / drags;
      target << 0.1 * std::sin(a), 0.05 * (1 - std::cos(a)), 0.1 * std::sin(2 * a);
      t0 = now();
      deformer.drag(target);
      times.push_back(std::chrono::duration<double, std::micro>(now() - t0).count());
    }
    std::sort(times.begin(), times.end());
    std::printf("%d vertices, %zu pinned, %d modes; handle of %zu vertices; setup %.2f ms\n", int(num_vertices(mesh)),
                feet.size(), k, handles[0].size(), 1e3 * setup);
    std::printf("%d drags: median %.2f us, max %.2f us per drag\n", drags, times[times.size() / 2], times.back());

    // The last pose: the handle's mean displacement meets the target; the full answer beside it.
    auto free_part = [&](const Eigen::VectorXd& all) {
      Eigen::VectorXd f(problem.H.rows());
      for(std::size_t i = 0; i < problem.free_unknowns.size(); ++i) f[Eigen::Index(i)] = all[problem.free_unknowns[i]];
      return f;
    };
    const Eigen::VectorXd u = deformer.displacement(), u_free = free_part(u);
    const VM::Handle_constraints c = VM::handle_constraints(problem, handles);
    const double handle_error = (c.C * u_free - target.col(0)).norm();
    t0 = now();
    const VM::Full_elastic_deformer full(problem, handles);
    const Eigen::VectorXd uf = free_part(full.deform(target));
    const double full_time = std::chrono::duration<double>(now() - t0).count();
    const Eigen::VectorXd d = u_free - uf;
    const double difference = std::sqrt(d.dot(problem.mass.cwiseProduct(d)) / uf.dot(problem.mass.cwiseProduct(uf)));
    std::printf("handle error %.1e; full resolution: %.0f ms (factor and solve), relative difference %.3g, "
                "energy %.4g (reduced %.4g)\n",
                handle_error, 1e3 * full_time, difference, uf.dot(problem.H * uf), deformer.energy());
    auto displacement = mesh.add_property_map<Vertex_index, Kernel::Vector_3>("v:displacement").first;
    VM::copy_displacement_to_vertex_map(mesh, u, displacement);
    for(auto v : vertices(mesh)) mesh.point(v) += displacement[v];
    if(!CGAL::IO::write_polygon_mesh(output, mesh, CGAL::parameters::stream_precision(17))) return 1;
    std::cout << "wrote " << output << "\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
