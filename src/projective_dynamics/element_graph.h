// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The element edge graph of an Elastic_model (compressed adjacency with Euclidean rest lengths),
// the vertices of each element, and Dijkstra distances on it.

#ifndef CGAL_PROJECTIVE_DYNAMICS_SRC_ELEMENT_GRAPH_H
#define CGAL_PROJECTIVE_DYNAMICS_SRC_ELEMENT_GRAPH_H

#include <CGAL/Projective_dynamics/Elastic_model.h>

#include <utility>
#include <vector>

namespace CGAL {
namespace Projective_dynamics {
namespace internal {

/// The vertices an element's rows of S touch, sorted.
std::vector<int> element_vertices(const Elastic_model& model, int element);

struct Element_graph
{
  std::vector<int> offsets;       // n + 1
  std::vector<int> neighbours;
  std::vector<double> lengths;
  int size() const { return int(offsets.size()) - 1; }
};

/// Edges within every element but bending (its one-ring is connected by the strain elements;
/// a model of bending only uses it all the same).
Element_graph element_graph(const Elastic_model& model);

/// Lowers `distance[v]` to the graph distance from `source` where that is smaller, visiting
/// only the vertices it improves (incremental farthest-point sampling).
void relax_from(const Element_graph& graph, int source, std::vector<double>& distance);

/// The vertices within graph distance `< radius` of `source` (and `source` itself), with
/// their distances.
std::vector<std::pair<int, double>> ball(const Element_graph& graph, int source, double radius);

/// Farthest-point samples on `graph` (see farthest_point_samples).
std::vector<int> farthest_point_samples(const Element_graph& graph, int count, std::vector<double>* distances);

} // namespace internal
} // namespace Projective_dynamics
} // namespace CGAL

#endif
