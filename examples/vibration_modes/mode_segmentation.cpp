// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Segmentation from the supports of compressed modes: compressed manifold modes of the
// mesh (the scalar problem of its cotangent Laplacian, local bumps), each vertex labelled by
// the mode strongest there, split into connected regions; writes a PLY with the label and a
// colour per vertex.
//
//   mode_segmentation [mesh.off] [output.ply] [modes] [mu factor]

#include "example_mesh.h"

#include <CGAL/Vibration_modes/compressed_modes.h>
#include <CGAL/Vibration_modes/lowest_vibration_modes.h>
#include <CGAL/Vibration_modes/mode_segmentation.h>

#include <CGAL/IO/Color.h>

#include <chrono>
#include <cstdio>
#include <fstream>

namespace VM = CGAL::Vibration_modes;
namespace DS = CGAL::Discrete_shells;

int main(int argc, char** argv)
{
  const std::string path = argc > 1 ? argv[1] : VM_DEFAULT_MESH;
  const std::string output = argc > 2 ? argv[2] : "mode_segmentation.ply";
  const int k = argc > 3 ? std::stoi(argv[3]) : 8;
  const double factor = argc > 4 ? std::stod(argv[4]) : 2.5;
  Mesh mesh;
  if(!read_unit_area_mesh(path, mesh)) return 1;
  try
  {
    const auto start = std::chrono::steady_clock::now();
    const VM::Mode_problem problem = VM::laplacian_mode_problem(DS::stacked_positions(mesh), DS::mesh_triangles(mesh));
    const VM::Modes ordinary = VM::lowest_vibration_modes(problem, k);
    // Modes may use the constants (compressed manifold modes): a bump on one part is then cheap.
    // mu scaled as the k-th eigenvalue per l1 norm of an even unit function (unit area: 1).
    VM::Compressed_mode_options o;
    o.orthogonal_to_kernel = false;
    o.sparsity_weight = factor * ordinary.energies[k - 1];
    const VM::Modes modes = VM::compressed_modes(problem, k, o);
    auto label = mesh.add_property_map<Vertex_index, int>("v:label", -1).first;
    const int regions = VM::segment_by_modes(mesh, modes, label);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::vector<int> size(std::size_t(regions), 0);
    int unassigned = 0;
    for(auto v : vertices(mesh)) label[v] < 0 ? ++unassigned : ++size[std::size_t(label[v])];
    std::printf("%d vertices, %d compressed modes (mu %.3g) in %.2f s: %d regions, sizes", int(num_vertices(mesh)), k,
                o.sparsity_weight, seconds, regions);
    for(int s : size) std::printf(" %d", s);
    std::printf(", %d unassigned\n", unassigned);
    // A colour per region (golden-ratio hues), grey for unassigned vertices.
    auto colour = mesh.add_property_map<Vertex_index, CGAL::IO::Color>("v:color").first;
    for(auto v : vertices(mesh))
    {
      if(label[v] < 0)
      {
        colour[v] = CGAL::IO::Color(128, 128, 128);
        continue;
      }
      const double h = std::fmod(0.618033988749895 * label[v], 1.0) * 6;
      const int i = int(h);
      const double f = h - i;
      const double rgb[6][3] = {{1, f, 0}, {1 - f, 1, 0}, {0, 1, f}, {0, 1 - f, 1}, {f, 0, 1}, {1, 0, 1 - f}};
      colour[v] = CGAL::IO::Color((unsigned char)(40 + 200 * rgb[i][0]), (unsigned char)(40 + 200 * rgb[i][1]),
                                  (unsigned char)(40 + 200 * rgb[i][2]));
    }
    std::ofstream out(output);
    if(!out || !CGAL::IO::write_PLY(out, mesh)) return 1;
    std::cout << "wrote " << output << " (vertex properties label, red, green, blue)\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
