// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Pictures of vibration modes (Cairo): one PNG per mode, a contact sheet of the first modes
// in a grid with captions, and a mesh coloured by segment.  Without Cairo they refuse with
// the reason.

#ifndef TVF_TOOL_MODE_PICTURES_H
#define TVF_TOOL_MODE_PICTURES_H

#include "tool.h"

#include <CGAL/Vibration_modes/Modes.h>

#include <string>
#include <vector>

namespace tvf_tool {

/// PREFIX_01.png ...: a displacement mode as the mesh moved along it (the largest entry of all
/// modes moved by `displacement` times the diagonal), coloured by |u|; a scalar mode as its values.
void write_mode_pictures(const std::string& prefix, const Tool_mesh& mesh, const CGAL::Vibration_modes::Modes& modes,
                         double displacement);

/// The first `count` modes in a grid of `columns` columns of `cell` x `cell` pixels, each with
/// a caption band of `contact_sheet_caption` pixels below it: "mode i" and its eigenvalue
/// (ordinary modes) or its energy (compressed).  The picture is columns * cell wide and
/// rows * (cell + contact_sheet_caption) high.
void write_contact_sheet(const std::string& path, const Tool_mesh& mesh, const CGAL::Vibration_modes::Modes& modes,
                         int count, int columns, int cell, double displacement);
constexpr int contact_sheet_caption = 28;

/// The mesh, each face coloured by the segment most of its vertices are in (-1: none).
void write_segment_picture(const std::string& path, const Tool_mesh& mesh, const std::vector<int>& label,
                           int segments);

} // namespace tvf_tool

#endif
