// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The small box and its hyper-reduction sizes, shared by the reduced simulator's tests
// (test_pd_reduced.cpp) and those of its saved precomputation (test_pd_reduced_file.cpp).

#ifndef PD_REDUCED_TEST_SUPPORT_H
#define PD_REDUCED_TEST_SUPPORT_H

#include <CGAL/Projective_dynamics/Reduced_simulator.h>
#include <CGAL/Projective_dynamics/make_models.h>
#include <CGAL/Projective_dynamics/mesh_generators.h>

namespace pd_test {

namespace PD = CGAL::Projective_dynamics;

inline PD::Tet_mesh small_box() { return PD::make_tet_box(6, 3, 3, {0, 0, 0}, {1.2, .6, .6}); }

inline PD::Elastic_model box_model(double stiffness = 1e4)
{
  return PD::make_solid_model(small_box(), PD::parameters::strain_stiffness(stiffness).density(1e3));
}

// Hyper-reduction sized for the small box (216 tetrahedra... 324): l = 40, s = 80.
inline PD::Reduction_options small_hyper(int samples = 12)
{
  PD::Reduction_options r;
  r.samples = samples;
  r.constraint_samples = 20;
  r.projection_columns = 40;
  r.sampled_elements = 80;
  return r;
}

} // namespace pd_test

#endif
