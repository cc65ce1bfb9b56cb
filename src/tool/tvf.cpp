// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// tvf: tangent vector fields on triangle meshes from the command line.  One binary
// with subcommands (tvf <command> --help for each); errors end the program with a
// one-line reason on stderr, "tvf: error: ...", and a non-zero exit code (2 for a
// bad command line, 1 for anything else).

#include "tool.h"

#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/keep_freed_memory.h>

#include <cstdio>
#include <iostream>
#include <new>

namespace {

using namespace tvf_tool;

const std::vector<Subcommand>& subcommands()
{
  static const std::vector<Subcommand> list = {
      {"info", "size, topology (components, genus, boundary loops, harmonic dimension) and warnings of a mesh",
       info_command},
      {"decompose", "Hodge decomposition of a field into exact, coexact and harmonic parts", decompose_command},
      {"basis", "compute the lowest eigenfields of the Hodge-Laplacian and save them (.tvfb)", basis_command},
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
       singularities_command},
      {"serve", "start the interactive field editor (a local web server and page)", serve_command}};
  return list;
}

void print_usage(std::ostream& out)
{
  out << "usage: tvf <command> <mesh> [options]\n"
         "       tvf <command> --help     the options of a command\n\n"
         "Tangent vector fields on triangle meshes (CGAL Tangent_vector_fields): Hodge decomposition,\n"
         "Hodge-Laplace eigenfields (filtering, compression), field design, streamlines and pictures.\n"
         "Meshes: any file CGAL::IO::read_polygon_mesh reads (.off, .obj, .ply, .stl, .ts); face fields:\n"
         ".tvf, .ply face properties, .vtp, .rawfield.  Face, vertex and edge indices are those of the\n"
         "mesh file's order.\n\ncommands:\n";
  for(const Subcommand& c : subcommands())
  {
    char line[160];
    std::snprintf(line, sizeof line, "  %-12s %s\n", c.name, c.summary);
    out << line;
  }
  out << "\nexit codes: 0 success, 1 failure (the reason on stderr), 2 bad command line\n";
}

const Subcommand* find_command(const std::string& name)
{
  for(const Subcommand& c : subcommands())
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
  CGAL::Tangent_vector_fields::keep_freed_memory();
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
    std::cout << "tvf 0.1.0 (CGAL Tangent_vector_fields)\n";
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
