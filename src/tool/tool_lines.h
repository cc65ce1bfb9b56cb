// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What `tvf streamlines` and `tvf render` share for lines, for vector fields and n-direction
// fields alike: the streamline and fur options, the polyline files, and the lines drawn.

#ifndef TVF_TOOL_TOOL_LINES_H
#define TVF_TOOL_TOOL_LINES_H

#include "tool_render.h"

#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>

#include <string>
#include <vector>

namespace tvf_tool {

/// `--unit`: diagonal, edge or absolute.
TVF::Length_unit length_unit(const std::string& name);
/// Why the ends of the streamlines stopped, such as "boundary 12, closed_loop 3".
std::string stop_summary(const std::vector<TVF::Streamline>& lines);
/// `--unit`, `--separation`, `--seed` and the fur group (`--strokes`, `--density`, `--length`, `--scale-by-magnitude`).
void add_streamline_options(Command_line& command);
TVF::Evenly_spaced_options evenly_spaced_options(const Command_line& command, TVF::Length_unit unit);
TVF::Fur_options fur_options(const Command_line& command, TVF::Length_unit unit);
/// Writes the polylines to every `-o` file (.obj, .ply or .vtp).
void write_streamline_files(const Command_line& command, const std::vector<TVF::Streamline>& lines);

#ifdef TVF_HAS_CAIRO
/// Draws the evenly spaced streamlines (`even` not null; for an n-field the hatching of every
/// family) and the fur (`fur` not null) of `tracer`; returns the number of lines drawn.
std::size_t add_lines(TVF::Field_renderer& renderer, const TVF::Streamline_tracer& tracer, const Command_line& command,
                      const TVF::Colour& colour, const TVF::Evenly_spaced_options* even, const TVF::Fur_options* fur);
#endif

} // namespace tvf_tool

#endif
