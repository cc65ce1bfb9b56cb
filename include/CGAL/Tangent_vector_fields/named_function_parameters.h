// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_NAMED_FUNCTION_PARAMETERS_H
#define CGAL_TANGENT_VECTOR_FIELDS_NAMED_FUNCTION_PARAMETERS_H

/// \file named_function_parameters.h
/// Named parameters that mix this package's options with CGAL's in one chain.
///
/// CGAL 5.5 cannot add members to its own parameter chain from outside, so this
/// package derives a thin subclass of `CGAL::Named_function_parameters` whose
/// member functions (CGAL's and ours) all return the subclass.  Start a chain
/// from `CGAL::Tangent_vector_fields::parameters` and mix freely:
/// \code
/// namespace TVF = CGAL::Tangent_vector_fields;
/// TVF::hodge_decomposition(mesh, field,
///     TVF::parameters::vertex_point_map(vpm).exact_part_map(exact));
/// \endcode
/// Plain CGAL chains (`CGAL::parameters::...`) are accepted as well; they simply
/// cannot name our options.  `parameters::combine(cgal_chain, our_chain)` joins two.

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {
namespace Tangent_vector_fields {

namespace internal_np {
#define TVF_add_named_parameter(X, Y, Z) enum X { Y };
#include <CGAL/Tangent_vector_fields/internal/parameters_interface.h>
#undef TVF_add_named_parameter
} // namespace internal_np

/// A `CGAL::Named_function_parameters` whose chaining functions include this
/// package's options.  It is a CGAL parameter pack: every CGAL function accepts it.
template <typename T, typename Tag, typename Base = CGAL::internal_np::No_property>
struct Named_function_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  typedef CGAL::Named_function_parameters<T, Tag, Base> cgal_parameters;
  typedef Named_function_parameters<T, Tag, Base> self;

  Named_function_parameters() : cgal_parameters() {}
  Named_function_parameters(const T& v) : cgal_parameters(v) {}
  Named_function_parameters(const T& v, const Base& b) : cgal_parameters(v, b) {}

#define CGAL_add_named_parameter(X, Y, Z)                                          \
  template <typename K>                                                            \
  Named_function_parameters<K, CGAL::internal_np::X, self> Z(const K& k) const     \
  {                                                                                \
    return Named_function_parameters<K, CGAL::internal_np::X, self>(k, *this);     \
  }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

#define TVF_add_named_parameter(X, Y, Z)                                           \
  template <typename K>                                                            \
  Named_function_parameters<K, internal_np::X, self> Z(const K& k) const           \
  {                                                                                \
    return Named_function_parameters<K, internal_np::X, self>(k, *this);           \
  }
#include <CGAL/Tangent_vector_fields/internal/parameters_interface.h>
#undef TVF_add_named_parameter
};

namespace parameters {

using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;
using CGAL::parameters::get_parameter_reference;
using CGAL::parameters::is_default_parameter;

typedef Named_function_parameters<bool, CGAL::internal_np::all_default_t> Default_named_parameters;

/// The empty chain.
inline Default_named_parameters default_values() { return Default_named_parameters(); }

// Starters for every CGAL parameter, returning our chain type.
#define CGAL_add_named_parameter(X, Y, Z)                                          \
  template <typename K>                                                            \
  Named_function_parameters<K, CGAL::internal_np::X> Z(const K& p)                 \
  {                                                                                \
    return Named_function_parameters<K, CGAL::internal_np::X>(p);                  \
  }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

// Starters for this package's parameters.
#define TVF_add_named_parameter(X, Y, Z)                                           \
  template <typename K>                                                            \
  Named_function_parameters<K, internal_np::X> Z(const K& p)                       \
  {                                                                                \
    return Named_function_parameters<K, internal_np::X>(p);                        \
  }
#include <CGAL/Tangent_vector_fields/internal/parameters_interface.h>
#undef TVF_add_named_parameter

namespace internal {
// Re-nests the links of `cgal` on top of `tail`, innermost first.
template <typename Tail>
const Tail& append(const CGAL::Named_function_parameters<bool, CGAL::internal_np::all_default_t,
                                                         CGAL::internal_np::No_property>&,
                   const Tail& tail)
{
  return tail;
}

template <typename T, typename Tag, typename Tail>
Named_function_parameters<T, Tag, Tail>
append(const CGAL::Named_function_parameters<T, Tag, CGAL::internal_np::No_property>& np, const Tail& tail)
{
  return Named_function_parameters<T, Tag, Tail>(np.v, tail);
}

template <typename T, typename Tag, typename Base, typename Tail>
auto append(const CGAL::Named_function_parameters<T, Tag, Base>& np, const Tail& tail)
{
  auto inner = append(static_cast<const Base&>(np), tail);
  return Named_function_parameters<T, Tag, decltype(inner)>(np.v, inner);
}
} // namespace internal

/// Joins a chain `first` (CGAL's or ours) with a chain of ours into one chain of our type.
template <typename T1, typename Tag1, typename Base1, typename T2, typename Tag2, typename Base2>
auto combine(const CGAL::Named_function_parameters<T1, Tag1, Base1>& first,
             const Named_function_parameters<T2, Tag2, Base2>& second)
{
  return internal::append(first, second);
}

} // namespace parameters
} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
