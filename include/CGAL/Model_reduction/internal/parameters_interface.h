// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// X-macro list of the named parameters that every package of the thesis shares.
// Deliberately without include guard: it is included several times with
// different definitions of MR_add_named_parameter(tag_type, tag_value, function_name).

// Polygon soup to mesh: for every face, the index of the polygon it comes from
MR_add_named_parameter(face_to_polygon_map_t, face_to_polygon_map, face_to_polygon_map)

// (Randomised algorithms take CGAL's own `random_seed`: a second one would be ambiguous.)

// Long computations: a callback with the progress, and the eigensolver's relative residual
MR_add_named_parameter(progress_callback_t, progress_callback, progress_callback)
MR_add_named_parameter(eigensolver_tolerance_t, eigensolver_tolerance, eigensolver_tolerance)
