// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Seeing a field: split a tangent field into its curl-free, divergence-free and
// harmonic parts, and draw them.
//   <prefix>_divergence.png / .svg  the mesh coloured by the divergence of the field,
//                                   with evenly spaced streamlines of its curl-free part
//   <prefix>_coexact_fur.png        the magnitude and fur strokes of the divergence-free part
//   <prefix>_harmonic.png           coloured by the magnitude of the harmonic part, its streamlines
//   <prefix>_arrows.png             the field itself as arrows
// and exports for other programs: <prefix>.vtp (mesh and the four fields, for ParaView),
// <prefix>_exact_streamlines.obj / .ply / .vtp, <prefix>_field.rawfield (Directional).
// The exports are read back and compared.
//
// Usage: field_pictures [mesh.off|obj|ply] [output-prefix] [image-width]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Tangent_vector_fields/Field_picture.h>
#include <CGAL/Tangent_vector_fields/field_export.h>
#include <CGAL/Tangent_vector_fields/hodge_decomposition.h>

#include <chrono>
#include <cstdio>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Face_index Face_index;
typedef Mesh::Vertex_index Vertex_index;
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
  const std::string prefix = argc > 2 ? argv[2] : "field_pictures";
  const int width = argc > 3 ? std::atoi(argv[3]) : 1200;

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(input, mesh, CGAL::parameters::verbose(false)) || is_empty(mesh))
  {
    std::cerr << "error: cannot read a polygon mesh from '" << input << "'\n";
    return 1;
  }
  std::cout << "mesh: " << input << ", " << mesh.number_of_faces() << " faces\n";

  try
  {
    // The field of the Hodge demo: a constant wind, a swirl about the z axis and a
    // source at the centre of the bounding box, projected onto the faces.
    TVF::Hodge_decomposition<Mesh> hodge(mesh);
    const auto& ops = hodge.operators();
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
    ops.from_frame_coordinates(ops.to_frame_coordinates(field), field);

    auto exact = mesh.add_property_map<Face_index, K::Vector_3>("f:exact").first;
    auto coexact = mesh.add_property_map<Face_index, K::Vector_3>("f:coexact").first;
    auto harmonic = mesh.add_property_map<Face_index, K::Vector_3>("f:harmonic").first;
    auto t = std::chrono::steady_clock::now();
    hodge(field, TVF::parameters::exact_part_map(exact).coexact_part_map(coexact).harmonic_part_map(harmonic));
    std::printf("Hodge decomposition: %.3f s (harmonic dimension %d)\n", seconds_since(t), hodge.harmonic_dimension());
    auto divergence = mesh.add_property_map<Vertex_index, double>("v:divergence", 0.).first;
    ops.divergence(field, divergence);

    // One camera for all pictures: y is up, seen from the front-right, a little above.
    TVF::Render_options options;
    options.width = width;
    options.height = width * 3 / 4;
    options.camera.azimuth = 15;
    options.camera.elevation = 10;
    TVF::Scalar_colouring signed_values;
    signed_values.map = TVF::Colour_map::cool_warm;
    signed_values.symmetric = true;
    signed_values.clip_fraction = 0.05; // a few large values at the tips would wash out the rest

    // 1. Divergence, with streamlines of the curl-free part: they leave the sources
    //    (red) and run into the sinks (blue).
    t = std::chrono::steady_clock::now();
    TVF::Field_picture<Mesh> divergence_picture(mesh, options);
    divergence_picture.options().title = "divergence, streamlines of the curl-free part";
    signed_values.label = "divergence";
    divergence_picture.colour_vertices(divergence, signed_values);
    TVF::Evenly_spaced_options even;
    even.separation = 0.018;
    TVF::Line_style dark;
    dark.width = 1.3;
    const std::vector<TVF::Streamline> exact_lines =
        divergence_picture.add_evenly_spaced_streamlines(exact, even, dark);
    const double t_trace = seconds_since(t);
    t = std::chrono::steady_clock::now();
    divergence_picture.write_png(prefix + "_divergence.png");
    const double t_render = seconds_since(t);
    divergence_picture.write_svg(prefix + "_divergence.svg");
    std::printf("curl-free part: %zu evenly spaced streamlines traced in %.3f s, picture rendered in %.3f s\n",
                exact_lines.size(), t_trace, t_render);

    // 2. The divergence-free part: its magnitude, and fur strokes along it (thick at
    //    the root, thin at the tip: the strokes point along the field).
    TVF::Field_picture<Mesh> fur_picture(mesh, options);
    fur_picture.options().title = "divergence-free part: magnitude and fur";
    TVF::Scalar_colouring magnitude;
    magnitude.label = "|divergence-free|";
    magnitude.clip_fraction = 0.01;
    fur_picture.colour_by_magnitude(coexact, magnitude);
    TVF::Fur_options fur;
    fur.number_of_strokes = 5000;
    fur.length = 0.03;
    TVF::Line_style white_fur = TVF::Field_picture<Mesh>::fur_style();
    white_fur.colour = {1, 1, 1};
    const auto strokes = fur_picture.add_fur(coexact, fur, white_fur);
    fur_picture.write_png(prefix + "_coexact_fur.png");
    std::printf("divergence-free part: %zu fur strokes\n", strokes.size());

    // 3. The harmonic part: its magnitude and its streamlines, which wind around the handles.
    TVF::Field_picture<Mesh> harmonic_picture(mesh, options);
    harmonic_picture.options().title = "harmonic part";
    magnitude.label = "|harmonic|";
    harmonic_picture.colour_by_magnitude(harmonic, magnitude);
    TVF::Line_style light;
    light.colour = {1, 1, 1};
    light.width = 1.3;
    even.separation = 0.022;
    harmonic_picture.add_evenly_spaced_streamlines(harmonic, even, light);
    harmonic_picture.write_png(prefix + "_harmonic.png");

    // 4. The field itself as arrows on the plain surface.
    TVF::Field_picture<Mesh> arrow_picture(mesh, options);
    arrow_picture.options().title = "the field";
    TVF::Arrow_style arrows;
    arrows.spacing = width / 45.0;
    arrow_picture.add_arrows(field, arrows);
    arrow_picture.write_png(prefix + "_arrows.png");

    // Exports, read back and compared.
    TVF::write_vtp(prefix + ".vtp", mesh,
                   std::vector<std::pair<std::string, decltype(field)>>{
                       {"input", field}, {"exact", exact}, {"coexact", coexact}, {"harmonic", harmonic}});
    TVF::write_streamlines_obj(prefix + "_exact_streamlines.obj", exact_lines);
    TVF::write_streamlines_ply(prefix + "_exact_streamlines.ply", exact_lines);
    TVF::write_streamlines_vtp(prefix + "_exact_streamlines.vtp", exact_lines);
    TVF::write_raw_field(prefix + "_field.rawfield", mesh, field);
    auto back = mesh.add_property_map<Face_index, K::Vector_3>("f:read_back").first;
    int mismatches = 0;
    TVF::read_raw_field(prefix + "_field.rawfield", mesh, back);
    for(Face_index f : mesh.faces()) mismatches += back[f] != field[f];
    TVF::read_vtp(prefix + ".vtp", mesh, "coexact", back);
    for(Face_index f : mesh.faces()) mismatches += back[f] != coexact[f];
    if(mismatches > 0)
    {
      std::cerr << "error: " << mismatches << " vectors differ after reading the exports back\n";
      return 1;
    }
    std::cout << "wrote " << prefix << "_{divergence.png,divergence.svg,coexact_fur.png,harmonic.png,arrows.png}, " << prefix
              << ".vtp, " << prefix << "_exact_streamlines.{obj,ply,vtp}, " << prefix
              << "_field.rawfield (read back: identical)\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
