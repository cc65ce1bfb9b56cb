// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// tvf segment: a mesh cut into parts by the supports of its compressed modes (Chapter 5).

#include "mode_pictures.h"
#include "tool_modes.h"

#include <CGAL/Model_reduction/Vtk_polydata.h>
#include <CGAL/Vibration_modes/mode_segmentation.h>

#include <algorithm>
#include <fstream>

namespace tvf_tool {

namespace {

// One row per vertex (file order): its segment (-1: none) and the mode it comes from (1-based, 0: none).
void write_labels(const std::string& path, const Mode_mesh& mesh, const VM::Mode_segmentation& s)
{
  std::ofstream out(path);
  if(!out) throw Tool_error("cannot open '" + path + "' for writing");
  MR::internal::prepare_exact_output(out);
  const auto mode_of = [&](int r) { return r < 0 ? 0 : s.region_mode[std::size_t(r)] + 1; }; // 1-based; 0: none
  if(extension(path) == "csv")
  {
    out << "vertex,segment,mode\n";
    for(std::size_t v = 0; v < s.region.size(); ++v) out << v << ',' << s.region[v] << ',' << mode_of(s.region[v]) << '\n';
  }
  else
  {
    out << "ply\nformat ascii 1.0\nelement vertex " << s.region.size()
        << "\nproperty double x\nproperty double y\nproperty double z\nproperty int segment\nproperty int mode\n"
        << "element face " << mesh.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
    for(std::size_t v = 0; v < s.region.size(); ++v)
      out << mesh.x[3 * Eigen::Index(v)] << ' ' << mesh.x[3 * Eigen::Index(v) + 1] << ' ' << mesh.x[3 * Eigen::Index(v) + 2]
          << ' ' << s.region[v] << ' ' << mode_of(s.region[v]) << '\n';
    for(const auto& t : mesh.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  }
  out.close();
  if(!out) throw Tool_error("writing '" + path + "' failed");
  say("wrote %s\n", path.c_str());
}

} // namespace

int segment_command(const Arguments& args)
{
  Command_line command(
      "tvf segment <mesh> [-k K] [--mu-scale S | --mu MU] [--shell] [--load FILE.vmb] -o LABELS.ply|.csv [--picture FILE.png]",
      "Cuts the mesh into parts by the supports of its compressed modes: each vertex goes to the mode with the\n"
      "largest |u_i(v)| (none if every mode vanishes there, or the winner is below --threshold of its peak), and\n"
      "the vertices of one mode are split into connected regions.  By default the modes are the K compressed\n"
      "manifold modes of the cotangent Laplacian (local bumps on parts; mu = 2.5 lambda_K / sqrt(area)); --shell\n"
      "takes the shell's compressed modes; --load takes modes saved by tvf modes, segment or vibrate.  Prints the\n"
      "segments and their sizes; writes a label per vertex (PLY vertex property 'segment', or CSV) and a picture.");
  command.positional("mesh", "the mesh file");
  add_mode_options(command, Mode_use::segmentation);
  command.group("segmentation").add_options()
    ("threshold", po::value<double>()->default_value(0.0)->value_name("T"),
     "leave a vertex unassigned (-1) if its winning mode is below T times that mode's peak; T in [0, 1)")
    ("output,o", po::value<std::string>()->value_name("FILE"),
     "the labels: .ply (the mesh with vertex properties 'segment', -1 for none, and 'mode', 1-based) or .csv "
     "(vertex,segment,mode)")
    ("picture", po::value<std::string>()->value_name("FILE.png"), "the mesh coloured by segment (.png or .svg)");
  if(!command.parse(args)) return 0; // --help
  if(command.has("output") && extension(command.get<std::string>("output")) != "ply" &&
     extension(command.get<std::string>("output")) != "csv")
    throw Usage_error("'--output': '" + command.get<std::string>("output") + "': labels are written as .ply or .csv");
  if(command.has("picture") && extension(command.get<std::string>("picture")) != "png" &&
     extension(command.get<std::string>("picture")) != "svg")
    throw Usage_error("'--picture': '" + command.get<std::string>("picture") + "' is not a .png or .svg file");
  const double threshold = command.get<double>("threshold");
  if(!(threshold >= 0 && threshold < 1)) throw Usage_error("'--threshold' must lie in [0, 1)");
  const Tool_mesh mesh(command.positional_value(), command.mollify());
  const Mode_mesh arrays(mesh);
  const Tool_modes result =
      obtain_modes(command, Mode_use::segmentation, mesh, arrays, pinned_vertices(command, arrays), false);
  const VM::Modes& modes = result.modes;
  const int group = modes.vectors.rows() == Eigen::Index(arrays.vertices()) ? 1 : 3;
  Step step("segmentation");
  const VM::Mode_segmentation s = VM::segment_by_modes(modes.vectors, group, arrays.triangles, threshold);
  step.done();
  const long unassigned = long(std::count(s.region.begin(), s.region.end(), -1));
  say("%d segments from %ld modes (%.3f s); %ld vertices unassigned\n", s.number_of_regions(), long(modes.vectors.cols()),
      step.seconds(), unassigned);
  say("| segment | mode | vertices |\n|---|---|---|\n");
  for(int r = 0; r < s.number_of_regions(); ++r)
    say("| %d | %d | %d |\n", r, s.region_mode[std::size_t(r)] + 1, s.region_size[std::size_t(r)]);
  if(command.has("output")) write_labels(command.get<std::string>("output"), arrays, s);
  if(command.has("picture")) write_segment_picture(command.get<std::string>("picture"), mesh, s.region, s.number_of_regions());
  return 0;
}

} // namespace tvf_tool
