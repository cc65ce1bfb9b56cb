// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_ERRORS_H
#define CGAL_TANGENT_VECTOR_FIELDS_ERRORS_H

/// \file errors.h
/// The exceptions this package throws: the shared ones of <CGAL/Model_reduction/errors.h>,
/// named in this namespace too so that a user catches `TVF::Invalid_mesh` without knowing
/// which package underneath refused the input.

#include <CGAL/Model_reduction/errors.h>

namespace CGAL {
namespace Tangent_vector_fields {

using Model_reduction::Infeasible_constraints;
using Model_reduction::Invalid_input;
using Model_reduction::Invalid_mesh;
using Model_reduction::Mesh_defect;
using Model_reduction::Numerical_failure;

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
