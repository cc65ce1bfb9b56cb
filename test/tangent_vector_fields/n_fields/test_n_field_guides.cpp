// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// n-field design guided beyond hard constraints: constraints at points of faces (the
// interpolation against fields linear in the plane), soft alignment to a guide field
// (stationarity from the operators alone, reduced against full, scale invariance, a guide
// that is already the spline), and the principal-curvature guide against analytic surfaces.

#include "n_field_test_support.h"

#include <CGAL/Tangent_vector_fields/N_field_basis.h>
#include <CGAL/Tangent_vector_fields/N_field_singularities.h>
#include <CGAL/Tangent_vector_fields/N_field_spline.h>
#include <CGAL/Tangent_vector_fields/N_field_spline_solver.h>
#include <CGAL/Tangent_vector_fields/curvature_direction_field.h>
#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/smoothest_n_field.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <complex>
#include <random>

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;
using namespace nfield_test;

namespace {

// [0, 1]^2 in k x k squares, every square split by the same diagonal: neighbouring
// triangles are point reflections of each other through their common edge's midpoint.
Mesh make_regular_grid(int k)
{
  std::vector<Point_3> points;
  for(int j = 0; j <= k; ++j)
    for(int i = 0; i <= k; ++i) points.emplace_back(double(i) / k, double(j) / k, 0);
  std::vector<std::array<int, 3>> triangles;
  for(int j = 0; j < k; ++j)
    for(int i = 0; i < k; ++i)
    {
      const int p00 = j * (k + 1) + i, p10 = p00 + 1, p01 = p00 + k + 1, p11 = p01 + 1;
      triangles.push_back({p00, p10, p11});
      triangles.push_back({p00, p11, p01});
    }
  return make_mesh(points, triangles);
}

// An open cylinder of radius r about the z axis, z in [-1, 1]: m vertices around, k rows of triangles.
Mesh make_cylinder(int m, int k, double r)
{
  std::vector<Point_3> points;
  for(int j = 0; j <= k; ++j)
    for(int i = 0; i < m; ++i)
    {
      const double t = 2 * M_PI * (i + 0.5 * (j % 2)) / m; // staggered rows: no preferred diagonal
      points.emplace_back(r * std::cos(t), r * std::sin(t), -1 + 2. * j / k);
    }
  std::vector<std::array<int, 3>> triangles;
  for(int j = 0; j < k; ++j)
    for(int i = 0; i < m; ++i)
    {
      const int a = j * m + i, b = j * m + (i + 1) % m, c = (j + 1) * m + i, d = (j + 1) * m + (i + 1) % m;
      triangles.push_back({a, b, d});
      triangles.push_back({a, d, c});
    }
  return make_mesh(points, triangles);
}

// A field given by its power in the plane's complex coordinate, in face f's frame.
std::complex<double> in_frame(const TVF::Intrinsic_mesh& mesh, int f, int n, std::complex<double> w)
{
  const auto& e1 = mesh.frame_e1(f);
  const double alpha = std::atan2(e1[1], e1[0]);
  const std::complex<double> z = w * std::polar(1., -n * alpha);
  return mesh.normal(f)[2] > 0 ? z : std::conj(z); // a frame seen from below is mirrored
}

// The value of a constraint's two rows on z (the field at the constraint's point).
std::complex<double> value_at(const TVF::N_field_operators& ops, const TVF::N_field_constraint& c, const Eigen::VectorXd& z)
{
  const auto rows = TVF::constraint_rows(ops, c);
  return {rows[0].dot(z), rows[1].dot(z)};
}

// A smooth guide: the projection of one ambient vector onto every face.
Eigen::VectorXd ambient_guide(const TVF::N_field_operators& ops, const std::array<double, 3>& a)
{
  const TVF::Intrinsic_mesh& mesh = ops.mesh();
  Eigen::VectorXd v(2 * mesh.number_of_faces());
  for(int f = 0; f < mesh.number_of_faces(); ++f)
  {
    const auto ab = mesh.to_frame(f, a);
    v[2 * f] = ab[0];
    v[2 * f + 1] = ab[1];
  }
  return ops.from_vectors(v);
}

// The gradient of E_B + omega E_D + s |z - g|^2_MX (halved), from S_n and MX alone.
Eigen::VectorXd aligned_gradient(const TVF::N_field_operators& ops, const Eigen::VectorXd& z, double omega, double s,
                                 const Eigen::VectorXd& guide)
{
  return ops.S() * ops.laplacian(z) + omega * (ops.S() * z) + s * ops.masses().cwiseProduct(z - guide);
}

} // namespace

TEST(NFieldPointConstraint, InterpolationIsExactForFieldsLinearInThePlane)
{
  const Mesh grid = make_regular_grid(8);
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u(0, 1);
  const std::complex<double> a(0.3, -0.2), b(1.1, 0.4), c(-0.5, 0.9); // w(x, y) = a + b x + c y
  for(int n : {1, 3})
  {
    const auto ops = n_field_operators(grid, n);
    const TVF::Intrinsic_mesh& mesh = ops->mesh();
    auto w = [&](const Eigen::Vector3d& p) { return a + b * p[0] + c * p[1]; };
    auto position = [&](int v) { return to_eigen(mesh.position(v)); };
    Eigen::VectorXd z(2 * mesh.number_of_faces());
    for(int f = 0; f < mesh.number_of_faces(); ++f)
    {
      const auto& v = mesh.face_vertices(f);
      const std::complex<double> zf = in_frame(mesh, f, n, w((position(v[0]) + position(v[1]) + position(v[2])) / 3));
      z[2 * f] = zf.real();
      z[2 * f + 1] = zf.imag();
    }
    int tested = 0;
    for(int f = 0; f < mesh.number_of_faces(); ++f)
    {
      const auto& e = mesh.face_edges(f);
      if(mesh.is_boundary_edge(e[0]) || mesh.is_boundary_edge(e[1]) || mesh.is_boundary_edge(e[2])) continue;
      double b0 = u(gen), b1 = u(gen) * (1 - b0);
      const std::array<double, 3> bary = {b0, b1, 1 - b0 - b1};
      const auto& v = mesh.face_vertices(f);
      const Eigen::Vector3d p = bary[0] * position(v[0]) + bary[1] * position(v[1]) + bary[2] * position(v[2]);
      const auto c_point = TVF::N_field_constraint::vector_at_point(f, bary, {1, 0, 0});
      EXPECT_LT(std::abs(value_at(*ops, c_point, z) - in_frame(mesh, f, n, w(p))), 1e-12) << "n = " << n << ", face " << f;
      // At the centroid: the face's own value, with the face constraint's rows.
      const auto centre = TVF::N_field_constraint::vector_at_point(f, {1. / 3, 1. / 3, 1. / 3}, {1, 0, 0});
      const auto face_rows = TVF::constraint_rows(*ops, TVF::N_field_constraint::vector_in_face(f, {1, 0, 0}));
      const auto centre_rows = TVF::constraint_rows(*ops, centre);
      ASSERT_EQ(centre_rows.size(), 2u);
      EXPECT_EQ(centre_rows[0].entries, face_rows[0].entries);
      EXPECT_EQ(centre_rows[1].entries, face_rows[1].entries);
      ++tested;
    }
    EXPECT_GT(tested, 60);
  }
}

TEST(NFieldPointConstraint, SplinesMeetThemAndValueEditsKeepTheRows)
{
  Mesh torus = make_torus(20, 12);
  jitter_vertices(torus, 0.05, 5);
  const auto ops = n_field_operators(torus, 4);
  const TVF::Intrinsic_mesh& mesh = ops->mesh();
  std::vector<TVF::N_field_constraint> constraints;
  const std::array<std::array<double, 3>, 4> points = {{{1, 0, 0}, {0.1, 0.1, 0.8}, {0.5, 0.5, 0}, {0.2, 0.3, 0.5}}};
  for(int i = 0; i < 4; ++i)
  {
    const int f = 37 * i + 11;
    constraints.push_back(TVF::N_field_constraint::vector_at_point(f, points[i], mesh.from_frame(f, std::cos(i), std::sin(i))));
  }
  constraints.push_back(TVF::N_field_constraint::direction_at_point(200, {0.6, 0.2, 0.2}, mesh.from_frame(200, 1, 1)));
  TVF::Full_n_field_spline_solver full(ops);
  const auto ids = full.add(constraints);
  const auto basis = std::make_shared<const TVF::N_field_basis>(ops, 120);
  TVF::Reduced_n_field_spline_solver reduced(basis, 120);
  reduced.add(constraints);
  for(const Eigen::VectorXd& z : {full.field(), reduced.field()})
    for(const auto& c : constraints)
    {
      const auto rows = TVF::constraint_rows(*ops, c);
      for(const auto& r : rows) EXPECT_NEAR(r.dot(z), r.value, 1e-9) << c.describe();
    }
  // A vertex corner is not the face: the field there differs from the face's value.
  const Eigen::VectorXd z = full.field();
  const int f0 = constraints[0].face;
  EXPECT_GT(std::abs(std::complex<double>(z[2 * f0], z[2 * f0 + 1]) - value_at(*ops, constraints[0], z)), 1e-3);
  // A new vector at the same point is a value edit.
  TVF::N_field_constraint moved = constraints[0];
  moved.vector = mesh.from_frame(f0, 0.2, -0.9);
  EXPECT_TRUE(constraints[0].same_rows_as(moved));
  full.change(ids[0], moved);
  for(const auto& r : TVF::constraint_rows(*ops, moved)) EXPECT_NEAR(r.dot(full.field()), r.value, 1e-9);
  TVF::N_field_constraint elsewhere = moved;
  elsewhere.barycentric = {0.2, 0.2, 0.6};
  EXPECT_FALSE(moved.same_rows_as(elsewhere));

  for(const std::array<double, 3> bad : {std::array<double, 3>{0.5, 0.6, -0.1}, {0.5, 0.6, 0.1}, {NAN, 0.5, 0.5}})
  {
    try
    {
      full.add(TVF::N_field_constraint::vector_at_point(3, bad, {1, 0, 0}));
      ADD_FAILURE() << "accepted barycentric " << bad[0] << " " << bad[1] << " " << bad[2];
    }
    catch(const TVF::Invalid_input& e)
    {
      EXPECT_NE(std::string(e.what()).find("barycentric coordinates must be non-negative and sum to 1"), std::string::npos)
          << e.what();
    }
  }
}

TEST(NFieldAlignment, AlignedSplineIsStationaryAndTheReducedOneConvergesToIt)
{
  Mesh torus = make_torus(24, 16);
  jitter_vertices(torus, 0.05, 29);
  const auto ops = n_field_operators(torus, 4);
  const double area = ops->face_areas().sum();
  const auto constraints = random_vector_constraints(ops->mesh(), 5, 31);
  TVF::N_field_alignment alignment;
  alignment.guide = ambient_guide(*ops, {1, 0.3, 0.2});
  alignment.weight = 2000; // comparable to lambda^2 of the lowest modes on the unit-area torus
  TVF::Spline_options options;
  options.omega = 30;
  TVF::Full_n_field_spline_solver full(ops, options, 2, alignment);
  EXPECT_EQ(full.harmonic_dimension(), 0); // nothing has zero energy: the kernel is no longer special
  full.add(constraints);
  const Eigen::VectorXd exact = full.field();
  for(const auto& c : constraints) EXPECT_LT(closest_vector_distance(*ops, exact, c.face, c.vector), 1e-9);
  // Stationarity from S_n and MX: the gradient vanishes on every unconstrained face.
  const Eigen::VectorXd gradient =
      aligned_gradient(*ops, exact, options.omega / area, alignment.weight / (area * area), alignment.guide);
  std::vector<char> constrained(ops->mesh().number_of_faces(), 0);
  for(const auto& c : constraints) constrained[c.face] = 1;
  double free_part = 0;
  for(int f = 0; f < ops->mesh().number_of_faces(); ++f)
    if(!constrained[f]) free_part = std::max(free_part, gradient.segment<2>(2 * f).norm());
  EXPECT_LT(free_part, 1e-8 * gradient.cwiseAbs().maxCoeff());
  // A penalty's distance never grows with its weight; a huge weight leaves the guide only
  // where the constraints are.
  TVF::Full_n_field_spline_solver free_spline(ops, options);
  free_spline.add(constraints);
  double distance = relative_difference(free_spline.field(), alignment.guide, ops->masses());
  Eigen::VectorXd limit = alignment.guide; // the guide, with the constrained faces' values
  for(const auto& c : constraints)
  {
    const auto rows = TVF::constraint_rows(*ops, c);
    limit.segment<2>(2 * c.face) = Eigen::Vector2d(rows[0].value, rows[1].value);
  }
  std::vector<double> to_limit;
  for(double weight : {200., 2000., 2e4, 2e6, 2e8, 2e10, 2e12})
  {
    TVF::N_field_alignment a = alignment;
    a.weight = weight;
    TVF::Full_n_field_spline_solver s(ops, options, 2, a);
    s.add(constraints);
    const Eigen::VectorXd z = s.field();
    const double d = relative_difference(z, alignment.guide, ops->masses());
    EXPECT_LT(d, distance) << "weight " << weight;
    distance = d;
    to_limit.push_back(relative_difference(z, limit, ops->masses()));
  }
  // First order in 1 / weight once the weight dominates (measured: 4.4e-3, then 4.6e-5).
  EXPECT_LT(to_limit.back(), 1e-4);
  EXPECT_GT(to_limit[to_limit.size() - 2] / to_limit.back(), 50);

  const auto basis = std::make_shared<const TVF::N_field_basis>(ops, 300);
  double previous = std::numeric_limits<double>::infinity();
  for(int d : {30, 100, 300})
  {
    TVF::Reduced_n_field_spline_solver reduced(basis, d, options, 2, alignment);
    reduced.add(constraints);
    const Eigen::VectorXd z = reduced.field();
    for(const auto& c : constraints) EXPECT_LT(closest_vector_distance(*ops, z, c.face, c.vector), 1e-9) << "d = " << d;
    const double error = relative_difference(z, exact, ops->masses());
    EXPECT_LT(error, previous) << "d = " << d;
    // The reduced energy (alignment included) is never below the exact minimum.
    EXPECT_GE(reduced.report().energy, full.report().energy * (1 - 1e-9)) << "d = " << d;
    previous = error;
  }
  EXPECT_LT(previous, 0.1);
}

TEST(NFieldAlignment, AGuideThatIsTheSplineChangesNothingAndScaleDoesNotMatter)
{
  Mesh reference = make_torus(16, 10);
  jitter_vertices(reference, 0.05, 37);
  const auto ops0 = n_field_operators(reference, 2);
  const auto constraints = random_vector_constraints(ops0->mesh(), 4, 41);
  TVF::Full_n_field_spline_solver plain(ops0);
  plain.add(constraints);
  TVF::N_field_alignment alignment;
  alignment.guide = plain.field();
  alignment.weight = 500;
  TVF::Full_n_field_spline_solver aligned(ops0, TVF::Spline_options(), 2, alignment);
  aligned.add(constraints);
  EXPECT_LT(relative_difference(aligned.field(), plain.field(), ops0->masses()), 1e-9);

  // Scaled and moved: the same field from the same weight (it is given for unit area).
  alignment.guide = ambient_guide(*ops0, {0.2, 1, -0.4});
  TVF::Full_n_field_spline_solver at_scale_1(ops0, TVF::Spline_options(), 2, alignment);
  at_scale_1.add(constraints);
  const auto R = rotation_matrix(Vector_3(0.3, 1, -1), 0.7);
  for(double s : {1e-6, 1e6})
  {
    Mesh mesh = reference;
    transform(mesh, s, R, Vector_3(s, -3 * s, 2 * s));
    const auto ops = n_field_operators(mesh, 2);
    std::vector<TVF::N_field_constraint> moved = constraints;
    for(auto& c : moved)
    {
      const auto v = c.vector;
      for(int i = 0; i < 3; ++i) c.vector[i] = R[3 * i] * v[0] + R[3 * i + 1] * v[1] + R[3 * i + 2] * v[2];
    }
    TVF::N_field_alignment moved_alignment = alignment;
    moved_alignment.guide = ambient_guide(*ops, {R[0] * 0.2 + R[1] - 0.4 * R[2], R[3] * 0.2 + R[4] - 0.4 * R[5],
                                                 R[6] * 0.2 + R[7] - 0.4 * R[8]});
    TVF::Full_n_field_spline_solver full(ops, TVF::Spline_options(), 2, moved_alignment);
    full.add(moved);
    EXPECT_LT((full.field() - at_scale_1.field()).norm(), 1e-7 * at_scale_1.field().norm()) << "scale " << s;
  }
}

TEST(NFieldAlignment, RefusedWithTheirReasonAndTheGenericInterface)
{
  Mesh sphere = make_icosphere(2);
  const auto ops = n_field_operators(sphere, 4);
  auto reason = [&](const TVF::N_field_alignment& a) {
    try
    {
      TVF::Full_n_field_spline_solver s(ops, TVF::Spline_options(), 2, a);
    }
    catch(const TVF::Invalid_input& e)
    {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  TVF::N_field_alignment a;
  a.weight = -1;
  EXPECT_NE(reason(a).find("alignment weight must be finite and non-negative"), std::string::npos) << reason(a);
  a.weight = 1;
  a.guide = Eigen::VectorXd::Ones(7);
  EXPECT_NE(reason(a).find("the alignment guide has 7 coordinates"), std::string::npos) << reason(a);
  a.guide = Eigen::VectorXd::Ones(2 * sphere.number_of_faces());
  a.guide[3] = NAN;
  EXPECT_NE(reason(a).find("the alignment guide is not finite"), std::string::npos) << reason(a);

  // Generic: a face map of 3D vectors as the guide gives the index solver's field.
  auto guide_map = sphere.add_property_map<Face_index, Vector_3>("f:guide", Vector_3(0, 0, 0)).first;
  const Eigen::VectorXd guide_power = ambient_guide(*ops, {0, 0.4, 1});
  const Eigen::VectorXd first = ops->to_vectors(guide_power);
  for(Face_index f : sphere.faces())
  {
    const auto v = ops->mesh().from_frame(int(f), first[2 * f], first[2 * f + 1]);
    guide_map[f] = Vector_3(v[0], v[1], v[2]);
  }
  TVF::N_field_spline<Mesh> spline(sphere, 4, TVF::parameters::alignment_field_map(guide_map).alignment_weight(300.));
  spline.add_vector(Face_index(10), Vector_3(1, 0, 0));
  auto out = sphere.add_property_map<Face_index, Vector_3>("f:out", Vector_3(0, 0, 0)).first;
  spline.field(out);
  TVF::N_field_alignment b;
  b.guide = guide_power;
  b.weight = 300;
  TVF::Full_n_field_spline_solver solver(ops, TVF::Spline_options(), 2, b);
  solver.add(spline.solver().constraint(0));
  const Eigen::VectorXd expected = ops->to_vectors(solver.field());
  for(Face_index f : sphere.faces())
  {
    const auto v = ops->mesh().from_frame(int(f), expected[2 * f], expected[2 * f + 1]);
    EXPECT_LT((out[f] - Vector_3(v[0], v[1], v[2])).squared_length(), 1e-20);
  }
}

TEST(CurvatureDirections, CircumferentialOnACylinderNothingOnASphereAndScaleFree)
{
  const Mesh cylinder = make_cylinder(48, 40, 0.5);
  const auto ops = n_field_operators(cylinder, 2);
  const TVF::Intrinsic_mesh& mesh = ops->mesh();
  TVF::Curvature_direction_report report;
  const Eigen::VectorXd x = TVF::curvature_directions(mesh, &report);
  EXPECT_EQ(report.unfitted_vertices, 0);
  EXPECT_NEAR(report.curvature_scale, 2., 0.05); // |k1| + |k2| = 1 / r
  int tested = 0;
  for(int f = 0; f < mesh.number_of_faces(); ++f)
  {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for(int v : mesh.face_vertices(f)) c += to_eigen(mesh.position(v)) / 3;
    if(std::abs(c[2]) > 0.8) continue; // jets at the rims are one-sided
    const Eigen::Vector3d line = to_eigen(mesh.from_frame(f, x[2 * f], x[2 * f + 1]));
    // The circumferential direction at the centroid, in the face's plane.
    const Eigen::Vector3d normal = to_eigen(mesh.normal(f));
    Eigen::Vector3d around(-c[1], c[0], 0);
    around = (around - around.dot(normal) * normal).normalized();
    EXPECT_NEAR(line.norm(), 1., 0.05) << "face " << f;
    EXPECT_GT(std::abs(line.normalized().dot(around)), std::cos(2 * M_PI / 180)) << "face " << f;
    ++tested;
  }
  EXPECT_GT(tested, 1000);

  // Scaled and moved: the same lines (up to sign), the same lengths.
  Mesh moved = cylinder;
  const auto R = rotation_matrix(Vector_3(1, 2, 3), 0.4);
  transform(moved, 1e-5, R, Vector_3(3e-5, 0, 1e-5));
  const Eigen::VectorXd y = TVF::curvature_directions(n_field_operators(moved, 2)->mesh());
  const Eigen::VectorXd x2 = ops->from_vectors(x), y2 = ops->from_vectors(y); // powers: signs drop out
  EXPECT_LT((x2 - y2).norm(), 1e-6 * x2.norm());

  // A sphere is umbilic everywhere: lengths at the level of the discretisation, against 1 above.
  const auto sphere_ops = n_field_operators(make_icosphere(4), 2);
  const Eigen::VectorXd s = TVF::curvature_directions(sphere_ops->mesh());
  EXPECT_LT(s.cwiseAbs().maxCoeff(), 0.02);
  // A plane: no curvature, no direction.
  const Eigen::VectorXd p = TVF::curvature_directions(n_field_operators(make_regular_grid(6), 2)->mesh());
  EXPECT_EQ(p.cwiseAbs().maxCoeff(), 0.);
}

TEST(CurvatureDirections, AGuideForCrossFieldsOnATorus)
{
  // On a torus of revolution the principal directions are the parameter lines; a cross field
  // aligned to them (smoothest, with the guide) follows them.
  Mesh torus = make_torus(64, 32, 1.0, 0.4, 0.0);
  auto guide = torus.add_property_map<Face_index, Vector_3>("f:guide", Vector_3(0, 0, 0)).first;
  const TVF::Curvature_direction_report report = TVF::curvature_direction_field(torus, guide);
  EXPECT_EQ(report.unfitted_vertices, 0);
  auto cross = torus.add_property_map<Face_index, Vector_3>("f:cross", Vector_3(0, 0, 0)).first;
  TVF::smoothest_n_field(torus, 4, cross, TVF::parameters::alignment_field_map(guide).alignment_weight(10.));
  double worst = 0;
  for(Face_index f : torus.faces())
  {
    Vector_3 c(0, 0, 0);
    for(auto v : CGAL::vertices_around_face(torus.halfedge(f), torus)) c = c + (torus.point(v) - CGAL::ORIGIN) / 3;
    const Vector_3 around = Vector_3(-c.y(), c.x(), 0) / std::sqrt(c.x() * c.x() + c.y() * c.y());
    const Vector_3 u = cross[f] / std::sqrt(cross[f].squared_length());
    // The angle of u to the nearest arm of the parameter cross: |sin 2 theta| / 2 ... use the 4-fold angle.
    const double cos_t = std::max(-1., std::min(1., u * around));
    const double t = std::acos(std::abs(cos_t));   // in [0, pi/2]
    worst = std::max(worst, std::min(t, M_PI / 2 - t));
  }
  EXPECT_LT(worst, 3 * M_PI / 180);
}

TEST(NFieldSpline, FieldAfterValueEditsEqualsAFreshSolve)
{
  // A drag in the editor (field_after_value_edit): the n-field is affine in the values of a
  // vector constraint and of an anchored singularity's anchor, so cached responses give the
  // field of a fresh solve; checked through value edits of one constraint, then of another,
  // and after a removal, reduced and full (1e-10, 1e-9: the responses are exact).
  Mesh torus = make_torus(20, 12);
  const auto ops = n_field_operators(torus, 4);
  const TVF::Intrinsic_mesh& mesh = ops->mesh();
  const auto basis = std::make_shared<const TVF::N_field_basis>(ops, 80);
  std::vector<TVF::N_field_constraint> constraints = random_vector_constraints(mesh, 3, 71);
  const int vertex = mesh.number_of_vertices() / 3, anchor = ops->vertex_fan(vertex).faces[0];
  constraints.push_back(TVF::N_field_constraint::singularity_at_vertex(vertex, 1, anchor, mesh.from_frame(anchor, 1, 0)));
  TVF::Reduced_n_field_spline_solver reduced(basis, 60);
  TVF::Full_n_field_spline_solver full(ops);
  const auto ids = reduced.add(constraints), full_ids = full.add(constraints);
  std::vector<bool> present(constraints.size(), true);
  const Eigen::VectorXd& mass = ops->masses();
  auto check = [&](int i, const std::string& step) {
    std::vector<TVF::N_field_constraint> current;
    for(std::size_t j = 0; j < constraints.size(); ++j)
      if(present[j]) current.push_back(constraints[j]);
    TVF::Reduced_n_field_spline_solver fresh(basis, 60);
    TVF::Full_n_field_spline_solver fresh_full(ops);
    fresh.add(current);
    fresh_full.add(current);
    EXPECT_LT(relative_difference(reduced.field_after_value_edit(ids[i]), fresh.field(), mass), 1e-10) << step;
    EXPECT_LT(relative_difference(full.field_after_value_edit(full_ids[i]), fresh_full.field(), mass), 1e-9) << step;
  };
  auto edit = [&](int i, const TVF::N_field_constraint& c) {
    constraints[i] = c;
    reduced.change(ids[i], c);
    full.change(full_ids[i], c);
  };
  for(double t : {0.5, 2.0, -1.0})
  {
    TVF::N_field_constraint c = constraints[0];
    c.vector = mesh.from_frame(c.face, t, 1 - t);
    edit(0, c);
    check(0, "vector edited to t = " + std::to_string(t));
  }
  TVF::N_field_constraint singularity = constraints[3];
  singularity.vector = mesh.from_frame(anchor, 0.2, 0.7);
  edit(3, singularity);
  check(3, "the singularity's anchor vector edited");
  check(0, "back to the vector after another constraint's edit");
  EXPECT_EQ(TVF::n_field_indices(*ops, reduced.field_after_value_edit(ids[3]))[vertex], 1);
  reduced.remove(ids[1]);
  full.remove(full_ids[1]);
  present[1] = false;
  check(0, "after a removal");
}
