// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The Surface_mesh front (the only translation unit of these tests with Surface_mesh): the
// model of a mesh is the model of its arrays, a closed curved shell rests still, a cloth
// hangs from pins, positions go back to the mesh, quads are refused; closed surfaces filled with
// tetrahedra (Mesh_3), checked against the volume they enclose, with their vertices embedded.

#include "expect_reason.h"
#include "test_meshes.h"

#include <CGAL/Projective_dynamics/Simulator.h>
#include <CGAL/Projective_dynamics/make_models.h>
#include <CGAL/Projective_dynamics/shell_model_of_mesh.h>
#include <CGAL/Projective_dynamics/tetrahedralize.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <vector>

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

// --- Tetrahedra of closed surfaces (tetrahedralize.h, CGAL Mesh_3) ------------------------------

namespace {

// The volume a closed, consistently oriented surface encloses (divergence theorem), computed
// here from the triangles alone.
double enclosed_volume(const std::vector<PD::Point>& p, const std::vector<PD::Triangle>& triangles)
{
  double v = 0;
  for(const PD::Triangle& t : triangles)
  {
    const Eigen::Vector3d a(p[t[0]].data()), b(p[t[1]].data()), c(p[t[2]].data());
    v += a.dot(b.cross(c)) / 6;
  }
  return std::abs(v);
}

double tet_volume(const PD::Tet_mesh& m)
{
  double v = 0;
  for(const PD::Tetrahedron& t : m.tetrahedra) v += PD::signed_volume(m.points, t);
  return v;
}

// The unit cube [0, 1]^3 as 12 outward triangles.
void unit_cube(std::vector<PD::Point>& p, std::vector<PD::Triangle>& t)
{
  p.clear();
  for(int i = 0; i < 8; ++i) p.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  t = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
       {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
}

} // namespace

TEST(Tetrahedralize, CubeKeepsItsCornersAndVolume)
{
  std::vector<PD::Point> p;
  std::vector<PD::Triangle> t;
  unit_cube(p, t);
  ASSERT_NEAR(enclosed_volume(p, t), 1.0, 1e-15);
  const PD::Tetrahedralized_surface s = PD::tetrahedralize(p, t, PD::Tetrahedralization_options{0.2, 0.01, 60});
  EXPECT_NO_THROW(PD::check_tet_mesh(s.mesh));
  for(const PD::Tetrahedron& tet : s.mesh.tetrahedra) EXPECT_GT(PD::signed_volume(s.mesh.points, tet), 0);
  // Sharp edges kept as features: the boundary lies on the cube's faces, the volume is the cube's.
  EXPECT_NEAR(tet_volume(s.mesh), 1.0, 1e-9);
  // The corners are vertices of the tetrahedra: embedded with weights in [0, 1], no distance.
  EXPECT_LT(s.largest_outside_distance, 1e-12);
  ASSERT_EQ(s.surface.weights.size(), p.size());
  for(const auto& w : s.surface.weights)
    for(double x : w) EXPECT_GE(x, -1e-12);
  const PD::Positions q = s.surface.embed(PD::to_positions(s.mesh.points));
  for(std::size_t i = 0; i < p.size(); ++i)
    for(int k = 0; k < 3; ++k) EXPECT_NEAR(q(Eigen::Index(i), k), p[i][std::size_t(k)], 1e-12);
  // Finer sizes, more tetrahedra.
  const PD::Tetrahedralized_surface fine = PD::tetrahedralize(p, t, PD::Tetrahedralization_options{0.1, 0.01, 60});
  EXPECT_GT(fine.mesh.tetrahedra.size(), 2 * s.mesh.tetrahedra.size());
}

TEST(Tetrahedralize, SphereVolumeEmbeddingAndARigidMotion)
{
  const Mesh sphere = make_icosphere(3); // 642 vertices on the unit sphere
  const PD::Tetrahedralized_surface s = PD::tetrahedralize(sphere, params::cell_size(0.08).facet_distance(0.002));
  std::vector<PD::Point> p;
  for(auto v : sphere.vertices()) p.push_back({sphere.point(v).x(), sphere.point(v).y(), sphere.point(v).z()});
  std::vector<PD::Triangle> t;
  for(auto f : sphere.faces())
  {
    PD::Triangle tri{};
    int k = 0;
    for(auto v : vertices_around_face(sphere.halfedge(f), sphere)) tri[std::size_t(k++)] = int(v);
    t.push_back(tri);
  }
  // The facet distance is 0.002 of the diagonal (2 sqrt 3): the volumes agree to ~1%.
  const double volume = enclosed_volume(p, t);
  EXPECT_NEAR(tet_volume(s.mesh) / volume, 1.0, 0.01) << tet_volume(s.mesh) << " against " << volume;
  EXPECT_LT(s.largest_outside_distance, 0.01);
  // Every vertex of the sphere comes back from the rest tetrahedra (made to fail: weights of the
  // wrong tetrahedron's corners).
  const PD::Positions rest = PD::to_positions(s.mesh.points);
  const PD::Positions q = s.surface.embed(rest);
  for(std::size_t i = 0; i < p.size(); ++i)
    for(int k = 0; k < 3; ++k) EXPECT_NEAR(q(Eigen::Index(i), k), p[i][std::size_t(k)], 1e-12);
  // The tetrahedra moved rigidly carry the surface rigidly.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::RowVector3d shift(4, -1, 2);
  const PD::Positions moved = (rest * R.transpose()).rowwise() + shift;
  const PD::Positions qm = s.surface.embed(moved);
  const PD::Positions expected = (q * R.transpose()).rowwise() + shift;
  EXPECT_LT((qm - expected).cwiseAbs().maxCoeff(), 1e-12);
  // A solid of these tetrahedra falls as one: after a few steps under gravity, the embedded
  // surface has moved down by the same amount as the tetrahedra's mean.
  PD::Simulator sim(PD::make_solid_model(s.mesh, params::strain_stiffness(1e4)));
  for(int i = 0; i < 3; ++i) sim.step();
  const double drop = (sim.positions().col(2) - rest.col(2)).mean();
  EXPECT_LT(drop, -0.01);
  EXPECT_NEAR((s.surface.embed(sim.positions()).col(2) - q.col(2)).mean(), drop, 1e-3);
}

TEST(Tetrahedralize, RefusesSurfacesThatBoundNoVolume)
{
  std::vector<PD::Point> p;
  std::vector<PD::Triangle> t;
  unit_cube(p, t);
  std::vector<PD::Triangle> open(t.begin(), t.end() - 1);
  EXPECT_THROW_REASON(PD::tetrahedralize(p, open), PD::Invalid_input, "the surface is open (3 border edges)");
  // Two overlapping cubes as one surface.
  std::vector<PD::Point> q = p;
  std::vector<PD::Triangle> u = t;
  for(const PD::Point& x : p) q.push_back({x[0] + 0.5, x[1] + 0.5, x[2] + 0.5});
  for(const PD::Triangle& f : t) u.push_back({f[0] + 8, f[1] + 8, f[2] + 8});
  EXPECT_THROW_REASON(PD::tetrahedralize(q, u), PD::Invalid_input, "the surface intersects itself");
  // A triangle used twice: an edge of more than two triangles.
  std::vector<PD::Triangle> doubled = t;
  doubled.push_back(t[0]);
  EXPECT_THROW_REASON(PD::tetrahedralize(p, doubled), PD::Invalid_input, "not an oriented 2-manifold");
  EXPECT_THROW_REASON(PD::tetrahedralize(p, t, PD::Tetrahedralization_options{0, 0.01, 60}), PD::Invalid_input,
                      "must be positive and finite");
  std::vector<PD::Triangle> bad = t;
  bad[3][1] = 8;
  EXPECT_THROW_REASON(PD::tetrahedralize(p, bad), PD::Invalid_input, "triangle 3 refers to vertex 8 of 8");
  EXPECT_THROW_REASON(PD::tetrahedralize(std::vector<PD::Point>(), std::vector<PD::Triangle>()), PD::Invalid_input,
                      "the surface is empty");
}
