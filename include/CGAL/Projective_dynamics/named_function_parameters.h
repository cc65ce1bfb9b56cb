// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PROJECTIVE_DYNAMICS_NAMED_FUNCTION_PARAMETERS_H
#define CGAL_PROJECTIVE_DYNAMICS_NAMED_FUNCTION_PARAMETERS_H

/// \file named_function_parameters.h
/// Named parameters of this package mixed with the shared ones and CGAL's in one chain:
/// \code
/// namespace PD = CGAL::Projective_dynamics;
/// PD::Simulator sim(PD::make_solid_model(tets, PD::parameters::strain_stiffness(1e4).density(1e3)),
///                   PD::parameters::time_step(1.0 / 60).number_of_iterations(10));
/// \endcode

#include <CGAL/Model_reduction/internal/named_parameters_base.h>

namespace CGAL {
namespace Projective_dynamics {
#define CGAL_MR_PACKAGE_PARAMETERS <CGAL/Projective_dynamics/internal/parameters_interface.h>
#include <CGAL/Model_reduction/internal/named_parameters_generator.h>
#undef CGAL_MR_PACKAGE_PARAMETERS
} // namespace Projective_dynamics
} // namespace CGAL

#endif
