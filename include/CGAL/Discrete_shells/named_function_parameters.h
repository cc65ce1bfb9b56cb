// Copyright (c) 2026 The Discrete_shells authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISCRETE_SHELLS_NAMED_FUNCTION_PARAMETERS_H
#define CGAL_DISCRETE_SHELLS_NAMED_FUNCTION_PARAMETERS_H

/// \file named_function_parameters.h
/// Named parameters of this package mixed with the shared ones and CGAL's in one chain:
/// \code
/// namespace DS = CGAL::Discrete_shells;
/// auto W = DS::make_shell_energy(mesh, DS::parameters::bending_stiffness(1e-4));
/// \endcode

#include <CGAL/Model_reduction/internal/named_parameters_base.h>

namespace CGAL {
namespace Discrete_shells {
#define CGAL_MR_PACKAGE_PARAMETERS <CGAL/Discrete_shells/internal/parameters_interface.h>
#include <CGAL/Model_reduction/internal/named_parameters_generator.h>
#undef CGAL_MR_PACKAGE_PARAMETERS
} // namespace Discrete_shells
} // namespace CGAL

#endif
