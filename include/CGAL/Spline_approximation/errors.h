// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SPLINE_APPROXIMATION_ERRORS_H
#define CGAL_SPLINE_APPROXIMATION_ERRORS_H

/// \file errors.h
/// The exceptions this package throws: the shared ones of <CGAL/Model_reduction/errors.h>,
/// named in this namespace too so that a user catches `Spline_approximation::Invalid_input`.

#include <CGAL/Model_reduction/errors.h>

namespace CGAL {
namespace Spline_approximation {

using Model_reduction::Invalid_input;
using Model_reduction::Numerical_failure;

} // namespace Spline_approximation
} // namespace CGAL

#endif
