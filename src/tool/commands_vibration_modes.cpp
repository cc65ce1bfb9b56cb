// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// tvf modes: vibration modes and compressed vibration modes of a mesh (Chapter 5), their
// .vtp export, pictures and contact sheet.

#include "mode_pictures.h"
#include "tool_modes.h"

#include <CGAL/Vibration_modes/mode_export.h>

namespace tvf_tool {

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
  add_mode_options(command, Mode_use::listing);
  command.group("output").add_options()
    ("output,o", po::value<std::string>()->value_name("FILE.vtp"), "the mesh with every mode as a point array")
    ("pictures", po::value<std::string>()->value_name("PREFIX"),
     "one PNG per mode, PREFIX_01.png ...: the mesh moved along the mode and coloured by |u| (scalar modes: values)")
    ("contact-sheet", po::value<std::string>()->value_name("FILE.png"),
     "the first modes in one picture, a grid of cells captioned with the mode's index and eigenvalue (or energy)")
    ("sheet-modes", po::value<int>()->value_name("N"), "contact sheet: how many modes (default all)")
    ("columns", po::value<int>()->default_value(4)->value_name("C"), "contact sheet: cells per row")
    ("cell-size", po::value<int>()->default_value(300)->value_name("PX"), "contact sheet: width and height of a cell")
    ("displacement", po::value<double>()->default_value(0.1)->value_name("D"),
     "pictures: the largest displacement as a fraction of the bounding box diagonal");
  if(!command.parse(args)) return 0; // --help
  if(command.has("contact-sheet") && extension(command.get<std::string>("contact-sheet")) != "png")
    throw Usage_error("'--contact-sheet': '" + command.get<std::string>("contact-sheet") + "' is not a .png file");
  const int columns = command.get<int>("columns"), cell = command.get<int>("cell-size");
  if(columns < 1) throw Usage_error("'--columns' must be at least 1");
  if(cell < 32 || cell > 4096) throw Usage_error("'--cell-size' must lie in [32, 4096] pixels");
  const Tool_mesh mesh(command.positional_value(), command.mollify());
  const Mode_mesh arrays(mesh);
  const Tool_modes result =
      obtain_modes(command, Mode_use::listing, mesh, arrays, pinned_vertices(command, arrays), false);
  const VM::Modes& modes = result.modes;
  const double displacement = command.get<double>("displacement");
  if(command.has("pictures")) write_mode_pictures(command.get<std::string>("pictures"), mesh, modes, displacement);
  if(command.has("contact-sheet"))
  {
    const int available = int(modes.vectors.cols());
    const int count = command.has("sheet-modes") ? command.get<int>("sheet-modes") : available;
    if(count < 1 || count > available)
      throw Usage_error("'--sheet-modes " + std::to_string(count) + "': there are " + std::to_string(available) +
                        " modes (1 to " + std::to_string(available) + ")");
    write_contact_sheet(command.get<std::string>("contact-sheet"), mesh, modes, count, std::min(columns, count), cell,
                        displacement);
  }
  if(command.has("output"))
  {
    const std::string path = command.get<std::string>("output");
    try
    {
      VM::write_modes_vtp(path, arrays.x, arrays.triangles, modes);
    }
    catch(const std::exception& e)
    {
      throw Tool_error(e.what());
    }
    say("wrote %s\n", path.c_str());
  }
  return 0;
}

} // namespace tvf_tool
