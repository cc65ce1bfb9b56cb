// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// X-macro list of the named parameters this package adds to CGAL's and the shared ones.
// Deliberately without include guard: it is included several times with
// different definitions of MR_add_named_parameter(tag_type, tag_value, function_name).
// (The number of local/global iterations per step is CGAL's own `number_of_iterations`.)

// The simulator: time step h, gravity (an acceleration, Eigen::Vector3d), worker threads of
// the local steps, friction factor of the obstacles in [0, 1]
MR_add_named_parameter(time_step_t, time_step, time_step)
MR_add_named_parameter(gravity_t, gravity, gravity)
MR_add_named_parameter(number_of_threads_t, number_of_threads, number_of_threads)
MR_add_named_parameter(friction_t, friction, friction)

// The elastic models built from meshes: mass density, stiffnesses per element type, and the
// strain limits [rmin, rmax] of the springs and strain elements (std::pair<double, double>)
MR_add_named_parameter(density_t, density, density)
MR_add_named_parameter(spring_stiffness_t, spring_stiffness, spring_stiffness)
MR_add_named_parameter(strain_stiffness_t, strain_stiffness, strain_stiffness)
MR_add_named_parameter(bending_stiffness_t, bending_stiffness, bending_stiffness)
MR_add_named_parameter(strain_limits_t, strain_limits, strain_limits)

// The reduced simulator (Reduced_simulator.h; its position samples m, k = 4m, are CGAL's own
// `number_of_samples`): the position samples'
// radius multiplier; hyper-reduction on or off; constraint-projection samples and their radius
// multiplier; projection columns l per element group; sampled elements s per group; the
// stiffness of the soft pins and grabs relative to mass / h^2
MR_add_named_parameter(radius_multiplier_t, radius_multiplier, radius_multiplier)
MR_add_named_parameter(hyper_reduction_t, hyper_reduction, hyper_reduction)
MR_add_named_parameter(number_of_constraint_samples_t, number_of_constraint_samples, number_of_constraint_samples)
MR_add_named_parameter(constraint_radius_multiplier_t, constraint_radius_multiplier, constraint_radius_multiplier)
MR_add_named_parameter(number_of_projection_columns_t, number_of_projection_columns, number_of_projection_columns)
MR_add_named_parameter(number_of_sampled_elements_t, number_of_sampled_elements, number_of_sampled_elements)
MR_add_named_parameter(pin_stiffness_t, pin_stiffness, pin_stiffness)

// Tetrahedra from a closed surface (tetrahedralize.h): sizes relative to the bounding box
// diagonal, and the dihedral angle that keeps an edge sharp
MR_add_named_parameter(cell_size_t, cell_size, cell_size)
MR_add_named_parameter(facet_distance_t, facet_distance, facet_distance)
MR_add_named_parameter(feature_angle_t, feature_angle, feature_angle)
