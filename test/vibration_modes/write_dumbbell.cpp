// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Writes the tests' dumbbell (two unit spheres at z = -1.6 and z = 1.6 joined by a neck of
// radius 0.25) as an OFF file, for the runs of `tvf segment` (cli_tests.cmake).

#include "shell_test_meshes.h"

#include <fstream>
#include <iostream>
#include <limits>

int main(int argc, char** argv)
{
  if(argc != 2)
  {
    std::cerr << "usage: write_dumbbell FILE.off\n";
    return 2;
  }
  const tvf_test::Mesh mesh = shell_test::make_dumbbell();
  std::ofstream out(argv[1]);
  out.precision(std::numeric_limits<double>::max_digits10);
  out << "OFF\n" << mesh.number_of_vertices() << ' ' << mesh.number_of_faces() << " 0\n";
  for(auto v : vertices(mesh)) out << mesh.point(v) << '\n';
  for(auto f : faces(mesh))
  {
    out << 3;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh)) out << ' ' << std::size_t(v);
    out << '\n';
  }
  out.close();
  return out ? 0 : 1;
}
