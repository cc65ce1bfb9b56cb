// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/internal/Spline_solver_impl.h>

namespace CGAL {
namespace Tangent_vector_fields {

template class Basic_spline_solver<Field_constraint, Operator_matrices>;

} // namespace Tangent_vector_fields
} // namespace CGAL
