// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// tvf: the thesis' systems on triangle meshes from the command line.  One binary with
// subcommands grouped by system (tvf <command> --help for each); errors end the program with a
// one-line reason on stderr, "tvf: error: ...", and a non-zero exit code (2 for a
// bad command line, 1 for anything else).

#include "tool.h"

#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Model_reduction/keep_freed_memory.h>

#include <cstdio>
#include <iostream>
#include <new>

namespace {

using namespace tvf_tool;

// The commands, by system of the thesis.  A chapter adds its commands as one more entry
// (doc/tangent_vector_fields/manual.md, "One tool"): its names must not clash with the others', since every
// command is called as `tvf <command>`.
struct Command_system
{
  const char* title;
  std::vector<Subcommand> commands;
};

const std::vector<Command_system>& systems()
{
  static const std::vector<Command_system> list = {
    {"Tangent vector fields and n-direction fields (Chapters 1-2, CGAL Tangent_vector_fields)",
     {{"info", "size, topology (components, genus, boundary loops, harmonic dimension) and warnings of a mesh",
       info_command},
      {"decompose", "Hodge decomposition of a field into exact, coexact and harmonic parts", decompose_command},
      {"basis", "compute the lowest eigenfields of the Hodge-Laplacian and save them (.tvfb; --n N: .tvfn)",
       basis_command},
      {"basis-info", "load a saved basis, check it against its mesh, print its spectrum", basis_info_command},
      {"eigenfield", "write one eigenfield of a saved basis as a field file", eigenfield_command},
      {"filter", "spectral filtering of a field: low-pass, high-pass, exact or coexact part", filter_command},
      {"compress", "keep the K lowest coefficients of a field in a basis (.tvfc)", compress_command},
      {"decompress", "rebuild a field from its coefficients (.tvfc)", decompress_command},
      {"design", "design a field from constraints (JSON): splines, full or reduced, or soft", design_command},
      {"render", "draw a field: colours, streamlines, fur or arrows; --n N: an n-field with glyphs (PNG or SVG)",
       render_command},
      {"streamlines", "trace evenly spaced streamlines or fur strokes (OBJ, PLY, VTP)", streamlines_command},
      {"export", "convert a field between .tvf, .ply, .vtp and .rawfield", export_command},
      {"smoothest", "the smoothest n-direction field (--n 4: cross field), optionally aligned to the curvature",
       smoothest_command},
      {"singularities", "the singular vertices of an n-field with their indices (.sing), Poincare-Hopf checked",
       singularities_command}}},
    {"Hyper-reduced Projective Dynamics (Chapter 3, CGAL Projective_dynamics)",
     {{"simulate", "an elastic solid (.mesh tetrahedra) or shell in a scene (drop, cantilever, grab), full or hyper-reduced",
       simulate_command}}},
    {"Vibration modes and compressed vibration modes (Chapter 5, CGAL Vibration_modes)",
     {{"modes", "the lowest vibration modes of a shell or a Laplacian, or compressed (local) modes; .vtp, pictures",
       modes_command},
      {"segment", "parts of a mesh from the supports of its compressed modes: labels per vertex (PLY, CSV), picture",
       segment_command},
      {"vibrate", "linearised vibration of a shell in the span of its modes (or full): frames (OBJ, PLY, VTP)",
       vibrate_command}}},
    {"Optimal spline approximation (Chapter 6, CGAL Spline_approximation)",
     {{"fit", "the spline with the fewest knots within an error of a curve (CSV or OBJ polyline); JSON, OBJ, SVG",
       fit_command},
      {"fit-motion", "a BVH motion compressed by splines within bounds in degrees and units; the report, BVH out",
       fit_motion_command}}},
    {"The viewer (every system)",
     {{"serve", "start the interactive viewer: a local web server and page (field editing; stroke fitting)", serve_command}}}};
  return list;
}

void print_usage(std::ostream& out)
{
  out << "usage: tvf <command> <mesh> [options]\n"
         "       tvf <command> --help     the options of a command\n\n"
         "The systems of the thesis 'Model Reduction for Interactive Geometry Processing' on CGAL\n"
         "meshes, one command-line tool with a group of commands per system.  Meshes: any file\n"
         "CGAL::IO::read_polygon_soup reads (.off, .obj, .ply, .stl, ...), repaired into a triangle mesh\n"
         "with a warning (or refused with --strict); face, vertex and edge indices are those of the\n"
         "mesh file's order.  Face fields: .tvf, .ply face properties, .vtp, .rawfield.\n\ncommands:\n";
  for(const Command_system& system : systems())
  {
    out << "\n" << system.title << ":\n";
    for(const Subcommand& c : system.commands)
    {
      char line[160];
      std::snprintf(line, sizeof line, "  %-14s %s\n", c.name, c.summary);
      out << line;
    }
  }
  out << "\nexit codes: 0 success, 1 failure (the reason on stderr), 2 bad command line\n";
}

const Subcommand* find_command(const std::string& name)
{
  for(const Command_system& system : systems())
    for(const Subcommand& c : system.commands)
      if(name == c.name) return &c;
  return nullptr;
}

int fail(int code, const std::string& reason)
{
  std::cout.flush();
  std::fprintf(stderr, "tvf: error: %s\n", one_line(reason).c_str());
  return code;
}

} // namespace

int main(int argc, char** argv)
{
  // Interactive commands (serve, design) allocate and free blocks of a few MB per edit.
  CGAL::Model_reduction::keep_freed_memory();
  std::vector<std::string> args(argv + 1, argv + argc);
  if(args.empty()) return fail(2, "no command given (run 'tvf --help' for the list of commands)");
  std::string name = args.front();
  if(name == "--help" || name == "-h" || name == "help")
  {
    if(args.size() > 1 && find_command(args[1]))
    {
      name = args[1];
      args = {name, "--help"};
    }
    else
    {
      if(args.size() > 1) return fail(2, "unknown command '" + args[1] + "' (run 'tvf --help' for the list of commands)");
      print_usage(std::cout);
      return 0;
    }
  }
  if(name == "--version")
  {
    // The packages whose commands the tool has.
    std::cout << "tvf 0.1.0 (CGAL Tangent_vector_fields, Projective_dynamics, Vibration_modes, Spline_approximation)\n";
    return 0;
  }
  const Subcommand* command = find_command(name);
  if(!command)
  {
    if(!name.empty() && name[0] == '-')
      return fail(2, "expected a command before the option '" + name + "' (run 'tvf --help')");
    return fail(2, "unknown command '" + name + "' (run 'tvf --help' for the list of commands)");
  }
  args.erase(args.begin());
  const std::string context = std::string(" (see 'tvf ") + command->name + " --help')";
  try
  {
    return command->run(args);
  }
  catch(const Usage_error& e)
  {
    return fail(2, std::string(command->name) + ": " + e.what() + context);
  }
  catch(const Tool_error& e)
  {
    return fail(1, e.what());
  }
  catch(const CGAL::Tangent_vector_fields::Infeasible_constraints& e)
  {
    return fail(1, std::string("infeasible constraints: ") + e.what());
  }
  catch(const CGAL::Tangent_vector_fields::Invalid_mesh& e)
  {
    return fail(1, std::string("invalid mesh: ") + e.what());
  }
  catch(const CGAL::Tangent_vector_fields::Invalid_input& e)
  {
    return fail(1, e.what());
  }
  catch(const CGAL::Tangent_vector_fields::Numerical_failure& e)
  {
    return fail(1, std::string("numerical failure: ") + e.what());
  }
  catch(const std::bad_alloc&)
  {
    return fail(1, "out of memory");
  }
  catch(const std::exception& e)
  {
    return fail(1, std::string(command->name) + ": " + e.what());
  }
  catch(...)
  {
    return fail(1, std::string(command->name) + ": unknown failure");
  }
}
