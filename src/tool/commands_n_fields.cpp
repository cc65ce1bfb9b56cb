// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// n-direction fields from the command line: `smoothest` and `singularities`, and the
// n-field forms of `basis`, `design`, `export` and `render` (chosen by `--n N`, or by the "n"
// of a constraint file).  Everything here works on the index-based view; files that need the
// mesh type (.tvf, .ply) go through Tool_mesh.

#include "tool.h"
#include "tool_n_fields.h"

#include <CGAL/Tangent_vector_fields/N_field_basis.h>
#include <CGAL/Tangent_vector_fields/N_field_singularities.h>
#include <CGAL/Tangent_vector_fields/N_field_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Smoothest_n_field_solver.h>
#include <CGAL/Tangent_vector_fields/curvature_direction_field.h>
#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/internal/constraint_json.h>
#include <CGAL/Tangent_vector_fields/n_field_constraint_file_io.h>
#include <CGAL/Tangent_vector_fields/n_field_files.h>


#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>

namespace tvf_tool {

void add_symmetry_options(Command_line& command)
{
  command.group("n-field").add_options()
    ("n", po::value<int>()->value_name("N"), "the symmetry: 1 vector field, 2 line field, 4 cross field, ... (N >= 1)")
    ("boundary", po::value<std::string>()->default_value("free")->value_name("B"),
     "boundary condition of the energy: free (no condition) or zero (the field vanishes across boundary edges)");
}

N_operators n_field_operators(const Command_line& command, const Tool_mesh& mesh,
                              const std::vector<std::pair<int, int>>& singularities, int n)
{
  if(n == 0)
  {
    command.require("n", "(the symmetry of the field: 1 vector, 2 line, 4 cross, ...)");
    n = command.get<int>("n");
  }
  if(n < 1) throw Usage_error("'--n' must be at least 1, not " + std::to_string(n));
  TVF::N_field_options options;
  const std::string boundary = command.get<std::string>("boundary");
  if(boundary == "zero") options.boundary = TVF::N_field_boundary::zero;
  else if(boundary != "free") throw Usage_error("'--boundary' is free or zero, not '" + boundary + "'");
  options.singularities = singularities;
  try
  {
    return std::make_shared<const TVF::N_field_operators>(mesh.shared_matrices(), n, options);
  }
  catch(const TVF::Invalid_input& e)
  {
    throw Tool_error(one_line(e.what()));
  }
}

// The input n-field: a .rawfield of degree n is checked to be one; other files give any one
// of the n vectors per face.
Eigen::VectorXd read_n_field(const Command_line& command, const Tool_mesh& mesh, const TVF::N_field_operators& ops)
{
  if(command.has("field") && extension(command.get<std::string>("field")) == "rawfield")
  {
    const std::string path = command.get<std::string>("field");
    std::ifstream in(path);
    if(!in) throw Tool_error("cannot open '" + path + "': " + std::strerror(errno));
    try
    {
      const TVF::Raw_field raw = TVF::read_raw_field(in);
      if(raw.degree > 1) return TVF::n_field_from_raw_field(ops, raw);
    }
    catch(const TVF::Invalid_input& e)
    {
      throw Tool_error(about(path, one_line(e.what())));
    }
  }
  return ops.from_vectors(read_input_field(command, mesh));
}

// Prints the singular vertices' counts, their index sum against N chi (Poincare-Hopf, exact by
// construction: a failure is a bug, reported as an error) and the first `list` of them.
void report_singularities(const Tool_mesh& mesh, int n, const std::vector<TVF::N_field_singularity>& singular, int list)
{
  int sum = 0, positive = 0, negative = 0, on_boundary = 0;
  for(const auto& s : singular)
  {
    sum += s.index;
    (s.index > 0 ? positive : negative) += 1;
    on_boundary += s.on_boundary;
  }
  int chi = 0;
  for(const auto& c : mesh.intrinsic().topology().components) chi += c.euler_characteristic();
  say("singularities: %zu (%d positive, %d negative, %d on the boundary); indices sum to %d/%d, N chi = %d: "
      "Poincare-Hopf %s\n",
      singular.size(), positive, negative, on_boundary, sum, n, n * chi, sum == n * chi ? "holds" : "FAILS");
  list = std::min<int>(list, static_cast<int>(singular.size()));
  for(int i = 0; i < list; ++i)
    say("  vertex %d: index %d/%d%s\n", singular[i].vertex, singular[i].index, n, singular[i].on_boundary ? " (boundary)" : "");
  if(list > 0 && list < static_cast<int>(singular.size())) say("  ... (--list K for more)\n");
  if(sum != n * chi) throw Tool_error("the indices sum to " + std::to_string(sum) + ", not N chi = " + std::to_string(n * chi));
}

namespace {




void add_n_output_options(Command_line& command, const std::string& what, const std::string& name)
{
  command.group("output").add_options()
    ("output,o", po::value<std::vector<std::string>>()->composing()->value_name("FILE"),
     (what + ", by extension: .rawfield (Directional: all N vectors per face), .vtp (ParaView: arrays NAME_0.. "
             "NAME_{N-1} and the vertex index NAME_index), .ply (face properties NAME_0_x.. per vector), .tvf "
             "(the first vector per face); repeat for several files").c_str())
    ("output-name", po::value<std::string>()->default_value(name)->value_name("NAME"), "name of the field in .vtp and .ply files")
    ("singularities", po::value<std::string>()->value_name("FILE"), "the singular vertices as a .sing file (Directional)")
    ("list", po::value<int>()->default_value(10)->value_name("K"), "print the first K singular vertices");
}

template <class Write>
void write_checked(const std::string& path, Write write)
{
  std::ofstream out(path);
  if(!out) throw Tool_error("cannot open '" + path + "' for writing: " + std::strerror(errno));
  try
  {
    write(out);
  }
  catch(const TVF::Invalid_input& e)
  {
    throw Tool_error(about(path, one_line(e.what())));
  }
  if(!out) throw Tool_error("writing '" + path + "' failed");
}


// Prints the singularities (and Poincare-Hopf); writes the outputs.
void report_and_write(const Command_line& command, const Tool_mesh& mesh, const TVF::N_field_operators& ops,
                      const Eigen::VectorXd& z)
{
  const int n = ops.n();
  report_singularities(mesh, n, TVF::n_field_singularities(ops, z), command.get<int>("list"));

  const std::string name = command.get<std::string>("output-name");
  if(command.has("output"))
    for(const std::string& path : command.get<std::vector<std::string>>("output"))
    {
      const std::string ext = extension(path);
      if(ext == "rawfield")
        write_checked(path, [&](std::ostream& out) { TVF::write_raw_field(out, TVF::n_field_to_raw_field(ops, z)); });
      else if(ext == "vtp")
        write_checked(path, [&](std::ostream& out) { TVF::write_vtk_polydata(out, TVF::n_field_polydata(ops, z, name)); });
      else if(ext == "ply")
      {
        std::vector<Named_field> branches;
        for(int j = 0; j < n; ++j) branches.push_back({name + "_" + std::to_string(j), ops.to_vectors(z, j)});
        mesh.write_fields(path, branches);
      }
      else if(ext == "tvf")
        mesh.write_fields(path, {{name, ops.to_vectors(z)}});
      else
        throw Usage_error("cannot write an n-field to '" + path + "': use .rawfield, .vtp, .ply or .tvf");
      say("wrote %s\n", path.c_str());
    }
  if(command.has("singularities"))
  {
    const std::string path = command.get<std::string>("singularities");
    write_checked(path, [&](std::ostream& out) { TVF::write_singularity_file(out, TVF::n_field_singularity_file(ops, z)); });
    say("wrote %s\n", path.c_str());
  }
}

void add_alignment_options(Command_line& command)
{
  command.group("alignment").add_options()
    ("align-curvature", "align to the principal curvature directions (CGAL's jet fitting; weighted by anisotropy)")
    ("align", po::value<std::string>()->value_name("FILE"), "align to a guide field read from FILE (any one of its N vectors per face)")
    ("alignment-weight", po::value<double>()->value_name("S"),
     "weight s of the alignment term, for the mesh scaled to unit area (default: 1 for smoothest, 1e4 for design)");
}

// The guide (power representation) and its weight; empty without --align*.
TVF::N_field_alignment read_alignment(const Command_line& command, const Tool_mesh& mesh, const TVF::N_field_operators& ops,
                                      double default_weight)
{
  command.at_most_one({"align-curvature", "align"});
  TVF::N_field_alignment a;
  if(!command.has("align-curvature") && !command.has("align"))
  {
    if(command.has("alignment-weight")) throw Usage_error("'--alignment-weight' needs '--align-curvature' or '--align'");
    return a;
  }
  a.weight = command.has("alignment-weight") ? command.get<double>("alignment-weight") : default_weight;
  if(!(a.weight > 0) || !std::isfinite(a.weight)) throw Usage_error("'--alignment-weight' must be a finite number > 0");
  if(command.has("align-curvature"))
  {
    TVF::Curvature_direction_report report;
    a.guide = ops.from_vectors(TVF::curvature_directions(mesh.intrinsic(), &report));
    say("curvature guide: %d vertices fitted, %d without a jet; curvature scale %.4g\n", report.fitted_vertices,
        report.unfitted_vertices, report.curvature_scale);
    if(report.curvature_scale == 0) throw Tool_error("the mesh has no curvature to align to (a plane?)");
  }
  else
  {
    Field_source source;
    source.file = command.get<std::string>("align");
    a.guide = ops.from_vectors(mesh.read_field(source));
  }
  return a;
}

bool has_option(const Arguments& args, const std::string& name)
{
  for(const std::string& a : args)
    if(a == name || a.rfind(name + "=", 0) == 0) return true;
  return false;
}

} // namespace

bool wants_n_field(const Arguments& args) { return has_option(args, "--n"); }

bool constraint_file_has_n(const Arguments& args)
{
  for(std::size_t i = 0; i < args.size(); ++i)
  {
    std::string path;
    if(args[i] == "--constraints" && i + 1 < args.size()) path = args[i + 1];
    else if(args[i].rfind("--constraints=", 0) == 0) path = args[i].substr(14);
    if(path.empty()) continue;
    try
    {
      std::ifstream in(path);
      const TVF::internal::Json root = TVF::internal::parse_json(in, path);
      return root.is_object() && root.contains("n");
    }
    catch(const std::exception&)
    {
      return false; // the vector-field reader reports what is wrong with it
    }
  }
  return false;
}

int smoothest_command(const Arguments& args)
{
  Command_line command("tvf smoothest <mesh> --n N [--align-curvature | --align FILE] -o FILE",
                       "The smoothest n-direction field (Knoeppel et al. 2013 with the package's weights): on each\n"
                       "component a parallel field if one exists, else the lowest eigenvector of L_n; with a guide the\n"
                       "minimiser of E_D + s |z - guide|^2.  Written as unit vectors; prints the singularities and\n"
                       "checks Poincare-Hopf (the indices sum to N times the Euler characteristic).");
  command.positional("mesh", "the mesh file");
  add_symmetry_options(command);
  command.group("n-field").add_options()("tolerance", po::value<double>()->default_value(1e-10)->value_name("T"),
                                         "relative residual of the eigenpair");
  add_alignment_options(command);
  add_n_output_options(command, "the field", "smoothest");
  if(!command.parse(args)) return 0; // --help
  const Tool_mesh mesh(command.positional_value(), command.mollify());
  const N_operators ops = n_field_operators(command, mesh);
  TVF::Smoothest_n_field_options options;
  options.tolerance = command.get<double>("tolerance");
  if(!(options.tolerance > 0 && options.tolerance < 1)) throw Usage_error("'--tolerance' must lie in (0, 1)");
  say("mesh: %s, %d faces; %s\n", mesh.path().c_str(), mesh.number_of_faces(), mesh.intrinsic().topology().summary().c_str());
  const TVF::N_field_alignment alignment = read_alignment(command, mesh, *ops, 1.);
  options.alignment = alignment.guide;
  options.alignment_weight = alignment.active() ? alignment.weight : 1.;
  Step step("smoothest field");
  const Eigen::VectorXd z = ops->normalized(TVF::smoothest_n_field(*ops, options));
  step.done();
  say("smoothest %d-field%s: %.3f s, E_D of the unit field %.6g\n", ops->n(), alignment.active() ? " (aligned)" : "",
      step.seconds(), ops->dirichlet_energy(z));
  report_and_write(command, mesh, *ops, z);
  return 0;
}

int singularities_command(const Arguments& args)
{
  Command_line command("tvf singularities <mesh> --n N --field FILE [--singularities FILE.sing]",
                       "The index of an n-field at every vertex (interior and boundary; see doc/tangent_vector_fields/n_fields.md): lists the\n"
                       "singular vertices, checks Poincare-Hopf, and writes them as a .sing file or with the field.");
  command.positional("mesh", "the mesh file");
  add_symmetry_options(command);
  add_field_options(command);
  add_n_output_options(command, "the field with its singularities", "field");
  if(!command.parse(args)) return 0; // --help
  const Tool_mesh mesh(command.positional_value(), command.mollify());
  const N_operators ops = n_field_operators(command, mesh);
  const Eigen::VectorXd z = read_n_field(command, mesh, *ops);
  report_and_write(command, mesh, *ops, z);
  return 0;
}

int n_field_export_command(const Arguments& args)
{
  Command_line command("tvf export <mesh> --n N --field FILE -o FILE",
                       "Converts an n-field between formats: a .rawfield of degree N (checked to be an n-field), or\n"
                       "any file with one of its vectors per face, to .rawfield (all N vectors), .vtp, .ply or .tvf.");
  command.positional("mesh", "the mesh file");
  add_symmetry_options(command);
  add_field_options(command);
  add_n_output_options(command, "the field", "field");
  if(!command.parse(args)) return 0; // --help
  command.require("output");
  const Tool_mesh mesh(command.positional_value(), command.mollify());
  const N_operators ops = n_field_operators(command, mesh);
  report_and_write(command, mesh, *ops, read_n_field(command, mesh, *ops));
  return 0;
}

int n_field_basis_command(const Arguments& args)
{
  Command_line command("tvf basis <mesh> --n N -k K -o FILE.tvfn | tvf basis <mesh> --n N --load FILE.tvfn",
                       "The n-field basis: the parallel fields and the lowest eigenpairs of L_n, in pairs (phi, J phi),\n"
                       "every residual checked and completeness proved by an inertia count; saved with the mesh's\n"
                       "fingerprint, N and the boundary condition.  With --load: reads one and checks it against the mesh.");
  command.positional("mesh", "the mesh file");
  add_symmetry_options(command);
  command.group("basis").add_options()
    ("eigenfields,k", po::value<int>()->default_value(100)->value_name("K"),
     "the K lowest elements (rounded up to even; -n K: the same, --n N is the symmetry)")
    ("tolerance", po::value<double>()->default_value(1e-10)->value_name("T"), "relative residual of every eigenpair")
    ("prescribed", po::value<std::string>()->value_name("FILE.sing"),
     "singularities prescribed in the connection (a .sing file; designs with the same \"singularities\" use the basis)")
    ("load", po::value<std::string>()->value_name("FILE"), "instead: load a basis and print its spectrum")
    ("list", po::value<int>()->default_value(16)->value_name("K"), "print the K lowest eigenvalues");
  command.group("output").add_options()("output,o", po::value<std::string>()->value_name("FILE"), "the basis (.tvfn)");
  if(!command.parse(with_basis_size_alias(args))) return 0; // --help
  command.exactly_one({"output", "load"});
  const Tool_mesh mesh(command.positional_value(), command.mollify());
  std::vector<std::pair<int, int>> prescribed;
  if(command.has("prescribed"))
  {
    const std::string path = command.get<std::string>("prescribed");
    std::ifstream in(path);
    if(!in) throw Tool_error("cannot open '" + path + "': " + std::strerror(errno));
    try
    {
      const TVF::Singularity_file file = TVF::read_singularity_file(in);
      command.require("n", "(the symmetry of the field: 1 vector, 2 line, 4 cross, ...)");
      if(file.n != command.get<int>("n"))
        throw Tool_error(about(path, "singularities of " + std::to_string(file.n) + "-fields, not " +
                                         std::to_string(command.get<int>("n")) + "-fields"));
      prescribed = file.singularities;
    }
    catch(const TVF::Invalid_input& e)
    {
      throw Tool_error(about(path, one_line(e.what())));
    }
  }
  const N_operators ops = n_field_operators(command, mesh, prescribed);
  std::shared_ptr<const TVF::N_field_basis> basis;
  if(command.has("load"))
  {
    const std::string path = command.get<std::string>("load");
    try
    {
      basis = std::make_shared<const TVF::N_field_basis>(TVF::N_field_basis::load(ops, path));
    }
    catch(const TVF::Invalid_input& e)
    {
      throw Tool_error(about(path, one_line(e.what())));
    }
    say("basis: %s, %d elements for N = %d\n", path.c_str(), basis->size(), ops->n());
  }
  else
  {
    const std::string output = command.get<std::string>("output");
    if(extension(output) != "tvfn") throw Usage_error("the n-field basis file '" + output + "' should end in .tvfn");
    TVF::Basis_options options;
    options.tolerance = command.get<double>("tolerance");
    if(!(options.tolerance > 0 && options.tolerance < 1)) throw Usage_error("'--tolerance' must lie in (0, 1)");
    const int k = command.get<int>("eigenfields");
    if(k < 1) throw Usage_error("'--eigenfields' must be at least 1");
    Progress_bar bar;
    options.progress = [&](const TVF::Spectral_progress& p) { bar.update(p.stage, p.fraction); };
    basis = std::make_shared<const TVF::N_field_basis>(ops, k, options);
    bar.finish();
    const TVF::N_field_basis_report& r = basis->report();
    say("basis: %d elements (%d parallel) in %.2f s; largest residual %.2e; complete below %.6g (inertia %d of %d)\n",
        basis->size(), basis->kernel_dimension(), r.seconds, r.max_residual, r.complete_below, r.inertia, r.expected);
    basis->save(output);
    say("wrote %s\n", output.c_str());
  }
  const int list = std::min(command.get<int>("list"), basis->size());
  say("lowest eigenvalues (unit-area mesh):");
  for(int i = 0; i < list; ++i) say(" %.6g", basis->eigenvalue(i) * mesh.area());
  say("\n");
  return 0;
}

int n_field_design_command(const Arguments& args)
{
  Command_line command("tvf design <mesh> --constraints FILE.json [--basis FILE.tvfn [-d D]] -o FILE",
                       "Designs an n-field (the constraint file has \"n\"): the spline min E_m + omega E_D subject to the\n"
                       "constraints (m = the file's \"order\", 2 by default), exact at full resolution or in the span of\n"
                       "a saved n-field basis; optionally aligned to the curvature or a guide.  Prints the residual,\n"
                       "the warnings and the singularities.");
  command.positional("mesh", "the mesh file");
  add_symmetry_options(command);
  command.group("design").add_options()
    ("constraints", po::value<std::string>()->value_name("FILE"), "the constraints (JSON with \"n\")")
    ("basis", po::value<std::string>()->value_name("FILE"), "solve in the span of this n-field basis (.tvfn)")
    ("basis-size,d", po::value<int>()->value_name("D"), "use the first D elements of the basis (even; default: all)")
    ("exact", "with --basis: refine the reduced spline to the exact one (written), printing the reduced answer's "
              "measured error next to its bound")
    ("omega", po::value<double>()->value_name("W"), "tension, for the mesh scaled to unit area; default: the file's")
    ("order", po::value<int>()->value_name("M"),
     "energy order: 1 the classical first-order design (min E_D), 2 the spline (E_B); default: the file's");
  add_alignment_options(command);
  add_n_output_options(command, "the designed field", "design");
  if(!command.parse(args)) return 0; // --help
  command.require("constraints");
  if(command.has("basis-size") && !command.has("basis")) throw Usage_error("'--basis-size' needs '--basis'");
  const Tool_mesh mesh(command.positional_value(), command.mollify());
  const std::string path = command.get<std::string>("constraints");
  TVF::N_field_constraint_file file;
  try
  {
    file = TVF::read_n_field_constraint_file(path, mesh.shared_matrices());
  }
  catch(const TVF::Invalid_input& e)
  {
    throw Tool_error(about(path, one_line(e.what())));
  }
  if(command.has("n") && command.get<int>("n") != file.n)
    throw Usage_error("'--n " + std::to_string(command.get<int>("n")) + "' contradicts the file's \"n\": " + std::to_string(file.n));
  const N_operators ops = n_field_operators(command, mesh, file.singularities, file.n);
  if(command.has("order"))
  {
    file.order = command.get<int>("order");
    if(file.order < 1) throw Usage_error("'--order' must be at least 1");
  }
  TVF::Spline_options options;
  options.omega = command.has("omega") ? command.get<double>("omega") : file.omega;
  if(!(options.omega >= 0) || !std::isfinite(options.omega)) throw Usage_error("'--omega' must be a finite number >= 0");
  say("mesh: %s, %d faces; %s\n", mesh.path().c_str(), mesh.number_of_faces(), mesh.intrinsic().topology().summary().c_str());
  const TVF::N_field_alignment alignment = read_alignment(command, mesh, *ops, 1e4);
  std::unique_ptr<TVF::N_field_spline_solver> solver;
  try
  {
    if(command.has("basis"))
    {
      const std::string basis_path = command.get<std::string>("basis");
      std::shared_ptr<const TVF::N_field_basis> basis;
      try
      {
        basis = std::make_shared<const TVF::N_field_basis>(TVF::N_field_basis::load(ops, basis_path));
      }
      catch(const TVF::Invalid_input& e)
      {
        throw Tool_error(about(basis_path, one_line(e.what())));
      }
      const int d = command.has("basis-size") ? command.get<int>("basis-size") : 0;
      solver = std::make_unique<TVF::Reduced_n_field_spline_solver>(basis, d, options, file.order, alignment);
    }
    else
      solver = std::make_unique<TVF::Full_n_field_spline_solver>(ops, options, file.order, alignment);
  }
  catch(const TVF::Invalid_input& e)
  {
    throw Tool_error(one_line(e.what()));
  }
  say("design: %d-field spline, order %d, omega %g, %zu constraints, %zu prescribed singularities%s, %s\n", file.n,
      file.order, options.omega, file.constraints.size(), file.singularities.size(), alignment.active() ? ", aligned" : "",
      command.has("basis") ? "reduced" : "full resolution");
  Step step("solving");
  solver->add(file.constraints);
  const Eigen::VectorXd z = solver->field();
  const TVF::Spline_report& report = solver->report();
  step.done();
  say("  %.3f s; %d rows; constraint residual %.2e; smallest independence %.3g; energy %.6g\n", step.seconds(), report.rows,
      report.constraint_residual, report.smallest_independence, report.energy);
  if(!command.has("basis") || !command.has("exact"))
  {
    if(command.has("basis")) say_error_bound(report);
    for(const std::string& w : report.warnings) say("  warning: %s\n", w.c_str());
    report_and_write(command, mesh, *ops, z);
    return 0;
  }
  say_error_bound(report);
  Step refine("refining to the exact spline");
  TVF::Full_n_field_spline_solver full(ops, options, file.order, alignment);
  full.add(file.constraints);
  const Eigen::VectorXd exact = full.field();
  refine.done();
  // L2 of power fields: |z|^2_MX.
  auto norm = [&](const Eigen::VectorXd& v) { return std::sqrt(v.cwiseAbs2().dot(ops->masses())); };
  say_reduced_against_exact(report, full.report(), norm(exact) > 0 ? norm(z - exact) / norm(exact) : 0.);
  for(const std::string& w : full.report().warnings) say("  warning: %s\n", w.c_str());
  report_and_write(command, mesh, *ops, exact);
  return 0;
}

} // namespace tvf_tool
