// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "tool_modes.h"

#include <CGAL/Discrete_shells/Shell_energy.h>
#include <CGAL/Vibration_modes/compressed_modes.h>
#include <CGAL/Vibration_modes/lowest_vibration_modes.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace tvf_tool {

namespace DS = CGAL::Discrete_shells;

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

bool is_scalar(const Command_line& command, Mode_use use)
{
  if(use == Mode_use::listing) return command.has("scalar");
  if(use == Mode_use::segmentation) return !command.has("shell");
  return false;
}

bool is_compressed(const Command_line& command, Mode_use use)
{
  return use == Mode_use::segmentation || command.has("compressed");
}

} // namespace

void add_mode_options(Command_line& command, Mode_use use)
{
  auto modes = command.group("modes").add_options();
  modes("modes,k", po::value<int>()->default_value(use == Mode_use::listing ? 10 : use == Mode_use::segmentation ? 6 : 20)
                       ->value_name("K"),
        "the number of modes");
  if(use == Mode_use::listing) modes("scalar", "modes of the cotangent Laplacian (one value per vertex) instead of the shell");
  if(use == Mode_use::segmentation)
    modes("shell", "compressed modes of the shell instead of the cotangent Laplacian's (compressed manifold modes)");
  modes("pin", po::value<std::string>()->value_name("LIST"), "vertices held in place, e.g. 0,5,17 (file order)")
    ("pin-end", "also hold the vertices within 5 % of the low end of the longer horizontal side (x or y) in place, as "
                "'tvf simulate --scene cantilever' does")
    ("stretching", po::value<double>()->default_value(1.0)->value_name("KS"), "shell: edge stretching stiffness")
    ("area", po::value<double>()->default_value(1.0)->value_name("KA"), "shell: triangle area stiffness")
    ("bending", po::value<double>()->default_value(1e-3)->value_name("KB"),
     "shell: bending stiffness (a squared length times the stretching stiffness, about thickness^2 / 12)");
  auto compressed = command.group("compressed modes").add_options();
  if(use != Mode_use::segmentation) compressed("compressed", "compressed modes instead of ordinary ones");
  if(use == Mode_use::listing)
    compressed("with-constants", "scalar compressed modes may use the constants (compressed manifold modes, as 'tvf "
                                 "segment' computes them) instead of being orthogonal to them");
  compressed("mu", po::value<double>()->value_name("MU"), "the sparsity weight mu (>= 0; 0 gives the ordinary modes)")
    ("mu-scale", po::value<double>()->default_value(use == Mode_use::segmentation ? 2.5 : 4.0)->value_name("S"),
     "mu = S lambda_K / sqrt(area): the weight relative to the K-th ordinary mode's eigenvalue")
    ("l1-budget", po::value<double>()->value_name("B"),
     "instead of mu: each mode minimises u^T H u with |u|_{1,M} <= B sqrt(area) (B in (0, 1]; 1 gives the ordinary modes)")
    ("iccm-iterations", po::value<int>()->default_value(200)->value_name("N"),
     "at most N ICCM (outer) iterations per compressed mode; a mode stopped there is reported");
  command.group("modes file").add_options()
    ("save", po::value<std::string>()->value_name("FILE.vmb"),
     "save the modes with the mesh's identity, pins and stiffnesses (for --load)")
    ("load", po::value<std::string>()->value_name("FILE.vmb"),
     "instead of computing: load modes saved for this mesh with the same pins and stiffnesses");
}

Mode_mesh::Mode_mesh(const Tool_mesh& mesh)
{
  const TVF::Intrinsic_mesh& m = mesh.intrinsic();
  x.resize(3 * Eigen::Index(m.number_of_vertices()));
  for(int v = 0; v < m.number_of_vertices(); ++v)
    for(int c = 0; c < 3; ++c) x[3 * v + c] = m.position(v)[std::size_t(c)];
  triangles.resize(std::size_t(m.number_of_faces()));
  for(int f = 0; f < m.number_of_faces(); ++f)
    for(int c = 0; c < 3; ++c) triangles[std::size_t(f)][c] = m.face_vertices(f)[std::size_t(c)];
}

std::vector<int> end_vertices(const Eigen::VectorXd& x)
{
  const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>> p(x.data(), x.size() / 3, 3);
  const Eigen::RowVector3d lo = p.colwise().minCoeff(), hi = p.colwise().maxCoeff();
  const int axis = hi[0] - lo[0] >= hi[1] - lo[1] ? 0 : 1;
  std::vector<int> end;
  for(Eigen::Index v = 0; v < p.rows(); ++v)
    if(p(v, axis) <= lo[axis] + 0.05 * (hi[axis] - lo[axis])) end.push_back(int(v));
  return end;
}

std::vector<int> pinned_vertices(const Command_line& command, const Mode_mesh& mesh)
{
  std::vector<int> pinned;
  if(command.has("pin")) pinned = parse_vertex_list(command.get<std::string>("pin"), mesh.vertices());
  if(command.has("pin-end"))
  {
    const std::vector<int> end = end_vertices(mesh.x);
    pinned.insert(pinned.end(), end.begin(), end.end());
  }
  std::sort(pinned.begin(), pinned.end());
  pinned.erase(std::unique(pinned.begin(), pinned.end()), pinned.end());
  return pinned;
}

// Names the compressed modes whose ICCM stopped at its iteration limit.
static void warn_unconverged(const VM::Modes& modes)
{
  std::string list;
  int count = 0, limit = 0;
  for(std::size_t i = 0; i < modes.converged.size(); ++i)
    if(!modes.converged[i])
    {
      list += (count++ ? ", " : "") + std::to_string(i + 1);
      limit = std::max(limit, modes.outer_iterations[i]);
    }
  if(count > 0)
    warn(std::string(count == 1 ? "mode " : "modes ") + list + " stopped at the limit of " + std::to_string(limit) +
         " ICCM iterations before meeting the stopping rule: feasible, but the objective may still fall "
         "(raise '--iccm-iterations')");
}

Tool_modes obtain_modes(const Command_line& command, Mode_use use, const Tool_mesh& mesh, const Mode_mesh& arrays,
                        const std::vector<int>& pinned, bool need_problem)
{
  const int k = command.get<int>("modes");
  if(k < 1) throw Usage_error("'--modes' must be at least 1");
  const bool scalar = is_scalar(command, use);
  Tool_modes result;
  result.settings.group_size = scalar ? 1 : 3;
  result.settings.pinned_vertices = pinned;
  result.settings.stiffness = {command.get<double>("stretching"), command.get<double>("area"),
                               command.get<double>("bending")};
  auto make_problem = [&] {
    return std::make_shared<const VM::Mode_problem>(
        scalar ? VM::laplacian_mode_problem(arrays.x, arrays.triangles, pinned)
               : VM::shell_mode_problem(DS::Shell_energy(arrays.x, arrays.triangles, result.settings.stiffness), pinned));
  };
  if(command.has("load"))
  {
    const std::string path = command.get<std::string>("load");
    VM::Mode_settings expected = result.settings;
    if(use == Mode_use::segmentation) expected.group_size = 0; // segments of any modes
    result.modes = VM::load_modes(path, arrays.x, arrays.triangles, &expected, &result.settings);
    result.loaded = true;
    say("loaded %ld %s modes from %s\n", long(result.modes.vectors.cols()),
        result.modes.objectives.size() > 0 ? "compressed" : "ordinary", path.c_str());
    warn_unconverged(result.modes);
    if(need_problem) result.problem = make_problem();
    return result;
  }

  Step setup("stiffness and mass");
  result.problem = make_problem();
  const VM::Mode_problem& problem = *result.problem;
  setup.done();
  const TVF::Intrinsic_mesh& m = mesh.intrinsic();
  say("mesh: %s, %d vertices, %d faces; %s problem, %ld unknowns, kernel %ld (%s), %.2f s\n", mesh.path().c_str(),
      m.number_of_vertices(), m.number_of_faces(), scalar ? "scalar (cotangent Laplacian)" : "shell",
      long(problem.H.rows()), long(problem.kernel.cols()), scalar ? "constants" : "rigid motions", setup.seconds());

  Step ordinary_step("ordinary modes");
  const VM::Modes ordinary = VM::lowest_vibration_modes(problem, k);
  ordinary_step.done();
  say("%d ordinary modes: %.2f s, eigenvalues %.6g ... %.6g, complete below %.6g (inertia proof)\n", k,
      ordinary_step.seconds(), ordinary.energies[0], ordinary.energies[k - 1], ordinary.complete_below);
  result.modes = ordinary;
  if(is_compressed(command, use))
  {
    double mu = command.get<double>("mu-scale") * ordinary.energies[k - 1] / std::sqrt(mesh.area());
    if(command.has("mu")) mu = command.get<double>("mu");
    if(!(mu >= 0) || !std::isfinite(mu)) throw Usage_error("the sparsity weight mu must be finite and >= 0");
    VM::Compressed_mode_options options;
    options.sparsity_weight = mu;
    options.max_outer_iterations = command.get<int>("iccm-iterations");
    if(options.max_outer_iterations < 1) throw Usage_error("'--iccm-iterations' must be at least 1");
    // Compressed manifold modes (bumps on parts) need the constants; shells stay orthogonal
    // to their rigid motions.
    options.orthogonal_to_kernel = !(scalar && (use == Mode_use::segmentation || command.has("with-constants")));
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
    result.modes = VM::compressed_modes(problem, k, options);
    bar.finish();
    step.done();
    if(command.has("l1-budget"))
      say("%d compressed modes, L1 budget %.6g: %.2f s\n", k, options.l1_budget, step.seconds());
    else
      say("%d compressed modes, mu %.6g: %.2f s\n", k, mu, step.seconds());
    const VM::Modes& r = result.modes;
    say("| mode | objective | energy u^T H u | support | ICCM iterations | ADMM iterations |\n|---|---|---|---|---|---|\n");
    for(int i = 0; i < k; ++i)
      say("| %d | %.6g | %.6g | %.1f %% | %d | %d |\n", i + 1, r.objectives[i], r.energies[i],
          100 * r.support_fractions[i], r.outer_iterations[std::size_t(i)], r.inner_iterations[std::size_t(i)]);
    warn_unconverged(r);
  }
  else
  {
    say("| mode | eigenvalue | residual |\n|---|---|---|\n");
    for(int i = 0; i < k; ++i) say("| %d | %.8g | %.1e |\n", i + 1, ordinary.energies[i], ordinary.residuals[i]);
  }
  if(command.has("save"))
  {
    VM::save_modes(command.get<std::string>("save"), result.modes, result.settings, arrays.x, arrays.triangles);
    say("saved %s\n", command.get<std::string>("save").c_str());
  }
  return result;
}

} // namespace tvf_tool
