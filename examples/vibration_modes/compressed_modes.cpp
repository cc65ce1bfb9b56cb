// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Vibration modes of a mesh as an elastic shell, ordinary and compressed, and the first
// compressed mode written as a displaced copy of the mesh.
//
//   compressed_modes [mesh.off] [output prefix] [modes]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Vibration_modes/vibration_modes.h>

#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace VM = CGAL::Vibration_modes;

int main(int argc, char** argv)
{
  const std::string path = argc > 1 ? argv[1] : VM_DEFAULT_MESH;
  const std::string prefix = argc > 2 ? argv[2] : "compressed_mode";
  const int k = argc > 3 ? std::stoi(argv[3]) : 6;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || mesh.is_empty())
  {
    std::cerr << "cannot read " << path << "\n";
    return 1;
  }
  // Unit area, so that the stiffnesses and mu mean the same on any mesh.
  const double area = CGAL::Polygon_mesh_processing::area(mesh);
  for(auto v : vertices(mesh)) mesh.point(v) = CGAL::ORIGIN + (mesh.point(v) - CGAL::ORIGIN) / std::sqrt(area);
  try
  {
    const auto stiffness = VM::parameters::bending_stiffness(1e-3);
    const VM::Modes ordinary = VM::vibration_modes(mesh, k, stiffness);
    std::cout << num_vertices(mesh) << " vertices, " << ordinary.kernel_dimension << " rigid motions deflated\n";
    std::cout << "ordinary modes: eigenvalues " << ordinary.energies.transpose() << ", largest residual "
              << ordinary.residuals.maxCoeff() << ", complete below " << ordinary.complete_below << "\n";
    // mu: a few times the k-th eigenvalue per unit of |u|_{1,M} (at unit area, that of an even mode).
    const double mu = 4 * ordinary.energies[k - 1];
    const VM::Modes local = VM::compressed_vibration_modes(mesh, k, stiffness.sparsity_weight(mu));
    const VM::Mode_problem p = VM::shell_mode_problem(CGAL::Discrete_shells::make_shell_energy(mesh, stiffness));
    const Eigen::MatrixXd G = local.vectors.transpose() * p.mass.asDiagonal() * local.vectors;
    std::cout << "compressed modes (mu " << mu << "): supports";
    for(int i = 0; i < k; ++i) std::cout << " " << int(100 * local.support_fractions[i] + 0.5) << "%";
    std::cout << "; max |U^T M U - I| = " << (G - Eigen::MatrixXd::Identity(k, k)).cwiseAbs().maxCoeff() << "\n";
    // The first compressed mode as a displaced mesh, scaled to a tenth of the mesh's size.
    auto u = mesh.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:mode").first;
    VM::copy_mode_to_vertex_map(mesh, local, 0, u);
    double largest = 0;
    for(auto v : vertices(mesh)) largest = std::max(largest, std::sqrt(u[v].squared_length()));
    Mesh displaced = mesh;
    for(auto v : vertices(displaced)) displaced.point(v) += 0.1 / largest * u[v];
    const std::string out = prefix + "_0.off";
    if(!CGAL::IO::write_polygon_mesh(out, displaced, CGAL::parameters::stream_precision(17))) return 1;
    std::cout << "wrote " << out << "\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
