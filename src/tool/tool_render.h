// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What `tvf render` of vector fields (commands_design.cpp) and of n-direction fields
// (commands_n_fields.cpp) share: the view, the colour scale, the style of arrows and glyphs,
// and the pictures written.  The options are declared with or without Cairo (so that --help
// works); reading them into the renderer's settings needs Cairo.

#ifndef TVF_TOOL_TOOL_RENDER_H
#define TVF_TOOL_TOOL_RENDER_H

#include "tool.h"

#ifdef TVF_HAS_CAIRO
#include <CGAL/Tangent_vector_fields/Field_renderer.h>
#endif

#include <array>
#include <chrono>
#include <string>

namespace tvf_tool {

/// `--colormap` and `--clip`.
void add_colour_scale_options(po::options_description& group);
/// `--arrow-spacing`, `--constant-arrows`, `--line-color`, `--line-width`.
void add_mark_options(po::options_description& group);
/// The "view" group (size, camera, shading, title, colour bar) and the "output" group (`-o`).
void add_view_and_output_options(Command_line& command);
/// \throws Tool_error if this tvf was built without Cairo.
void require_pictures();

#ifdef TVF_HAS_CAIRO
/// The view options, checked; and every `-o` checked to be .png or .svg.
TVF::Render_options render_options(const Command_line& command);
/// `--colormap` (else `default_map`) and `--clip`, checked.
TVF::Scalar_colouring colour_scale(const Command_line& command, TVF::Colour_map default_map);
/// `--line-color`, else white on a dark surface (viridis colours) and black on a light one.
TVF::Colour line_colour(const Command_line& command, bool dark_surface);
/// Arrows (and glyphs): `--arrow-spacing` (default width / 45), `--line-width`, `--constant-arrows`.
TVF::Arrow_style arrow_style(const Command_line& command, const TVF::Render_options& options, const TVF::Colour& colour);
/// Draws every `-o` file and reports "wrote FILE (W x H<details>) in T s".
void write_pictures(const Command_line& command, const TVF::Field_renderer& renderer, const std::string& details,
                    std::chrono::steady_clock::time_point start);
#endif

} // namespace tvf_tool

#endif
