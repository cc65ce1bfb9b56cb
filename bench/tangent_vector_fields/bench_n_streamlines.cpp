// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Benchmark: streamlines of the smoothest n-field (default: a cross field) of a mesh given on
// the command line (default: the shared armadillo, Loop-subdivided once to 345,928 faces).
// Prints one row per step -- faces, lines, total length, seconds -- for the smoothest field,
// the tracer (with the singular vertices), single streamlines along every branch from random
// seeds, the evenly spaced hatching of all families at two separations, fur of all branches,
// and (with Cairo) a picture of the hatching.
//
// Usage: bench_n_streamlines [mesh] [loop-subdivisions] [--n N] [--seeds K] [--picture PREFIX]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <CGAL/Tangent_vector_fields/N_field_operators.h>
#include <CGAL/Tangent_vector_fields/Smoothest_n_field_solver.h>
#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>
#include <CGAL/Tangent_vector_fields/internal/Mesh_adapter.h>
#ifdef TVF_HAS_CAIRO
#include <CGAL/Tangent_vector_fields/Field_renderer.h>
#endif

#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <iostream>
#include <memory>
#include <random>
#include <string>

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

double total_length(const std::vector<TVF::Streamline>& lines)
{
  double l = 0;
  for(const TVF::Streamline& s : lines) l += s.length();
  return l;
}

void row(const std::string& step, int faces, const std::vector<TVF::Streamline>* lines, double seconds)
{
  if(lines)
    std::printf("%-50s %9d %9zu %13.4g %9.3f\n", step.c_str(), faces, lines->size(), total_length(*lines), seconds);
  else
    std::printf("%-50s %9d %9s %13s %9.3f\n", step.c_str(), faces, "", "", seconds);
}

} // namespace

int main(int argc, char** argv)
{
  std::string input = std::string(TVF_SHARED_DATA_DIR) + "/armadillo.obj", picture;
  int subdivisions = 1, n = 4, seeds = 1000, positional = 0;
  for(int i = 1; i < argc; ++i)
  {
    const bool has_value = i + 1 < argc;
    if(!std::strcmp(argv[i], "--n") && has_value)
      n = std::atoi(argv[++i]);
    else if(!std::strcmp(argv[i], "--seeds") && has_value)
      seeds = std::atoi(argv[++i]);
    else if(!std::strcmp(argv[i], "--picture") && has_value)
      picture = argv[++i];
    else if(argv[i][0] != '-' && positional < 2)
    {
      if(positional++ == 0)
        input = argv[i];
      else
        subdivisions = std::atoi(argv[i]);
    }
    else
    {
      std::cerr << "usage: bench_n_streamlines [mesh] [loop-subdivisions] [--n N] [--seeds K] [--picture PREFIX]\n";
      return 1;
    }
  }

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(input, mesh, CGAL::parameters::verbose(false)) || is_empty(mesh))
  {
    std::cerr << "error: cannot read '" << input << "'\n";
    return 1;
  }
  if(subdivisions > 0)
    CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(subdivisions));
  const int faces = static_cast<int>(mesh.number_of_faces());
  std::printf("mesh: %s, %d Loop subdivision(s): %zu vertices, %d faces; n = %d\n\n", input.c_str(), subdivisions,
              static_cast<std::size_t>(mesh.number_of_vertices()), faces, n);
  std::printf("%-50s %9s %9s %13s %9s\n", "step", "faces", "lines", "total length", "seconds");

  try
  {
    const auto im = TVF::internal::Mesh_adapter<Mesh>(mesh, TVF::parameters::default_values()).intrinsic_mesh();
    const TVF::N_field_operators ops(std::make_shared<const TVF::Operator_matrices>(im), n);
    Eigen::VectorXd z;
    row("smoothest field (operators, eigenpair)", faces, nullptr, time_of([&] { z = TVF::smoothest_n_field(ops); }));

    std::unique_ptr<TVF::Streamline_tracer> tracer;
    row("tracer (layout, vertex fans, singular vertices)", faces, nullptr,
        time_of([&] { tracer = std::make_unique<TVF::Streamline_tracer>(ops, z); }));
    std::printf("  %zu singular vertices, %d families\n", tracer->singular_vertices().size(),
                tracer->number_of_families());

    std::vector<TVF::Streamline> single;
    std::mt19937 gen(1);
    std::uniform_int_distribution<int> face(0, faces - 1);
    TVF::Streamline_options limit;
    limit.maximum_segments = 20000;
    const double t_single = time_of([&] {
      for(int i = 0; i < seeds; ++i)
      {
        const int f = face(gen);
        for(int j = 0; j < n; ++j)
        {
          limit.branch = j;
          single.push_back(tracer->trace(f, {0.2, 0.3, 0.5}, limit));
        }
      }
    });
    row(std::to_string(seeds) + " seeds x " + std::to_string(n) + " branches, both directions", faces, &single,
        t_single);

    std::vector<TVF::Streamline> hatching;
    for(double separation : {0.01, 0.005})
    {
      TVF::Evenly_spaced_options options;
      options.separation = separation;
      const double t = time_of([&] { hatching = tracer->evenly_spaced(options); });
      char name[80];
      std::snprintf(name, sizeof name, "hatching, separation %.3g x diagonal", separation);
      row(name, faces, &hatching, t);
    }

    std::vector<TVF::Streamline> fur;
    TVF::Fur_options hair;
    hair.number_of_strokes = 20000;
    hair.length = 0.005;
    row("fur, 20000 roots x all branches, 0.005 x diagonal", faces, &fur,
        time_of([&] { fur = tracer->fur(hair); }));

#ifdef TVF_HAS_CAIRO
    if(!picture.empty())
    {
      TVF::Render_options options;
      options.width = 1600;
      options.height = 1200;
      options.camera.azimuth = 0;
      options.camera.elevation = 10;
      TVF::Field_renderer renderer(im, options);
      renderer.add_streamlines(hatching);
      row("picture of the fine hatching, 1600 x 1200 (PNG)", faces, &hatching,
          time_of([&] { renderer.write_png(picture + "_hatching.png"); }));
    }
#else
    if(!picture.empty()) std::printf("(no picture: built without Cairo)\n");
#endif
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
