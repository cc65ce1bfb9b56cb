// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Subcommands on the structure of fields: info, decompose, basis, basis-info,
// eigenfield, filter (compress and decompress: commands_compression.cpp).  They work on frame coordinates through
// the index-based classes (no Surface_mesh here; see tool_mesh.cpp).

#include "tool.h"

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Hodge_solver.h>
#include <CGAL/Tangent_vector_fields/Spectral_filter.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

namespace tvf_tool {

namespace {

const char* type_letter(TVF::Eigenfield_type t)
{
  return t == TVF::Eigenfield_type::exact ? "E" : t == TVF::Eigenfield_type::coexact ? "C" : "H";
}

const char* type_name(TVF::Eigenfield_type t)
{
  return t == TVF::Eigenfield_type::exact ? "exact (curl-free)"
         : t == TVF::Eigenfield_type::coexact ? "coexact (divergence-free)"
                                              : "harmonic";
}


// The spectrum of a basis: counts, range, the first eigenvalues, and the evidence.
void print_spectrum(const TVF::Eigenfield_basis& b, double area, int list)
{
  say("  %d eigenfields: %d harmonic, %d exact (curl-free), %d coexact (divergence-free)\n", b.size(),
      b.number_of_harmonic(), b.number_of_exact(), b.number_of_coexact());
  if(b.size() == 0) return;
  say("  eigenvalues lambda * area (unit-area scale): %.6g to %.6g (lambda: %.6g to %.6g)\n", b.eigenvalue(0) * area,
      b.eigenvalue(b.size() - 1) * area, b.eigenvalue(0), b.eigenvalue(b.size() - 1));
  const int shown = std::min(list, b.size());
  if(shown > 0)
  {
    say("  lowest (H harmonic, E exact, C coexact; lambda * area):");
    for(int k = 0; k < shown; ++k) say("%s%s %.4g", k % 8 == 0 ? "\n   " : "   ", type_letter(b.type(k)), b.eigenvalue(k) * area);
    say("\n");
  }
  const TVF::Basis_report& r = b.report();
  say("  largest relative residual %.2g; completeness (Sylvester inertia): exact %d/%d, coexact %d/%d\n",
      r.max_residual, r.exact_inertia, r.exact_expected, r.coexact_inertia, r.coexact_expected);
  say("  computed in %.2f s (exact %.2f s, coexact %.2f s, harmonic %.2f s)\n",
      r.exact_seconds + r.coexact_seconds + r.harmonic_seconds, r.exact_seconds, r.coexact_seconds, r.harmonic_seconds);
  say("  eigenfunctions stored in %s: %.1f MB\n",
      b.precision() == TVF::Eigenfunction_precision::float32 ? "float32" : "double", b.memory_bytes() / 1e6);
}

// The Hodge demo's field: a constant wind, a swirl about the z axis and a source at
// the centre of the bounding box, projected onto the faces.
Eigen::VectorXd demo_field(const Tool_mesh& mesh)
{
  const TVF::Intrinsic_mesh& m = mesh.intrinsic();
  std::array<double, 3> lo{{HUGE_VAL, HUGE_VAL, HUGE_VAL}}, hi{{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}};
  for(int v = 0; v < m.number_of_vertices(); ++v)
    for(int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], m.position(v)[k]);
      hi[k] = std::max(hi[k], m.position(v)[k]);
    }
  const double size = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  Eigen::VectorXd x(2 * m.number_of_faces());
  for(int f = 0; f < m.number_of_faces(); ++f)
  {
    std::array<double, 3> d{{0, 0, 0}};
    for(int corner : m.face_vertices(f))
      for(int k = 0; k < 3; ++k) d[k] += m.position(corner)[k] / 3;
    for(int k = 0; k < 3; ++k) d[k] = (d[k] - (lo[k] + hi[k]) / 2) / size;
    const std::array<double, 3> w{{1 - 4 * d[1] + 2 * d[0], 0.3 + 4 * d[0] + 2 * d[1], 2 * d[2]}};
    const auto ab = m.to_frame(f, w);
    x[2 * f] = ab[0];
    x[2 * f + 1] = ab[1];
  }
  return x;
}

void write_one(const Tool_mesh& mesh, const std::string& path, const std::string& name, const Eigen::VectorXd& x)
{
  mesh.write_fields(path, {{name, x}});
  say("wrote %s\n", path.c_str());
}

} // namespace

void add_basis_option(Command_line& command, bool required)
{
  command.group("spectral basis").add_options()(
      "basis", po::value<std::string>()->value_name("FILE"),
      required ? "the basis (.tvfb, written by 'tvf basis' for this mesh)"
               : "a basis (.tvfb, written by 'tvf basis' for this mesh)");
}

std::shared_ptr<const TVF::Eigenfield_basis> load_basis(const Tool_mesh& mesh, const std::string& path)
{
  {
    std::ifstream in(path, std::ios::binary);
    if(!in) throw Tool_error("cannot open basis file '" + path + "': " + std::strerror(errno));
  }
  Step step("loading the basis");
  try
  {
    return std::make_shared<const TVF::Eigenfield_basis>(
        TVF::Eigenfield_basis::load(std::make_shared<TVF::Hodge_solver>(mesh.shared_matrices()), path));
  }
  catch(const TVF::Invalid_input& e)
  {
    throw Tool_error(about(path, one_line(e.what())));
  }
}

// --- info ------------------------------------------------------------------------------

int info_command(const Arguments& args)
{
  Command_line command("tvf info <mesh> [options]",
                       "Reads a mesh and prints the repairs it needed, its size, area, topology (components, genus,\n"
                       "boundary loops), the dimension of its harmonic fields, the face fields stored in it (PLY),\n"
                       "and warnings.");
  command.positional("mesh", "the mesh file");
  command.group("info").add_options()("components", po::value<int>()->default_value(10)->value_name("N"),
                                      "list at most N components");
  if(!command.parse(args)) return 0; // --help
  const Tool_mesh mesh(command.positional_value(), command.mollify());
  const TVF::Intrinsic_mesh& m = mesh.intrinsic();
  const TVF::Mesh_topology& t = m.topology();
  say("mesh: %s\n", mesh.path().c_str());
  say("  repairs: %s\n", mesh.repair_report().changed() ? mesh.repair_report().summary().c_str() : "none");
  say("  %d vertices, %d edges (%d interior, %d boundary), %d faces\n", m.number_of_vertices(), m.number_of_edges(),
      m.number_of_interior_edges(), m.number_of_edges() - m.number_of_interior_edges(), m.number_of_faces());
  say("  area %.6g, mean edge length %.6g, bounding box diagonal %.6g\n", mesh.area(), m.mean_edge_length(),
      mesh.bounding_box_diagonal());
  say("  topology: %s\n", t.summary().c_str());
  const int listed = std::min(command.get<int>("components"), t.number_of_components());
  for(int c = 0; c < listed; ++c)
  {
    const TVF::Component_topology& k = t.components[c];
    say("    component %d: %d vertices, %d edges, %d faces, Euler characteristic %d, genus %d, %d boundary loop%s, "
        "harmonic dimension %d\n",
        c, k.number_of_vertices, k.number_of_edges, k.number_of_faces, k.euler_characteristic(), k.genus,
        k.number_of_boundary_loops, k.number_of_boundary_loops == 1 ? "" : "s", k.harmonic_dimension());
  }
  if(listed < t.number_of_components()) say("    ... %d more components\n", t.number_of_components() - listed);

  // The smallest angle: the accuracy of the operators degrades like 1 / angle.
  double smallest = M_PI;
  int smallest_face = 0;
  for(int f = 0; f < m.number_of_faces(); ++f)
    for(int k = 0; k < 3; ++k)
    {
      const double angle = std::atan2(1., m.cotangent(f, k));
      if(angle < smallest)
      {
        smallest = angle;
        smallest_face = f;
      }
    }
  say("  smallest angle %.3g degrees (face %d)\n", smallest * 180 / M_PI, smallest_face);
  if(m.mollification_delta() > 0)
    say("  mollification added %.3g (%.2g mean edge lengths) to every edge length\n", m.mollification_delta(),
        m.mollification_delta() / m.mean_edge_length());
  const std::vector<std::string> fields = mesh.face_fields_in_file();
  if(!fields.empty())
  {
    std::string list;
    for(const std::string& f : fields) list += (list.empty() ? "" : ", ") + f;
    say("  face fields in the file: %s\n", list.c_str());
  }

  std::vector<std::string> warnings = m.warnings();
  if(smallest < M_PI / 180)
    warnings.push_back("nearly degenerate faces (smallest angle below 1 degree): expect a loss of accuracy, or use "
                       "--mollify");
  if(t.number_of_components() > 1)
    warnings.push_back(std::to_string(t.number_of_components()) +
                       " components: potentials have zero mean on each, eigenfields live on one at a time");
  if(warnings.empty()) say("  warnings: none\n");
  for(const std::string& w : warnings) say("  warning: %s\n", one_line(w).c_str());
  return 0;
}

// --- decompose -----------------------------------------------------------------------------

int decompose_command(const Arguments& args)
{
  Command_line command("tvf decompose <mesh> (--field FILE | --field-ply NAME | --demo-field) [outputs]",
                       "Splits a field into its curl-free (exact), divergence-free (coexact) and harmonic parts,\n"
                       "v = G f + J G* g + h, and prints their sizes.  Only the parts asked for are computed.");
  command.positional("mesh", "the mesh file");
  add_field_options(command);
  command.group("field input").add_options()(
      "demo-field", "use the field of the Hodge demo instead: a constant wind, a swirl about the z axis and a source at "
                    "the centre of the bounding box");
  command.group("output").add_options()
    ("output,o", po::value<std::vector<std::string>>()->composing()->value_name("FILE"),
     "all parts and the input in one file: .vtp (arrays field, exact, coexact, harmonic) or .ply (face properties "
     "field_*, exact_*, coexact_*, harmonic_*); repeatable")
    ("exact", po::value<std::string>()->value_name("FILE"), "the exact part (.tvf, .ply, .vtp, .rawfield)")
    ("coexact", po::value<std::string>()->value_name("FILE"), "the coexact part")
    ("harmonic", po::value<std::string>()->value_name("FILE"), "the harmonic part")
    ("save-field", po::value<std::string>()->value_name("FILE"),
     "the input field as the decomposition sees it (projected onto the faces)");
  if(!command.parse(args)) return 0; // --help
  command.exactly_one({"field", "field-ply", "demo-field"});
  const Tool_mesh mesh(command.positional_value(), command.mollify());
  const Eigen::VectorXd v = command.has("demo-field") ? demo_field(mesh) : read_input_field(command, mesh);

  unsigned outputs = 0;
  if(command.has("exact")) outputs |= TVF::hodge_exact;
  if(command.has("coexact")) outputs |= TVF::hodge_coexact;
  if(command.has("harmonic")) outputs |= TVF::hodge_harmonic;
  if(command.has("output") || outputs == 0) outputs = TVF::hodge_exact | TVF::hodge_coexact | TVF::hodge_harmonic;

  const TVF::Hodge_solver hodge(mesh.shared_matrices());
  Step step("decomposing");
  const TVF::Hodge_parts parts = hodge.decompose(v, outputs);
  const double seconds = step.seconds();
  step.done();

  const TVF::Operator_matrices& ops = mesh.matrices();
  const double nv = field_norm(ops, v);
  say("mesh: %s, %d faces; %s\n", mesh.path().c_str(), mesh.number_of_faces(),
      mesh.intrinsic().topology().summary().c_str());
  say("  |field| = %.6g", nv);
  if(parts.exact.size()) say("   |exact| = %.6g", field_norm(ops, parts.exact));
  if(parts.coexact.size()) say("   |coexact| = %.6g", field_norm(ops, parts.coexact));
  if(parts.harmonic.size()) say("   |harmonic| = %.6g", field_norm(ops, parts.harmonic));
  say("   (L2 norms)\n");
  if(parts.exact.size() && parts.coexact.size() && parts.harmonic.size() && nv > 0)
    say("  |exact + coexact + harmonic - field| / |field| = %.2e\n",
        field_norm(ops, parts.exact + parts.coexact + parts.harmonic - v) / nv);
  say("  decomposed in %.3f s (operators, factorisations%s)\n", seconds,
      (outputs & TVF::hodge_harmonic) && hodge.harmonic_dimension() > 0 ? ", harmonic basis" : "");

  if(command.has("save-field")) write_one(mesh, command.get<std::string>("save-field"), "field", v);
  if(command.has("exact")) write_one(mesh, command.get<std::string>("exact"), "exact", parts.exact);
  if(command.has("coexact")) write_one(mesh, command.get<std::string>("coexact"), "coexact", parts.coexact);
  if(command.has("harmonic")) write_one(mesh, command.get<std::string>("harmonic"), "harmonic", parts.harmonic);
  if(command.has("output"))
    for(const std::string& path : command.get<std::vector<std::string>>("output"))
    {
      const std::string ext = extension(path);
      if(ext != "vtp" && ext != "ply")
        throw Usage_error("'--output " + path + "': all parts go into a .vtp or .ply file; use --exact, --coexact, "
                          "--harmonic for single-field files");
      mesh.write_fields(path, {{"field", v}, {"exact", parts.exact}, {"coexact", parts.coexact}, {"harmonic", parts.harmonic}});
      say("wrote %s\n", path.c_str());
    }
  return 0;
}

// --- basis ---------------------------------------------------------------------------------

int basis_command(const Arguments& args)
{
  if(wants_n_field(args)) return n_field_basis_command(args);
  Command_line command("tvf basis <mesh> -o FILE.tvfb [-k K | --exact N --coexact N | --max-eigenvalue L]",
                       "Computes the lowest eigenfields of the Hodge-Laplacian (harmonic fields first) by spectrum\n"
                       "slicing, with a proof of completeness (Sylvester inertia), and saves them to a binary .tvfb\n"
                       "file that 'filter', 'compress', 'design --basis' and 'eigenfield' read.  A progress bar is\n"
                       "drawn on stderr when it is a terminal.  With --n N: the basis of n-direction fields (.tvfn; see\n"
                       "'tvf basis --n 4 --help').");
  command.positional("mesh", "the mesh file");
  command.group("basis").add_options()
    ("eigenfields,k", po::value<int>()->default_value(100)->value_name("K"), "the K lowest eigenfields (-n K: the same)")
    ("exact", po::value<int>()->value_name("N"), "instead: N exact eigenfields (with --coexact), plus all harmonic ones")
    ("coexact", po::value<int>()->value_name("N"), "instead: N coexact eigenfields (with --exact)")
    ("max-eigenvalue", po::value<double>()->value_name("L"),
     "instead: every eigenfield with lambda * area <= L (eigenvalue of the mesh scaled to unit area)")
    ("tolerance", po::value<double>()->default_value(1e-10)->value_name("T"), "relative residual of every eigenpair")
    ("seed", po::value<unsigned>()->default_value(1)->value_name("S"), "seed of the Lanczos start blocks")
    ("list", po::value<int>()->default_value(16)->value_name("N"), "print the N lowest eigenvalues");
  command.group("output").add_options()("output,o", po::value<std::string>()->value_name("FILE"),
                                        "the basis file (.tvfb)")(
      "float32", "store the eigenfunctions in float32: half the file and memory; each entry is rounded, which adds "
                 "a relative error of 1e-5 to 2e-4 to every field (20k to 346k faces; the reduction error is 1e-2 or more)");
  if(!command.parse(with_basis_size_alias(args))) return 0; // --help
  command.require("output");
  command.at_most_one({"eigenfields", "exact", "max-eigenvalue"});
  command.at_most_one({"eigenfields", "coexact", "max-eigenvalue"});
  const std::string output = command.get<std::string>("output");
  if(extension(output) != "tvfb") throw Usage_error("the basis file '" + output + "' should end in .tvfb");
  const double tolerance = command.get<double>("tolerance");
  if(!(tolerance > 0 && tolerance < 1)) throw Usage_error("'--tolerance' must lie in (0, 1)");
  const Tool_mesh mesh(command.positional_value(), command.mollify());

  TVF::Basis_request request;
  std::string what;
  if(command.has("exact") || command.has("coexact"))
  {
    const int e = command.has("exact") ? command.get<int>("exact") : 0;
    const int c = command.has("coexact") ? command.get<int>("coexact") : 0;
    if(e < 0 || c < 0) throw Usage_error("'--exact' and '--coexact' must not be negative");
    request = TVF::Basis_request::per_type(e, c);
    what = std::to_string(e) + " exact and " + std::to_string(c) + " coexact eigenfields and all harmonic ones";
  }
  else if(command.has("max-eigenvalue"))
  {
    const double l = command.get<double>("max-eigenvalue");
    if(!(l > 0)) throw Usage_error("'--max-eigenvalue' must be positive");
    request = TVF::Basis_request::below(l / mesh.area());
    what = "every eigenfield with lambda * area <= " + std::to_string(l);
  }
  else
  {
    const int n = command.get<int>("eigenfields");
    if(n <= 0) throw Usage_error("'--eigenfields' must be positive");
    if(n > 2 * mesh.number_of_faces())
      throw Tool_error("the mesh has only " + std::to_string(2 * mesh.number_of_faces()) + " eigenfields (2 per face), " +
                       std::to_string(n) + " were asked for");
    request = TVF::Basis_request::lowest(n);
    what = "the " + std::to_string(n) + " lowest eigenfields";
  }
  if(command.has("float32")) request.precision = TVF::Eigenfunction_precision::float32;
  TVF::Basis_options options;
  options.tolerance = tolerance;
  options.seed = command.get<unsigned>("seed");
  Progress_bar bar;
  options.progress = [&bar](const TVF::Spectral_progress& p) { bar.update(p.stage, p.fraction); };
  say("mesh: %s, %d faces; %s\n", mesh.path().c_str(), mesh.number_of_faces(),
      mesh.intrinsic().topology().summary().c_str());
  say("computing %s of the Hodge-Laplacian\n", what.c_str());
  const auto start = std::chrono::steady_clock::now();
  const TVF::Eigenfield_basis basis(std::make_shared<TVF::Hodge_solver>(mesh.shared_matrices()), request, options);
  bar.finish();
  const double seconds = seconds_since(start);
  basis.save(output);
  say("  done in %.2f s\n", seconds);
  print_spectrum(basis, mesh.area(), command.get<int>("list"));
  say("wrote %s\n", output.c_str());
  return 0;
}

// --- basis-info ------------------------------------------------------------------------------

int basis_info_command(const Arguments& args)
{
  Command_line command("tvf basis-info <basis.tvfb> --mesh <mesh> [options]",
                       "Loads a basis, checks that it belongs to the mesh (connectivity and edge lengths) and that\n"
                       "its elements are orthonormal eigenfields (on a sample spread over the spectrum), and prints\n"
                       "its spectrum.");
  command.positional("basis", "the basis file (.tvfb)");
  command.group("basis").add_options()
    ("mesh", po::value<std::string>()->value_name("FILE"), "the mesh the basis was computed for")
    ("list", po::value<int>()->default_value(16)->value_name("N"), "print the N lowest eigenvalues")
    ("samples", po::value<int>()->default_value(16)->value_name("N"), "check N elements (0: no check)");
  if(!command.parse(args)) return 0; // --help
  command.require("mesh");
  const std::string path = command.positional_value();
  const Tool_mesh mesh(command.get<std::string>("mesh"), command.mollify());
  const auto basis = load_basis(mesh, path);
  const TVF::Eigenfield_basis& b = *basis;
  say("basis: %s, for %s (%d faces)\n", path.c_str(), mesh.path().c_str(), mesh.number_of_faces());
  print_spectrum(b, mesh.area(), command.get<int>("list"));

  const int samples = std::min(command.get<int>("samples"), b.size());
  if(samples <= 0) return 0;
  Step step("checking");
  const TVF::Operator_matrices& ops = mesh.matrices();
  const Eigen::VectorXd& mx = ops.field_masses();
  double lambda_reference = 0; // residuals of harmonic fields are measured against the lowest positive eigenvalue
  for(int k = 0; k < b.size() && lambda_reference == 0; ++k) lambda_reference = b.eigenvalue(k);
  double orthonormality = 0, residual = 0;
  for(int i = 0; i < samples; ++i)
  {
    const int k = samples == 1 ? 0 : static_cast<int>(std::lround(double(i) * (b.size() - 1) / (samples - 1)));
    const Eigen::VectorXd phi = b.eigenfield(k);
    Eigen::VectorXd a = b.coefficients(phi);
    a[k] -= 1;
    orthonormality = std::max(orthonormality, a.cwiseAbs().maxCoeff());
    const Eigen::VectorXd r = ops.S() * phi - b.eigenvalue(k) * mx.cwiseProduct(phi);
    const double lambda = std::max(b.eigenvalue(k), lambda_reference);
    if(lambda > 0) residual = std::max(residual, std::sqrt(r.dot(r.cwiseQuotient(mx))) / lambda);
  }
  step.done();
  say("  check of %d elements: largest |<Phi_i, Phi_k> - delta_ik| = %.2g, largest |L Phi - lambda Phi| / lambda = "
      "%.2g\n", samples, orthonormality, residual);
  // float32 entries carry rounding noise of relative size 6e-8: orthonormality keeps it, but L
  // amplifies it by up to lambda_max / lambda, so the residual says nothing about such a file.
  const bool single = b.precision() == TVF::Eigenfunction_precision::float32;
  if(single) say("  (float32 eigenfunctions: orthonormality checked to 1e-5, the residual not checked)\n");
  if(!(orthonormality < (single ? 1e-5 : 1e-6)) || !(single || residual < 1e-6))
  {
    std::ostringstream message; // scientific: a failing 1e-7 must not read as 0.000000
    message << "basis file '" << path << "' fails its check (orthonormality " << orthonormality << ", residual "
            << residual << ")";
    throw Tool_error(message.str());
  }
  say("  the basis is fine\n");
  return 0;
}

// --- eigenfield ---------------------------------------------------------------------------------

int eigenfield_command(const Arguments& args)
{
  Command_line command("tvf eigenfield <mesh> --basis FILE --index K -o FILE",
                       "Writes element K (0-based, in the order of the basis: harmonic fields first, then by\n"
                       "eigenvalue) of a basis as a field, with unit L2 norm.");
  command.positional("mesh", "the mesh file");
  add_basis_option(command, true);
  command.group("spectral basis").add_options()("index,k", po::value<int>()->value_name("K"), "which element");
  add_output_options(command, "the eigenfield", "eigenfield");
  if(!command.parse(args)) return 0; // --help
  command.require("basis");
  command.require("index");
  command.require("output");
  const Tool_mesh mesh(command.positional_value(), command.mollify());
  const auto basis = load_basis(mesh, command.get<std::string>("basis"));
  const int k = command.get<int>("index");
  if(k < 0 || k >= basis->size())
    throw Tool_error("the basis has elements 0 to " + std::to_string(basis->size() - 1) + ", not " + std::to_string(k));
  say("element %d: %s, eigenvalue %.6g (lambda * area = %.6g)\n", k, type_name(basis->type(k)), basis->eigenvalue(k),
      basis->eigenvalue(k) * mesh.area());
  write_outputs(command, mesh, basis->eigenfield(k));
  return 0;
}

// --- filter ---------------------------------------------------------------------------------------

int filter_command(const Arguments& args)
{
  Command_line command("tvf filter <mesh> --basis FILE (--field FILE | --field-ply NAME) <filter> -o FILE",
                       "Filters a field through the spectral basis (SPEC 6): each coefficient a_k is multiplied by a\n"
                       "transfer function of lambda_k.  Times T are for the mesh scaled to unit area, so the same T\n"
                       "smooths any scaled copy of a mesh alike.  The rest of the field (the frequencies above the\n"
                       "basis) is dropped by --low-pass and the part filters, kept (and doubled) by --high-pass.");
  command.positional("mesh", "the mesh file");
  add_basis_option(command, true);
  add_field_options(command);
  command.group("filter (exactly one)").add_options()
    ("low-pass", po::value<double>()->value_name("T"), "heat-kernel smoothing exp(-T lambda area)")
    ("high-pass", po::value<double>()->value_name("T"), "sharpening 2 - exp(-T lambda area)")
    ("exact-only", "keep the curl-free part (exact eigenfields)")
    ("coexact-only", "keep the divergence-free part without harmonic fields (coexact eigenfields)")
    ("harmonic-only", "keep the harmonic part");
  add_output_options(command, "the filtered field", "filtered");
  if(!command.parse(args)) return 0; // --help
  command.require("basis");
  command.exactly_one({"low-pass", "high-pass", "exact-only", "coexact-only", "harmonic-only"});
  command.require("output");
  const Tool_mesh mesh(command.positional_value(), command.mollify());
  const Eigen::VectorXd v = read_input_field(command, mesh);
  const auto basis = load_basis(mesh, command.get<std::string>("basis"));
  const TVF::Eigenfield_basis& b = *basis;
  const double area = mesh.area();

  TVF::Spectral_filter filter;
  std::string description;
  if(command.has("low-pass") || command.has("high-pass"))
  {
    const bool low = command.has("low-pass");
    const double t = command.get<double>(low ? "low-pass" : "high-pass");
    if(!(t >= 0) || !std::isfinite(t)) throw Usage_error("the filter time T must be a finite number >= 0");
    filter = low ? TVF::Spectral_filter::low_pass(t * area) : TVF::Spectral_filter::high_pass(t * area);
    const double top = b.size() > 0 ? b.eigenvalue(b.size() - 1) * area : 0;
    const double gain_at_top = low ? std::exp(-t * top) : 2 - std::exp(-t * top);
    char text[300];
    std::snprintf(text, sizeof text, "%s, T = %g: gain %s at lambda * area = %.4g, %.3g at the top of the basis "
                  "(lambda * area = %.4g)", low ? "low-pass exp(-T lambda area)" : "high-pass 2 - exp(-T lambda area)",
                  t, low ? "1/2" : "3/2", t > 0 ? std::log(2.) / t : HUGE_VAL, gain_at_top, top);
    description = text;
    if(low && gain_at_top > 0.01)
      description += "\n  note: the gain is still large at the top of the basis, where the rest of the field is cut "
                     "off: use a larger T or a larger basis";
  }
  else if(command.has("exact-only"))
  {
    filter = TVF::Spectral_filter::exact_part();
    description = "the exact (curl-free) part in the basis";
  }
  else if(command.has("coexact-only"))
  {
    filter = TVF::Spectral_filter::coexact_part();
    description = "the coexact (divergence-free) part in the basis";
  }
  else
  {
    filter.exact = [](double) { return 0.; };
    filter.coexact = [](double) { return 0.; };
    filter.harmonic_factor = 1;
    filter.rest_factor = 0;
    description = "the harmonic part";
    if(b.number_of_harmonic() < mesh.intrinsic().topology().harmonic_dimension())
      description += "\n  note: the basis holds fewer harmonic fields than the mesh has";
  }
  const Eigen::VectorXd out = b.filter(v, filter);
  const Eigen::VectorXd a = b.coefficients(v), a_out = b.coefficients(out);
  say("filter: %s\n", description.c_str());
  say("  |field| = %.6g, |filtered| = %.6g (L2); Dirichlet energy in the basis %.6g -> %.6g\n",
      field_norm(mesh.matrices(), v), field_norm(mesh.matrices(), out), b.dirichlet_energy(a), b.dirichlet_energy(a_out));
  write_outputs(command, mesh, out);
  return 0;
}

// --- compress / decompress -----------------------------------------------------------------------

} // namespace tvf_tool
