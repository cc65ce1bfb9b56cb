// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// X-macro list of the named parameters this package adds to CGAL's and the shared ones.
// Deliberately without include guard: it is included several times with
// different definitions of MR_add_named_parameter(tag_type, tag_value, function_name).

// (The shell energy's stiffnesses come from Discrete_shells: named_function_parameters.h.)

// Vertices held in place (a range of vertex descriptors)
MR_add_named_parameter(pinned_vertices_t, pinned_vertices, pinned_vertices)

// Compressed modes: the sparsity weight mu
MR_add_named_parameter(sparsity_weight_t, sparsity_weight, sparsity_weight)

MR_add_named_parameter(l1_budget_t, l1_budget, l1_budget)

// Segmentation by modes: a vertex whose winning mode is below this fraction of its peak is unassigned
MR_add_named_parameter(segmentation_threshold_t, segmentation_threshold, segmentation_threshold)
