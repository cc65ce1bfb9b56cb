// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The main demo: load a mesh (default: CGAL's elephant), make a tangent field,
// split it into its curl-free, divergence-free and harmonic parts, print the sizes
// of the parts, the topology and the timings, and write everything to files.
//
// Usage: hodge_decomposition_demo [mesh.off|obj|ply|stl] [output-prefix]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Tangent_vector_fields/face_field_io.h>
#include <CGAL/Tangent_vector_fields/hodge_decomposition.h>

#include <chrono>
#include <cstdio>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Face_index Face_index;
namespace TVF = CGAL::Tangent_vector_fields;

namespace {
double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
} // namespace

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : TVF_DEFAULT_MESH;
  const std::string prefix = argc > 2 ? argv[2] : "hodge_demo";

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(input, mesh, CGAL::parameters::verbose(false)) || is_empty(mesh))
  {
    std::cerr << "error: cannot read a polygon mesh from '" << input << "'\n";
    return 1;
  }
  std::cout << "mesh: " << input << "\n  " << mesh.number_of_vertices() << " vertices, " << mesh.number_of_faces()
            << " faces\n";

  try
  {
    auto t = std::chrono::steady_clock::now();
    TVF::Hodge_decomposition<Mesh> hodge(mesh);
    const double t_mesh = seconds_since(t);
    for(const std::string& w : hodge.operators().intrinsic_mesh().warnings()) std::cout << "  warning: " << w << '\n';
    std::cout << "  topology: " << hodge.topology().summary() << '\n';

    // A field with all three parts: a constant wind, a swirl about the z axis, and a
    // source at the bounding box centre, projected onto the faces.
    auto field = mesh.add_property_map<Face_index, K::Vector_3>("f:input").first;
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
    const K::Point_3 centre((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2, (box.zmin() + box.zmax()) / 2);
    const double size = std::max({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
    for(Face_index f : mesh.faces())
    {
      const K::Point_3 c = CGAL::centroid(mesh.point(mesh.source(mesh.halfedge(f))),
                                          mesh.point(mesh.target(mesh.halfedge(f))),
                                          mesh.point(mesh.target(mesh.next(mesh.halfedge(f)))));
      const K::Vector_3 d = (c - centre) / size;
      field[f] = K::Vector_3(1, 0.3, 0) + K::Vector_3(-d.y(), d.x(), 0) * 4 + d * 2;
    }
    // Keep the tangent part only (what the decomposition sees), so the files show it.
    hodge.operators().from_frame_coordinates(hodge.operators().to_frame_coordinates(field), field);

    auto exact = mesh.add_property_map<Face_index, K::Vector_3>("f:exact").first;
    auto coexact = mesh.add_property_map<Face_index, K::Vector_3>("f:coexact").first;
    auto harmonic = mesh.add_property_map<Face_index, K::Vector_3>("f:harmonic").first;
    t = std::chrono::steady_clock::now();
    hodge(field, TVF::parameters::exact_part_map(exact).coexact_part_map(coexact).harmonic_part_map(harmonic));
    const double t_first = seconds_since(t);
    t = std::chrono::steady_clock::now();
    hodge(field, TVF::parameters::exact_part_map(exact).coexact_part_map(coexact).harmonic_part_map(harmonic));
    const double t_cached = seconds_since(t);
    t = std::chrono::steady_clock::now();
    const int basis_size = static_cast<int>(hodge.solver().harmonic_basis().cols());
    const double t_basis = seconds_since(t);

    // Sizes of the parts in the L2 norm of fields (sum of area * |v|^2).
    const auto& ops = hodge.operators();
    const Eigen::VectorXd& mx = ops.matrices().field_masses();
    auto norm = [&](const Eigen::VectorXd& x) { return std::sqrt(x.dot(mx.cwiseProduct(x))); };
    const Eigen::VectorXd v = ops.to_frame_coordinates(field), e = ops.to_frame_coordinates(exact),
                          c = ops.to_frame_coordinates(coexact), h = ops.to_frame_coordinates(harmonic);
    const double nv = norm(v);
    std::printf("  |input| = %.6g   |exact| = %.6g   |coexact| = %.6g   |harmonic| = %.6g\n", nv, norm(e), norm(c),
                norm(h));
    std::printf("  exact^2 + coexact^2 + harmonic^2 - input^2 = %.2e (relative)\n",
                (norm(e) * norm(e) + norm(c) * norm(c) + norm(h) * norm(h) - nv * nv) / (nv * nv));
    std::printf("  |exact + coexact + harmonic - input| = %.2e (relative)\n", norm(e + c + h - v) / nv);
    std::printf("  harmonic dimension: %d (topology), %d (numerical rank of the harmonic basis)\n",
                hodge.harmonic_dimension(), basis_size);
    std::printf("timings [s]: mesh checks %.3f, first decomposition (operators + 2 factorisations) %.3f, "
                "cached decomposition %.3f, harmonic basis %.3f  [%s]\n",
                t_mesh, t_first, t_cached, t_basis, TVF::Sparse_spd_solver::backend_name());

    TVF::add_face_field_properties(mesh, "input", field);
    TVF::add_face_field_properties(mesh, "exact", exact);
    TVF::add_face_field_properties(mesh, "coexact", coexact);
    TVF::add_face_field_properties(mesh, "harmonic", harmonic);
    const std::string ply = prefix + ".ply";
    if(!CGAL::IO::write_PLY(ply, mesh, CGAL::parameters::use_binary_mode(false)))
    {
      std::cerr << "error: cannot write '" << ply << "'\n";
      return 1;
    }
    TVF::write_face_field(prefix + "_exact.tvf", mesh, exact);
    TVF::write_face_field(prefix + "_coexact.tvf", mesh, coexact);
    TVF::write_face_field(prefix + "_harmonic.tvf", mesh, harmonic);
    std::cout << "wrote " << ply << " (mesh with face properties input_*, exact_*, coexact_*, harmonic_*) and "
              << prefix << "_{exact,coexact,harmonic}.tvf\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
