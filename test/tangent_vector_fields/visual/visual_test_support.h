// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// What the tests of streamlines, exports and pictures share: face fields in property maps
// and a field whose streamlines are known exactly.

#ifndef TVF_VISUAL_TEST_SUPPORT_H
#define TVF_VISUAL_TEST_SUPPORT_H

#include "test_meshes.h"

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>

#include <array>
#include <string>

namespace tvf_test {

typedef Mesh::Property_map<Face_index, Vector_3> Field;
typedef std::array<double, 3> P3;

inline Field field_map(Mesh& mesh, const std::string& name)
{
  return mesh.add_property_map<Face_index, Vector_3>("f:" + name, Vector_3(0, 0, 0)).first;
}

// J grad z: tangent to the level sets of the (piecewise-linear) height z, so its
// streamlines are exactly the level polygons z = const.
inline void rotated_height_gradient(Mesh& mesh, Field out)
{
  auto z = mesh.add_property_map<Vertex_index, double>("v:z", 0.).first;
  for(Vertex_index v : mesh.vertices()) z[v] = mesh.point(v).z();
  Field g = field_map(mesh, "grad_z");
  CGAL::Tangent_vector_fields::Discrete_operators<Mesh> ops(mesh);
  ops.gradient(z, g);
  ops.rotate(g, out);
}

} // namespace tvf_test

#endif // TVF_VISUAL_TEST_SUPPORT_H
