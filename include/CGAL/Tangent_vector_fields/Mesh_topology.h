// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_MESH_TOPOLOGY_H
#define CGAL_TANGENT_VECTOR_FIELDS_MESH_TOPOLOGY_H

/// \file Mesh_topology.h
/// Connected components, genus and boundary loops of a triangle mesh, and the
/// dimension of its space of discrete harmonic fields (SPEC section 3).

#include <string>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

/// Topology of one connected component (vertices reached by faces only).
struct Component_topology
{
  int number_of_vertices = 0;
  int number_of_edges = 0;
  int number_of_faces = 0;
  int number_of_boundary_loops = 0;
  int genus = 0;

  int euler_characteristic() const { return number_of_vertices - number_of_edges + number_of_faces; }
  bool is_closed() const { return number_of_boundary_loops == 0; }
  /// `2g` for a closed component, `2g + b - 1` with `b` boundary loops.
  int harmonic_dimension() const
  {
    return is_closed() ? 2 * genus : 2 * genus + number_of_boundary_loops - 1;
  }
};

/// Topology of a whole mesh: one entry per connected component.
struct Mesh_topology
{
  std::vector<Component_topology> components;
  int number_of_isolated_vertices = 0; ///< vertices referenced by no face (ignored)

  int number_of_components() const { return static_cast<int>(components.size()); }
  int harmonic_dimension() const
  {
    int d = 0;
    for(const Component_topology& c : components) d += c.harmonic_dimension();
    return d;
  }
  int total_genus() const
  {
    int g = 0;
    for(const Component_topology& c : components) g += c.genus;
    return g;
  }
  int number_of_boundary_loops() const
  {
    int b = 0;
    for(const Component_topology& c : components) b += c.number_of_boundary_loops;
    return b;
  }
  /// One line such as "2 components, genus 3, 106 boundary loops, harmonic dimension 111".
  std::string summary() const;
};

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
