// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_VIBRATION_MODES_NAMED_FUNCTION_PARAMETERS_H
#define CGAL_VIBRATION_MODES_NAMED_FUNCTION_PARAMETERS_H

/// \file named_function_parameters.h
/// Named parameters of this package (and of the shell energy) mixed with the shared ones
/// and CGAL's in one chain:
/// \code
/// namespace VM = CGAL::Vibration_modes;
/// VM::compressed_vibration_modes(mesh, 20, VM::parameters::sparsity_weight(0.5).bending_stiffness(1e-3));
/// \endcode

#include <CGAL/Discrete_shells/named_function_parameters.h>

namespace CGAL {
namespace Vibration_modes {
#define CGAL_MR_PACKAGE_PARAMETERS <CGAL/Vibration_modes/internal/parameters_interface.h>
#define CGAL_MR_BASE_PARAMETERS <CGAL/Discrete_shells/internal/parameters_interface.h>
#define CGAL_MR_BASE_NAMESPACE CGAL::Discrete_shells
#include <CGAL/Model_reduction/internal/named_parameters_generator.h>
#undef CGAL_MR_BASE_NAMESPACE
#undef CGAL_MR_BASE_PARAMETERS
#undef CGAL_MR_PACKAGE_PARAMETERS
} // namespace Vibration_modes
} // namespace CGAL

#endif
