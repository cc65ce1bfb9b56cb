// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_VIBRATION_MODES_ERRORS_H
#define CGAL_VIBRATION_MODES_ERRORS_H

/// \file errors.h
/// The exceptions this package throws: the shared ones of <CGAL/Model_reduction/errors.h>.

#include <CGAL/Model_reduction/errors.h>

namespace CGAL {
namespace Vibration_modes {

using Model_reduction::Cancelled;
using Model_reduction::Invalid_input;
using Model_reduction::Invalid_mesh;
using Model_reduction::Mesh_defect;
using Model_reduction::Numerical_failure;

} // namespace Vibration_modes
} // namespace CGAL

#endif
