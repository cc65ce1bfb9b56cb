// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// tvf vibrate: the linearised elastodynamics of a shell about its rest shape (Chapter 5), in the
// span of its modes or at full resolution, in a scripted scene, written as a frame sequence.

#include "frame_writer.h"
#include "tool_modes.h"

#include <CGAL/Vibration_modes/linear_simulation.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace tvf_tool {

namespace {

Eigen::Vector3d parse_vector(const std::string& option, const std::string& text)
{
  double a = 0, b = 0, c = 0;
  char end = 0;
  if(std::sscanf(text.c_str(), "%lf,%lf,%lf%c", &a, &b, &c, &end) != 3 || !std::isfinite(a + b + c))
    throw Usage_error("'--" + option + "': '" + text + "' is not three numbers a,b,c");
  return Eigen::Vector3d(a, b, c);
}

std::vector<int> parse_vertices(const std::string& option, const std::string& text, int count)
{
  std::vector<int> list;
  std::stringstream in(text);
  std::string item;
  while(std::getline(in, item, ','))
  {
    char* end = nullptr;
    const long v = std::strtol(item.c_str(), &end, 10);
    if(item.empty() || *end != 0) throw Usage_error("'--" + option + "': '" + item + "' is not a vertex index");
    if(v < 0 || v >= count)
      throw Usage_error("'--" + option + "': vertex " + item + " is not in the mesh (" + std::to_string(count) + " vertices)");
    list.push_back(int(v));
  }
  return list;
}

struct Run
{
  const char* name;
  VM::Linear_trajectory trajectory;
  double seconds = 0;
};

// Largest vertex displacement of a trajectory over all its frames.
double largest_displacement(const Eigen::MatrixXd& u)
{
  double largest = 0;
  for(Eigen::Index v = 0; v < u.rows() / 3; ++v)
    for(Eigen::Index f = 0; f < u.cols(); ++f) largest = std::max(largest, u.block<3, 1>(3 * v, f).norm());
  return largest;
}

} // namespace

int vibrate_command(const Arguments& args)
{
  Command_line command(
      "tvf vibrate <mesh> [--scene gravity|mode|push] [-k K | --load FILE.vmb] [--full] [--compare] [-o FOLDER]",
      "The linearised elastodynamics of the mesh as a shell about its rest shape, M u'' + (a M + b H) u' + H u = f,\n"
      "by the trapezoidal rule (implicit, unconditionally stable; undamped, it keeps the energy).  Reduced by\n"
      "default: u in the span of K modes (computed as by tvf modes, or --load) and the rigid motions left free;\n"
      "--full steps all unknowns (CHOLMOD); --compare runs both and prints the reduced run's relative M-norm error.\n"
      "Scenes: 'gravity' (9.81 along -z on the lumped masses; with no --pin, the end pinned as by --pin-end),\n"
      "'mode' (released from rest displaced along mode I), 'push' (a constant force on chosen vertices).\n"
      "Prints the time per frame; -o writes frame_0000.obj ... (.ply, or .vtp with a ParaView frames.pvd).");
  command.positional("mesh", "the mesh file");
  add_mode_options(command, Mode_use::simulation);
  command.group("scene").add_options()
    ("scene", po::value<std::string>()->default_value("gravity")->value_name("S"), "gravity, mode or push")
    ("gravity", po::value<double>()->default_value(9.81)->value_name("G"), "gravity: acceleration along -z")
    ("mode", po::value<int>()->default_value(1)->value_name("I"), "mode: the mode (1 to K) the body starts along")
    ("amplitude", po::value<double>()->default_value(0.05)->value_name("A"),
     "mode: the largest starting displacement as a fraction of the bounding box diagonal")
    ("push", po::value<std::string>()->value_name("LIST"), "push: the vertices pushed, e.g. 3,9 (file order)")
    ("force", po::value<std::string>()->default_value("0,0,-1")->value_name("a,b,c"), "push: the force on each")
    ("frames", po::value<int>()->default_value(100)->value_name("N"), "time steps, each written as a frame")
    ("time-step", po::value<double>()->value_name("H"),
     "seconds per step (default: a fortieth of the period of the slowest mode)")
    ("damping-mass", po::value<double>()->default_value(0.0)->value_name("A"), "Rayleigh damping a (of M)")
    ("damping-stiffness", po::value<double>()->default_value(0.0)->value_name("B"), "Rayleigh damping b (of H)");
  command.group("simulation").add_options()
    ("full", "the full simulation (all unknowns) instead of the reduced one")
    ("compare", "run both and print the relative M-norm error of the reduced trajectory against the full one");
  command.group("output").add_options()
    ("output,o", po::value<std::string>()->value_name("FOLDER"), "write one file per frame into FOLDER")
    ("format", po::value<std::string>()->value_name("F")->default_value("obj"), "obj, ply, or vtp (with frames.pvd)");
  if(!command.parse(args)) return 0; // --help
  const std::string scene = command.get<std::string>("scene"), format = command.get<std::string>("format");
  if(scene != "gravity" && scene != "mode" && scene != "push")
    throw Usage_error("'--scene' must be gravity, mode or push, not '" + scene + "'");
  if(!Frame_writer::known_format(format)) throw Usage_error("'--format' must be obj, ply or vtp, not '" + format + "'");
  const int frames = command.get<int>("frames");
  if(frames < 1) throw Usage_error("'--frames' must be at least 1");
  if(command.has("time-step") && !(command.get<double>("time-step") > 0 && std::isfinite(command.get<double>("time-step"))))
    throw Usage_error("'--time-step' must be finite and positive");
  const double alpha = command.get<double>("damping-mass"), beta = command.get<double>("damping-stiffness");
  if(!(alpha >= 0 && beta >= 0 && std::isfinite(alpha + beta)))
    throw Usage_error("'--damping-mass' and '--damping-stiffness' must be finite and >= 0");
  if(scene == "push" && !command.has("push")) throw Usage_error("'--scene push' needs the vertices: give '--push LIST'");
  if(scene == "mode" && !(command.get<double>("amplitude") > 0 && std::isfinite(command.get<double>("amplitude"))))
    throw Usage_error("'--amplitude' must be finite and positive");

  const Tool_mesh mesh(command.positional_value(), command.mollify());
  const Mode_mesh arrays(mesh);
  const int n = arrays.vertices();
  std::vector<int> pinned = pinned_vertices(command, arrays);
  if(scene == "gravity" && pinned.empty())
  {
    pinned = end_vertices(arrays.x);
    say("gravity: no pins given, the end pinned (%zu vertices, as --pin-end)\n", pinned.size());
  }
  const std::vector<int> pushed =
      scene == "push" ? parse_vertices("push", command.get<std::string>("push"), n) : std::vector<int>();
  Tool_modes source = obtain_modes(command, Mode_use::simulation, mesh, arrays, pinned, true);
  if(source.modes.vectors.rows() != 3 * Eigen::Index(n))
    throw Tool_error("'" + command.get<std::string>("load") + "' holds scalar modes: vibrate needs a shell's modes");
  const VM::Mode_problem& problem = *source.problem;
  int k = int(source.modes.vectors.cols());
  if(source.loaded && command.has("modes"))
  {
    if(command.get<int>("modes") > k)
      throw Usage_error("'-k " + std::to_string(command.get<int>("modes")) + "': the file holds " + std::to_string(k) +
                        " modes");
    k = command.get<int>("modes");
  }
  const int mode = command.get<int>("mode");
  if(scene == "mode" && (mode < 1 || mode > k))
    throw Usage_error("'--mode " + std::to_string(mode) + "': there are " + std::to_string(k) + " modes (1 to " +
                      std::to_string(k) + ")");

  VM::Linear_simulation_options o;
  o.steps = frames;
  o.rayleigh_mass = alpha;
  o.rayleigh_stiffness = beta;
  const double slowest = source.modes.energies[0];
  o.time_step = command.has("time-step") ? command.get<double>("time-step")
                : slowest > 0              ? 2 * M_PI / std::sqrt(slowest) / 40
                                           : 1e-2;
  const Eigen::VectorXd mass = problem.expand(problem.mass); // zero at pinned unknowns
  const double diagonal = mesh.bounding_box_diagonal();
  if(scene == "gravity")
  {
    o.force = Eigen::VectorXd::Zero(3 * Eigen::Index(n));
    for(Eigen::Index v = 0; v < n; ++v) o.force[3 * v + 2] = -command.get<double>("gravity") * mass[3 * v + 2];
  }
  else if(scene == "push")
  {
    const Eigen::Vector3d f = parse_vector("force", command.get<std::string>("force"));
    o.force = Eigen::VectorXd::Zero(3 * Eigen::Index(n));
    for(int v : pushed) o.force.segment<3>(3 * v) += f;
  }
  else
  {
    const Eigen::VectorXd phi = source.modes.vectors.col(mode - 1);
    double largest = 0;
    for(Eigen::Index v = 0; v < n; ++v) largest = std::max(largest, phi.segment<3>(3 * v).norm());
    o.initial_displacement = command.get<double>("amplitude") * diagonal / largest * phi;
  }
  say("scene %s: %d frames of %.4g s, damping %.3g M + %.3g H, %zu vertices pinned\n", scene.c_str(), frames,
      o.time_step, alpha, beta, pinned.size());

  std::vector<Run> runs;
  const bool full = command.has("full") || command.has("compare"), reduced = !command.has("full") || command.has("compare");
  if(reduced)
  {
    Step step("reduced simulation");
    Run r{"reduced", VM::reduced_linear_simulation(problem, source.modes, k, o)};
    step.done();
    r.seconds = step.seconds();
    say("reduced: %d modes and %ld rigid motions, %.3f ms in all, %.4f ms per frame\n", k, long(problem.kernel.cols()),
        1e3 * r.seconds, 1e3 * r.seconds / frames);
    runs.push_back(std::move(r));
  }
  if(full)
  {
    Step step("full simulation");
    Run r{"full", VM::full_linear_simulation(problem, o)};
    step.done();
    r.seconds = step.seconds();
    say("full: %ld unknowns, %.3f ms in all, %.4f ms per frame (factorisation included)\n", long(problem.H.rows()),
        1e3 * r.seconds, 1e3 * r.seconds / frames);
    runs.push_back(std::move(r));
  }
  if(runs.size() == 2)
    say("relative M-norm error of the reduced trajectory against the full one: %.3e (%d modes)\n",
        VM::relative_trajectory_error(problem, runs[0].trajectory, runs[1].trajectory), k);

  // The frames of the run asked for (the full one with --full).
  const Run& shown = command.has("full") ? runs.back() : runs.front();
  const Eigen::MatrixXd& u = shown.trajectory.displacements;
  const double largest = largest_displacement(u);
  say("%s run: energy %.6g at the start, %.6g at the end; largest displacement %.4g (%.3g of the diagonal)\n",
      shown.name, shown.trajectory.energies[0], shown.trajectory.energies[u.cols() - 1], largest, largest / diagonal);
  if(largest > 0.2 * diagonal)
  {
    // The motion is linear in the load: say which gravity keeps it to a tenth of the diagonal.
    std::string hint = "lower the load or raise the stiffnesses";
    if(scene == "gravity")
    {
      char text[96];
      std::snprintf(text, sizeof text, "--gravity %.3g keeps them to a tenth", command.get<double>("gravity") * 0.1 * diagonal / largest);
      hint = text;
    }
    warn("displacements beyond a fifth of the diagonal: the linearisation no longer describes the body (" + hint + ")");
  }
  double pin_drift = 0, mean_dz = 0;
  for(int v : pinned) pin_drift = std::max(pin_drift, u.block<3, 1>(3 * v, u.cols() - 1).norm());
  for(Eigen::Index v = 0; v < n; ++v) mean_dz += u(3 * v + 2, u.cols() - 1) / n;
  if(!pinned.empty()) say("pinned vertices: %zu, largest displacement %.3g\n", pinned.size(), pin_drift);
  if(scene == "gravity") say("sag at the end: mean change of height %.6g\n", mean_dz);

  Frame_writer writer(command.has("output") ? command.get<std::string>("output") : std::string(), format,
                      arrays.triangles, o.time_step);
  Frame_writer::Positions q(n, 3);
  for(Eigen::Index f = 0; f < u.cols() && command.has("output"); ++f)
  {
    for(Eigen::Index v = 0; v < n; ++v)
      for(int c = 0; c < 3; ++c) q(v, c) = arrays.x[3 * v + c] + u(3 * v + c, f);
    writer.write(int(f), q);
  }
  const std::string written = writer.finish();
  if(!written.empty()) say("%s\n", written.c_str());
  return 0;
}

} // namespace tvf_tool
