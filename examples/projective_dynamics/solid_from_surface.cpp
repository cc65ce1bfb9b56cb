// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// A closed surface made a solid: tetrahedra by Mesh_3 (tetrahedralize), a drop onto a floor with
// full Projective Dynamics, and the user's own surface moved with the tetrahedra and written back.
//   solid_from_surface [mesh.off] [frames] [out.off]   (default: a Loop-subdivided icosahedron)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Projective_dynamics/Simulator.h>
#include <CGAL/Projective_dynamics/make_models.h>
#include <CGAL/Projective_dynamics/tetrahedralize.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <iostream>
#include <string>

namespace PD = CGAL::Projective_dynamics;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

int main(int argc, char** argv)
{
  Mesh surface;
  if(argc > 1)
  {
    if(!CGAL::IO::read_polygon_mesh(argv[1], surface))
    {
      std::cerr << "cannot read " << argv[1] << "\n";
      return 1;
    }
  }
  else
  {
    CGAL::make_icosahedron(surface, K::Point_3(0, 0, 1), 0.5);
    CGAL::Subdivision_method_3::Loop_subdivision(surface, CGAL::parameters::number_of_iterations(2));
  }
  const int frames = argc > 2 ? std::stoi(argv[2]) : 60;
  try
  {
    const PD::Tetrahedralized_surface solid = PD::tetrahedralize(surface, PD::parameters::cell_size(0.1));
    std::cout << "surface: " << surface.number_of_vertices() << " vertices; tetrahedra: " << solid.mesh.points.size()
              << " vertices, " << solid.mesh.tetrahedra.size() << " tetrahedra; the surface at most "
              << solid.largest_outside_distance << " of the diagonal outside them\n";
    PD::Simulator sim(PD::make_solid_model(solid.mesh, PD::parameters::strain_stiffness(1e5).density(1e3)),
                      PD::parameters::time_step(1.0 / 60));
    double floor = 1e300;
    for(const PD::Point& p : solid.mesh.points) floor = std::min(floor, p[2]);
    floor -= 0.2;
    sim.add_floor({0, 0, floor}, {0, 0, 1});
    for(int f = 0; f < frames; ++f) sim.step();
    // The user's surface follows its tetrahedra.
    const PD::Positions q = solid.surface.embed(sim.positions());
    for(auto v : surface.vertices())
    {
      const Eigen::Index i = Eigen::Index(std::size_t(v)); // the vertex index map of a Surface_mesh
      surface.point(v) = K::Point_3(q(i, 0), q(i, 1), q(i, 2));
    }
    double lowest = 1e300;
    for(auto v : surface.vertices()) lowest = std::min(lowest, surface.point(v).z());
    std::cout << "after " << frames << " frames: floor at z = " << floor << ", lowest surface vertex at z = " << lowest
              << "\n";
    if(argc > 3 && !CGAL::IO::write_polygon_mesh(argv[3], surface, CGAL::parameters::stream_precision(17)))
      std::cerr << "cannot write " << argv[3] << "\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
