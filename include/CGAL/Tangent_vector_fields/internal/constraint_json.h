// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_CONSTRAINT_JSON_H
#define CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_CONSTRAINT_JSON_H

// The parsed-JSON side of constraint_file_io.h, for readers that hold the JSON tree
// already (the editor's protocol embeds constraints and whole constraint files in
// its messages).

#include <CGAL/Tangent_vector_fields/constraint_file_io.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <boost/property_tree/ptree.hpp>

#include <array>
#include <string>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

/// Reads the members of one JSON object; every failure throws `Invalid_input` starting with `name`.
struct Json_reader
{
  const boost::property_tree::ptree& node;
  std::string name;

  [[noreturn]] void fail(const std::string& what) const { throw Invalid_input(name + ": " + what); }
  bool has(const char* key) const { return node.count(key) > 0; }
  double number(const char* key) const;
  int index(const char* key) const;
  std::array<double, 3> triple(const char* key) const;
  /// A point in `face`: "point" (3D) or "vertices" + "barycentric"; barycentric coordinates in face order.
  std::array<double, 3> point(const Intrinsic_mesh& mesh, int face) const;
};

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
