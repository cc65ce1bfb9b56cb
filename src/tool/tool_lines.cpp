// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "tool_lines.h"

#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/field_files.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>

namespace tvf_tool {

TVF::Length_unit length_unit(const std::string& name)
{
  if(name == "diagonal") return TVF::Length_unit::bounding_box_diagonal;
  if(name == "edge") return TVF::Length_unit::mean_edge_length;
  if(name == "absolute") return TVF::Length_unit::absolute;
  throw Usage_error("unknown length unit '" + name + "' (diagonal, edge or absolute)");
}

// A summary of why the ends of the streamlines stopped, such as "boundary 12, closed_loop 3".
std::string stop_summary(const std::vector<TVF::Streamline>& lines)
{
  std::map<std::string, int> counts;
  for(const TVF::Streamline& s : lines)
    for(TVF::Streamline_stop stop : {s.backward_stop, s.forward_stop})
      if(stop != TVF::Streamline_stop::none) ++counts[TVF::to_string(stop)];
  std::string text;
  for(const auto& c : counts) text += (text.empty() ? "" : ", ") + c.first + " " + std::to_string(c.second);
  return text.empty() ? "none" : text;
}

void add_streamline_options(Command_line& command)
{
  command.group("streamlines").add_options()
    ("unit", po::value<std::string>()->default_value("diagonal")->value_name("U"),
     "unit of the lengths (--separation, --length, --max-length): diagonal (of the bounding box), edge (mean edge "
     "length) or absolute")
    ("separation", po::value<double>()->default_value(0.02)->value_name("S"),
     "distance between evenly spaced streamlines (in --unit)")
    ("seed", po::value<unsigned>()->default_value(1)->value_name("N"), "random seed of the seeds and fur roots");
  command.group("fur").add_options()
    ("strokes", po::value<int>()->value_name("N"), "number of fur strokes (default 5000, or from --density)")
    ("density", po::value<double>()->value_name("D"), "instead: strokes per unit area (mesh units squared)")
    ("length", po::value<double>()->default_value(0.03)->value_name("L"), "length of a stroke (in --unit)")
    ("scale-by-magnitude", "stroke lengths proportional to the magnitude at their roots");
}

TVF::Evenly_spaced_options evenly_spaced_options(const Command_line& command, TVF::Length_unit unit)
{
  TVF::Evenly_spaced_options even;
  even.separation = command.get<double>("separation");
  if(!(even.separation > 0) || !std::isfinite(even.separation)) throw Usage_error("'--separation' must be positive");
  even.separation_unit = unit;
  even.random_seed = command.get<unsigned>("seed");
  return even;
}

TVF::Fur_options fur_options(const Command_line& command, TVF::Length_unit unit)
{
  TVF::Fur_options fur;
  command.at_most_one({"strokes", "density"});
  fur.number_of_strokes = command.has("strokes") ? command.get<int>("strokes") : 0;
  if(command.has("density")) fur.density = command.get<double>("density");
  else if(!command.has("strokes")) fur.number_of_strokes = 5000;
  if(fur.number_of_strokes < 0 || (command.has("strokes") && fur.number_of_strokes == 0))
    throw Usage_error("'--strokes' must be positive");
  if(command.has("density") && !(fur.density > 0)) throw Usage_error("'--density' must be positive");
  fur.length = command.get<double>("length");
  if(!(fur.length > 0) || !std::isfinite(fur.length)) throw Usage_error("'--length' must be positive");
  fur.length_unit = unit;
  fur.scale_length_by_magnitude = command.has("scale-by-magnitude");
  fur.random_seed = command.get<unsigned>("seed");
  return fur;
}

void write_streamline_files(const Command_line& command, const std::vector<TVF::Streamline>& lines)
{
  for(const std::string& path : command.get<std::vector<std::string>>("output"))
  {
    const std::string ext = extension(path);
    std::ofstream out(path);
    if(!out) throw Tool_error("cannot open '" + path + "' for writing: " + std::strerror(errno));
    try
    {
      if(ext == "obj") TVF::write_streamlines_obj(out, lines);
      else if(ext == "ply") TVF::write_streamlines_ply(out, lines);
      else TVF::write_vtk_polydata(out, TVF::streamlines_polydata(lines));
    }
    catch(const TVF::Invalid_input& e)
    {
      throw Tool_error(about(path, one_line(e.what())));
    }
    say("wrote %s\n", path.c_str());
  }
}

#ifdef TVF_HAS_CAIRO
std::size_t add_lines(TVF::Field_renderer& renderer, const TVF::Streamline_tracer& tracer, const Command_line& command,
                      const TVF::Colour& colour, const TVF::Evenly_spaced_options* even, const TVF::Fur_options* fur)
{
  std::size_t drawn = 0;
  if(even)
  {
    Step step(tracer.n() > 1 ? "hatching" : "tracing streamlines");
    TVF::Line_style style;
    style.colour = colour;
    style.width = command.has("line-width") ? command.get<double>("line-width") : 1.3;
    std::vector<TVF::Streamline> traced = tracer.evenly_spaced(*even);
    drawn += traced.size();
    renderer.add_streamlines(std::move(traced), style);
  }
  if(fur)
  {
    Step step("growing fur");
    TVF::Line_style style;
    style.taper = true;
    style.width = command.has("line-width") ? command.get<double>("line-width") : 1.6;
    style.opacity = 0.85;
    style.colour = colour;
    std::vector<TVF::Streamline> strokes = tracer.fur(*fur);
    drawn += strokes.size();
    renderer.add_streamlines(std::move(strokes), style);
  }
  return drawn;
}
#endif

} // namespace tvf_tool
