// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_CONSTRAINT_JSON_H
#define CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_CONSTRAINT_JSON_H

// The JSON side of the constraint files (constraint_file_io.h, n_field_constraint_file_io.h)
// and of the editor's messages, which embed constraints and whole constraint files: strict
// parsing (nlohmann::json, with duplicate keys and deep nesting refused) and a reader that
// checks every member's presence, type and range and refuses unknown keys, naming the key.

#include <CGAL/Tangent_vector_fields/constraint_file_io.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <nlohmann/json.hpp>

#include <array>
#include <initializer_list>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

struct N_field_constraint;
struct N_field_constraint_file;
class N_field_operators;

namespace internal {

typedef nlohmann::json Json;

/// Parses JSON text.  Refused, with `Invalid_input` starting with `what`: syntax errors (with
/// line and column), numbers that overflow a double, a key repeated in one object (naming it),
/// nesting deeper than `max_depth` (checked while parsing, before any deep structure is built).
Json parse_json(const std::string& text, const std::string& what, int max_depth = 64);
Json parse_json(std::istream& in, const std::string& what, int max_depth = 64);

/// Reads the members of one JSON object; every failure throws `Invalid_input` starting with `name`.
struct Json_reader
{
  const Json& node;
  std::string name;

  [[noreturn]] void fail(const std::string& what) const { throw Invalid_input(name + ": " + what); }
  /// Fails unless the node is an object.
  void expect_object() const;
  /// Fails on a key not in `keys`, naming it (with `context`, e.g. " for a vector constraint")
  /// and the keys allowed: misspellings are caught.
  void allow_only(const std::vector<const char*>& keys, const std::string& context = std::string()) const;
  bool has(const char* key) const { return node.is_object() && node.contains(key); }
  /// The member, or a failure "missing "key"".
  const Json& member(const char* key) const;
  /// A finite number.
  double number(const char* key) const;
  /// An integer in [lowest, highest].
  long long integer(const char* key, long long lowest, long long highest) const;
  /// A non-negative integer below 2^31 (an element index).
  int index(const char* key) const;
  std::string text(const char* key) const;
  /// An array of 3 finite numbers.
  std::array<double, 3> triple(const char* key) const;
  /// An array (of anything).
  const Json& array(const char* key) const;
  /// A point in `face`: "point" (3D) or "vertices" + "barycentric"; barycentric coordinates in face order.
  std::array<double, 3> point(const Intrinsic_mesh& mesh, int face) const;
};

/// One entry of `"constraints"`, checked like `read_constraint_file` does; errors start
/// with `name`.  The optional `"weight"` goes to `weight` if given (1 if absent); without
/// `weight` a "weight" member is refused.
/// \throws Invalid_input
Field_constraint parse_constraint(const Json& node, const std::string& name, const Operator_matrices& operators,
                                  double* weight = nullptr);

/// A whole constraint file object.  \throws Invalid_input
Constraint_file parse_constraint_file(const Json& root, const Operator_matrices& operators);

/// One entry of an n-field constraint file's `"constraints"`, checked against `operators`
/// (its rows can be made); errors start with `name`.  \throws Invalid_input
N_field_constraint parse_n_field_constraint(const Json& node, const std::string& name, const N_field_operators& operators);

/// A whole n-field constraint file object.  \throws Invalid_input
N_field_constraint_file parse_n_field_constraint_file(const Json& root, std::shared_ptr<const Operator_matrices> operators);

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
