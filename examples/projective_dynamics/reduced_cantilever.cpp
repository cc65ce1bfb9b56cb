// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// A cantilever sagging, simulated by hyper-reduced Projective Dynamics beside full PD; the drawn
// surface's positions are made only for the boundary vertices (positions_of), then the rod is
// made ten times stiffer while it moves (only the k x k matrix is refactored).
//   reduced_cantilever [frames]

#include <CGAL/Projective_dynamics/Reduced_simulator.h>
#include <CGAL/Projective_dynamics/Simulator.h>
#include <CGAL/Projective_dynamics/make_models.h>
#include <CGAL/Projective_dynamics/mesh_generators.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <vector>

namespace PD = CGAL::Projective_dynamics;

int main(int argc, char** argv)
{
  const int frames = argc > 1 ? std::max(1, std::atoi(argv[1])) : 60;
  const PD::Tet_mesh mesh = PD::make_tet_rod(20, 4, 1.0, 0.2);
  const PD::Elastic_model model = PD::make_solid_model(mesh, PD::parameters::strain_stiffness(1e6).density(1e3));
  std::vector<int> pinned;
  for(std::size_t v = 0; v < mesh.points.size(); ++v)
    if(mesh.points[v][0] == 0) pinned.push_back(int(v));
  std::set<int> surface_set;
  for(const PD::Triangle& t : mesh.triangles) surface_set.insert(t.begin(), t.end());
  const std::vector<int> surface(surface_set.begin(), surface_set.end());
  // The tip: the vertex at (1, 0, 0).
  const int tip = int(std::find_if(mesh.points.begin(), mesh.points.end(),
                                   [](const PD::Point& p) { return p[0] == 1.0 && p[1] == 0 && p[2] == 0; }) -
                      mesh.points.begin());

  PD::Simulator full(model, PD::parameters::time_step(1.0 / 60));
  full.set_pinned_vertices(pinned);
  PD::Reduced_simulator reduced(model, PD::parameters::time_step(1.0 / 60)
                                           .number_of_samples(40)              // k = 160
                                           .number_of_projection_columns(60)   // l
                                           .number_of_sampled_elements(400)    // s
                                           .number_of_constraint_samples(30));
  reduced.set_pinned_vertices(pinned);
  std::printf("cantilever: %zu tetrahedra, %zu vertices, %zu drawn; k = %d, %zu sampled elements on %zu vertices\n",
              mesh.tetrahedra.size(), mesh.points.size(), surface.size(), reduced.dimension(),
              reduced.sampled_elements().size(), reduced.used_vertices().size());
  double lowest = 0;
  for(int t = 0; t < frames; ++t)
  {
    full.step();
    reduced.step();
    const PD::Positions drawn = reduced.positions_of(surface); // what a viewer would draw
    lowest = std::min(lowest, drawn.col(2).minCoeff());
  }
  std::printf("tip deflection after %d frames: full PD %.4f m, hyper-reduced %.4f m; lowest drawn z %.4f m\n", frames,
              full.positions()(tip, 2), reduced.positions_of({tip})(0, 2), lowest);
  reduced.set_stiffness(0, 1e7);
  for(int t = 0; t < frames; ++t) reduced.step();
  std::printf("ten times stiffer: tip %.4f m after %d more frames (%d factorisations of the %d x %d matrix)\n",
              reduced.positions_of({tip})(0, 2), frames, reduced.number_of_factorizations(), reduced.dimension(),
              reduced.dimension());
  return 0;
}
