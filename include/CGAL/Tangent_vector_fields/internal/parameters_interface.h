// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// X-macro list of the named parameters this package adds to CGAL's and the shared ones.
// Deliberately without include guard: it is included several times with
// different definitions of MR_add_named_parameter(tag_type, tag_value, function_name).
// The parameters every package shares are in <CGAL/Model_reduction/internal/parameters_interface.h>.

// Hodge decomposition outputs (face maps with Vector_3 values, vertex and edge maps with FT values)
MR_add_named_parameter(exact_part_map_t, exact_part_map, exact_part_map)
MR_add_named_parameter(coexact_part_map_t, coexact_part_map, coexact_part_map)
MR_add_named_parameter(harmonic_part_map_t, harmonic_part_map, harmonic_part_map)
MR_add_named_parameter(potential_map_t, potential_map, potential_map)
MR_add_named_parameter(copotential_map_t, copotential_map, copotential_map)

// Construction of the intrinsic geometry
MR_add_named_parameter(use_intrinsic_mollification_t, use_intrinsic_mollification, use_intrinsic_mollification)
MR_add_named_parameter(mollification_epsilon_t, mollification_epsilon, mollification_epsilon)
MR_add_named_parameter(degeneracy_tolerance_t, degeneracy_tolerance, degeneracy_tolerance)

// Spectral basis (what to compute, and how)
MR_add_named_parameter(number_of_eigenfields_t, number_of_eigenfields, number_of_eigenfields)
MR_add_named_parameter(number_of_exact_eigenfields_t, number_of_exact_eigenfields, number_of_exact_eigenfields)
MR_add_named_parameter(number_of_coexact_eigenfields_t, number_of_coexact_eigenfields, number_of_coexact_eigenfields)
MR_add_named_parameter(maximum_eigenvalue_t, maximum_eigenvalue, maximum_eigenvalue)

// Field design
MR_add_named_parameter(spline_tension_t, spline_tension, spline_tension)
MR_add_named_parameter(harmonic_eigenvalue_t, harmonic_eigenvalue, harmonic_eigenvalue)

MR_add_named_parameter(alignment_field_map_t, alignment_field_map, alignment_field_map)
MR_add_named_parameter(alignment_weight_t, alignment_weight, alignment_weight)
MR_add_named_parameter(n_field_boundary_t, n_field_boundary, n_field_boundary)
