// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Benchmark: streamline tracing and rendering on a large mesh (default: the shared
// armadillo, Loop-subdivided once to 345,928 faces).  Prints the time of each step:
// the intrinsic mesh, the tracer, evenly spaced streamlines at two separations,
// fur strokes, single streamlines, and pictures (surface alone, with streamlines,
// with fur) as PNG and SVG.
//
// Usage: bench_visual [mesh] [loop-subdivisions] [image-width] [output-prefix]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>
#include <CGAL/Tangent_vector_fields/internal/Mesh_adapter.h>
#ifdef TVF_HAS_CAIRO
#include <CGAL/Tangent_vector_fields/Field_renderer.h>
#endif

#include <chrono>
#include <cstdio>
#include <functional>
#include <iostream>
#include <random>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace TVF = CGAL::Tangent_vector_fields;

namespace {

double time_of(const std::function<void()>& f)
{
  const auto t = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

std::size_t segments_of(const std::vector<TVF::Streamline>& lines)
{
  std::size_t n = 0;
  for(const auto& s : lines) n += s.number_of_segments();
  return n;
}

} // namespace

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : std::string(TVF_SHARED_DATA_DIR) + "/armadillo.obj";
  const int subdivisions = argc > 2 ? std::atoi(argv[2]) : 1;
  const int width = argc > 3 ? std::atoi(argv[3]) : 1600;
  const std::string prefix = argc > 4 ? argv[4] : "bench_visual";

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(input, mesh, CGAL::parameters::verbose(false)) || is_empty(mesh))
  {
    std::cerr << "error: cannot read '" << input << "'\n";
    return 1;
  }
  const double t_subdivide = time_of([&] {
    if(subdivisions > 0)
      CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(subdivisions));
  });
  std::printf("mesh: %s, %d Loop subdivision(s): %zu vertices, %zu faces (subdivision %.2f s)\n", input.c_str(),
              subdivisions, static_cast<std::size_t>(mesh.number_of_vertices()),
              static_cast<std::size_t>(mesh.number_of_faces()), t_subdivide);

  std::shared_ptr<const TVF::Intrinsic_mesh> im;
  const double t_mesh = time_of([&] { im = TVF::internal::Mesh_adapter<Mesh>(mesh, TVF::parameters::default_values()).intrinsic_mesh(); });

  // A smooth field: a swirl about the vertical axis plus a wind, projected on the faces.
  Eigen::VectorXd field(2 * im->number_of_faces());
  for(int f = 0; f < im->number_of_faces(); ++f)
  {
    std::array<double, 3> c = {0, 0, 0};
    for(int v : im->face_vertices(f))
      for(int i = 0; i < 3; ++i) c[i] += im->position(v)[i] / 3;
    const auto ab = im->to_frame(f, {-c[2] + 0.3, 0.2, c[0]});
    field[2 * f] = ab[0];
    field[2 * f + 1] = ab[1];
  }

  std::unique_ptr<TVF::Streamline_tracer> tracer;
  const double t_tracer = time_of([&] { tracer = std::make_unique<TVF::Streamline_tracer>(im, field); });
  std::printf("\n%-52s %10s %10s %12s\n", "step", "time [s]", "lines", "segments");
  std::printf("%-52s %10.3f\n", "intrinsic mesh (validation, lengths, layout)", t_mesh);
  std::printf("%-52s %10.3f\n", "tracer set-up (layout gradients, vertex fans)", t_tracer);

  std::vector<TVF::Streamline> coarse, fine, fur, single;
  for(double separation : {0.01, 0.005})
  {
    TVF::Evenly_spaced_options options;
    options.separation = separation;
    std::vector<TVF::Streamline>& out = separation == 0.01 ? coarse : fine;
    const double t = time_of([&] { out = tracer->evenly_spaced(options); });
    char name[80];
    std::snprintf(name, sizeof name, "evenly spaced, separation %.3g x diagonal", separation);
    std::printf("%-52s %10.3f %10zu %12zu\n", name, t, out.size(), segments_of(out));
  }
  TVF::Fur_options hair;
  hair.number_of_strokes = 50000;
  hair.length = 0.01;
  const double t_fur = time_of([&] { fur = tracer->fur(hair); });
  std::printf("%-52s %10.3f %10zu %12zu\n", "fur, 50000 strokes of 0.01 x diagonal", t_fur, fur.size(), segments_of(fur));
  std::mt19937 gen(1);
  std::uniform_int_distribution<int> face(0, im->number_of_faces() - 1);
  TVF::Streamline_options limit;
  limit.maximum_segments = 20000;
  const double t_single = time_of([&] {
    for(int i = 0; i < 1000; ++i) single.push_back(tracer->trace(face(gen), {0.2, 0.3, 0.5}, limit));
  });
  std::printf("%-52s %10.3f %10zu %12zu\n", "1000 single streamlines (both directions)", t_single, single.size(),
              segments_of(single));

#ifdef TVF_HAS_CAIRO
  TVF::Render_options options;
  options.width = width;
  options.height = width * 3 / 4;
  options.camera.azimuth = 0; // the armadillo faces +z
  options.camera.elevation = 10;
  TVF::Field_renderer renderer(im, options);
  const double t_plain = time_of([&] { renderer.write_png(prefix + "_surface.png"); });
  std::printf("%-52s %10.3f\n", ("picture " + std::to_string(width) + " px wide, surface only (PNG)").c_str(), t_plain);
  renderer.add_streamlines(fine);
  const double t_lines = time_of([&] { renderer.write_png(prefix + "_streamlines.png"); });
  std::printf("%-52s %10.3f %10zu %12zu\n", "picture with the fine streamlines (PNG)", t_lines, fine.size(),
              segments_of(fine));
  const double t_svg = time_of([&] { renderer.write_svg(prefix + "_streamlines.svg"); });
  std::printf("%-52s %10.3f\n", "the same as SVG", t_svg);
  renderer.clear_overlays();
  TVF::Line_style tapered;
  tapered.taper = true;
  renderer.add_streamlines(fur, tapered);
  std::vector<double> height(im->number_of_vertices());
  for(int v = 0; v < im->number_of_vertices(); ++v) height[v] = im->position(v)[1];
  renderer.colour_vertices(height, TVF::Scalar_colouring());
  const double t_fur_picture = time_of([&] { renderer.write_png(prefix + "_fur.png"); });
  std::printf("%-52s %10.3f %10zu %12zu\n", "picture with colours and fur (PNG)", t_fur_picture, fur.size(),
              segments_of(fur));
#else
  (void)width;
  std::printf("(pictures not measured: built without Cairo)\n");
#endif
  return 0;
}
