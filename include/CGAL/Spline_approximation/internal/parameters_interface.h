// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// X-macro list of the named parameters this package adds to CGAL's and the shared ones.
// Deliberately without include guard: it is included several times with
// different definitions of MR_add_named_parameter(tag_type, tag_value, function_name).

// The spline: degree (1 to 3) and the caller's curve parameters (one per sample)
MR_add_named_parameter(spline_degree_t, spline_degree, spline_degree)
MR_add_named_parameter(curve_parameters_t, curve_parameters, curve_parameters)
// A closed curve: the last point joins the first, the spline is periodic
MR_add_named_parameter(closed_curve_t, closed_curve, closed_curve)

// What is minimised: a penalty per knot, or the fewest knots within an error bound
MR_add_named_parameter(knot_penalty_t, knot_penalty, knot_penalty)
MR_add_named_parameter(max_error_bound_t, max_error_bound, max_error_bound)
MR_add_named_parameter(rms_error_bound_t, rms_error_bound, rms_error_bound)

// How: the algorithm, and the candidate knots (0: every sample parameter; g: a uniform grid of g)
MR_add_named_parameter(fit_algorithm_t, fit_algorithm, fit_algorithm)
MR_add_named_parameter(candidate_grid_size_t, candidate_grid_size, candidate_grid_size)
// Above how many candidates the heuristics start from a coarse-to-fine knot set
MR_add_named_parameter(coarse_start_above_t, coarse_start_above, coarse_start_above)
MR_add_named_parameter(relocate_knots_up_to_t, relocate_knots_up_to, relocate_knots_up_to)
