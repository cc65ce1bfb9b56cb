// Copyright (c) 2026 The Discrete_shells authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISCRETE_SHELLS_ERRORS_H
#define CGAL_DISCRETE_SHELLS_ERRORS_H

/// \file errors.h
/// The exceptions this package throws: the shared ones of <CGAL/Model_reduction/errors.h>,
/// named in this namespace too.

#include <CGAL/Model_reduction/errors.h>

namespace CGAL {
namespace Discrete_shells {

using Model_reduction::Invalid_input;
using Model_reduction::Invalid_mesh;
using Model_reduction::Mesh_defect;
using Model_reduction::Numerical_failure;

} // namespace Discrete_shells
} // namespace CGAL

#endif
