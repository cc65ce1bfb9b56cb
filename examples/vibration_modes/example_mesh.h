// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the examples of Vibration_modes share: reading a mesh scaled to unit area (so that
// stiffnesses and time scales mean the same on any mesh) and choosing the vertices to pin.

#ifndef VIBRATION_MODES_EXAMPLE_MESH_H
#define VIBRATION_MODES_EXAMPLE_MESH_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex_index;

/// Reads `path` and scales it to unit area; false (with a message) if it cannot be read.
inline bool read_unit_area_mesh(const std::string& path, Mesh& mesh)
{
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || mesh.is_empty())
  {
    std::cerr << "cannot read " << path << "\n";
    return false;
  }
  const double area = CGAL::Polygon_mesh_processing::area(mesh);
  for(auto v : vertices(mesh)) mesh.point(v) = CGAL::ORIGIN + (mesh.point(v) - CGAL::ORIGIN) / std::sqrt(area);
  return true;
}

/// The vertices within `fraction` of the height above the lowest one along y (the feet of a
/// standing model with y up).
inline std::vector<Vertex_index> lowest_vertices(const Mesh& mesh, double fraction)
{
  double low = 1e300, high = -1e300;
  for(auto v : vertices(mesh)) low = std::min(low, mesh.point(v).y()), high = std::max(high, mesh.point(v).y());
  std::vector<Vertex_index> pins;
  for(auto v : vertices(mesh))
    if(mesh.point(v).y() <= low + fraction * (high - low)) pins.push_back(v);
  return pins;
}

#endif
