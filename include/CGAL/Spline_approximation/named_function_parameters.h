// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SPLINE_APPROXIMATION_NAMED_FUNCTION_PARAMETERS_H
#define CGAL_SPLINE_APPROXIMATION_NAMED_FUNCTION_PARAMETERS_H

/// \file named_function_parameters.h
/// Named parameters of this package mixed with the shared ones and CGAL's in one chain
/// (the machinery: <CGAL/Model_reduction/named_function_parameters.h>):
/// \code
/// namespace SA = CGAL::Spline_approximation;
/// SA::approximate_curve(points, SA::parameters::spline_degree(1).max_error_bound(0.01));
/// \endcode

#include <CGAL/Model_reduction/internal/named_parameters_base.h>

namespace CGAL {
namespace Spline_approximation {
#define CGAL_MR_PACKAGE_PARAMETERS <CGAL/Spline_approximation/internal/parameters_interface.h>
#include <CGAL/Model_reduction/internal/named_parameters_generator.h>
#undef CGAL_MR_PACKAGE_PARAMETERS
} // namespace Spline_approximation
} // namespace CGAL

#endif
