// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `tvf serve`: the viewer (src/viewer) with the sessions of Chapters 1 and 2, designing
// tangent vector fields and n-direction fields on the mesh, the stroke fitting of Chapter 6
// (the `curve` kind, which needs no mesh) and the mesh simulated in real time by Chapter 3
// (the `simulation` kind) (doc/viewer/protocol.md).  Here:
// the options, the mesh and the background job that provides the basis.

#include "tool.h"
#include "server.h"
#include "tangent_vector_fields/field_kinds.h"
#include "tangent_vector_fields/field_session.h"
#include "spline_approximation/curve_session.h"
#include "projective_dynamics/simulation_session.h"

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Hodge_solver.h>
#include <CGAL/Tangent_vector_fields/N_field_basis.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <boost/asio/ip/address.hpp>

#include <cstdio>
#include <fstream>
#include <thread>

#ifndef TVF_VIEWER_DIST_DIR
#define TVF_VIEWER_DIST_DIR ""
#endif

namespace tvf_tool {

using tvf_viewer::Field_limits;
using tvf_viewer::Field_model;

namespace {

// The mesh as the simulation session simulates it (its vertices in the page's order).
std::shared_ptr<const tvf_viewer::Simulation_surface> simulation_surface(const Tool_mesh& mesh, const std::string& name)
{
  auto surface = std::make_shared<tvf_viewer::Simulation_surface>();
  const TVF::Intrinsic_mesh& m = mesh.intrinsic();
  surface->name = name;
  for(int v = 0; v < m.number_of_vertices(); ++v) surface->points.push_back(m.position(v));
  for(int f = 0; f < m.number_of_faces(); ++f) surface->triangles.push_back(m.face_vertices(f));
  surface->closed = true;
  for(int e = 0; e < m.number_of_edges(); ++e) surface->closed = surface->closed && !m.is_boundary_edge(e);
  return surface;
}

} // namespace

int serve_command(const Arguments& args)
{
  Command_line command(
      "tvf serve <mesh> [--basis FILE.tvfb] [-n N] [-d D] [--port P] [--bind ADDRESS]",
      "Starts the interactive field editor: a local web server that serves the editor page and answers\n"
      "constraint edits with the new field (tangent vector field splines in a spectral basis: the\n"
      "reduced solver, and the full-resolution one on request).  Open the address it prints in a browser.\n"
      "The basis is loaded from --basis if that file exists, else computed (the N lowest eigenfields,\n"
      "with progress on the page) and saved there, so the precomputation is done once.  The page also\n"
      "designs n-direction fields (line fields, cross fields, ...): the basis of n-fields (N elements) is\n"
      "made when a page first asks for its n, loaded from or saved to FILE.n<n>.tvfn beside --basis.\n"
      "The page's Session menu (or &kind=curve in the address) opens stroke fitting instead: draw a curve\n"
      "and watch its spline's knots follow the tolerance (Chapter 6; the mesh is not used there), and\n"
      "&kind=simulation the mesh as cloth (or, closed, a solid) falling onto a floor in real time: grab,\n"
      "drag and poke it, change its stiffness while it moves (Projective Dynamics, Chapter 3).\n"
      "Only this machine's names (and --allow-host ones) are answered, only the page's own origin (and\n"
      "--allow-origin ones) may use it, and the WebSocket needs the token of the printed address:\n"
      "other web pages open in the browser cannot reach the session.  Stop with Ctrl-C.");
  command.positional("mesh", "the mesh file");
  command.group("basis").add_options()
    ("basis", po::value<std::string>()->value_name("FILE"), "the basis: loaded if the file exists, else computed and saved")
    ("eigenfields,n", po::value<int>()->default_value(300)->value_name("N"), "eigenfields to compute if there is no basis file")
    ("size,d", po::value<int>()->value_name("D"), "basis size a new session starts with (default: all)");
  command.group("server").add_options()
    ("port", po::value<int>()->default_value(8080)->value_name("P"), "TCP port (0: any free port)")
    ("bind", po::value<std::string>()->default_value("127.0.0.1")->value_name("ADDRESS"),
     "address to listen on (the default serves this machine only)")
    ("web-root", po::value<std::string>()->value_name("DIR"), "directory of the page (default: the one built with tvf)")
    ("max-connections", po::value<int>()->default_value(16)->value_name("N"), "connections served at once")
    ("stall-timeout", po::value<int>()->default_value(20)->value_name("S"),
     "seconds a request or message may take to arrive once begun; a client that stalls longer is disconnected")
    ("allow-host", po::value<std::vector<std::string>>()->composing()->value_name("NAME"),
     "a further name this server answers to in the Host header, besides 127.0.0.1, localhost, [::1] and "
     "the --bind address (repeatable; e.g. the machine's name when bound to 0.0.0.0)")
    ("allow-origin", po::value<std::vector<std::string>>()->composing()->value_name("ORIGIN"),
     "a further web origin (scheme://host[:port]) whose pages may use the server, besides the page's own "
     "(repeatable; e.g. https://proxy.example)");
  if(!command.parse(args)) return 0; // --help
  const int port = command.get<int>("port");
  if(port < 0 || port > 65535) throw Usage_error("'--port' must lie in [0, 65535]");
  const int eigenfields = command.get<int>("eigenfields");
  if(eigenfields <= 0) throw Usage_error("'--eigenfields' must be positive");
  const int size = command.has("size") ? command.get<int>("size") : 0;
  if(command.has("size") && size <= 0) throw Usage_error("'--size' must be positive");
  const int max_connections = command.get<int>("max-connections");
  if(max_connections <= 0) throw Usage_error("'--max-connections' must be positive");
  const int stall_timeout = command.get<int>("stall-timeout");
  if(stall_timeout <= 0) throw Usage_error("'--stall-timeout' must be positive");
  std::string basis_path = command.has("basis") ? command.get<std::string>("basis") : std::string();
  if(!basis_path.empty() && extension(basis_path) != "tvfb")
    throw Usage_error("the basis file '" + basis_path + "' should end in .tvfb");
  boost::system::error_code error;
  boost::asio::ip::make_address(command.get<std::string>("bind"), error);
  if(error) throw Usage_error("'--bind': '" + command.get<std::string>("bind") + "' is not an IP address");

  const Tool_mesh mesh(command.positional_value(), command.mollify());
  if(!basis_path.empty() && !std::ifstream(basis_path) && eigenfields > 2 * mesh.number_of_faces())
    throw Tool_error("the mesh has only " + std::to_string(2 * mesh.number_of_faces()) + " eigenfields");
  auto hodge = std::make_shared<TVF::Hodge_solver>(mesh.shared_matrices());
  std::string name = mesh.path();
  name = name.substr(name.find_last_of('/') + 1);
  auto model = std::make_shared<Field_model>(mesh.shared_matrices(), hodge, name, mesh.bounding_box_diagonal(), size,
                                              Field_limits());

  // n-field bases: beside the basis file (FILE.n4.tvfn), loaded if there, else computed and saved.
  model->set_n_field_basis_source([basis_path, eigenfields](std::shared_ptr<const TVF::N_field_operators> ops,
                                                            const std::function<void(const std::string&, double)>& progress) {
    const std::string path = basis_path.empty() ? std::string()
                                                : basis_path.substr(0, basis_path.size() - 5) + ".n" +
                                                      std::to_string(ops->n()) + ".tvfn";
    if(!path.empty() && std::ifstream(path))
    {
      progress("loading the basis of n-fields " + path, 0);
      return std::make_shared<const TVF::N_field_basis>(TVF::N_field_basis::load(ops, path));
    }
    TVF::Basis_options options;
    options.progress = [&progress](const TVF::Spectral_progress& p) {
      progress("computing the basis of n-fields: " + p.stage, p.fraction);
    };
    const int count = std::min(eigenfields + eigenfields % 2, 2 * ops->mesh().number_of_faces());
    auto basis = std::make_shared<const TVF::N_field_basis>(ops, count, options);
    if(!path.empty())
    {
      progress("saving the basis of n-fields to " + path, 1);
      basis->save(path);
    }
    return basis;
  });

  tvf_viewer::Server_options options;
  options.web_root = command.has("web-root") ? command.get<std::string>("web-root") : std::string(TVF_VIEWER_DIST_DIR);
  options.max_connections = max_connections;
  options.stall_timeout = std::chrono::seconds(stall_timeout);
  options.max_message_bytes = model->limits().max_message_bytes;
  options.quiet = command.quiet();
  if(command.has("allow-host")) options.allowed_hosts = command.get<std::vector<std::string>>("allow-host");
  if(command.has("allow-origin")) options.allowed_origins = command.get<std::vector<std::string>>("allow-origin");
  if(!std::ifstream(options.web_root + "/index.html"))
    std::fprintf(stderr, "tvf: warning: no viewer page in '%s' (built with npm; see --web-root)\n",
                 options.web_root.c_str());
  tvf_viewer::Session_kinds kinds;
  tvf_viewer::add_field_kinds(kinds, model);
  kinds.add(std::make_shared<tvf_viewer::Curve_kind>()); // strokes (Chapter 6): no mesh needed, never the default
  kinds.add(std::make_shared<tvf_viewer::Simulation_kind>(simulation_surface(mesh, name)));
  tvf_viewer::Server server(kinds, options);
  try
  {
    server.listen(command.get<std::string>("bind"), port);
  }
  catch(const std::runtime_error& e)
  {
    throw Tool_error(e.what());
  }

  // The basis: loaded or computed in the background, so that the page can show progress.
  const bool quiet = command.quiet();
  std::thread([model, hodge, basis_path, eigenfields, quiet] {
    try
    {
      std::shared_ptr<const TVF::Eigenfield_basis> basis;
      if(!basis_path.empty() && std::ifstream(basis_path))
      {
        model->set_progress("loading the basis " + basis_path, 0);
        basis = std::make_shared<const TVF::Eigenfield_basis>(TVF::Eigenfield_basis::load(hodge, basis_path));
      }
      else
      {
        TVF::Basis_options options;
        options.progress = [&model](const TVF::Spectral_progress& p) {
          model->set_progress("computing the basis: " + p.stage, p.fraction);
        };
        basis = std::make_shared<const TVF::Eigenfield_basis>(hodge, TVF::Basis_request::lowest(eigenfields), options);
        if(!basis_path.empty())
        {
          model->set_progress("saving the basis to " + basis_path, 1);
          basis->save(basis_path);
        }
      }
      model->set_basis(basis);
      if(!quiet) std::printf("basis ready: %d eigenfields\n", basis->size()), std::fflush(stdout);
    }
    catch(const std::exception& e)
    {
      model->set_failure(one_line(e.what()));
      std::fprintf(stderr, "tvf: error: the basis: %s\n", one_line(e.what()).c_str());
    }
  }).detach();

  // Always printed (also with --quiet): scripts and tests read the address and its token from it.
  std::printf("listening on %s\n", server.url().c_str());
  std::fflush(stdout);
  server.run();
}

} // namespace tvf_tool
