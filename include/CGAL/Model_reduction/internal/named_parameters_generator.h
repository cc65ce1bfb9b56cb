// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Generates a package's named-parameter chain: included (deliberately without include
// guard) once per package, inside that package's namespace, after
// <CGAL/Model_reduction/internal/named_parameters_base.h>.  If
// CGAL_MR_PACKAGE_PARAMETERS is defined, it names the package's X-macro list of
// MR_add_named_parameter(tag_type, tag_value, function_name) entries.
//
// It defines, in the including namespace:
// - `internal_np`: the package's tags, and the shared ones through a using-directive;
// - `Named_function_parameters<T, Tag, Base>`: a CGAL parameter pack whose chaining
//   functions are CGAL's, the shared ones and the package's, all returning this type;
// - `parameters`: starters for all of them, `default_values()` and `combine()`.
// A package built on another (Vibration_modes on Discrete_shells) also defines
// CGAL_MR_BASE_PARAMETERS (the base's list) and CGAL_MR_BASE_NAMESPACE (the base's
// namespace): its chain then carries the base's tags themselves, so that the base's
// functions read them from it.
//
// CGAL 5.5 cannot add members to its own chain from outside; a subclass per package is
// the way, and generating it here keeps the machinery written once.

namespace internal_np {
using namespace CGAL::Model_reduction::internal_np;
#ifdef CGAL_MR_BASE_NAMESPACE
using namespace CGAL_MR_BASE_NAMESPACE::internal_np;
#endif
#ifdef CGAL_MR_PACKAGE_PARAMETERS
#define MR_add_named_parameter(X, Y, Z) enum X { Y };
#include CGAL_MR_PACKAGE_PARAMETERS
#undef MR_add_named_parameter
#endif
} // namespace internal_np

/// A `CGAL::Named_function_parameters` whose chaining functions include the shared and
/// this package's options.  It is a CGAL parameter pack: every CGAL function accepts it.
template <typename T, typename Tag, typename Base = CGAL::internal_np::No_property>
struct Named_function_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  typedef CGAL::Named_function_parameters<T, Tag, Base> cgal_parameters;
  typedef Named_function_parameters<T, Tag, Base> self;

  Named_function_parameters() : cgal_parameters() {}
  Named_function_parameters(const T& v) : cgal_parameters(v) {}
  Named_function_parameters(const T& v, const Base& b) : cgal_parameters(v, b) {}

#define CGAL_MR_CHAIN_MEMBER(TAG, Z)                                                \
  template <typename K>                                                            \
  Named_function_parameters<K, TAG, self> Z(const K& k) const                      \
  {                                                                                \
    return Named_function_parameters<K, TAG, self>(k, *this);                      \
  }
#define CGAL_add_named_parameter(X, Y, Z) CGAL_MR_CHAIN_MEMBER(CGAL::internal_np::X, Z)
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter
#define MR_add_named_parameter(X, Y, Z) CGAL_MR_CHAIN_MEMBER(CGAL::Model_reduction::internal_np::X, Z)
#include <CGAL/Model_reduction/internal/parameters_interface.h>
#undef MR_add_named_parameter
#ifdef CGAL_MR_BASE_PARAMETERS
#define MR_add_named_parameter(X, Y, Z) CGAL_MR_CHAIN_MEMBER(CGAL_MR_BASE_NAMESPACE::internal_np::X, Z)
#include CGAL_MR_BASE_PARAMETERS
#undef MR_add_named_parameter
#endif
#ifdef CGAL_MR_PACKAGE_PARAMETERS
#define MR_add_named_parameter(X, Y, Z) CGAL_MR_CHAIN_MEMBER(internal_np::X, Z)
#include CGAL_MR_PACKAGE_PARAMETERS
#undef MR_add_named_parameter
#endif
#undef CGAL_MR_CHAIN_MEMBER
};

namespace parameters {

using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;
using CGAL::parameters::get_parameter_reference;
using CGAL::parameters::is_default_parameter;

typedef Named_function_parameters<bool, CGAL::internal_np::all_default_t> Default_named_parameters;

/// The empty chain.
inline Default_named_parameters default_values() { return Default_named_parameters(); }

// Starters for every parameter, returning this package's chain type.
#define CGAL_MR_CHAIN_STARTER(TAG, Z)                                               \
  template <typename K>                                                            \
  Named_function_parameters<K, TAG> Z(const K& p)                                  \
  {                                                                                \
    return Named_function_parameters<K, TAG>(p);                                   \
  }
#define CGAL_add_named_parameter(X, Y, Z) CGAL_MR_CHAIN_STARTER(CGAL::internal_np::X, Z)
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter
#define MR_add_named_parameter(X, Y, Z) CGAL_MR_CHAIN_STARTER(CGAL::Model_reduction::internal_np::X, Z)
#include <CGAL/Model_reduction/internal/parameters_interface.h>
#undef MR_add_named_parameter
#ifdef CGAL_MR_BASE_PARAMETERS
#define MR_add_named_parameter(X, Y, Z) CGAL_MR_CHAIN_STARTER(CGAL_MR_BASE_NAMESPACE::internal_np::X, Z)
#include CGAL_MR_BASE_PARAMETERS
#undef MR_add_named_parameter
#endif
#ifdef CGAL_MR_PACKAGE_PARAMETERS
#define MR_add_named_parameter(X, Y, Z) CGAL_MR_CHAIN_STARTER(internal_np::X, Z)
#include CGAL_MR_PACKAGE_PARAMETERS
#undef MR_add_named_parameter
#endif
#undef CGAL_MR_CHAIN_STARTER

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

/// Joins a chain `first` (CGAL's, another package's or ours) with a chain of ours into one chain of our type.
template <typename T1, typename Tag1, typename Base1, typename T2, typename Tag2, typename Base2>
auto combine(const CGAL::Named_function_parameters<T1, Tag1, Base1>& first,
             const Named_function_parameters<T2, Tag2, Base2>& second)
{
  return internal::append(first, second);
}

} // namespace parameters
