// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_NAMED_FUNCTION_PARAMETERS_H
#define CGAL_MODEL_REDUCTION_NAMED_FUNCTION_PARAMETERS_H

/// \file named_function_parameters.h
/// Named parameters that mix the shared options with CGAL's in one chain.
///
/// CGAL 5.5 cannot add members to its own parameter chain from outside, so each package
/// of the thesis derives a thin subclass of `CGAL::Named_function_parameters` whose member
/// functions (CGAL's, the shared ones and the package's own) all return the subclass;
/// `internal/named_parameters_generator.h` writes it.  This is the shared package's chain:
/// \code
/// namespace MR = CGAL::Model_reduction;
/// MR::polygon_soup_to_mesh(points, polygons, mesh,
///     MR::parameters::face_to_polygon_map(origin).vertex_point_map(vpm));
/// \endcode
/// Every package's tags are types of their own, so a function reads its options from any
/// package's chain or from a plain CGAL chain (`CGAL::parameters::...`), which simply
/// cannot name our options.  `parameters::combine(first, second)` joins two chains.
///
/// A package adds its own list (an X-macro file of
/// `MR_add_named_parameter(tag_type, tag_value, function_name)` lines) like this, in its
/// `named_function_parameters.h`:
/// \code
/// namespace CGAL { namespace My_package {
/// #define CGAL_MR_PACKAGE_PARAMETERS <CGAL/My_package/internal/parameters_interface.h>
/// #include <CGAL/Model_reduction/internal/named_parameters_generator.h>
/// #undef CGAL_MR_PACKAGE_PARAMETERS
/// } }
/// \endcode

#include <CGAL/Model_reduction/internal/named_parameters_base.h>

namespace CGAL {
namespace Model_reduction {
#include <CGAL/Model_reduction/internal/named_parameters_generator.h>
} // namespace Model_reduction
} // namespace CGAL

#endif
