// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PROJECTIVE_DYNAMICS_ERRORS_H
#define CGAL_PROJECTIVE_DYNAMICS_ERRORS_H

/// \file errors.h
/// The exceptions this package throws: the shared ones of <CGAL/Model_reduction/errors.h>,
/// named in this namespace too.

#include <CGAL/Model_reduction/errors.h>

namespace CGAL {
namespace Projective_dynamics {

using Model_reduction::Cancelled;
using Model_reduction::Invalid_input;
using Model_reduction::Invalid_mesh;
using Model_reduction::Mesh_defect;
using Model_reduction::Numerical_failure;

} // namespace Projective_dynamics
} // namespace CGAL

#endif
