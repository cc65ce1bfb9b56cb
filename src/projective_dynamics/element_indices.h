// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PROJECTIVE_DYNAMICS_SRC_ELEMENT_INDICES_H
#define CGAL_PROJECTIVE_DYNAMICS_SRC_ELEMENT_INDICES_H

// The vertex indices of one element (tet, triangle, edge), checked where meshes and models
// take them in.

#include <CGAL/Projective_dynamics/errors.h>

#include <cstddef>
#include <string>

namespace CGAL {
namespace Projective_dynamics {
namespace internal {

/// \throws Invalid_mesh (`invalid_index`) naming the `kind` and `index` of the element if one
///         of its `count` vertices lies outside `[0, n)` or appears twice.
inline void check_element_indices(const int* v, int count, int n, const char* kind, std::size_t index)
{
  for(int i = 0; i < count; ++i)
  {
    if(v[i] < 0 || v[i] >= n)
      throw Invalid_mesh(Mesh_defect::invalid_index, std::string(kind) + " " + std::to_string(index) + " has vertex index " +
                                                         std::to_string(v[i]) + " outside [0, " + std::to_string(n) + ")");
    for(int j = 0; j < i; ++j)
      if(v[i] == v[j])
        throw Invalid_mesh(Mesh_defect::invalid_index,
                           std::string(kind) + " " + std::to_string(index) + " repeats vertex " + std::to_string(v[i]));
  }
}

} // namespace internal
} // namespace Projective_dynamics
} // namespace CGAL

#endif
