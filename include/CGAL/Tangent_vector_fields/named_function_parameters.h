// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_NAMED_FUNCTION_PARAMETERS_H
#define CGAL_TANGENT_VECTOR_FIELDS_NAMED_FUNCTION_PARAMETERS_H

/// \file named_function_parameters.h
/// Named parameters that mix this package's options with the shared ones and CGAL's in
/// one chain (the machinery: <CGAL/Model_reduction/named_function_parameters.h>).
/// Start a chain from `CGAL::Tangent_vector_fields::parameters` and mix freely:
/// \code
/// namespace TVF = CGAL::Tangent_vector_fields;
/// TVF::hodge_decomposition(mesh, field,
///     TVF::parameters::vertex_point_map(vpm).exact_part_map(exact));
/// \endcode
/// Plain CGAL chains (`CGAL::parameters::...`) and the shared package's chains are
/// accepted as well.  `parameters::combine(cgal_chain, our_chain)` joins two.

#include <CGAL/Model_reduction/internal/named_parameters_base.h>

namespace CGAL {
namespace Tangent_vector_fields {
#define CGAL_MR_PACKAGE_PARAMETERS <CGAL/Tangent_vector_fields/internal/parameters_interface.h>
#include <CGAL/Model_reduction/internal/named_parameters_generator.h>
#undef CGAL_MR_PACKAGE_PARAMETERS
} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
