// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Cross fields (n = 4) three ways on one mesh, side by side:
//   1. the smoothest cross field (no constraints), with its singularities;
//   2. the classical first-order design: minimise E_D subject to a few crosses;
//   3. the higher-order spline: minimise E_B = |L_n z|^2 subject to the same crosses,
//      exact and reduced on a basis of the lowest eigenfields (an edit timed);
// a cross field with two prescribed singularities (+1/4, -1/4) built into the connection;
// and 4. cross fields softly aligned to the principal curvature directions (CGAL's jet
// fitting), smoothest and spline, against their unaligned versions.  Prints energies and singularities (Poincare-Hopf: indices sum to 4 chi), and
// writes the fields (first vector per face) as PLY face properties and the hatching of the
// smoothest cross field (its evenly spaced streamlines, two families) as OBJ polylines; with
// Cairo, a picture of the smoothest cross field (<prefix>_smoothest.png): coloured by its energy
// density (where it turns), a cross per grid cell, the singular vertices marked.
//
// Usage: n_field_design [mesh] [output-prefix] [number-of-eigenfields]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Tangent_vector_fields/N_field_spline.h>
#include <CGAL/Tangent_vector_fields/Streamlines.h>
#include <CGAL/Tangent_vector_fields/curvature_direction_field.h>
#include <CGAL/Tangent_vector_fields/face_field_io.h>
#include <CGAL/Tangent_vector_fields/field_export.h>
#include <CGAL/Tangent_vector_fields/smoothest_n_field.h>
#ifdef TVF_HAS_CAIRO
#include <CGAL/Tangent_vector_fields/Field_picture.h>
#endif

#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Face_index Face_index;
typedef Mesh::Vertex_index Vertex_index;
namespace TVF = CGAL::Tangent_vector_fields;

namespace {

int index_sum(const std::vector<std::pair<Vertex_index, int>>& singular)
{
  int sum = 0;
  for(const auto& s : singular) sum += s.second;
  return sum;
}

// E_D and E_B of a face field of first vectors (with magnitude), through the operators.
std::pair<double, double> energies(const TVF::N_field_operators& ops, const Mesh& mesh,
                                   Mesh::Property_map<Face_index, K::Vector_3> field)
{
  Eigen::VectorXd x(2 * mesh.number_of_faces());
  for(Face_index f : mesh.faces())
  {
    const auto ab = ops.mesh().to_frame(static_cast<int>(f), {field[f].x(), field[f].y(), field[f].z()});
    x[2 * f] = ab[0];
    x[2 * f + 1] = ab[1];
  }
  const Eigen::VectorXd z = ops.from_vectors(x);
  return {ops.dirichlet_energy(z), ops.m_harmonic_energy(z, 2)};
}

// Mean angle (degrees) between the crosses of `field` and those of `guide`, weighted by the
// guide's length (where the curvature defines a direction).
double angle_to_guide(const TVF::N_field_operators& ops, const Mesh& mesh, Mesh::Property_map<Face_index, K::Vector_3> field,
                      Mesh::Property_map<Face_index, K::Vector_3> guide)
{
  double sum = 0, weight = 0;
  for(Face_index f : mesh.faces())
  {
    const int i = static_cast<int>(f);
    const auto u = ops.mesh().to_frame(i, {field[f].x(), field[f].y(), field[f].z()});
    const auto g = ops.mesh().to_frame(i, {guide[f].x(), guide[f].y(), guide[f].z()});
    const double w = std::hypot(g[0], g[1]);
    if(w == 0 || std::hypot(u[0], u[1]) == 0) continue;
    // The crosses' angle: the difference of 4 theta, wrapped, over 4.
    const double d = std::remainder(4 * (std::atan2(u[1], u[0]) - std::atan2(g[1], g[0])), 2 * M_PI) / 4;
    sum += w * std::abs(d);
    weight += w;
  }
  return weight > 0 ? sum / weight * 180 / M_PI : 0;
}

} // namespace

int main(int argc, char** argv)
{
  const std::string path = argc > 1 ? argv[1] : TVF_DEFAULT_MESH;
  const std::string prefix = argc > 2 ? argv[2] : "n_field_design";
  const int d = argc > 3 ? std::atoi(argv[3]) : 200;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || mesh.is_empty() || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "cannot read a triangle mesh from " << path << "\n";
    return 1;
  }
  const int chi = static_cast<int>(mesh.number_of_vertices()) - static_cast<int>(mesh.number_of_edges()) +
                  static_cast<int>(mesh.number_of_faces());
  std::cout << path << ": " << mesh.number_of_faces() << " faces, Euler characteristic " << chi
            << " (cross-field indices sum to 4 chi = " << 4 * chi << ")\n";

  // 1. The smoothest cross field.
  auto smoothest = mesh.add_property_map<Face_index, K::Vector_3>("f:smoothest", CGAL::NULL_VECTOR).first;
  auto start = std::chrono::steady_clock::now();
  const auto singular = TVF::smoothest_n_field(mesh, 4, smoothest);
  std::cout << "smoothest cross field: " << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
            << " s, " << singular.size() << " singularities, indices sum to " << index_sum(singular) << "/4\n";
  // Its hatching: evenly spaced streamlines of both families, stopping at the singularities.
  TVF::Evenly_spaced_options even;
  even.separation = 0.01; // of the bounding-box diagonal
  const std::vector<TVF::Streamline> hatching = TVF::evenly_spaced_n_field_streamlines(mesh, 4, smoothest, even);
  int into_singularities = 0;
  for(const TVF::Streamline& s : hatching)
    into_singularities += (s.backward_stop == TVF::Streamline_stop::singular_vertex) +
                          (s.forward_stop == TVF::Streamline_stop::singular_vertex);
  TVF::write_streamlines_obj(prefix + "_hatching.obj", hatching);
  std::cout << "  hatching: " << hatching.size() << " streamlines, " << into_singularities
            << " ends at singularities (" << prefix << "_hatching.obj)\n";

  // 2 and 3: the same six crosses, first-order and higher-order.
  std::vector<std::pair<Face_index, K::Vector_3>> crosses;
  for(int i = 0; i < 6; ++i)
  {
    const Face_index f(static_cast<Mesh::size_type>((2 * i + 1) * mesh.number_of_faces() / 12));
    const auto h = mesh.halfedge(f);
    crosses.push_back({f, mesh.point(mesh.target(h)) - mesh.point(mesh.source(h))}); // along an edge
  }
  auto first_order = mesh.add_property_map<Face_index, K::Vector_3>("f:first_order", CGAL::NULL_VECTOR).first;
  auto spline = mesh.add_property_map<Face_index, K::Vector_3>("f:spline", CGAL::NULL_VECTOR).first;
  auto reduced = mesh.add_property_map<Face_index, K::Vector_3>("f:reduced", CGAL::NULL_VECTOR).first;
  auto index = mesh.add_property_map<Vertex_index, int>("v:index", 0).first;
  TVF::N_field_spline<Mesh> design1(mesh, 4, TVF::parameters::default_values(), {}, 1);
  TVF::N_field_spline<Mesh> design2(mesh, 4);
  TVF::N_field_spline<Mesh> design2_reduced(mesh, 4, TVF::parameters::number_of_eigenfields(d));
  for(const auto& [f, v] : crosses)
  {
    design1.add_vector(f, v);
    design2.add_vector(f, v);
    design2_reduced.add_vector(f, v);
  }
  design1.field(first_order);
  design2.field(spline);
  start = std::chrono::steady_clock::now();
  design2_reduced.field(reduced);
  const double reduced_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto& ops = design2.operators();
  const auto e1 = energies(ops, mesh, first_order), e2 = energies(ops, mesh, spline), e3 = energies(ops, mesh, reduced);
  std::cout << "six crosses, first-order design (min E_D): E_D " << e1.first << ", E_B " << e1.second << ", "
            << design1.singularities(index).size() << " singularities\n"
            << "six crosses, higher-order spline (min E_B): E_D " << e2.first << ", E_B " << e2.second << ", "
            << design2.singularities(index).size() << " singularities\n"
            << "  reduced on " << design2_reduced.basis()->size() << " eigenfields: E_B " << e3.second << " (field "
            << reduced_seconds * 1e3 << " ms)\n";
  // An edit of the reduced spline: turn the first cross by 30 degrees.
  const auto& [f0, v0] = crosses.front();
  const auto n0 = CGAL::cross_product(mesh.point(mesh.target(mesh.halfedge(f0))) - mesh.point(mesh.source(mesh.halfedge(f0))),
                                      mesh.point(mesh.target(mesh.next(mesh.halfedge(f0)))) -
                                          mesh.point(mesh.source(mesh.next(mesh.halfedge(f0)))));
  const K::Vector_3 turned = std::cos(M_PI / 6) * v0 + std::sin(M_PI / 6) * CGAL::cross_product(n0, v0) /
                                                           std::sqrt(n0.squared_length());
  start = std::chrono::steady_clock::now();
  design2_reduced.set_vector(0, turned);
  design2_reduced.solver().field();
  std::cout << "  edit (turn a cross) + reconstruction: "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() * 1e3 << " ms\n";

  // A prescribed pair of singularities, in the connection.
  auto prescribed = mesh.add_property_map<Face_index, K::Vector_3>("f:prescribed", CGAL::NULL_VECTOR).first;
  const Vertex_index a(0), b(static_cast<Mesh::size_type>(mesh.number_of_vertices() / 2));
  if(!mesh.is_border(a) && !mesh.is_border(b))
  {
    TVF::N_field_spline<Mesh> designed(mesh, 4, TVF::parameters::default_values(), {{a, 1}, {b, -1}});
    designed.add_vector(crosses.front().first, crosses.front().second);
    designed.field(prescribed);
    designed.singularities(index);
    std::cout << "prescribed +1/4 at vertex " << a << " and -1/4 at vertex " << b << ": the field has " << index[a]
              << "/4 and " << index[b] << "/4 there\n";
    if(index[a] != 1 || index[b] != -1) return 1;
  }

  // 4. Aligned to the principal curvature directions: a guide of weight |k1 - k2| per face.
  auto curvature = mesh.add_property_map<Face_index, K::Vector_3>("f:curvature", CGAL::NULL_VECTOR).first;
  auto aligned = mesh.add_property_map<Face_index, K::Vector_3>("f:aligned", CGAL::NULL_VECTOR).first;
  auto aligned_spline = mesh.add_property_map<Face_index, K::Vector_3>("f:aligned_spline", CGAL::NULL_VECTOR).first;
  const TVF::Curvature_direction_report fit = TVF::curvature_direction_field(mesh, curvature);
  const auto aligned_singular =
      TVF::smoothest_n_field(mesh, 4, aligned, TVF::parameters::alignment_field_map(curvature).alignment_weight(10.));
  TVF::N_field_spline<Mesh> design_aligned(mesh, 4,
                                           TVF::parameters::alignment_field_map(curvature).alignment_weight(1e4));
  for(const auto& [f, v] : crosses) design_aligned.add_vector(f, v);
  design_aligned.field(aligned_spline);
  const double before = angle_to_guide(ops, mesh, smoothest, curvature), after = angle_to_guide(ops, mesh, aligned, curvature);
  std::cout << "curvature directions by jet fitting (" << fit.fitted_vertices << " vertices fitted, " << fit.unfitted_vertices
            << " not)\n"
            << "  smoothest cross field: " << before << " degrees from them on average; aligned (weight 10): " << after
            << " degrees, " << aligned_singular.size() << " singularities\n"
            << "  six crosses, spline: " << angle_to_guide(ops, mesh, spline, curvature) << " degrees; aligned (weight 1e4): "
            << angle_to_guide(ops, mesh, aligned_spline, curvature) << " degrees\n";
  if(!(after < before)) return 1;

  for(const char* name : {"smoothest", "first_order", "spline", "reduced", "prescribed", "curvature", "aligned",
                          "aligned_spline"})
  {
    auto map = mesh.property_map<Face_index, K::Vector_3>(std::string("f:") + name).first;
    TVF::add_face_field_properties(mesh, name, map);
  }
#ifdef TVF_HAS_CAIRO
  {
    TVF::Render_options view;
    view.width = 900;
    view.height = 700;
    view.title = "smoothest cross field";
    TVF::Field_picture<Mesh> picture(mesh, view);
    TVF::Scalar_colouring turning;
    turning.logarithmic = true; // the density peaks at the singularities, orders of magnitude above the rest
    turning.clip_fraction = 0.02;
    turning.label = "energy density (log scale)";
    picture.colour_by_n_field_energy(smoothest, 4, turning);
    TVF::Arrow_style white_crosses;
    white_crosses.colour = {1, 1, 1};
    white_crosses.spacing = 18;
    picture.add_n_field_glyphs(smoothest, 4, white_crosses);
    picture.add_n_field_singularities(smoothest, 4);
    picture.write_png(prefix + "_smoothest.png");
    std::cout << "wrote " << prefix << "_smoothest.png\n";
  }
#endif
  std::ofstream out(prefix + ".ply", std::ios::binary);
  CGAL::IO::write_PLY(out, mesh);
  std::cout << "wrote " << prefix << ".ply (face properties smoothest, first_order, spline, reduced, prescribed, curvature, "
               "aligned, aligned_spline)\n";
  return index_sum(singular) == 4 * chi ? 0 : 1;
}
