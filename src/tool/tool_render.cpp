// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The options and outputs that the two forms of `tvf render` share (see tool_render.h).

#include "tool_render.h"

#include <CGAL/Tangent_vector_fields/errors.h>

#include <cmath>
#include <cstdio>
#include <map>

namespace tvf_tool {

namespace {

#ifdef TVF_HAS_CAIRO
TVF::Colour parse_colour(const std::string& text)
{
  static const std::map<std::string, TVF::Colour> names = {
      {"black", {0.08, 0.08, 0.08}}, {"white", {1, 1, 1}},     {"grey", {0.5, 0.5, 0.5}},  {"gray", {0.5, 0.5, 0.5}},
      {"red", {0.8, 0.1, 0.1}},      {"blue", {0.1, 0.2, 0.8}}, {"green", {0.1, 0.6, 0.2}}, {"orange", {0.95, 0.55, 0.1}}};
  const auto it = names.find(text);
  if(it != names.end()) return it->second;
  unsigned r = 0, g = 0, b = 0;
  char end = 0;
  if(text.size() == 7 && text[0] == '#' && std::sscanf(text.c_str() + 1, "%2x%2x%2x%c", &r, &g, &b, &end) == 3)
    return {r / 255., g / 255., b / 255.};
  throw Usage_error("unknown colour '" + text + "' (black, white, grey, red, blue, green, orange or #rrggbb)");
}

std::array<double, 3> parse_direction(const std::string& text)
{
  static const std::map<std::string, std::array<double, 3>> axes = {
      {"x", {{1, 0, 0}}}, {"y", {{0, 1, 0}}}, {"z", {{0, 0, 1}}}, {"-x", {{-1, 0, 0}}}, {"-y", {{0, -1, 0}}}, {"-z", {{0, 0, -1}}}};
  const auto it = axes.find(text);
  if(it != axes.end()) return it->second;
  std::array<double, 3> d{{0, 0, 0}};
  char end = 0;
  if(std::sscanf(text.c_str(), "%lf,%lf,%lf%c", &d[0], &d[1], &d[2], &end) == 3 &&
     std::isfinite(d[0] + d[1] + d[2]) && d[0] * d[0] + d[1] * d[1] + d[2] * d[2] > 0)
    return d;
  throw Usage_error("'" + text + "' is not a direction (x, y, z, -x, -y, -z or three numbers a,b,c)");
}
#endif

} // namespace

void add_colour_scale_options(po::options_description& group)
{
  group.add_options()
    ("colormap", po::value<std::string>()->value_name("MAP"), "viridis, cool_warm or greys instead of the default")
    ("clip", po::value<double>()->default_value(0.02)->value_name("F"),
     "leave this fraction of the values out at each end of the colour range");
}

void add_mark_options(po::options_description& group)
{
  group.add_options()
    ("arrow-spacing", po::value<double>()->value_name("PX"), "distance between arrows in pixels (default width / 45)")
    ("constant-arrows", "arrows of one length instead of proportional to the magnitude")
    ("line-color", po::value<std::string>()->value_name("C"),
     "lines and arrows: black, white, grey, red, blue, green, orange or #rrggbb (default: white on viridis, else black)")
    ("line-width", po::value<double>()->value_name("PX"), "line width in pixels (default 1.3, fur 1.6)");
}

void add_view_and_output_options(Command_line& command)
{
  command.group("view").add_options()
    ("width", po::value<int>()->default_value(1200)->value_name("PX"), "image width")
    ("height", po::value<int>()->default_value(900)->value_name("PX"), "image height")
    ("azimuth", po::value<double>()->default_value(30)->value_name("DEG"), "camera angle about the up axis")
    ("elevation", po::value<double>()->default_value(20)->value_name("DEG"), "camera angle above the horizon")
    ("up", po::value<std::string>()->default_value("y")->value_name("DIR"), "up axis: x, y, z, -x, -y, -z or a,b,c")
    ("view-direction", po::value<std::string>()->value_name("a,b,c"),
     "look along this direction instead of --azimuth and --elevation")
    ("zoom", po::value<double>()->default_value(1)->value_name("Z"), "enlarge the model")
    ("orthographic", "orthographic instead of perspective projection")
    ("flat", "flat shading (one normal per face)")
    ("title", po::value<std::string>()->value_name("TEXT"), "text in the top-left corner")
    ("no-legend", "no colour bar");
  command.group("output").add_options()("output,o", po::value<std::vector<std::string>>()->composing()->value_name("FILE"),
                                        "the picture: .png or .svg; repeatable");
}

void require_pictures()
{
#ifndef TVF_HAS_CAIRO
  throw Tool_error("this tvf was built without Cairo, so it draws no pictures (install libcairo2-dev and rebuild)");
#endif
}

#ifdef TVF_HAS_CAIRO
TVF::Render_options render_options(const Command_line& command)
{
  command.require("output");
  for(const std::string& path : command.get<std::vector<std::string>>("output"))
    if(extension(path) != "png" && extension(path) != "svg")
      throw Usage_error("cannot draw into '" + path + "': use .png or .svg");
  TVF::Render_options options;
  options.width = command.get<int>("width");
  options.height = command.get<int>("height");
  if(options.width < 16 || options.height < 16 || options.width > 16384 || options.height > 16384)
    throw Usage_error("the image size must be between 16 and 16384 pixels");
  options.camera.azimuth = command.get<double>("azimuth");
  options.camera.elevation = command.get<double>("elevation");
  options.camera.up = parse_direction(command.get<std::string>("up"));
  if(command.has("view-direction")) options.camera.view_direction = parse_direction(command.get<std::string>("view-direction"));
  options.camera.zoom = command.get<double>("zoom");
  if(!(options.camera.zoom > 0)) throw Usage_error("'--zoom' must be positive");
  if(command.has("orthographic")) options.camera.projection = TVF::Projection::orthographic;
  options.smooth_shading = !command.has("flat");
  options.legend = !command.has("no-legend");
  if(command.has("title")) options.title = command.get<std::string>("title");
  return options;
}

TVF::Scalar_colouring colour_scale(const Command_line& command, TVF::Colour_map default_map)
{
  TVF::Scalar_colouring colouring;
  colouring.clip_fraction = command.get<double>("clip");
  if(!(colouring.clip_fraction >= 0 && colouring.clip_fraction < 0.5)) throw Usage_error("'--clip' must lie in [0, 0.5)");
  colouring.map = default_map;
  if(command.has("colormap"))
  {
    const std::string map = command.get<std::string>("colormap");
    if(map == "viridis") colouring.map = TVF::Colour_map::viridis;
    else if(map == "cool_warm") colouring.map = TVF::Colour_map::cool_warm;
    else if(map == "greys") colouring.map = TVF::Colour_map::greys;
    else throw Usage_error("unknown --colormap '" + map + "' (viridis, cool_warm or greys)");
  }
  return colouring;
}

TVF::Colour line_colour(const Command_line& command, bool dark_surface)
{
  if(command.has("line-color")) return parse_colour(command.get<std::string>("line-color"));
  return dark_surface ? TVF::Colour{1, 1, 1} : TVF::Colour{0.08, 0.08, 0.08};
}

TVF::Arrow_style arrow_style(const Command_line& command, const TVF::Render_options& options, const TVF::Colour& colour)
{
  TVF::Arrow_style style;
  style.colour = colour;
  style.spacing = command.has("arrow-spacing") ? command.get<double>("arrow-spacing") : options.width / 45.0;
  if(!(style.spacing >= 4)) throw Usage_error("'--arrow-spacing' must be at least 4 pixels");
  if(command.has("line-width")) style.width = command.get<double>("line-width");
  style.scale_by_magnitude = !command.has("constant-arrows");
  return style;
}

void write_pictures(const Command_line& command, const TVF::Field_renderer& renderer, const std::string& details,
                    std::chrono::steady_clock::time_point start)
{
  for(const std::string& path : command.get<std::vector<std::string>>("output"))
  {
    Step step("drawing");
    try
    {
      if(extension(path) == "png") renderer.write_png(path);
      else renderer.write_svg(path);
    }
    catch(const TVF::Invalid_input& e)
    {
      throw Tool_error(about(path, one_line(e.what())));
    }
    step.done();
    say("wrote %s (%d x %d%s) in %.2f s\n", path.c_str(), renderer.options().width, renderer.options().height,
        details.c_str(), seconds_since(start));
  }
}
#endif

} // namespace tvf_tool
