// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The Surface_mesh front (the only translation unit of these tests with Surface_mesh): the
// model of a mesh is the model of its arrays, a closed curved shell rests still, a cloth
// hangs from pins, positions go back to the mesh, quads are refused.

#include "expect_reason.h"
#include "test_meshes.h"

#include <CGAL/Projective_dynamics/Simulator.h>
#include <CGAL/Projective_dynamics/shell_model_of_mesh.h>

#include <gtest/gtest.h>

namespace PD = CGAL::Projective_dynamics;
namespace params = PD::parameters;
using namespace tvf_test;

TEST(Surface_mesh_front, ClosedCurvedShellRestsStill)
{
  const Mesh sphere = make_icosphere(2);
  PD::Elastic_model model = PD::make_shell_model_of_mesh(sphere, params::strain_stiffness(10.0).bending_stiffness(0.1));
  EXPECT_EQ(model.number_of_vertices(), int(sphere.number_of_vertices()));
  EXPECT_EQ(model.number_of_groups(), 2);
  // Bending at every vertex of a closed surface, with the sphere's mean curvature: |H| = 2 / r.
  int bending = 0;
  for(const PD::Element& e : model.elements())
    if(e.type == PD::Element_type::bending)
    {
      ++bending;
      EXPECT_NEAR(e.min_value, 2.0, 0.1); // discretisation error of a 162-vertex icosphere
    }
  EXPECT_EQ(bending, int(sphere.number_of_vertices()));
  EXPECT_LT(model.elastic_energy(model.rest_positions()), 1e-24);
  const PD::Positions rest = model.rest_positions();
  PD::Simulator sim(std::move(model), params::gravity(Eigen::Vector3d::Zero()));
  for(int i = 0; i < 10; ++i) sim.step();
  EXPECT_LT((sim.positions() - rest).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(Surface_mesh_front, ClothHangsFromPinsAndGoesBackToTheMesh)
{
  Mesh cloth = make_disk(6, 0.0, 0.0);
  PD::Simulator sim(PD::make_shell_model_of_mesh(cloth, params::strain_stiffness(1e3).bending_stiffness(1e-2).density(0.5)),
                    params::time_step(0.01));
  // Pin the two vertices farthest apart in x.
  const PD::Positions& q0 = sim.positions();
  Eigen::Index lo, hi;
  q0.col(0).minCoeff(&lo);
  q0.col(0).maxCoeff(&hi);
  sim.set_pinned_vertices({int(lo), int(hi)});
  const Eigen::RowVector3d pinned = q0.row(lo);
  for(int i = 0; i < 50; ++i) sim.step();
  ASSERT_TRUE(sim.positions().allFinite());
  EXPECT_EQ(sim.positions().row(lo), pinned);
  EXPECT_LT(sim.positions().col(2).mean(), -0.01); // it sags
  PD::copy_positions_to_mesh(sim.positions(), cloth);
  const Point_3 p = cloth.point(Vertex_index(7));
  EXPECT_EQ(p.z(), sim.positions()(7, 2));
}

TEST(Surface_mesh_front, QuadsAreRefused)
{
  Mesh quad;
  const auto a = quad.add_vertex(Point_3(0, 0, 0)), b = quad.add_vertex(Point_3(1, 0, 0)),
             c = quad.add_vertex(Point_3(1, 1, 0)), d = quad.add_vertex(Point_3(0, 1, 0));
  quad.add_face(a, b, c, d);
  EXPECT_THROW_REASON(PD::make_shell_model_of_mesh(quad), PD::Invalid_mesh, "face 0 has 4 vertices, not 3");
}
