// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the vibration-mode commands share (tvf modes, segment, vibrate): the options that say
// which modes (problem, pins, stiffnesses, compressed or not) and the modes themselves,
// computed with their report or loaded from a .vmb file, and saved.

#ifndef TVF_TOOL_TOOL_MODES_H
#define TVF_TOOL_TOOL_MODES_H

#include "tool.h"

#include <CGAL/Vibration_modes/Mode_problem.h>
#include <CGAL/Vibration_modes/Modes.h>
#include <CGAL/Vibration_modes/modes_file.h>

#include <memory>
#include <vector>

namespace tvf_tool {

namespace VM = CGAL::Vibration_modes;

/// What the modes are for: each command's defaults.
enum class Mode_use {
  listing,      ///< tvf modes: shell (--scalar), ordinary (--compressed), mu = 4 lambda_K / sqrt(area)
  segmentation, ///< tvf segment: compressed always, scalar with the constants allowed (--shell), 2.5
  simulation    ///< tvf vibrate: shell only, ordinary (--compressed), 4
};

/// The groups "modes", "compressed modes" and "modes file" (--save, --load).
void add_mode_options(Command_line& command, Mode_use use);

/// The mesh as the Vibration_modes arrays: stacked positions and triangles (intrinsic order).
struct Mode_mesh
{
  explicit Mode_mesh(const Tool_mesh& mesh);
  Eigen::VectorXd x;
  std::vector<CGAL::Discrete_shells::Shell_energy::Triangle> triangles;
  int vertices() const { return int(x.size() / 3); }
};

/// The vertices within 5 % of the low end of the rest shape's longer horizontal side (x or y),
/// as `tvf simulate --scene cantilever` pins them.
std::vector<int> end_vertices(const Eigen::VectorXd& x);

/// `--pin LIST` and `--pin-end`, joined (sorted, without repeats).
std::vector<int> pinned_vertices(const Command_line& command, const Mode_mesh& mesh);

struct Tool_modes
{
  VM::Modes modes;
  VM::Mode_settings settings;
  bool loaded = false;
  /// The problem the modes solve (built when computing, or when `need_problem`).
  std::shared_ptr<const VM::Mode_problem> problem;
};

/// Computes the modes the options ask for (with the report and table of `tvf modes`), or
/// loads them with `--load` (refused, with the reason, for another mesh, pins or stiffnesses);
/// saves them with `--save`.
Tool_modes obtain_modes(const Command_line& command, Mode_use use, const Tool_mesh& mesh, const Mode_mesh& arrays,
                        const std::vector<int>& pinned, bool need_problem);

} // namespace tvf_tool

#endif
