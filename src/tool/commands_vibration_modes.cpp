// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// tvf modes: vibration modes and compressed vibration modes of a mesh (Chapter 5).

#include "tool.h"

#include <CGAL/Discrete_shells/Shell_energy.h>
#include <CGAL/Vibration_modes/Mode_problem.h>
#include <CGAL/Vibration_modes/compressed_modes.h>
#include <CGAL/Vibration_modes/lowest_vibration_modes.h>
#include <CGAL/Vibration_modes/mode_export.h>
#include <CGAL/Vibration_modes/modes_file.h>

#ifdef TVF_HAS_CAIRO
#include <CGAL/Tangent_vector_fields/Field_renderer.h>
#endif

#include <cmath>
#include <cstdio>
#include <sstream>

namespace tvf_tool {

namespace DS = CGAL::Discrete_shells;
namespace VM = CGAL::Vibration_modes;

namespace {

std::vector<int> parse_vertex_list(const std::string& text, int vertex_count)
{
  std::vector<int> list;
  std::stringstream in(text);
  std::string item;
  while(std::getline(in, item, ','))
  {
    std::size_t used = 0;
    long v = -1;
    try
    {
      v = std::stol(item, &used);
    }
    catch(const std::exception&)
    {
      used = 0;
    }
    if(used == 0 || used != item.size())
      throw Usage_error("'--pin': '" + item + "' is not a vertex index (a comma-separated list is expected)");
    if(v < 0 || v >= vertex_count)
      throw Usage_error("'--pin': vertex " + item + " is not in the mesh (" + std::to_string(vertex_count) + " vertices)");
    list.push_back(int(v));
  }
  return list;
}

// One picture per mode: a displacement mode as the mesh moved along it, coloured by |u|; a
// scalar mode as its values on the mesh (diverging colours).
void write_mode_pictures(const std::string& prefix, const TVF::Intrinsic_mesh& mesh, const VM::Modes& modes,
                         double scale)
{
#ifdef TVF_HAS_CAIRO
  const int n = mesh.number_of_vertices();
  const bool scalar = modes.vectors.rows() == n;
  std::vector<std::array<int, 3>> faces(std::size_t(mesh.number_of_faces()));
  for(int f = 0; f < mesh.number_of_faces(); ++f) faces[std::size_t(f)] = mesh.face_vertices(f);
  for(Eigen::Index i = 0; i < modes.vectors.cols(); ++i)
  {
    const Eigen::VectorXd u = modes.vectors.col(i);
    std::vector<TVF::Intrinsic_mesh::Point> moved(static_cast<std::size_t>(n));
    std::vector<double> values(static_cast<std::size_t>(n), 0.0);
    for(int v = 0; v < n; ++v)
    {
      moved[std::size_t(v)] = mesh.position(v);
      if(scalar)
      {
        values[std::size_t(v)] = u[v];
        continue;
      }
      for(int c = 0; c < 3; ++c) moved[std::size_t(v)][std::size_t(c)] += scale * u[3 * v + c];
      values[std::size_t(v)] = u.segment<3>(3 * v).norm();
    }
    TVF::Field_renderer renderer(std::make_shared<const TVF::Intrinsic_mesh>(moved, faces));
    TVF::Scalar_colouring colouring;
    colouring.map = scalar ? TVF::Colour_map::cool_warm : TVF::Colour_map::viridis;
    colouring.symmetric = scalar;
    colouring.label = scalar ? "mode " + std::to_string(i + 1) : "|u| of mode " + std::to_string(i + 1);
    renderer.colour_vertices(values, colouring);
    char name[32];
    std::snprintf(name, sizeof name, "_%02ld.png", long(i + 1));
    renderer.write_png(prefix + name);
  }
  say("wrote %ld pictures %s_01.png ...\n", long(modes.vectors.cols()), prefix.c_str());
#else
  (void)mesh, (void)modes, (void)scale;
  throw Tool_error("'--pictures " + prefix + "': this tvf was built without Cairo (TVF_USE_CAIRO)");
#endif
}

} // namespace

int modes_command(const Arguments& args)
{
  Command_line command(
      "tvf modes <mesh> [-k K] [--compressed --mu-scale S | --mu MU] [--scalar] [--pin LIST] [-o FILE.vtp]",
      "Vibration modes of the mesh as an elastic shell (stretching, area and bending; the lowest K modes of\n"
      "H u = lambda M u after the rigid motions, every residual checked and completeness proved by an inertia\n"
      "count), or of its cotangent Laplacian (--scalar).  With --compressed: compressed modes, local modes that\n"
      "minimise u^T H u + mu |u|_{1,M} one after the other (ICCM with ADMM), with their objective and support.\n"
      "Written as a .vtp with every mode a point array (mode_1, mode_2, ...; ParaView: Warp By Vector).");
  command.positional("mesh", "the mesh file");
  command.group("modes").add_options()
    ("modes,k", po::value<int>()->default_value(10)->value_name("K"), "the number of modes")
    ("scalar", "modes of the cotangent Laplacian (one value per vertex) instead of the shell")
    ("pin", po::value<std::string>()->value_name("LIST"), "vertices held in place, e.g. 0,5,17 (file order)")
    ("stretching", po::value<double>()->default_value(1.0)->value_name("KS"), "shell: edge stretching stiffness")
    ("area", po::value<double>()->default_value(1.0)->value_name("KA"), "shell: triangle area stiffness")
    ("bending", po::value<double>()->default_value(1e-3)->value_name("KB"),
     "shell: bending stiffness (a squared length times the stretching stiffness, about thickness^2 / 12)");
  command.group("compressed modes").add_options()
    ("compressed", "compressed modes instead of ordinary ones")
    ("mu", po::value<double>()->value_name("MU"), "the sparsity weight mu (>= 0; 0 gives the ordinary modes)")
    ("mu-scale", po::value<double>()->default_value(4.0)->value_name("S"),
     "mu = S lambda_K / sqrt(area): the weight relative to the K-th ordinary mode's eigenvalue")
    ("l1-budget", po::value<double>()->value_name("B"),
     "instead of mu: each mode minimises u^T H u with |u|_{1,M} <= B sqrt(area) (B in (0, 1]; 1 gives the ordinary modes)");
  command.group("output").add_options()
    ("output,o", po::value<std::string>()->value_name("FILE.vtp"), "the mesh with every mode as a point array")
    ("save", po::value<std::string>()->value_name("FILE.vmb"),
     "save the modes with the mesh's identity, pins and stiffnesses (for --load)")
    ("load", po::value<std::string>()->value_name("FILE.vmb"),
     "instead of computing: load modes saved for this mesh with the same pins and stiffnesses")
    ("pictures", po::value<std::string>()->value_name("PREFIX"),
     "one PNG per mode, PREFIX_01.png ...: the mesh moved along the mode and coloured by |u| (scalar modes: values)")
    ("displacement", po::value<double>()->default_value(0.1)->value_name("D"),
     "pictures: the largest displacement as a fraction of the bounding box diagonal");
  if(!command.parse(args)) return 0; // --help
  const int k = command.get<int>("modes");
  if(k < 1) throw Usage_error("'--modes' must be at least 1");
  const Tool_mesh mesh(command.positional_value(), command.mollify());
  const TVF::Intrinsic_mesh& m = mesh.intrinsic();
  Eigen::VectorXd x(3 * Eigen::Index(m.number_of_vertices()));
  for(int v = 0; v < m.number_of_vertices(); ++v)
    for(int c = 0; c < 3; ++c) x[3 * v + c] = m.position(v)[std::size_t(c)];
  std::vector<DS::Shell_energy::Triangle> triangles(std::size_t(m.number_of_faces()));
  for(int f = 0; f < m.number_of_faces(); ++f)
    for(int c = 0; c < 3; ++c) triangles[std::size_t(f)][c] = m.face_vertices(f)[std::size_t(c)];
  const std::vector<int> pinned =
      command.has("pin") ? parse_vertex_list(command.get<std::string>("pin"), m.number_of_vertices()) : std::vector<int>();

  const bool scalar = command.has("scalar");
  VM::Mode_settings settings;
  settings.group_size = scalar ? 1 : 3;
  settings.pinned_vertices = pinned;
  settings.stiffness = {command.get<double>("stretching"), command.get<double>("area"), command.get<double>("bending")};
  auto write = [&](const VM::Modes& modes) {
    if(command.has("pictures"))
    {
      const double largest = modes.vectors.cwiseAbs().maxCoeff();
      write_mode_pictures(command.get<std::string>("pictures"), m, modes,
                          largest > 0 ? command.get<double>("displacement") * mesh.bounding_box_diagonal() / largest : 0);
    }
    if(!command.has("output")) return;
    const std::string path = command.get<std::string>("output");
    try
    {
      VM::write_modes_vtp(path, x, triangles, modes);
    }
    catch(const std::exception& e)
    {
      throw Tool_error(e.what());
    }
    say("wrote %s\n", path.c_str());
  };
  if(command.has("load"))
  {
    const VM::Modes loaded = VM::load_modes(command.get<std::string>("load"), x, triangles, &settings);
    say("loaded %ld %s modes from %s\n", long(loaded.vectors.cols()),
        loaded.objectives.size() > 0 ? "compressed" : "ordinary", command.get<std::string>("load").c_str());
    write(loaded);
    return 0;
  }

  Step setup("stiffness and mass");
  const VM::Mode_problem problem =
      scalar ? VM::laplacian_mode_problem(x, triangles, pinned)
             : VM::shell_mode_problem(DS::Shell_energy(x, triangles, settings.stiffness), pinned);
  setup.done();
  say("mesh: %s, %d vertices, %d faces; %s problem, %ld unknowns, kernel %ld (%s), %.2f s\n", mesh.path().c_str(),
      m.number_of_vertices(), m.number_of_faces(), scalar ? "scalar (cotangent Laplacian)" : "shell",
      long(problem.H.rows()), long(problem.kernel.cols()), scalar ? "constants" : "rigid motions", setup.seconds());

  Step ordinary_step("ordinary modes");
  const VM::Modes ordinary = VM::lowest_vibration_modes(problem, k);
  ordinary_step.done();
  say("%d ordinary modes: %.2f s, eigenvalues %.6g ... %.6g, complete below %.6g (inertia proof)\n", k,
      ordinary_step.seconds(), ordinary.energies[0], ordinary.energies[k - 1], ordinary.complete_below);
  VM::Modes result = ordinary;
  if(command.has("compressed"))
  {
    double mu = command.get<double>("mu-scale") * ordinary.energies[k - 1] / std::sqrt(mesh.area());
    if(command.has("mu")) mu = command.get<double>("mu");
    if(!(mu >= 0) || !std::isfinite(mu)) throw Usage_error("the sparsity weight mu must be finite and >= 0");
    VM::Compressed_mode_options options;
    options.sparsity_weight = mu;
    if(command.has("l1-budget"))
    {
      if(command.has("mu")) throw Usage_error("give either '--mu' or '--l1-budget', not both");
      const double b = command.get<double>("l1-budget");
      if(!(b > 0) || !std::isfinite(b)) throw Usage_error("'--l1-budget' must be finite and > 0");
      options.sparsity_weight = mu = 0;
      // The budget's unit: the mass-weighted L1 norm of a unit vector is at most sqrt(total mass).
      options.l1_budget = b * std::sqrt(problem.mass.sum() / problem.group_size);
    }
    Progress_bar bar;
    options.progress = [&](const VM::Compressed_mode_progress& p) {
      bar.update("compressed mode " + std::to_string(p.mode + 1) + " of " + std::to_string(p.count),
                 (p.mode + std::min(1.0, p.outer_iteration / 50.0)) / p.count);
      return true;
    };
    Step step("compressed modes");
    result = VM::compressed_modes(problem, k, options);
    bar.finish();
    step.done();
    if(command.has("l1-budget"))
      say("%d compressed modes, L1 budget %.6g: %.2f s\n", k, options.l1_budget, step.seconds());
    else
      say("%d compressed modes, mu %.6g: %.2f s\n", k, mu, step.seconds());
    say("| mode | objective | energy u^T H u | support | ICCM iterations | ADMM iterations |\n|---|---|---|---|---|---|\n");
    for(int i = 0; i < k; ++i)
      say("| %d | %.6g | %.6g | %.1f %% | %d | %d |\n", i + 1, result.objectives[i], result.energies[i],
          100 * result.support_fractions[i], result.outer_iterations[std::size_t(i)],
          result.inner_iterations[std::size_t(i)]);
  }
  else
  {
    say("| mode | eigenvalue | residual |\n|---|---|---|\n");
    for(int i = 0; i < k; ++i) say("| %d | %.8g | %.1e |\n", i + 1, result.energies[i], result.residuals[i]);
  }
  write(result);
  if(command.has("save"))
  {
    VM::save_modes(command.get<std::string>("save"), result, settings, x, triangles);
    say("saved %s\n", command.get<std::string>("save").c_str());
  }
  return 0;
}

} // namespace tvf_tool
