// Copyright (c) 2026 The Discrete_shells authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// X-macro list of the named parameters this package adds to CGAL's and the shared ones.
// Deliberately without include guard: it is included several times with
// different definitions of MR_add_named_parameter(tag_type, tag_value, function_name).
// Packages built on the shell energy include this list in theirs.

// The stiffnesses of the shell energy (Shell_stiffness): stretching, area and bending
MR_add_named_parameter(stretching_stiffness_t, stretching_stiffness, stretching_stiffness)
MR_add_named_parameter(area_stiffness_t, area_stiffness, area_stiffness)
MR_add_named_parameter(bending_stiffness_t, bending_stiffness, bending_stiffness)
