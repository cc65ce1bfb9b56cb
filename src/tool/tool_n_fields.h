// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the n-field commands share (commands_n_fields.cpp, commands_n_field_pictures.cpp): the
// symmetry options, the operators, the input field and the report of the singularities.

#ifndef TVF_TOOL_TOOL_N_FIELDS_H
#define TVF_TOOL_TOOL_N_FIELDS_H

#include "tool_lines.h"

#include <CGAL/Tangent_vector_fields/N_field_operators.h>
#include <CGAL/Tangent_vector_fields/N_field_singularities.h>

#include <memory>
#include <utility>
#include <vector>

namespace tvf_tool {

typedef std::shared_ptr<const TVF::N_field_operators> N_operators;

/// `--n` and `--boundary`.
void add_symmetry_options(Command_line& command);
/// The operators for `--n` (or `n` if given) and `--boundary`, with prescribed singularities.
N_operators n_field_operators(const Command_line& command, const Tool_mesh& mesh,
                              const std::vector<std::pair<int, int>>& singularities = {}, int n = 0);
/// The input n-field: a .rawfield of degree n checked to be one, else one vector per face.
Eigen::VectorXd read_n_field(const Command_line& command, const Tool_mesh& mesh, const TVF::N_field_operators& ops);
/// Prints the singular vertices (the first `list`) and checks Poincare-Hopf.
void report_singularities(const Tool_mesh& mesh, int n, const std::vector<TVF::N_field_singularity>& singular, int list);

} // namespace tvf_tool

#endif
