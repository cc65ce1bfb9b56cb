// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// X-macro list of the named parameters this package adds to CGAL's.
// Deliberately without include guard: it is included several times with
// different definitions of TVF_add_named_parameter(tag_type, tag_value, function_name).

// Hodge decomposition outputs (face maps with Vector_3 values, vertex and edge maps with FT values)
TVF_add_named_parameter(exact_part_map_t, exact_part_map, exact_part_map)
TVF_add_named_parameter(coexact_part_map_t, coexact_part_map, coexact_part_map)
TVF_add_named_parameter(harmonic_part_map_t, harmonic_part_map, harmonic_part_map)
TVF_add_named_parameter(potential_map_t, potential_map, potential_map)
TVF_add_named_parameter(copotential_map_t, copotential_map, copotential_map)

// Polygon soup to mesh: for every face, the index of the polygon it comes from
TVF_add_named_parameter(face_to_polygon_map_t, face_to_polygon_map, face_to_polygon_map)

// Construction of the intrinsic geometry
TVF_add_named_parameter(use_intrinsic_mollification_t, use_intrinsic_mollification, use_intrinsic_mollification)
TVF_add_named_parameter(mollification_epsilon_t, mollification_epsilon, mollification_epsilon)
TVF_add_named_parameter(degeneracy_tolerance_t, degeneracy_tolerance, degeneracy_tolerance)

// Harmonic basis
TVF_add_named_parameter(random_seed_t, random_seed, random_seed)

// Spectral basis (what to compute, and how)
TVF_add_named_parameter(number_of_eigenfields_t, number_of_eigenfields, number_of_eigenfields)
TVF_add_named_parameter(number_of_exact_eigenfields_t, number_of_exact_eigenfields, number_of_exact_eigenfields)
TVF_add_named_parameter(number_of_coexact_eigenfields_t, number_of_coexact_eigenfields, number_of_coexact_eigenfields)
TVF_add_named_parameter(maximum_eigenvalue_t, maximum_eigenvalue, maximum_eigenvalue)
TVF_add_named_parameter(eigensolver_tolerance_t, eigensolver_tolerance, eigensolver_tolerance)
TVF_add_named_parameter(progress_callback_t, progress_callback, progress_callback)

// Field design
TVF_add_named_parameter(spline_tension_t, spline_tension, spline_tension)
TVF_add_named_parameter(harmonic_eigenvalue_t, harmonic_eigenvalue, harmonic_eigenvalue)

TVF_add_named_parameter(alignment_field_map_t, alignment_field_map, alignment_field_map)
TVF_add_named_parameter(alignment_weight_t, alignment_weight, alignment_weight)
TVF_add_named_parameter(n_field_boundary_t, n_field_boundary, n_field_boundary)
