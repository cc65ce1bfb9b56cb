// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The main demo: load a mesh (default: CGAL's elephant; quad meshes, soups and non-manifold
// meshes are repaired first, see Model_reduction::polygon_soup_to_mesh), make a tangent field,
// split it into its curl-free, divergence-free and harmonic parts, print the sizes
// of the parts, the topology and the timings; then compute the lowest eigenfields
// of the Hodge-Laplacian (with a progress bar; saved, so the next run loads them),
// show the spectrum and filter the field; write everything to files.
//
// Usage: hodge_decomposition_demo [mesh.off|obj|ply|stl] [output-prefix] [number-of-eigenfields]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <CGAL/Tangent_vector_fields/face_field_io.h>
#include <CGAL/Tangent_vector_fields/Spectral_basis.h>
#include <CGAL/Tangent_vector_fields/hodge_decomposition.h>
#include <CGAL/Model_reduction/polygon_soup_to_mesh.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Face_index Face_index;
namespace TVF = CGAL::Tangent_vector_fields;
namespace MR = CGAL::Model_reduction;

namespace {
double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A one-line progress bar on stderr.
void draw_progress(const TVF::Spectral_progress& p)
{
  const int width = 30, filled = static_cast<int>(p.fraction * width + 0.5);
  std::fprintf(stderr, "\r  [%s%s] %3d%%  %-26s", std::string(filled, '#').c_str(),
               std::string(width - filled, '-').c_str(), static_cast<int>(100 * p.fraction + 0.5), p.stage.c_str());
  if(p.fraction >= 1) std::fprintf(stderr, "\n");
}

const char* type_letter(TVF::Eigenfield_type t)
{
  return t == TVF::Eigenfield_type::exact ? "E" : t == TVF::Eigenfield_type::coexact ? "C" : "H";
}
} // namespace

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : TVF_DEFAULT_MESH;
  const std::string prefix = argc > 2 ? argv[2] : "hodge_demo";
  const int eigenfields = argc > 3 ? std::atoi(argv[3]) : 300;

  // Read as a polygon soup and made a triangle mesh: quad meshes, inconsistently oriented
  // soups and non-manifold vertices are repaired (the report says how).
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  if(!CGAL::IO::read_polygon_soup(input, points, polygons, CGAL::parameters::verbose(false)) || polygons.empty())
  {
    std::cerr << "error: cannot read a polygon mesh from '" << input << "'\n";
    return 1;
  }
  Mesh mesh;
  MR::Mesh_repair_report repairs;
  try
  {
    repairs = MR::polygon_soup_to_mesh(points, polygons, mesh);
  }
  catch(const TVF::Invalid_mesh& e)
  {
    std::cerr << "error: '" << input << "': " << e.what() << '\n';
    return 1;
  }
  std::cout << "mesh: " << input << "\n  " << mesh.number_of_vertices() << " vertices, " << mesh.number_of_faces()
            << " faces\n  repairs: " << repairs << '\n';

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
                t_mesh, t_first, t_cached, t_basis, MR::Sparse_spd_solver::backend_name());

    // Spectral basis: the lowest eigenfields, loaded from the file of an earlier run
    // when it belongs to this mesh (a changed mesh is refused and recomputed).
    typedef TVF::Spectral_basis<Mesh> Basis;
    const std::string basis_file = prefix + "_basis.tvfb";
    std::unique_ptr<Basis> basis;
    t = std::chrono::steady_clock::now();
    if(std::ifstream(basis_file).good())
    {
      try
      {
        basis = std::make_unique<Basis>(Basis::load(mesh, basis_file));
        if(basis->size() != eigenfields) basis.reset();
        else std::printf("spectral basis: loaded %d eigenfields from %s in %.3f s\n", basis->size(),
                         basis_file.c_str(), seconds_since(t));
      }
      catch(const TVF::Invalid_input& e)
      {
        std::cout << "spectral basis: not reusing " << basis_file << " (" << e.what() << ")\n";
      }
    }
    if(!basis)
    {
      std::printf("spectral basis: computing the %d lowest eigenfields of the Hodge-Laplacian\n", eigenfields);
      std::function<void(const TVF::Spectral_progress&)> bar = draw_progress;
      t = std::chrono::steady_clock::now();
      basis = std::make_unique<Basis>(
          mesh, TVF::parameters::number_of_eigenfields(eigenfields).progress_callback(bar));
      std::printf("  computed in %.2f s; saved to %s\n", seconds_since(t), basis_file.c_str());
      basis->save(basis_file);
    }
    const TVF::Eigenfield_basis& b = basis->basis();
    const TVF::Basis_report& report = b.report();
    std::printf("  %d harmonic + %d exact (curl-free) + %d coexact (divergence-free) eigenfields; largest relative "
                "residual %.1e;\n  completeness (Sylvester inertia): exact %d/%d, coexact %d/%d below the last shift\n",
                b.number_of_harmonic(), b.number_of_exact(), b.number_of_coexact(), report.max_residual,
                report.exact_inertia, report.exact_expected, report.coexact_inertia, report.coexact_expected);
    std::printf("  spectrum (H harmonic, E exact, C coexact; unit-area eigenvalues = lambda * area):\n  ");
    const double area = ops.matrices().face_areas().sum();
    for(int k = 0; k < std::min(basis->size(), 24); ++k)
      std::printf("%s %.1f%s", type_letter(basis->type(k)), basis->eigenvalue(k) * area, (k % 8 == 7) ? "\n  " : "   ");
    std::printf("... %s %.1f\n", type_letter(basis->type(basis->size() - 1)), basis->eigenvalue(basis->size() - 1) * area);

    // Filters: heat-kernel smoothing and the smooth divergence-free part.
    const Eigen::VectorXd a = b.coefficients(v);
    const double t_smooth = 10.0 / b.eigenvalue(std::min(basis->size() - 1, 50));
    auto smooth = mesh.add_property_map<Face_index, K::Vector_3>("f:low_pass").first;
    basis->filter(field, TVF::Spectral_filter::low_pass(t_smooth), smooth);
    TVF::Spectral_filter divergence_free = TVF::Spectral_filter::low_pass(t_smooth);
    divergence_free.exact = [](double) { return 0.; };
    auto swirl = mesh.add_property_map<Face_index, K::Vector_3>("f:smooth_divergence_free").first;
    basis->filter(field, divergence_free, swirl);
    const Eigen::VectorXd a_smooth = basis->coefficients(smooth);
    const TVF::Compressed_fields compressed = b.compress(v, basis->size());
    std::printf("  input in the basis: %.1f%% of its L2 norm (the rest is above the basis' top frequency)\n",
                100 * std::sqrt(std::max(0., 1 - compressed.relative_errors[0] * compressed.relative_errors[0])));
    std::printf("  low-pass exp(-t lambda), t = %.3g: Dirichlet energy of the basis part %.4g -> %.4g\n", t_smooth,
                b.dirichlet_energy(a), b.dirichlet_energy(a_smooth));
    const Eigen::MatrixXd bands = b.band_energies(a, {0, 1e-12, b.eigenvalue(basis->size() - 1) / 4,
                                                      b.eigenvalue(basis->size() - 1) * 1.000001});
    std::printf("  energy of the coefficients (harmonic | exact | coexact): zero frequency %.3g | %.3g | %.3g; low band "
                "%.3g | %.3g | %.3g; high band %.3g | %.3g | %.3g\n",
                bands(0, 0), bands(0, 1), bands(0, 2), bands(1, 0), bands(1, 1), bands(1, 2), bands(2, 0), bands(2, 1),
                bands(2, 2));

    TVF::add_face_field_properties(mesh, "low_pass", smooth);
    TVF::add_face_field_properties(mesh, "smooth_divergence_free", swirl);
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
    std::cout << "wrote " << ply << " (mesh with face properties input_*, exact_*, coexact_*, harmonic_*, low_pass_*, "
              << "smooth_divergence_free_*), " << prefix << "_{exact,coexact,harmonic}.tvf and " << basis_file << "\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
