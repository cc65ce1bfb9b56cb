// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Bad and extreme input to n-fields (SPEC 10): n out of range, prescribed singularities
// that cannot exist, bad guides, fields and constraints, and degenerate meshes.  Valid
// results are checked against Poincare-Hopf with the Euler characteristic counted here.

#include "bad_input_support.h"

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>
#include <CGAL/Tangent_vector_fields/N_field_singularities.h>
#include <CGAL/Tangent_vector_fields/N_field_spline.h>
#include <CGAL/Tangent_vector_fields/Smoothest_n_field_solver.h>
#include <CGAL/Tangent_vector_fields/curvature_direction_field.h>
#include <CGAL/Tangent_vector_fields/smoothest_n_field.h>

#include <limits>
#include <numeric>

using namespace bad_input;

namespace {

typedef Mesh::Property_map<Face_index, Vector_3> Field;
typedef TVF::N_field_constraint N_constraint;

std::shared_ptr<const TVF::N_field_operators> n_ops(const Mesh& mesh, int n,
                                                    const std::vector<std::pair<int, int>>& singularities = {})
{
  TVF::N_field_options options;
  options.singularities = singularities;
  return std::make_shared<const TVF::N_field_operators>(TVF::Discrete_operators<Mesh>(mesh).shared_matrices(), n,
                                                        options);
}

long long index_sum(const std::vector<int>& k) { return std::accumulate(k.begin(), k.end(), 0LL); }

// The smoothest n-field written to a map is unit (or zero) and tangent in every face, and its
// indices sum to n chi.
void expect_sound_n_field(Mesh& mesh, int n)
{
  SCOPED_TRACE("n = " + std::to_string(n) + ", " + std::to_string(mesh.number_of_faces()) + " faces");
  Field out = mesh.add_property_map<Face_index, Vector_3>("f:smoothest", Vector_3(7, 7, 7)).first;
  TVF::smoothest_n_field(mesh, n, out);
  const auto ops = n_ops(mesh, n);
  int unit = 0;
  for(Face_index f : mesh.faces())
  {
    const Vector_3 v = out[f];
    ASSERT_TRUE(std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()));
    const double length = std::sqrt(v.squared_length());
    EXPECT_TRUE(length == 0 || std::abs(length - 1) < 1e-12) << length;
    unit += length > 0;
    const auto& nn = ops->mesh().normal(static_cast<int>(f));
    EXPECT_LT(std::abs(v.x() * nn[0] + v.y() * nn[1] + v.z() * nn[2]), 1e-12);
  }
  EXPECT_GT(unit, 0);
  const Eigen::VectorXd vectors = TVF::Discrete_operators<Mesh>(mesh).to_frame_coordinates(out);
  EXPECT_EQ(index_sum(TVF::n_field_indices(*ops, ops->from_vectors(vectors))),
            static_cast<long long>(n) * euler_and_boundary_loops(mesh).first);
}

// The smoothest n-field of a connection with prescribed singularities has them where they are
// prescribed: its indices are measured with the surface's own connection (not the one that
// carries the prescription), so a prescription the field does not honour shows.  Poincare-Hopf
// (indices summing to n chi) is the sanity line; it holds for any field.
void expect_prescribed_found(const Mesh& mesh, int n, const std::vector<std::pair<int, int>>& prescribed)
{
  SCOPED_TRACE("n = " + std::to_string(n) + ", " + std::to_string(mesh.number_of_faces()) + " faces, prescribed");
  const Eigen::VectorXd z = TVF::smoothest_n_field(*n_ops(mesh, n, prescribed));
  ASSERT_TRUE(z.allFinite());
  const std::vector<int> k = TVF::n_field_indices(*n_ops(mesh, n), z);
  for(const auto& [v, index] : prescribed) EXPECT_EQ(k[v], index) << "vertex " << v;
  EXPECT_EQ(index_sum(k), static_cast<long long>(n) * euler_and_boundary_loops(mesh).first);
}

} // namespace

TEST(BadNFields, NOutOfRangeIsRefusedEverywhere)
{
  Mesh mesh = make_icosphere(1);
  Field out = mesh.add_property_map<Face_index, Vector_3>("f:out").first;
  for(int n : {0, -3, std::numeric_limits<int>::min()})
  {
    const std::string phrase = "n must be at least 1 (got " + std::to_string(n) + ")";
    expect_error<TVF::Invalid_input>([&] { n_ops(mesh, n); }, phrase);
    expect_error<TVF::Invalid_input>([&] { TVF::smoothest_n_field(mesh, n, out); }, phrase);
    expect_error<TVF::Invalid_input>([&] { TVF::N_field_spline<Mesh> s(mesh, n); }, phrase);
  }
  const int max_n = TVF::N_field_operators::max_n;
  for(int n : {max_n + 1, std::numeric_limits<int>::max()})
  {
    expect_error<TVF::Invalid_input>([&] { n_ops(mesh, n); }, "n must be at most " + std::to_string(max_n));
    expect_error<TVF::Invalid_input>([&] { TVF::smoothest_n_field(mesh, n, out); }, "n must be at most");
  }
}

TEST(BadNFields, LargeNStillSatisfiesPoincareHopf)
{
  // n = 1000 and the largest n accepted: the index sum n chi is far from small numbers.
  Mesh sphere = make_icosphere(1), torus = make_torus(10, 6);
  expect_sound_n_field(sphere, 1000);
  expect_sound_n_field(torus, 1000);
  expect_sound_n_field(sphere, TVF::N_field_operators::max_n);
}

TEST(BadNFields, AwkwardMeshesGiveUnitTangentFieldsWithTheRightIndexSum)
{
  Mesh triangle = single_triangle(), band = boundary_only_band(12), strip = boundary_only_strip(8),
       slab = holed_slab(5, 2), pair = sphere_with_tiny_companion(1e-6), lonely = make_torus(12, 6);
  lonely.add_vertex(Point_3(9, 9, 9));
  for(Mesh* mesh : {&triangle, &band, &strip, &slab, &pair, &lonely})
    for(int n : {1, 2, 4})
      expect_sound_n_field(*mesh, n);
  // Known singularities: a +1/n, -1/n pair on the torus with a lonely vertex (n chi = 0),
  // and a +1/4 with a -1/4 beside it.
  for(int n : {1, 2, 4}) expect_prescribed_found(lonely, n, {{0, 1}, {40, -1}});
  expect_prescribed_found(lonely, 4, {{5, 1}, {6, -1}});
}

TEST(BadNFields, PrescribedSingularitiesThatCannotExistAreRefused)
{
  Mesh sphere = make_icosphere(1); // 42 vertices, chi = 2
  const Vertex_index isolated = sphere.add_vertex(Point_3(5, 5, 5));
  expect_error<TVF::Invalid_input>([&] { n_ops(sphere, 4, {{42 + 1, 1}}); }, "no such vertex");
  expect_error<TVF::Invalid_input>([&] { n_ops(sphere, 4, {{-1, 1}}); }, "no such vertex");
  expect_error<TVF::Invalid_input>([&] { n_ops(sphere, 4, {{3, 1}, {3, 1}}); }, "prescribed twice");
  expect_error<TVF::Invalid_input>([&] { n_ops(sphere, 4, {{static_cast<int>(isolated), 1}}); }, "in no face");
  const Mesh disk = make_disk(3);
  int boundary_vertex = -1;
  for(Vertex_index v : disk.vertices())
    if(disk.is_border(v)) boundary_vertex = static_cast<int>(v);
  expect_error<TVF::Invalid_input>([&] { n_ops(disk, 4, {{boundary_vertex, 1}}); }, "on the boundary");

  // Every vertex prescribed: the indices must sum to n chi = 8 (Poincare-Hopf); 42 do not.
  std::vector<std::pair<int, int>> all;
  for(int v = 0; v < 42; ++v) all.push_back({v, 1});
  expect_error<TVF::Invalid_input>([&] { n_ops(sphere, 4, all); }, "sum to 42/4, not n chi = 8/4");
}

TEST(BadNFields, SingularitiesNotSummingToChiAreCompletedElsewhere)
{
  // One +1/4 on a sphere (n chi = 8): the free vertices take up the other 7/4.  The smoothest
  // field of that connection has the prescribed index and Poincare-Hopf holds.
  const Mesh sphere = make_icosphere(2);
  const auto ops = n_ops(sphere, 4, {{0, 1}});
  const Eigen::VectorXd z = TVF::smoothest_n_field(*ops);
  ASSERT_TRUE(z.allFinite());
  const std::vector<int> k = TVF::n_field_indices(*ops, z);
  EXPECT_EQ(k[0], 1);
  EXPECT_EQ(index_sum(k), 8);
  expect_prescribed_found(sphere, 4, {{0, 1}}); // the same, measured with the sphere's own connection
  // Every vertex of an icosahedron prescribed, summing to n chi: valid and met exactly.
  const Mesh ico = make_icosphere(0);
  std::vector<std::pair<int, int>> twelve;
  for(int v = 0; v < 12; ++v) twelve.push_back({v, v < 8 ? 1 : 0});
  const auto all = n_ops(ico, 4, twelve);
  const std::vector<int> k12 = TVF::n_field_indices(*all, TVF::smoothest_n_field(*all));
  EXPECT_EQ(index_sum(k12), 8);
  for(int v = 0; v < 12; ++v) EXPECT_EQ(k12[v], v < 8 ? 1 : 0) << v;
  expect_prescribed_found(ico, 4, twelve);
}

TEST(BadNFields, BadFieldsAndGuidesAreRefused)
{
  Mesh mesh = make_torus(12, 6);
  const auto ops = n_ops(mesh, 4);
  const int nf = mesh.number_of_faces();
  Eigen::VectorXd z = random_field(nf, 4);
  z[5] = std::nan("");
  expect_error<TVF::Invalid_input>([&] { TVF::n_field_indices(*ops, z); }, "non-finite");
  expect_error<TVF::Invalid_input>([&] { TVF::n_field_indices(*ops, Eigen::VectorXd::Ones(3)); }, "has 3 values");
  expect_error<TVF::Invalid_input>([&] { ops->energy_density(Eigen::VectorXd::Ones(3)); }, "3 coordinates");
  expect_error<TVF::Invalid_input>([&] { ops->m_harmonic_energy(random_field(nf, 1), 0); }, "m must be at least 1");
  // Through the generic interface: a NaN vector in the face map.
  Field field = mesh.add_property_map<Face_index, Vector_3>("f:field", Vector_3(1, 0, 0)).first;
  auto index = mesh.add_property_map<Vertex_index, int>("v:index", 0).first;
  field[Face_index(3)] = Vector_3(0, HUGE_VAL, 0);
  expect_error<TVF::Invalid_input>([&] { TVF::n_field_singularities(mesh, 4, field, index); }, "non-finite");
  // The zero field is valid: every face has angle 0, and Poincare-Hopf holds (chi = 0).
  EXPECT_EQ(index_sum(TVF::n_field_indices(*ops, Eigen::VectorXd::Zero(2 * nf))), 0);

  TVF::Smoothest_n_field_options bad;
  bad.alignment = random_field(nf, 2);
  for(double w : {0., -1., std::nan(""), HUGE_VAL})
  {
    bad.alignment_weight = w;
    expect_error<TVF::Invalid_input>([&] { TVF::smoothest_n_field(*ops, bad); }, "alignment weight");
  }
  bad.alignment_weight = 1;
  bad.alignment[0] = std::nan("");
  expect_error<TVF::Invalid_input>([&] { TVF::smoothest_n_field(*ops, bad); }, "not finite");
  bad.alignment = Eigen::VectorXd::Ones(4);
  expect_error<TVF::Invalid_input>([&] { TVF::smoothest_n_field(*ops, bad); }, "alignment field has 4");
  TVF::Smoothest_n_field_options nan_tolerance;
  nan_tolerance.tolerance = std::nan("");
  expect_error<TVF::Invalid_input>([&] { TVF::smoothest_n_field(*ops, nan_tolerance); }, "tolerance");
}

TEST(BadNFields, BadConstraintsAreRefusedAndDuplicatesAreInfeasible)
{
  Mesh mesh = make_icosphere(1);
  const auto ops = n_ops(mesh, 4);
  TVF::Full_n_field_spline_solver solver(ops);
  const double nan = std::nan("");
  const auto& normal = ops->mesh().normal(2);
  const std::vector<std::pair<N_constraint, std::string>> bad = {
      {N_constraint::vector_in_face(80, {1, 0, 0}), "in face 80\" (n = 4): no such face"},
      {N_constraint::vector_in_face(-1, {1, 0, 0}), "in face -1\" (n = 4): no such face"},
      {N_constraint::direction_in_face(2, {0, 0, 0}), "the direction is zero"},
      {N_constraint::vector_in_face(2, {nan, 0, 0}), "the vector is not finite"},
      {N_constraint::vector_in_face(2, {normal[0], normal[1], normal[2]}), "normal"},
      {N_constraint::vector_at_point(2, {0.7, 0.7, -0.4}, {1, 0, 0}), "barycentric"},
      {N_constraint::singularity_at_vertex(42, 1), "at vertex 42\" (n = 4): no such vertex"},
      // Index 100/4 around a vertex of 5 faces turns by more than pi per face.
      {N_constraint::singularity_at_vertex(0, 100), "its 5 faces cannot show a turning of 100 periods"},
  };
  for(const auto& [c, phrase] : bad)
    expect_error<TVF::Invalid_input>([&] { solver.add(c); }, phrase);
  EXPECT_EQ(solver.number_of_constraints(), 0);
  // A zero vector is valid: the n-field vanishes in that face.
  solver.add(N_constraint::vector_in_face(30, {0, 0, 0}));
  // The same vector twice, and two vectors 1e-14 apart: dependent rows.
  const std::array<double, 3> v = {0.3, 0.5, -0.2}, w = {0.3 * (1 + 1e-14), 0.5, -0.2};
  solver.add(N_constraint::vector_in_face(9, v));
  expect_error<TVF::Infeasible_constraints>([&] { solver.add(N_constraint::vector_in_face(9, v)); }, "depends on");
  expect_error<TVF::Infeasible_constraints>([&] { solver.add(N_constraint::vector_in_face(9, w)); }, "depends on");
  EXPECT_EQ(solver.number_of_constraints(), 2);
  const Eigen::VectorXd z = solver.field();
  ASSERT_TRUE(z.allFinite());
  EXPECT_LT(z.segment<2>(60).norm(), 1e-12);
  const Eigen::VectorXd want = ops->from_vectors([&] {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(160);
    const auto a = ops->mesh().to_frame(9, v);
    u[18] = a[0];
    u[19] = a[1];
    return u;
  }());
  EXPECT_LT((z.segment<2>(18) - want.segment<2>(18)).norm(), 1e-9 * want.segment<2>(18).norm());
}

TEST(BadNFields, BadSplineOptionsAreRefused)
{
  Mesh mesh = make_icosphere(1);
  const auto ops = n_ops(mesh, 2);
  TVF::Spline_options options;
  expect_error<TVF::Invalid_input>([&] { TVF::Full_n_field_spline_solver s(ops, options, 0); }, "m must be at least 1");
  options.omega = -1;
  expect_error<TVF::Invalid_input>([&] { TVF::Full_n_field_spline_solver s(ops, options); }, "omega");
  options.omega = 0;
  TVF::N_field_alignment alignment;
  alignment.guide = random_field(80, 1);
  alignment.weight = -2;
  expect_error<TVF::Invalid_input>([&] { TVF::Full_n_field_spline_solver s(ops, options, 2, alignment); },
                                   "alignment weight");
  const auto basis = std::make_shared<const TVF::N_field_basis>(ops, 8);
  expect_error<TVF::Invalid_input>([&] { TVF::Reduced_n_field_spline_solver s(basis, 5); }, "even");
  expect_error<TVF::Invalid_input>([&] { TVF::Reduced_n_field_spline_solver s(basis, 10); }, "basis size 10");
  expect_error<TVF::Invalid_input>([&] { TVF::Reduced_n_field_spline_solver s(basis, -2); }, "-2");
  // The generic spline: a basis too large for the mesh, a basis of another mesh.
  expect_error<TVF::Invalid_input>(
      [&] { TVF::N_field_spline<Mesh> s(mesh, 2, TVF::parameters::number_of_eigenfields(161)); }, "dimension 160");
  const Mesh other = make_icosphere(2);
  expect_error<TVF::Invalid_input>([&] { TVF::N_field_spline<Mesh> s(other, basis); }, "another number of faces");
  expect_error<TVF::Invalid_input>([&] { TVF::N_field_spline<Mesh> s(other, nullptr); }, "no basis");
}

TEST(BadNFields, CurvatureDirectionsOfDegenerateMeshesAreFiniteAndZeroWhereUndefined)
{
  // One triangle (no jet can be fitted), a flat disk (no curvature), a sphere with a tiny
  // companion: finite everywhere, zero where the direction is not defined.
  Mesh triangle = single_triangle(), flat = make_disk(4), pair = sphere_with_tiny_companion(1e-6);
  for(Mesh* mesh : {&triangle, &flat, &pair})
  {
    Field out = mesh->add_property_map<Face_index, Vector_3>("f:curvature", Vector_3(7, 7, 7)).first;
    const TVF::Curvature_direction_report report = TVF::curvature_direction_field(*mesh, out);
    EXPECT_EQ(report.fitted_vertices + report.unfitted_vertices, static_cast<int>(mesh->number_of_vertices()));
    for(Face_index f : mesh->faces())
    {
      ASSERT_TRUE(std::isfinite(out[f].x()) && std::isfinite(out[f].y()) && std::isfinite(out[f].z()));
      if(mesh != &pair) EXPECT_LT(out[f].squared_length(), 1e-20);
    }
  }
  EXPECT_EQ(TVF::curvature_direction_field(triangle, triangle.property_map<Face_index, Vector_3>("f:curvature").first)
                .fitted_vertices,
            0);
}
