// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The benchmark meshes: a file of ../shared/data, Loop-subdivided a few times, as a
// Hodge solver on its operators.  Included by one translation unit per benchmark.

#ifndef TVF_BENCH_MESHES_H
#define TVF_BENCH_MESHES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <CGAL/Tangent_vector_fields/Hodge_solver.h>
#include <CGAL/Tangent_vector_fields/internal/Mesh_adapter.h>

#include <iostream>
#include <memory>
#include <string>

namespace tvf_bench {

/// Reads `dir/file`, subdivides it, and returns a Hodge solver on it (null if the file
/// cannot be read); `faces` receives the number of faces.  With `save_as`, the subdivided
/// mesh is also written there (OFF, 17 digits: the same mesh for `tvf`, bit for bit).
inline std::shared_ptr<CGAL::Tangent_vector_fields::Hodge_solver> load_mesh(const std::string& dir,
                                                                            const std::string& file,
                                                                            int subdivisions, int& faces,
                                                                            const std::string& save_as = std::string())
{
  namespace TVF = CGAL::Tangent_vector_fields;
  typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(dir + "/" + file, mesh))
  {
    std::cerr << "cannot read " << dir << "/" << file << "\n";
    return nullptr;
  }
  for(int i = 0; i < subdivisions; ++i) CGAL::Subdivision_method_3::Loop_subdivision(mesh);
  faces = static_cast<int>(mesh.number_of_faces());
  if(!save_as.empty() && !CGAL::IO::write_polygon_mesh(save_as, mesh, CGAL::parameters::stream_precision(17)))
    std::cerr << "cannot write " << save_as << "\n";
  TVF::internal::Mesh_adapter<Mesh> adapter(mesh, CGAL::parameters::default_values());
  auto ops = std::make_shared<TVF::Operator_matrices>(adapter.intrinsic_mesh());
  return std::make_shared<TVF::Hodge_solver>(ops);
}

} // namespace tvf_bench

#endif
