// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Seeing n-direction fields from the command line: `render --n N` (glyphs, hatching, fur, the
// singular vertices, the energy density) and `streamlines --n N` (the hatching as polylines).

#include "tool_n_fields.h"

#include <CGAL/Tangent_vector_fields/errors.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace tvf_tool {

int n_field_render_command(const Arguments& args)
{
  Command_line command("tvf render <mesh> --n N --field FILE [--color Q] [--glyphs] [view] -o FILE.png|.svg",
                       "Draws an n-field: the surface coloured by its smoothness energy density (per unit area, on a\n"
                       "log scale: where the field turns) or its magnitude, the field as n-fold glyphs on a screen grid\n"
                       "(N spokes from each cell centre: a segment for N = 2, a cross for N = 4; arrows for N = 1), and\n"
                       "the singular vertices as discs (red positive, blue negative, area by |index|) where the surface\n"
                       "shows them.  Prints the energy and the singularities.  PNG or SVG.");
  command.positional("mesh", "the mesh file");
  add_symmetry_options(command);
  add_field_options(command);
  po::options_description& picture = command.group("picture");
  picture.add_options()
    ("color", po::value<std::string>()->default_value("energy")->value_name("Q"),
     "colour the surface by: energy (the energy density of the field, log scale), magnitude (faces) or none");
  add_colour_scale_options(picture);
  picture.add_options()
    ("glyphs", "draw the field as n-fold glyphs (the default)")
    ("no-overlay", "draw no glyphs (colours and singularities only)")
    ("streamlines", "hatching: evenly spaced streamlines of all N families (lines of one family keep --separation)")
    ("fur", "fur strokes along every one of the N vectors of each root")
    ("no-singularities", "do not mark the singular vertices")
    ("singularity-labels", "write the index k/N next to each singular vertex")
    ("singularity-size", po::value<double>()->value_name("PX"), "radius of the mark of index 1/N (default width / 200)")
    ("list", po::value<int>()->default_value(0)->value_name("K"), "print the first K singular vertices");
  add_mark_options(picture);
  add_streamline_options(command);
  add_view_and_output_options(command);
  if(!command.parse(args)) return 0; // --help
  require_pictures();
#ifdef TVF_HAS_CAIRO
  command.at_most_one({"glyphs", "no-overlay"});
  command.at_most_one({"no-overlay", "streamlines"});
  command.at_most_one({"no-overlay", "fur"});
  const TVF::Length_unit unit = length_unit(command.get<std::string>("unit"));
  const TVF::Evenly_spaced_options even = evenly_spaced_options(command, unit);
  const TVF::Fur_options fur = fur_options(command, unit);
  const TVF::Render_options options = render_options(command);
  const std::string colour = command.get<std::string>("color");
  if(colour != "energy" && colour != "magnitude" && colour != "none")
    throw Usage_error("unknown --color '" + colour + "' for an n-field (energy, magnitude or none)");
  TVF::Scalar_colouring colouring = colour_scale(command, TVF::Colour_map::viridis);
  TVF::Singularity_style marks;
  marks.radius = command.has("singularity-size") ? command.get<double>("singularity-size") : std::max(3., options.width / 200.);
  if(!(marks.radius > 0) || !std::isfinite(marks.radius)) throw Usage_error("'--singularity-size' must be positive");
  marks.labels = command.has("singularity-labels");
  if(command.get<int>("list") < 0) throw Usage_error("'--list' must be at least 0");

  const Tool_mesh mesh(command.positional_value(), command.mollify());
  const N_operators ops = n_field_operators(command, mesh);
  const int n = ops->n();
  const Eigen::VectorXd z = read_n_field(command, mesh, *ops);
  const auto start = std::chrono::steady_clock::now();
  TVF::Field_renderer renderer(mesh.shared_intrinsic(), options);
  const Eigen::VectorXd density = ops->energy_density(z);
  say("%d-field on %d faces: E_D %.6g; energy density from %.4g to %.4g per unit area\n", n, mesh.number_of_faces(),
      ops->dirichlet_energy(z), density.minCoeff(), density.maxCoeff());
  if(colour == "energy")
  {
    colouring.logarithmic = true; // it peaks at the singularities, orders of magnitude above the rest
    colouring.label = "energy density";
    renderer.colour_faces(to_std_vector(density), colouring);
  }
  else if(colour == "magnitude")
  {
    colouring.label = "|field|";
    std::vector<double> m(static_cast<std::size_t>(mesh.number_of_faces()));
    for(std::size_t f = 0; f < m.size(); ++f) m[f] = std::hypot(z[2 * f], z[2 * f + 1]); // |z_f|: the vectors' length
    renderer.colour_faces(std::move(m), colouring);
  }
  // Overlays: hatching and fur through the n-field tracer (the branch matched across edges, stops
  // at the singular vertices); glyphs unless lines were asked for, sharing the arrows' options.
  const TVF::Colour lines = line_colour(command, colour != "none" && colouring.map == TVF::Colour_map::viridis);
  std::size_t lines_drawn = 0;
  if(command.has("streamlines") || command.has("fur"))
    lines_drawn = add_lines(renderer, TVF::Streamline_tracer(*ops, z), command, lines,
                            command.has("streamlines") ? &even : nullptr, command.has("fur") ? &fur : nullptr);
  const bool glyphs = command.has("glyphs") || (!command.has("no-overlay") && lines_drawn == 0);
  if(glyphs) renderer.add_glyphs(ops->to_vectors(z), n, arrow_style(command, options, lines));
  const std::vector<TVF::N_field_singularity> singular = TVF::n_field_singularities(*ops, z);
  report_singularities(mesh, n, singular, command.get<int>("list"));
  if(!command.has("no-singularities"))
  {
    std::vector<std::pair<int, int>> vertex_k;
    for(const TVF::N_field_singularity& s : singular) vertex_k.emplace_back(s.vertex, s.index);
    renderer.add_singularities(vertex_k, n, marks);
  }
  std::string details;
  if(colour != "none") details += ", colours: " + colour;
  if(glyphs) details += ", " + std::to_string(n) + "-fold glyphs";
  if(lines_drawn > 0) details += ", " + std::to_string(lines_drawn) + " lines";
  if(!command.has("no-singularities")) details += ", " + std::to_string(singular.size()) + " singularities";
  write_pictures(command, renderer, details, start);
#endif
  return 0;
}

int n_field_streamlines_command(const Arguments& args)
{
  Command_line command("tvf streamlines <mesh> --n N --field FILE [--separation S | --fur ...] -o FILE",
                       "The hatching of an n-field: evenly spaced streamlines of every family (N/2 for even N, N for\n"
                       "odd N; the branch matched face by face, stopping at the singular vertices), or fur strokes\n"
                       "along each of the N vectors of random roots; written as polylines (.obj, .ply, .vtp).");
  command.positional("mesh", "the mesh file");
  add_symmetry_options(command);
  add_field_options(command);
  command.group("streamlines").add_options()
    ("fur", "fur strokes instead of the hatching");
  add_streamline_options(command);
  command.group("output").add_options()("output,o", po::value<std::vector<std::string>>()->composing()->value_name("FILE"),
                                        "the polylines: .obj, .ply or .vtp; repeatable");
  if(!command.parse(args)) return 0; // --help
  command.require("output");
  for(const std::string& path : command.get<std::vector<std::string>>("output"))
    if(extension(path) != "obj" && extension(path) != "ply" && extension(path) != "vtp")
      throw Usage_error("cannot write streamlines to '" + path + "': use .obj, .ply or .vtp");
  const TVF::Length_unit unit = length_unit(command.get<std::string>("unit"));
  const TVF::Evenly_spaced_options even = evenly_spaced_options(command, unit);
  const TVF::Fur_options fur = fur_options(command, unit);
  const Tool_mesh mesh(command.positional_value(), command.mollify());
  const N_operators ops = n_field_operators(command, mesh);
  const Eigen::VectorXd z = read_n_field(command, mesh, *ops);
  const auto start = std::chrono::steady_clock::now();
  const TVF::Streamline_tracer tracer(*ops, z);
  std::vector<TVF::Streamline> lines;
  {
    Step step(command.has("fur") ? "growing fur" : "hatching");
    lines = command.has("fur") ? tracer.fur(fur) : tracer.evenly_spaced(even);
  }
  double length = 0;
  for(const TVF::Streamline& l : lines) length += l.length();
  say("%d-field: %zu %s in %d families, total length %.6g (%.4g bounding box diagonals), %zu singular vertices; %.3f s\n",
      ops->n(), lines.size(), command.has("fur") ? "fur strokes" : "streamlines", tracer.number_of_families(), length,
      length / mesh.bounding_box_diagonal(), tracer.singular_vertices().size(), seconds_since(start));
  if(!command.has("fur")) say("  ends: %s\n", stop_summary(lines).c_str());
  write_streamline_files(command, lines);
  return 0;
}

} // namespace tvf_tool
