// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_CONSTRAINT_JSON_H
#define CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_CONSTRAINT_JSON_H

// The parsed-JSON side of constraint_file_io.h, for readers that hold the JSON tree
// already (the editor's protocol embeds constraints and whole constraint files in
// its messages).

#include <CGAL/Tangent_vector_fields/constraint_file_io.h>

#include <boost/property_tree/ptree.hpp>

#include <string>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

/// A JSON number (the tree keeps its text).  Strict: the whole text must be a number; an
/// overflowing one such as `1e999` reads as infinite, so that callers can say "not finite".
bool read_json_number(const boost::property_tree::ptree& node, double& x);

/// One entry of `"constraints"`, checked like `read_constraint_file` does; errors start
/// with `name`.  The optional `"weight"` goes to `weight` if given (1 if absent).
/// \throws Invalid_input
Field_constraint parse_constraint(const boost::property_tree::ptree& node, const std::string& name,
                                  const Operator_matrices& operators, double* weight = nullptr);

/// A whole constraint file object.  \throws Invalid_input
Constraint_file parse_constraint_file(const boost::property_tree::ptree& root, const Operator_matrices& operators);

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
