// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Subcommands that make and show fields: design, render, streamlines, export.  They
// work on frame coordinates through the index-based classes (no Surface_mesh here).

#include "tool.h"
#include "tool_lines.h"

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Full_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Hodge_solver.h>
#include <CGAL/Tangent_vector_fields/Reduced_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Soft_field_design.h>
#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>
#include <CGAL/Tangent_vector_fields/constraint_file_io.h>
#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/field_files.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>

namespace tvf_tool {

// --- design -------------------------------------------------------------------------------------

int design_command(const Arguments& args)
{
  if(wants_n_field(args) || constraint_file_has_n(args)) return n_field_design_command(args);
  Command_line command(
      "tvf design <mesh> --constraints FILE.json [--basis FILE [-d D] [--exact]] [--soft] [--omega W] -o FILE",
      "Designs a field from constraints (vectors, directions, divergences, curls; JSON, see doc/tangent_vector_fields/manual.md).\n"
      "By default the tangent vector field spline at full resolution (min E_B + omega E_D subject to the\n"
      "constraints, exact); with --basis the same spline in the span of a spectral basis (the real-time\n"
      "editor's answer, printed with a guaranteed bound on its error; --exact refines it to the exact\n"
      "spline and prints the error measured); with --soft the soft-constrained design of Fisher et al. (min E_D + omega E_B +\n"
      "sum w_i |C_i x - c_i|^2, weights from the file), full or reduced.  Prints the constraint residual and\n"
      "the warnings of the solver.  A constraint file with \"n\" designs an n-direction field instead (see\n"
      "'tvf design --n 4 --help').");
  command.positional("mesh", "the mesh file");
  command.group("design").add_options()
    ("constraints", po::value<std::string>()->value_name("FILE"), "the constraints (JSON)")
    ("basis", po::value<std::string>()->value_name("FILE"), "solve in the span of this basis (.tvfb)")
    ("basis-size,d", po::value<int>()->value_name("D"), "use the first D elements of the basis (default: all)")
    ("exact", "with --basis: refine the reduced spline to the exact one (written), printing the reduced answer's "
              "measured error next to its bound")
    ("soft", "soft constraints (weights from the file) instead of a spline")
    ("omega", po::value<double>()->value_name("W"),
     "spline tension (or the soft design's biharmonic weight), for the mesh scaled to unit area; default: the "
     "file's \"omega\", else 0");
  add_output_options(command, "the designed field", "design");
  if(!command.parse(args)) return 0; // --help
  command.require("constraints");
  if(command.has("basis-size") && !command.has("basis")) throw Usage_error("'--basis-size' needs '--basis'");
  if(command.has("exact") && command.has("soft"))
    throw Usage_error("'--exact' refines a spline; for the exact soft design drop '--basis'");
  const Tool_mesh mesh(command.positional_value(), command.mollify());

  const std::string constraint_path = command.get<std::string>("constraints");
  {
    std::ifstream in(constraint_path);
    if(!in) throw Tool_error("cannot open constraint file '" + constraint_path + "': " + std::strerror(errno));
  }
  TVF::Constraint_file file;
  try
  {
    file = TVF::read_constraint_file(constraint_path, mesh.matrices());
  }
  catch(const TVF::Invalid_input& e)
  {
    throw Tool_error(about(constraint_path, one_line(e.what())));
  }
  if(file.constraints.empty()) throw Tool_error("'" + constraint_path + "' has no constraints: the design would be zero");
  const double omega = command.has("omega") ? command.get<double>("omega") : file.omega;
  if(!(omega >= 0) || !std::isfinite(omega)) throw Usage_error("'--omega' must be a finite number >= 0");
  const bool soft = command.has("soft");
  const bool weighted = std::any_of(file.weights.begin(), file.weights.end(), [](double w) { return w != 1; });

  std::shared_ptr<const TVF::Eigenfield_basis> basis;
  if(command.has("basis")) basis = load_basis(mesh, command.get<std::string>("basis"));
  const int d = command.has("basis-size") ? command.get<int>("basis-size") : 0;
  if(command.has("basis-size") && (d <= 0 || d > basis->size()))
    throw Tool_error("'--basis-size' must lie in [1, " + std::to_string(basis->size()) + "] (the basis size), not " +
                     std::to_string(d));

  say("mesh: %s, %d faces; %s\n", mesh.path().c_str(), mesh.number_of_faces(),
      mesh.intrinsic().topology().summary().c_str());
  std::string method = soft ? "soft design" : "spline";
  method += basis ? ", reduced to " + std::to_string(d > 0 ? d : basis->size()) + " eigenfields" : ", full resolution";
  say("design: %s, omega %g, %zu constraints from %s\n", method.c_str(), omega, file.constraints.size(),
      constraint_path.c_str());
  if(weighted && !soft) say("  note: the file's weights are used by --soft only\n");

  const auto start = std::chrono::steady_clock::now();
  Eigen::VectorXd x;
  std::vector<std::string> warnings;
  Step step("solving");
  if(!soft)
  {
    TVF::Spline_options options;
    options.omega = omega;
    std::unique_ptr<TVF::Spline_solver> solver;
    if(basis) solver = std::make_unique<TVF::Reduced_spline_solver>(basis, d, options);
    else solver = std::make_unique<TVF::Full_spline_solver>(std::make_shared<TVF::Hodge_solver>(mesh.shared_matrices()), options);
    solver->add(file.constraints);
    x = solver->field();
    const TVF::Spline_report& report = solver->report();
    step.done();
    say("  %d constraints, %d rows; smallest independence (sin^2 of a row's angle to the others) %.3g\n",
        report.constraints, report.rows, report.smallest_independence);
    say("  constraint residual %.2e (largest |C x - c| / largest |c|); energy E_B + omega E_D = %.6g\n",
        report.constraint_residual, report.energy);
    if(report.undetermined_harmonic > 0)
      say("  %d harmonic directions are seen by no constraint (set to zero)\n", report.undetermined_harmonic);
    if(basis) say_error_bound(report);
    warnings = report.warnings;
    if(basis && command.has("exact"))
    {
      Step refine("refining to the exact spline");
      TVF::Full_spline_solver full(std::make_shared<TVF::Hodge_solver>(mesh.shared_matrices()), options);
      full.add(file.constraints);
      const Eigen::VectorXd exact = full.field();
      refine.done();
      const double norm = field_norm(mesh.matrices(), exact);
      say_reduced_against_exact(report, full.report(), norm > 0 ? field_norm(mesh.matrices(), x - exact) / norm : 0.);
      x = exact;
      warnings = full.report().warnings;
    }
  }
  else
  {
    TVF::Soft_design_options options;
    options.omega = omega;
    std::unique_ptr<TVF::Soft_field_design> design;
    if(basis) design = std::make_unique<TVF::Reduced_soft_design>(basis, d, options);
    else design = std::make_unique<TVF::Full_soft_design>(std::make_shared<TVF::Hodge_solver>(mesh.shared_matrices()), options);
    for(std::size_t i = 0; i < file.constraints.size(); ++i) design->add(file.constraints[i], file.weights[i]);
    x = design->field();
    step.done();
    // Soft constraints are met only approximately: how far, and where worst.
    double largest_value = 0, largest_residual = 0;
    std::size_t worst = 0;
    for(std::size_t i = 0; i < file.constraints.size(); ++i)
      for(const TVF::Constraint_row& row : TVF::constraint_rows(mesh.matrices(), file.constraints[i]))
      {
        largest_value = std::max(largest_value, std::abs(row.value) * row.unit_area_scale);
        const double r = std::abs(row.dot(x) - row.value) * row.unit_area_scale;
        if(r > largest_residual)
        {
          largest_residual = r;
          worst = i;
        }
      }
    say("  energy E_D + omega E_B = %.6g; constraint residual %.3g (largest |C x - c| / largest |c|, unit-area "
        "scale), worst at constraint %zu (%s)\n",
        design->energy(), largest_value > 0 ? largest_residual / largest_value : largest_residual, worst,
        file.constraints[worst].describe().c_str());
    if(design->undetermined_harmonic() > 0)
      say("  %d harmonic directions are seen by no constraint (set to zero)\n", design->undetermined_harmonic());
  }
  say("  solved in %.3f s; |field| = %.6g (L2)\n", seconds_since(start), field_norm(mesh.matrices(), x));
  if(warnings.empty()) say("  warnings: none\n");
  for(const std::string& w : warnings) say("  warning: %s\n", one_line(w).c_str());
  if(!write_outputs(command, mesh, x)) say("(no --output given: nothing written)\n");
  return 0;
}

// --- render ---------------------------------------------------------------------------------------

int render_command(const Arguments& args)
{
  if(wants_n_field(args)) return n_field_render_command(args);
  Command_line command(
      "tvf render <mesh> [--field FILE] [--color Q] [--streamlines | --fur | --arrows] [view] -o FILE.png|.svg",
      "Draws the mesh, coloured by a quantity of the field, with evenly spaced streamlines, fur strokes\n"
      "(thick at the root, thin at the tip) or arrows on top; lines behind the surface are hidden.  With a\n"
      "field and no overlay option, streamlines are drawn.  PNG or SVG (the surface as an embedded image,\n"
      "lines and the colour bar as vectors).  With --n N: an n-field (see 'tvf render --n 4 --help').");
  command.positional("mesh", "the mesh file");
  add_field_options(command);
  po::options_description& picture = command.group("picture");
  picture.add_options()
    ("color", po::value<std::string>()->value_name("Q"),
     "colour the surface by: divergence, curl (vertex values, blue-grey-red), magnitude (faces, viridis) or "
     "none; default: magnitude with a field, none without");
  add_colour_scale_options(picture);
  picture.add_options()
    ("streamlines", "draw evenly spaced streamlines")
    ("fur", "draw fur strokes")
    ("arrows", "draw arrows on a screen grid")
    ("no-overlay", "draw only the colours");
  add_mark_options(picture);
  add_streamline_options(command);
  add_view_and_output_options(command);
  if(!command.parse(args)) return 0; // --help
  require_pictures();
#ifdef TVF_HAS_CAIRO
  const TVF::Render_options options = render_options(command);
  const bool has_field = command.has("field") || command.has("field-ply");
  const std::string colour = command.has("color") ? command.get<std::string>("color") : (has_field ? "magnitude" : "none");
  if(colour != "divergence" && colour != "curl" && colour != "magnitude" && colour != "none")
    throw Usage_error("unknown --color '" + colour + "' (divergence, curl, magnitude or none)");
  command.at_most_one({"no-overlay", "streamlines"});
  command.at_most_one({"no-overlay", "fur"});
  command.at_most_one({"no-overlay", "arrows"});
  const bool streamlines = command.has("streamlines") ||
                           (has_field && !command.has("fur") && !command.has("arrows") && !command.has("no-overlay"));
  if(!has_field && (colour != "none" || command.has("streamlines") || command.has("fur") || command.has("arrows")))
    throw Usage_error("colours and overlays need a field (--field or --field-ply)");
  const bool signed_quantity = colour == "divergence" || colour == "curl";
  TVF::Scalar_colouring colouring = colour_scale(command, signed_quantity ? TVF::Colour_map::cool_warm : TVF::Colour_map::viridis);
  const TVF::Length_unit unit = length_unit(command.get<std::string>("unit"));
  const TVF::Evenly_spaced_options even = evenly_spaced_options(command, unit);
  const TVF::Fur_options fur = fur_options(command, unit);

  const Tool_mesh mesh(command.positional_value(), command.mollify());
  Eigen::VectorXd x;
  if(has_field) x = read_input_field(command, mesh);
  const auto start = std::chrono::steady_clock::now();
  TVF::Field_renderer renderer(mesh.shared_intrinsic(), options);

  // A diverging map is centred on zero for signed quantities.
  colouring.symmetric = signed_quantity && colouring.map == TVF::Colour_map::cool_warm;
  if(signed_quantity)
  {
    colouring.label = colour;
    renderer.colour_vertices(
        to_std_vector(colour == "divergence" ? mesh.matrices().divergence(x) : mesh.matrices().curl(x)), colouring);
  }
  else if(colour == "magnitude")
  {
    colouring.label = "|field|";
    std::vector<double> m(static_cast<std::size_t>(mesh.number_of_faces()));
    for(std::size_t f = 0; f < m.size(); ++f) m[f] = std::hypot(x[2 * f], x[2 * f + 1]);
    renderer.colour_faces(std::move(m), colouring);
  }

  const TVF::Colour lines = line_colour(command, colour != "none" && colouring.map == TVF::Colour_map::viridis);
  std::size_t lines_drawn = 0;
  if(streamlines || command.has("fur"))
    lines_drawn = add_lines(renderer, TVF::Streamline_tracer(mesh.shared_intrinsic(), x), command, lines,
                            streamlines ? &even : nullptr, command.has("fur") ? &fur : nullptr);
  if(command.has("arrows")) renderer.add_arrows(x, arrow_style(command, options, lines));
  std::string details;
  if(colour != "none") details += ", colours: " + colour;
  if(lines_drawn > 0) details += ", " + std::to_string(lines_drawn) + " lines";
  write_pictures(command, renderer, details, start);
#endif
  return 0;
}

// --- streamlines ---------------------------------------------------------------------------------

int streamlines_command(const Arguments& args)
{
  if(wants_n_field(args)) return n_field_streamlines_command(args);
  Command_line command("tvf streamlines <mesh> (--field FILE | --field-ply NAME) [--separation S | --fur ...] -o FILE",
                       "Traces evenly spaced streamlines of a field (exactly, face by face; Jobard and Lefer on the\n"
                       "surface), or fur strokes from random roots, and writes them as polylines: .obj (v and l\n"
                       "lines), .ply (vertices with face and streamline, edges) or .vtp (VTK polylines).");
  command.positional("mesh", "the mesh file");
  add_field_options(command);
  command.group("streamlines").add_options()
    ("fur", "fur strokes instead of evenly spaced streamlines")
    ("max-length", po::value<double>()->value_name("L"), "longest streamline in each direction from its seed (in --unit)")
    ("max-lines", po::value<int>()->value_name("N"), "stop after N streamlines");
  add_streamline_options(command);
  command.group("output").add_options()("output,o", po::value<std::vector<std::string>>()->composing()->value_name("FILE"),
                                        "the polylines: .obj, .ply or .vtp; repeatable");
  if(!command.parse(args)) return 0; // --help
  command.require("output");
  for(const std::string& path : command.get<std::vector<std::string>>("output"))
  {
    const std::string ext = extension(path);
    if(ext != "obj" && ext != "ply" && ext != "vtp")
      throw Usage_error("cannot write streamlines to '" + path + "': use .obj, .ply or .vtp");
  }
  const TVF::Length_unit unit = length_unit(command.get<std::string>("unit"));
  TVF::Evenly_spaced_options even = evenly_spaced_options(command, unit);
  const TVF::Fur_options fur = fur_options(command, unit);
  if(command.has("max-length"))
  {
    even.tracing.maximum_length = command.get<double>("max-length");
    even.tracing.length_unit = unit;
    if(!(even.tracing.maximum_length > 0)) throw Usage_error("'--max-length' must be positive");
  }
  if(command.has("max-lines"))
  {
    even.maximum_streamlines = command.get<int>("max-lines");
    if(even.maximum_streamlines <= 0) throw Usage_error("'--max-lines' must be positive");
  }
  const Tool_mesh mesh(command.positional_value(), command.mollify());
  const Eigen::VectorXd x = read_input_field(command, mesh);
  const auto start = std::chrono::steady_clock::now();
  const TVF::Streamline_tracer tracer(mesh.shared_intrinsic(), x);
  std::vector<TVF::Streamline> lines;
  {
    Step step(command.has("fur") ? "growing fur" : "tracing streamlines");
    lines = command.has("fur") ? tracer.fur(fur) : tracer.evenly_spaced(even);
  }
  double length = 0;
  int closed = 0;
  std::size_t points = 0;
  for(const TVF::Streamline& s : lines)
  {
    length += s.length();
    closed += s.closed;
    points += s.points.size();
  }
  say("%zu %s, %zu points, total length %.6g (%.4g bounding box diagonals), %d closed; traced in %.3f s\n",
      lines.size(), command.has("fur") ? "fur strokes" : "streamlines", points, length,
      length / mesh.bounding_box_diagonal(), closed, seconds_since(start));
  if(!command.has("fur")) say("  ends: %s\n", stop_summary(lines).c_str());
  write_streamline_files(command, lines);
  return 0;
}

// --- export ----------------------------------------------------------------------------------------

int export_command(const Arguments& args)
{
  if(wants_n_field(args)) return n_field_export_command(args);
  Command_line command("tvf export <mesh> (--field FILE | --field-ply NAME) -o FILE",
                       "Converts a field between the formats the tool reads and writes: .tvf (text), .ply (the mesh\n"
                       "with face properties), .vtp (ParaView), .rawfield (Directional).  Reading a .rawfield and\n"
                       "writing a .tvf imports a Directional field.  With --n N: an n-field (see 'tvf export --n 4 --help').");
  command.positional("mesh", "the mesh file");
  add_field_options(command);
  add_output_options(command, "the field", "field");
  if(!command.parse(args)) return 0; // --help
  command.require("output");
  const Tool_mesh mesh(command.positional_value(), command.mollify());
  const Eigen::VectorXd x = read_input_field(command, mesh);
  say("field: %d faces, |field| = %.6g (L2)\n", mesh.number_of_faces(), field_norm(mesh.matrices(), x));
  write_outputs(command, mesh, x);
  return 0;
}

} // namespace tvf_tool
