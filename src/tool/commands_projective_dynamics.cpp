// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// tvf simulate: Projective Dynamics (Chapter 3) of a solid (tetrahedra of a Medit .mesh file)
// or a shell (a surface mesh), full or hyper-reduced, in a scripted scene (a drop on a floor, a
// cantilever, a grabbed end lifted), one OBJ or VTP file per frame (VTP with a ParaView .pvd
// series).

#include "frame_writer.h"
#include "tool.h"

#include <CGAL/Model_reduction/errors.h>
#include <CGAL/Projective_dynamics/Reduced_simulator.h>
#include <CGAL/Projective_dynamics/Simulator.h>
#include <CGAL/Projective_dynamics/make_models.h>
#include <CGAL/Projective_dynamics/medit_io.h>
#include <CGAL/Projective_dynamics/tetrahedralize.h>
#include <CGAL/Projective_dynamics/internal/scene_setup.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace tvf_tool {

namespace PD = CGAL::Projective_dynamics;
namespace MR = CGAL::Model_reduction;

namespace {

using Body = PD::internal::Simulated_body;

Body read_body(const std::string& path, const Command_line& command)
{
  const double stiffness = command.get<double>("stiffness"), density = command.get<double>("density");
  const std::string extension = std::filesystem::path(path).extension().string();
  try
  {
    if(extension == ".mesh")
    {
      const PD::Tet_mesh tets = PD::read_medit(path);
      PD::check_tet_mesh(tets);
      return Body(PD::make_solid_model(tets, PD::parameters::strain_stiffness(stiffness).density(density)),
                  tets.triangles.empty() ? PD::boundary_triangles(tets.points, tets.tetrahedra) : tets.triangles, true,
                  int(tets.tetrahedra.size()));
    }
    const Tool_mesh mesh(path, command.mollify());
    const auto& m = mesh.intrinsic();
    std::vector<PD::Point> points(std::size_t(m.number_of_vertices()));
    for(int v = 0; v < m.number_of_vertices(); ++v) points[std::size_t(v)] = m.position(v);
    std::vector<PD::Triangle> triangles(std::size_t(m.number_of_faces()));
    for(int f = 0; f < m.number_of_faces(); ++f) triangles[std::size_t(f)] = m.face_vertices(f);
    PD::internal::Body_material material;
    material.stiffness = stiffness;
    material.density = density;
    material.bending = command.get<double>("bending");
    if(!command.has("solid")) return PD::internal::body_of_surface(points, triangles, false, material);
    PD::Tetrahedralization_options o;
    o.cell_size = command.get<double>("cell-size");
    o.facet_distance = command.get<double>("facet-distance");
    o.feature_angle = command.get<double>("feature-angle");
    Step meshing("tetrahedra (Mesh_3)");
    Body body = PD::internal::body_of_surface(points, triangles, true, material, o);
    meshing.done();
    say("tetrahedra: %zu vertices, %zu tetrahedra (Mesh_3, %.3f s); the surface's vertices embedded, at most %.3g of "
        "the diagonal outside them\n",
        body.tetrahedra.points.size(), body.tetrahedra.tetrahedra.size(), meshing.seconds(),
        body.largest_outside_distance);
    if(command.has("tetrahedra"))
    {
      PD::write_medit(command.get<std::string>("tetrahedra"), body.tetrahedra);
      say("wrote %s\n", command.get<std::string>("tetrahedra").c_str());
    }
    return body;
  }
  catch(const std::invalid_argument& e) // Invalid_input or Invalid_mesh
  {
    throw Tool_error("'" + path + "': " + one_line(e.what()));
  }
}

// The scene's handles, placed from the rest shape's bounding box: gravity along -z; the
// cantilever's and the grab's axis is the longer horizontal side of the box.
struct Scene
{
  std::string name;
  double floor_height = 0;
  std::vector<int> pinned, grabbed;
  PD::Positions grab_start;
  double lift = 0; // of the grabbed vertices over the whole run
};

Scene make_scene(const std::string& name, const PD::Positions& rest)
{
  const Eigen::RowVector3d lo = rest.colwise().minCoeff(), hi = rest.colwise().maxCoeff();
  const Eigen::RowVector3d extent = hi - lo;
  const int axis = extent[0] >= extent[1] ? 0 : 1;
  const double length = extent[axis];
  Scene s;
  s.name = name;
  if(name == "drop")
  {
    s.floor_height = PD::internal::drop_floor_height(rest);
    return s;
  }
  // Cantilever and grab: the vertices within 5% of the length of one end are pinned.
  for(Eigen::Index v = 0; v < rest.rows(); ++v)
  {
    if(rest(v, axis) <= lo[axis] + 0.05 * length) s.pinned.push_back(int(v));
    if(name == "grab" && rest(v, axis) >= hi[axis] - 0.05 * length) s.grabbed.push_back(int(v));
  }
  if(name == "grab")
  {
    s.grab_start.resize(Eigen::Index(s.grabbed.size()), 3);
    for(std::size_t i = 0; i < s.grabbed.size(); ++i) s.grab_start.row(Eigen::Index(i)) = rest.row(s.grabbed[i]);
    s.lift = 0.3 * length;
  }
  return s;
}

double percentile(std::vector<double> v, double p)
{
  if(v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, std::size_t(p * double(v.size())))];
}

// Runs the scene on either simulator (their scene interfaces agree) and reports what moved.
template <class Simulator>
void run_scene(Simulator& sim, const Scene& scene, const PD::Positions& rest, const Body& body, int frames,
               Frame_writer& writer)
{
  if(scene.name == "drop")
  {
    sim.add_floor(Eigen::Vector3d(0, 0, scene.floor_height), Eigen::Vector3d(0, 0, 1));
    // Reduced: the floor holds what is drawn (full PD holds every vertex).
    if constexpr(std::is_same_v<Simulator, PD::Reduced_simulator>) sim.set_collision_vertices(PD::internal::collision_vertices(body, int(rest.rows())));
  }
  if(!scene.pinned.empty()) sim.set_pinned_vertices(scene.pinned);
  if(!scene.grabbed.empty()) sim.grab(scene.grabbed, scene.grab_start);
  writer.write(0, body.drawn(sim.positions()));
  std::vector<double> step_ms;
  double local = 0, global = 0, contact = 0, lowest = rest.col(2).minCoeff();
  for(int f = 1; f <= frames; ++f)
  {
    if(!scene.grabbed.empty())
    {
      PD::Positions target = scene.grab_start;
      target.col(2).array() += scene.lift * double(f) / frames;
      sim.move_grabbed(target);
    }
    sim.step();
    const auto& t = sim.last_step_timings();
    step_ms.push_back(1e3 * t.total);
    local += t.local;
    global += t.global;
    if constexpr(std::is_same_v<Simulator, PD::Reduced_simulator>) contact += t.contact;
    const PD::Positions q = sim.positions();
    lowest = std::min(lowest, q.col(2).minCoeff());
    writer.write(f, body.drawn(q));
  }
  double sum = 0;
  for(double ms : step_ms) sum += ms;
  say("%d frames: step %.3f ms mean, %.3f ms p90 (local %.3f, global %.3f, contact %.3f ms mean)\n", frames,
      sum / frames, percentile(step_ms, 0.9), 1e3 * local / frames, 1e3 * global / frames, 1e3 * contact / frames);
  const PD::Positions q = sim.positions();
  if(scene.name == "drop")
    say("floor at z = %.6g; lowest vertex: %.6g at the end, %.6g over the run\n", scene.floor_height,
        q.col(2).minCoeff(), lowest);
  if(!scene.pinned.empty())
  {
    double pin_drift = 0;
    for(int v : scene.pinned) pin_drift = std::max(pin_drift, (q.row(v) - rest.row(v)).norm());
    say("pinned vertices: %zu, largest distance from their rest positions %.3g\n", scene.pinned.size(), pin_drift);
  }
  if(scene.name == "cantilever")
    say("sag: mean change of height %.6g, largest drop %.6g\n", (q.col(2) - rest.col(2)).mean(),
        (rest.col(2) - q.col(2)).maxCoeff());
  if(!scene.grabbed.empty())
  {
    double miss = 0;
    for(std::size_t i = 0; i < scene.grabbed.size(); ++i)
    {
      Eigen::RowVector3d target = scene.grab_start.row(Eigen::Index(i));
      target[2] += scene.lift;
      miss = std::max(miss, (q.row(scene.grabbed[i]) - target).norm());
    }
    say("grabbed vertices: %zu lifted by %.6g; largest distance from their targets at the end %.3g\n",
        scene.grabbed.size(), scene.lift, miss);
  }
}

} // namespace

int simulate_command(const Arguments& args)
{
  Command_line command(
      "tvf simulate <body.mesh|surface mesh> [--scene drop|cantilever|grab] [--frames N] [--reduced] [-o FOLDER]",
      "Simulates an elastic body with Projective Dynamics (Chapter 3, SPEC 12): a solid from the tetrahedra of a\n"
      "Medit .mesh file (CGAL Mesh_3, TetGen -g, Gmsh), or a shell from a surface mesh (stretching and\n"
      "bending).  Units are the mesh's, with gravity 9.81 along -z.  Scenes: 'drop' (falls onto a floor a\n"
      "quarter of its height below it), 'cantilever' (the vertices within 5% of one end of its longer\n"
      "horizontal side pinned, sagging under gravity), 'grab' (pinned as the cantilever, the other end's\n"
      "vertices grabbed and lifted by 0.3 of the length over the run).  Full PD by default; --reduced for\n"
      "hyper-reduced PD (its sizes capped to what the mesh allows; --save and --load keep its\n"
      "precomputation with the body's identity).  Prints the step time (local and global)\n"
      "and what the scene moved; -o writes frame_0000.obj ... (.ply, or .vtp with a ParaView frames.pvd series).");
  command.positional("body", "a Medit .mesh file (a solid) or a surface mesh (a shell)");
  command.group("scene").add_options()
    ("scene", po::value<std::string>()->value_name("S")->default_value("drop"), "drop, cantilever or grab")
    ("frames", po::value<int>()->value_name("N")->default_value(60), "time steps to simulate")
    ("time-step", po::value<double>()->value_name("H")->default_value(1.0 / 30), "seconds per step")
    ("iterations", po::value<int>()->value_name("K")->default_value(10), "local/global iterations per step")
    ("threads", po::value<int>()->value_name("T")->default_value(0), "threads of the local steps (0: all cores)");
  command.group("solid from a surface").add_options()
    ("solid", "fill a closed surface mesh with tetrahedra (CGAL Mesh_3) and simulate the solid; the frames show "
              "the surface")
    ("cell-size", po::value<double>()->value_name("C")->default_value(0.05),
     "largest tetrahedron circumradius, relative to the bounding box diagonal")
    ("facet-distance", po::value<double>()->value_name("D")->default_value(0.002),
     "largest distance of the tetrahedra's boundary from the surface, relative to the diagonal")
    ("feature-angle", po::value<double>()->value_name("A")->default_value(60.0),
     "edges whose faces' normals differ by more than A degrees stay sharp (0: none)")
    ("tetrahedra", po::value<std::string>()->value_name("FILE.mesh"), "write the tetrahedra (Medit)");
  command.group("material").add_options()
    ("stiffness", po::value<double>()->value_name("K")->default_value(1e7), "strain stiffness (per volume or area)")
    ("density", po::value<double>()->value_name("RHO")->default_value(1e3), "mass per volume (solids) or area (shells)")
    ("bending", po::value<double>()->value_name("B")->default_value(0.0), "bending stiffness of shells");
  command.group("reduction").add_options()
    ("reduced", "hyper-reduced PD instead of full PD")
    ("samples", po::value<int>()->value_name("M")->default_value(150),
     "position samples (k = 4M coordinates; by default at most one per 16 vertices)")
    ("projection-columns", po::value<int>()->value_name("L")->default_value(120), "projection subspace size per group")
    ("sampled-elements", po::value<int>()->value_name("S")->default_value(1000), "sampled elements per group")
    ("save", po::value<std::string>()->value_name("FILE.pdr"), "save the precomputation (for --load)")
    ("load", po::value<std::string>()->value_name("FILE.pdr"),
     "instead of precomputing: load one saved for this body with the same reduction options");
  command.group("output").add_options()
    ("output,o", po::value<std::string>()->value_name("FOLDER"), "write one file per frame into FOLDER")
    ("format", po::value<std::string>()->value_name("F")->default_value("obj"), "obj, ply, or vtp (with frames.pvd)");
  if(!command.parse(args)) return 0; // --help
  const std::string scene_name = command.get<std::string>("scene"), format = command.get<std::string>("format");
  if(scene_name != "drop" && scene_name != "cantilever" && scene_name != "grab")
    throw Usage_error("'--scene' must be drop, cantilever or grab, not '" + scene_name + "'");
  if(!Frame_writer::known_format(format))
    throw Usage_error("'--format' must be obj, ply or vtp, not '" + format + "'");
  if((command.has("save") || command.has("load")) && !command.has("reduced"))
    throw Usage_error("'--save' and '--load' keep the hyper-reduced precomputation: give '--reduced'");
  const int frames = command.get<int>("frames");
  if(frames < 1) throw Usage_error("'--frames' must be at least 1");

  const std::string path = command.positional_value();
  Step reading("reading the body");
  Body body = read_body(path, command);
  reading.done();
  const PD::Positions rest = body.model.rest_positions();
  say("body: %s, a %s, %d vertices, %d %s, %d element groups\n", path.c_str(), body.solid ? "solid" : "shell",
      body.model.number_of_vertices(), body.elements, body.solid ? "tetrahedra" : "triangles",
      body.model.number_of_groups());
  const Scene scene = make_scene(scene_name, rest);

  PD::Simulator_options options;
  options.time_step = command.get<double>("time-step");
  options.iterations = command.get<int>("iterations");
  options.threads = command.get<int>("threads");
  Frame_writer writer(command.has("output") ? command.get<std::string>("output") : std::string(), format, body.surface,
                      options.time_step);
  try
  {
    if(command.has("reduced"))
    {
      const int n = body.model.number_of_vertices();
      PD::Reduction_options r = PD::internal::capped_reduction_options(
          n, command.get<int>("samples"), command.has("samples"), command.get<int>("projection-columns"),
          command.get<int>("sampled-elements"));
      Progress_bar bar;
      r.progress = [&](const PD::Reduced_precomputation_progress& p) {
        bar.update(p.stage, p.fraction);
        return true;
      };
      Step precomputation(command.has("load") ? "loading the precomputation" : "hyper-reduced PD precomputation");
      PD::Reduced_simulator sim = command.has("load")
                                      ? PD::Reduced_simulator::load(std::move(body.model), command.get<std::string>("load"),
                                                                    options, r)
                                      : PD::Reduced_simulator(std::move(body.model), options, r);
      bar.finish();
      precomputation.done();
      say("hyper-reduced PD: %d position samples (k = %d), l = %d, s = %d; %s %.3f s\n", r.samples, sim.dimension(),
          r.projection_columns, r.sampled_elements, command.has("load") ? "loaded in" : "precomputation",
          precomputation.seconds());
      if(command.has("save"))
      {
        sim.save(command.get<std::string>("save"));
        say("saved the precomputation to %s\n", command.get<std::string>("save").c_str());
      }
      run_scene(sim, scene, rest, body, frames, writer); // body: its embedding only (the model moved)
    }
    else
    {
      Step factor("full PD set-up");
      PD::Simulator sim(std::move(body.model), options);
      factor.done();
      say("full PD: %ld unknowns, set-up %.3f s\n", long(rest.rows()), factor.seconds());
      run_scene(sim, scene, rest, body, frames, writer); // body: its embedding only (the model moved)
    }
  }
  catch(const MR::Invalid_input& e)
  {
    throw Tool_error("'" + path + "': " + one_line(e.what()));
  }
  catch(const MR::Numerical_failure& e)
  {
    throw Tool_error("'" + path + "': " + one_line(e.what()));
  }
  const std::string written = writer.finish();
  if(!written.empty()) say("%s\n", written.c_str());
  return 0;
}

} // namespace tvf_tool
