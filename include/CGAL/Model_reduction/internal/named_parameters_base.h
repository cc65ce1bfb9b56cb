// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_INTERNAL_NAMED_PARAMETERS_BASE_H
#define CGAL_MODEL_REDUCTION_INTERNAL_NAMED_PARAMETERS_BASE_H

// What every package's named-parameter chain (named_parameters_generator.h) builds on:
// CGAL's chain and helpers, and the tags of the parameters all packages share.

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {
namespace Model_reduction {
namespace internal_np {
#define MR_add_named_parameter(X, Y, Z) enum X { Y };
#include <CGAL/Model_reduction/internal/parameters_interface.h>
#undef MR_add_named_parameter
} // namespace internal_np
} // namespace Model_reduction
} // namespace CGAL

#endif
