// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Field design (SPEC 7): tangent vector field splines, reduced and full, and their
// constraints: constraints met, energies nested in the basis size, reduced against
// full, sources and vortices, harmonic parts, edits, scale invariance, and the
// refusals of constraint sets that cannot be met.

#include "expect_reason.h"
#include "design_test_support.h"

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>
#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Full_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Reduced_face_vectors.h>
#include <CGAL/Tangent_vector_fields/Reduced_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Soft_field_design.h>
#include <CGAL/Tangent_vector_fields/Vector_field_spline.h>
#include <CGAL/Tangent_vector_fields/constraint_file_io.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <Eigen/QR>
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <sstream>

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;
using namespace design_test;

TEST(Spline, ConstraintsMetReducedAndFullOnSphereAndTorus)
{
  // Genus 0 (no harmonic fields) and genus 1 (two): every row met to 1e-9 (relative
  // to the largest value) by both solvers; the full solver's pull-backs reach the
  // CG tolerance.
  for(int genus : {0, 1})
  {
    const Mesh mesh = genus == 0 ? make_icosphere(2) : make_torus(16, 10);
    Design_setup s = setup(mesh, 200);
    const auto constraints = mixed_constraints(s.ops->mesh(), 6, 3);
    TVF::Spline_options options;
    options.omega = 10;
    TVF::Reduced_spline_solver reduced(s.basis, 0, options);
    reduced.add(constraints);
    TVF::Full_spline_solver full(s.hodge, options);
    full.add(constraints);
    EXPECT_LT(constraint_residual(*s.ops, constraints, reduced.field()), 1e-9) << "genus " << genus;
    EXPECT_LT(constraint_residual(*s.ops, constraints, full.field()), 1e-9) << "genus " << genus;
    EXPECT_LT(reduced.report().constraint_residual, 1e-9);
    EXPECT_LT(full.report().constraint_residual, 1e-9);
    EXPECT_LT(full.statistics().residual, 1e-10);
    EXPECT_EQ(reduced.harmonic_dimension(), 2 * genus);
    EXPECT_EQ(full.harmonic_dimension(), 2 * genus);
    EXPECT_EQ(full.report().undetermined_harmonic, 0);
    EXPECT_TRUE(full.report().warnings.empty()) << full.report().warnings.front();
  }
}

// The reduced field face by face (the editor's preview) against the whole field U a of the basis
// (the truth): every face, in double within rounding, in float32 within float32 rounding, on a
// torus (harmonic, exact and coexact elements) with a basis size that cuts a type short.
TEST(Spline, ReducedFaceVectorsAreTheWholeReducedField)
{
  const Mesh mesh = make_torus(16, 10);
  Design_setup s = setup(mesh, 120);
  TVF::Reduced_spline_solver reduced(s.basis, 75);
  reduced.add(mixed_constraints(s.ops->mesh(), 6, 3));
  const Eigen::VectorXd a = reduced.coefficients(), x = reduced.field();
  const double largest = x.cwiseAbs().maxCoeff();
  ASSERT_GT(largest, 0);
  for(const auto precision : {TVF::Eigenfunction_precision::float64, TVF::Eigenfunction_precision::float32})
  {
    const auto rows = std::make_shared<const TVF::Eigenfield_rows>(s.basis, 75, precision);
    EXPECT_EQ(rows->number_of_faces(), s.nf);
    TVF::Reduced_face_vectors field(rows);
    field.set_coefficients(a);
    const double tolerance = precision == TVF::Eigenfunction_precision::float64 ? 1e-12 : 1e-6;
    double worst = 0;
    for(int f = 0; f < s.nf; ++f)
    {
      const std::array<double, 2> v = field.face_vector(f);
      worst = std::max({worst, std::abs(v[0] - x[2 * f]), std::abs(v[1] - x[2 * f + 1])});
    }
    EXPECT_LE(worst, tolerance * largest) << (precision == TVF::Eigenfunction_precision::float64 ? "f64" : "f32");
    EXPECT_EQ(field.faces_asked(), static_cast<std::size_t>(s.nf));
    // Fewer coefficients: the first elements only, as Eigenfield_basis::field.
    field.set_coefficients(a.head(10));
    const Eigen::VectorXd x10 = s.basis->field(a.head(10));
    EXPECT_NEAR(field.face_vector(5)[1], x10[11], tolerance * x10.cwiseAbs().maxCoeff() + 1e-300);
    EXPECT_EQ(field.faces_asked(), 1u);
    EXPECT_THROW(field.set_coefficients(Eigen::VectorXd::Ones(76)), TVF::Invalid_input);
  }
}

TEST(Spline, ReducedEnergyDecreasesWithBasisSizeToTheFullEnergy)
{
  // Nested subspaces: the reduced minimum cannot increase with d; with the whole
  // basis (2nf fields) it is the full minimum, and the fields agree.
  for(int genus : {0, 1})
  {
    const Mesh mesh = genus == 0 ? make_icosphere(2) : make_torus(14, 8);
    Design_setup s = setup(mesh, 0);
    const auto constraints = mixed_constraints(s.ops->mesh(), 5, 11);
    TVF::Spline_options options;
    options.omega = 3;
    TVF::Full_spline_solver full(s.hodge, options);
    full.add(constraints);
    const double full_energy = full.report().energy;
    double previous = std::numeric_limits<double>::infinity();
    double previous_error = std::numeric_limits<double>::infinity();
    for(int d : {40, 80, 160, 320, 2 * s.nf})
    {
      TVF::Reduced_spline_solver reduced(s.basis, d, options);
      reduced.add(constraints);
      const double energy = reduced.report().energy;
      const double error = relative_mx_error(*s.ops, reduced.field(), full.field());
      EXPECT_LE(energy, previous * (1 + 1e-10)) << "d = " << d;
      EXPECT_GE(energy, full_energy * (1 - 1e-9)) << "d = " << d;
      EXPECT_LE(error, previous_error * 1.05) << "d = " << d; // a projection error: decreases in practice
      previous = energy;
      previous_error = error;
    }
    EXPECT_NEAR(previous / full_energy, 1, 1e-8);
    EXPECT_LT(previous_error, 1e-7);
  }
}

TEST(Spline, PositiveDivergenceIsASourceAndPositiveCurlACounterClockwiseVortex)
{
  // On the sphere, one divergence (curl) constraint at the centroid of a face gives a
  // field pointing away from it (turning counter-clockwise about the outward normal)
  // in every face of the ring around that face; the same for a divergence at a vertex.
  const Mesh mesh = make_icosphere(3);
  Design_setup s = setup(mesh, 100);
  const TVF::Intrinsic_mesh& m = s.ops->mesh();
  auto centroid = [&](int f) {
    std::array<double, 3> c{{0, 0, 0}};
    for(int k = 0; k < 3; ++k)
      for(int i = 0; i < 3; ++i) c[i] += m.position(m.face_vertices(f)[k])[i] / 3;
    return c;
  };
  const int center_face = 17;
  const int center_vertex = m.face_vertices(center_face)[1];
  for(int kind = 0; kind < 3; ++kind)
  {
    const bool curl = kind == 1;
    const TVF::Field_constraint c =
        kind == 0 ? TVF::Field_constraint::divergence_at_point(center_face, {{1. / 3, 1. / 3, 1. / 3}}, 1.0)
        : kind == 1 ? TVF::Field_constraint::curl_at_point(center_face, {{1. / 3, 1. / 3, 1. / 3}}, 1.0)
                    : TVF::Field_constraint::divergence_at_vertex(center_vertex, 1.0);
    const std::array<double, 3> center = kind == 2 ? m.position(center_vertex) : centroid(center_face);
    TVF::Reduced_spline_solver reduced(s.basis, 0);
    TVF::Full_spline_solver full(s.hodge);
    reduced.add(c);
    full.add(c);
    for(const Eigen::VectorXd& x : {reduced.field(), full.field()})
    {
      int faces = 0;
      for(int f = 0; f < m.number_of_faces(); ++f)
      {
        if(f == center_face && kind != 2) continue;
        bool ring = false;
        for(int a : m.face_vertices(f))
          ring = ring || (kind == 2 ? a == center_vertex
                                    : (a == m.face_vertices(center_face)[0] || a == m.face_vertices(center_face)[1] ||
                                       a == m.face_vertices(center_face)[2]));
        if(!ring) continue;
        ++faces;
        const std::array<double, 3> p = centroid(f);
        const std::array<double, 2> r = m.to_frame(f, {{p[0] - center[0], p[1] - center[1], p[2] - center[2]}});
        // Frame coordinates of the radial direction; the counter-clockwise direction is J r.
        const double a = curl ? -r[1] : r[0], b = curl ? r[0] : r[1];
        EXPECT_GT(a * x[2 * f] + b * x[2 * f + 1], 0) << c.describe() << ", face " << f;
      }
      EXPECT_GE(faces, 5);
    }
  }
}

TEST(Spline, HarmonicPartFromConstraintsOrZeroWhenUndetermined)
{
  // Torus: divergence and curl constraints see no harmonic field, so the harmonic
  // part stays undetermined (2 directions, set to zero: the field is then orthogonal
  // to the harmonic fields); vector constraints determine it.
  const Mesh mesh = make_torus(16, 10);
  Design_setup s = setup(mesh, 150);
  const TVF::Intrinsic_mesh& m = s.ops->mesh();
  const Eigen::MatrixXd& H = s.hodge->harmonic_basis();
  const Eigen::VectorXd& masses = s.ops->field_masses();
  {
    TVF::Full_spline_solver full(s.hodge);
    TVF::Reduced_spline_solver reduced(s.basis);
    const std::vector<TVF::Field_constraint> c = {TVF::Field_constraint::divergence_at_vertex(5, 1.0),
                                                  TVF::Field_constraint::curl_at_edge(m.interior_edges()[40], 1.0)};
    full.add(c);
    reduced.add(c);
    EXPECT_EQ(full.report().undetermined_harmonic, 2);
    EXPECT_EQ(reduced.report().undetermined_harmonic, 2);
    EXPECT_FALSE(full.report().warnings.empty());
    const Eigen::VectorXd x = full.field();
    EXPECT_LT((H.transpose() * masses.asDiagonal() * x).norm(), 1e-9 * std::sqrt(x.dot(masses.cwiseProduct(x))));
    EXPECT_LT(constraint_residual(*s.ops, c, x), 1e-9);
  }
  {
    // Two vector constraints: their 4 rows determine both harmonic directions; the
    // harmonic part of the spline is then non-zero.
    TVF::Full_spline_solver full(s.hodge);
    full.add(TVF::Field_constraint::vector_in_face(3, tangent(m, 3, 1, 0)));
    full.add(TVF::Field_constraint::vector_in_face(100, tangent(m, 100, 0, 1)));
    EXPECT_EQ(full.report().undetermined_harmonic, 0);
    const Eigen::VectorXd x = full.field();
    EXPECT_GT((H.transpose() * masses.asDiagonal() * x).norm(), 1e-3 * std::sqrt(x.dot(masses.cwiseProduct(x))));
  }
}

TEST(Spline, EditsEqualAFreshSolve)
{
  // Value edits (one back-substitution), removals (re-triangularised factor) and
  // re-additions give the same spline as a solver built from scratch.
  const Mesh mesh = make_torus(16, 10);
  Design_setup s = setup(mesh, 150);
  const TVF::Intrinsic_mesh& m = s.ops->mesh();
  auto constraints = mixed_constraints(m, 6, 5);
  TVF::Reduced_spline_solver edited(s.basis);
  TVF::Full_spline_solver edited_full(s.hodge);
  std::vector<TVF::Constraint_id> ids = edited.add(constraints);
  std::vector<TVF::Constraint_id> full_ids = edited_full.add(constraints);
  edited.field();
  // Change values of a vector and a divergence; move a curl point (not a value edit).
  constraints[1].vector = tangent(m, constraints[1].face, -0.3, 0.8);
  constraints[7].value = 2.5;
  constraints[10].barycentric = {{0.2, 0.2, 0.6}};
  for(int i : {1, 7, 10})
  {
    edited.change(ids[i], constraints[i]);
    edited_full.change(full_ids[i], constraints[i]);
  }
  // Remove one in the middle.
  edited.remove(ids[3]);
  edited_full.remove(full_ids[3]);
  std::vector<TVF::Field_constraint> remaining;
  for(std::size_t i = 0; i < constraints.size(); ++i)
    if(i != 3) remaining.push_back(constraints[i]);
  TVF::Reduced_spline_solver fresh(s.basis);
  fresh.add(remaining);
  TVF::Full_spline_solver fresh_full(s.hodge);
  fresh_full.add(remaining);
  EXPECT_LT(relative_mx_error(*s.ops, edited.field(), fresh.field()), 1e-10);
  EXPECT_LT(relative_mx_error(*s.ops, edited_full.field(), fresh_full.field()), 1e-9);
  EXPECT_EQ(edited.number_of_constraints(), static_cast<int>(remaining.size()));
  // Tension changes rebuild everything; then equal to a solver made with that tension.
  edited.set_omega(20);
  TVF::Spline_options options;
  options.omega = 20;
  TVF::Reduced_spline_solver fresh20(s.basis, 0, options);
  fresh20.add(remaining);
  EXPECT_LT(relative_mx_error(*s.ops, edited.field(), fresh20.field()), 1e-10);
  EXPECT_GT(relative_mx_error(*s.ops, fresh.field(), fresh20.field()), 1e-4); // the tension matters
}

TEST(Spline, FieldAfterValueEditsEqualsAFreshSolve)
{
  // The fast path of a drag (field_after_value_edit: cached responses, no solve and no
  // reconstruction) against solvers built from scratch with the edited constraints, through
  // a sequence that must invalidate the cache: value edits of one constraint, then of
  // another, a move (new rows), a removal and a new tension.  1e-10: the responses are exact
  // (the spline is affine in the values); rounding of a few products remains.
  const Mesh mesh = make_torus(16, 10);
  Design_setup s = setup(mesh, 150);
  const TVF::Intrinsic_mesh& m = s.ops->mesh();
  auto constraints = mixed_constraints(m, 5, 11);
  TVF::Reduced_spline_solver reduced(s.basis);
  TVF::Full_spline_solver full(s.hodge);
  const std::vector<TVF::Constraint_id> ids = reduced.add(constraints), full_ids = full.add(constraints);
  std::vector<bool> present(constraints.size(), true);
  double omega = 0;
  auto check = [&](int i, const std::string& step) {
    std::vector<TVF::Field_constraint> current;
    for(std::size_t j = 0; j < constraints.size(); ++j)
      if(present[j]) current.push_back(constraints[j]);
    TVF::Spline_options options;
    options.omega = omega;
    TVF::Reduced_spline_solver fresh(s.basis, 0, options);
    TVF::Full_spline_solver fresh_full(s.hodge, options);
    fresh.add(current);
    fresh_full.add(current);
    EXPECT_LT(relative_mx_error(*s.ops, reduced.field_after_value_edit(ids[i]), fresh.field()), 1e-10) << step;
    EXPECT_LT(relative_mx_error(*s.ops, full.field_after_value_edit(full_ids[i]), fresh_full.field()), 1e-9) << step;
  };
  auto edit = [&](int i, const TVF::Field_constraint& c) {
    constraints[i] = c;
    reduced.change(ids[i], c);
    full.change(full_ids[i], c);
  };
  check(0, "no edit yet");
  for(double t : {0.3, -1.7, 4.0}) // a vector dragged
  {
    TVF::Field_constraint c = constraints[0];
    c.vector = tangent(m, c.face, t, 1 - t);
    edit(0, c);
    check(0, "vector 0 edited to t = " + std::to_string(t));
  }
  TVF::Field_constraint divergence = constraints[6];
  ASSERT_EQ(divergence.kind, TVF::Constraint_kind::divergence);
  divergence.value = -3;
  edit(6, divergence); // another constraint's value: the cache of constraint 0 is stale
  check(0, "after a value edit of the divergence");
  check(6, "the divergence's own edits");
  divergence.value = 5;
  edit(6, divergence);
  check(6, "the divergence edited again");
  TVF::Field_constraint moved = constraints[1];
  moved.face = (moved.face + 17) % m.number_of_faces();
  moved.vector = tangent(m, moved.face, 1, 1);
  edit(1, moved); // new rows
  check(0, "after a move");
  reduced.remove(ids[2]);
  full.remove(full_ids[2]);
  present[2] = false;
  check(0, "after a removal");
  omega = 30;
  reduced.set_omega(omega);
  full.set_omega(omega);
  check(0, "after a new tension");
  // Unknown ids are refused by name.
  try
  {
    reduced.field_after_value_edit(ids[2]);
    ADD_FAILURE() << "a removed constraint's id was accepted";
  }
  catch(const TVF::Invalid_input& e)
  {
    EXPECT_NE(std::string(e.what()).find("no constraint with id"), std::string::npos) << e.what();
  }
}

TEST(Spline, InvariantToScaleAndRigidMotion)
{
  // Vector constraints keep their values; divergence and curl scale as 1/length.
  // Reduced (with the basis of the scaled mesh) and full give the same field.
  const Mesh base = make_torus(14, 8);
  Design_setup s0 = setup(base, 120);
  const auto constraints0 = mixed_constraints(s0.ops->mesh(), 5, 9);
  TVF::Spline_options options;
  options.omega = 5;
  TVF::Reduced_spline_solver r0(s0.basis, 0, options);
  r0.add(constraints0);
  TVF::Full_spline_solver f0(s0.hodge, options);
  f0.add(constraints0);
  for(double scale : {1e-8, 1e8})
  {
    Mesh mesh = base;
    transform(mesh, scale, rotation_matrix(Vector_3(1, 2, 3), 0.7), Vector_3(5, -2, 1));
    Design_setup s = setup(mesh, 120);
    // Same constraints, vectors rotated with the mesh (the frame follows), div/curl / scale.
    auto constraints = constraints0;
    for(auto& c : constraints)
    {
      if(c.kind == TVF::Constraint_kind::vector || c.kind == TVF::Constraint_kind::direction)
      {
        const std::array<double, 2> a = s0.ops->mesh().to_frame(c.face, c.vector);
        c.vector = s.ops->mesh().from_frame(c.face, a[0], a[1]);
      }
      else
        c.value /= scale;
    }
    TVF::Reduced_spline_solver r(s.basis, 0, options);
    r.add(constraints);
    TVF::Full_spline_solver f(s.hodge, options);
    f.add(constraints);
    EXPECT_LT(relative_mx_error(*s0.ops, r.field(), r0.field()), 1e-7) << scale;
    EXPECT_LT(relative_mx_error(*s0.ops, f.field(), f0.field()), 1e-7) << scale;
  }
}

TEST(Spline, ConstraintSetsThatCannotBeMetAreRefused)
{
  const Mesh mesh = make_icosphere(2);
  Design_setup s = setup(mesh, 60);
  const TVF::Intrinsic_mesh& m = s.ops->mesh();
  auto expect_infeasible = [](TVF::Spline_solver& solver, const TVF::Field_constraint& c, double residual) {
    const int before = solver.number_of_constraints();
    try
    {
      solver.add(c);
      ADD_FAILURE() << "accepted: " << c.describe();
    }
    catch(const TVF::Infeasible_constraints& e)
    {
      EXPECT_LT(e.independence(), 1e-10);
      EXPECT_NEAR(e.residual(), residual, 1e-6 + 1e-6 * residual) << e.what();
    }
    EXPECT_EQ(solver.number_of_constraints(), before); // nothing added
    EXPECT_TRUE(solver.field().allFinite());
  };
  for(int full = 0; full < 2; ++full)
  {
    std::unique_ptr<TVF::Spline_solver> solver;
    if(full) solver = std::make_unique<TVF::Full_spline_solver>(s.hodge);
    else solver = std::make_unique<TVF::Reduced_spline_solver>(s.basis);
    // Two different vectors in one face: the second contradicts the first by |(0,1)-(1,0)| in its first row.
    solver->add(TVF::Field_constraint::vector_in_face(10, tangent(m, 10, 1, 0)));
    expect_infeasible(*solver, TVF::Field_constraint::vector_in_face(10, tangent(m, 10, 0, 1)), 1.0);
    // Contradictory divergence at one vertex, and a curl contradicting itself.
    solver->add(TVF::Field_constraint::divergence_at_vertex(40, 1.0));
    expect_infeasible(*solver, TVF::Field_constraint::divergence_at_vertex(40, 3.0), 2.0);
    solver->add(TVF::Field_constraint::curl_at_edge(100, -1.0));
    expect_infeasible(*solver, TVF::Field_constraint::curl_at_edge(100, 0.5), 1.5);
    // A direction in a face whose vector is fixed already (consistent: residual 0, still dependent).
    expect_infeasible(*solver, TVF::Field_constraint::direction_in_face(10, tangent(m, 10, 1, 0)), 0.0);
    EXPECT_LT(solver->report().constraint_residual, 1e-9);
  }
  // More independent constraints than the basis can satisfy: 60 fields, 31 vector constraints = 62 rows.
  TVF::Reduced_spline_solver small(s.basis);
  bool refused = false;
  for(int f = 0; f < 31 && !refused; ++f)
  {
    try
    {
      small.add(TVF::Field_constraint::vector_in_face(f * 10, tangent(m, f * 10, 1, 1)));
    }
    catch(const TVF::Infeasible_constraints& e)
    {
      refused = true;
      EXPECT_NE(std::string(e.what()).find("larger basis"), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(refused);
  EXPECT_TRUE(small.field().allFinite());
  EXPECT_LT(small.report().constraint_residual, 1e-8);
  // Nearly dependent: divergences at two points 1e-4 apart in one face (rows that
  // differ by ~1e-4, sin^2 ~ 1e-8): accepted with a warning, constraints still met.
  for(int full = 0; full < 2; ++full)
  {
    std::unique_ptr<TVF::Spline_solver> near;
    if(full) near = std::make_unique<TVF::Full_spline_solver>(s.hodge);
    else near = std::make_unique<TVF::Reduced_spline_solver>(s.basis);
    near->add(TVF::Field_constraint::divergence_at_point(5, {{0.3, 0.3, 0.4}}, 1.0));
    near->add(TVF::Field_constraint::divergence_at_point(5, {{0.3001, 0.3, 0.3999}}, 1.0));
    EXPECT_LT(near->report().smallest_independence, 1e-6);
    EXPECT_GT(near->report().smallest_independence, 1e-10);
    EXPECT_FALSE(near->report().warnings.empty());
    EXPECT_LT(near->report().constraint_residual, 1e-8);
    EXPECT_TRUE(near->field().allFinite());
    // Exactly the same point with another value: refused.
    expect_infeasible(*near, TVF::Field_constraint::divergence_at_point(5, {{0.3, 0.3, 0.4}}, 2.0), 1.0);
  }
}

TEST(Spline, MalformedConstraintsAreInvalidInput)
{
  const Mesh mesh = make_disk(6);
  Design_setup s = setup(mesh, 30);
  const TVF::Intrinsic_mesh& m = s.ops->mesh();
  TVF::Full_spline_solver full(s.hodge);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Each with the reason it must be refused for.
  const std::vector<std::pair<TVF::Field_constraint, std::string>> bad = {
      {TVF::Field_constraint::vector_in_face(-1, {{1, 0, 0}}), "face index -1 out of range"},
      {TVF::Field_constraint::vector_in_face(m.number_of_faces(), {{1, 0, 0}}),
       "face index " + std::to_string(m.number_of_faces()) + " out of range"},
      {TVF::Field_constraint::vector_in_face(0, {{nan, 0, 0}}), "non-finite number"},
      {TVF::Field_constraint::vector_in_face(0, m.normal(0)), "normal to its face"},
      {TVF::Field_constraint::direction_in_face(0, {{0, 0, 0}}), "needs a non-zero direction"},
      {TVF::Field_constraint::divergence_at_vertex(m.number_of_vertices(), 1),
       "vertex index " + std::to_string(m.number_of_vertices()) + " out of range"},
      {TVF::Field_constraint::divergence_at_point(0, {{0.5, 0.6, 0.1}}, 1), "barycentric coordinates must be non-negative and sum to 1"}, // sum 1.2
      {TVF::Field_constraint::curl_at_point(0, {{-0.5, 1.0, 0.5}}, 1), "barycentric coordinates must be non-negative"}, // negative
      {TVF::Field_constraint::curl_at_edge(m.number_of_edges(), 1),
       "edge index " + std::to_string(m.number_of_edges()) + " out of range"},
      {TVF::Field_constraint::curl_at_edge(0, std::numeric_limits<double>::infinity()), "non-finite number"}};
  for(const auto& [c, reason] : bad) EXPECT_THROW_REASON(full.add(c), TVF::Invalid_input, reason);
  EXPECT_EQ(full.number_of_constraints(), 0);
  // Boundary alignment: only on boundary edges; the field is then parallel to the edge.
  EXPECT_THROW_REASON(TVF::Field_constraint::boundary_alignment(m, m.interior_edges()[0]), TVF::Invalid_input,
                      "is not a boundary edge");
  int boundary_edge = -1;
  for(int e = 0; e < m.number_of_edges() && boundary_edge < 0; ++e)
    if(m.is_boundary_edge(e)) boundary_edge = e;
  full.add(TVF::Field_constraint::boundary_alignment(m, boundary_edge));
  full.add(TVF::Field_constraint::vector_in_face(m.number_of_faces() / 2, tangent(m, m.number_of_faces() / 2, 1, 0)));
  const Eigen::VectorXd x = full.field();
  const int f = m.edge_faces(boundary_edge)[0];
  const auto& p = m.position(m.edge_vertices(boundary_edge)[0]);
  const auto& q = m.position(m.edge_vertices(boundary_edge)[1]);
  const std::array<double, 2> t = m.to_frame(f, {{q[0] - p[0], q[1] - p[1], q[2] - p[2]}});
  EXPECT_LT(std::abs(t[0] * x[2 * f + 1] - t[1] * x[2 * f]), 1e-9 * std::hypot(t[0], t[1]) * std::hypot(x[2 * f], x[2 * f + 1]));
  EXPECT_GT(std::hypot(x[2 * f], x[2 * f + 1]), 1e-6);
}


TEST(Spline, HarmonicEigenvalueOptionPenalisesTheHarmonicPartInBothSolvers)
{
  // The thesis' choice: harmonic fields get a small eigenvalue.  Reduced on the complete
  // basis equals full; the harmonic part shrinks as the eigenvalue grows and tends to
  // the free solution as it goes to 0.
  const Mesh mesh = make_torus(14, 8);
  Design_setup s = setup(mesh, 0);
  const auto constraints = mixed_constraints(s.ops->mesh(), 5, 17);
  const Eigen::MatrixXd& H = s.hodge->harmonic_basis();
  const Eigen::VectorXd& masses = s.ops->field_masses();
  auto harmonic_norm = [&](const Eigen::VectorXd& x) { return (H.transpose() * masses.asDiagonal() * x).norm(); };
  TVF::Full_spline_solver free(s.hodge);
  free.add(constraints);
  double previous = harmonic_norm(free.field());
  for(double lambda : {1e-4, 1.0, 10.0})
  {
    TVF::Spline_options options;
    options.harmonic_eigenvalue = lambda;
    TVF::Full_spline_solver full(s.hodge, options);
    full.add(constraints);
    TVF::Reduced_spline_solver reduced(s.basis, 0, options);
    reduced.add(constraints);
    EXPECT_LT(relative_mx_error(*s.ops, reduced.field(), full.field()), 1e-7) << lambda;
    EXPECT_NEAR(reduced.report().energy / full.report().energy, 1, 1e-7);
    EXPECT_LT(full.report().constraint_residual, 1e-9);
    const double h = harmonic_norm(full.field());
    EXPECT_LE(h, previous * (1 + 1e-9)) << lambda;
    if(lambda == 1e-4) EXPECT_LT(relative_mx_error(*s.ops, full.field(), free.field()), 1e-3);
    previous = h;
  }
}

TEST(Spline, FullSplineOnALargeMeshIsTheConstrainedMinimum)
{
  // 20480 faces and 114 constraint rows: the pull-back's two chains run side by side and
  // the field is combined on two threads (the paths for large meshes).  Independent of the
  // Hodge route: the energy Q = B + (omega / area) S is assembled from the operators, and
  // the spline must be Q-orthogonal to every field z that leaves the constraint rows at 0
  // (the first-order condition of the minimum).  |x^T Q z| / sqrt(x^T Q x z^T Q z) is at
  // most the relative energy-norm error of x; wrong pull-backs (a column mixed up, a wrong
  // rotation) would still meet the constraints but give a cosine of order 1.
  const Mesh mesh = make_icosphere(5);
  TVF::Discrete_operators<Mesh> operators(mesh);
  const auto ops = operators.shared_matrices();
  const auto hodge = std::make_shared<TVF::Hodge_solver>(ops);
  const TVF::Intrinsic_mesh& m = ops->mesh();
  ASSERT_GE(m.number_of_faces(), 20000);
  const auto constraints = mixed_constraints(m, 54, 17);
  std::vector<TVF::Constraint_row> rows;
  for(const auto& c : constraints)
    for(const TVF::Constraint_row& r : TVF::constraint_rows(*ops, c)) rows.push_back(r);
  Eigen::MatrixXd Ct = Eigen::MatrixXd::Zero(2 * m.number_of_faces(), rows.size());
  for(std::size_t j = 0; j < rows.size(); ++j)
    for(const auto& e : rows[j].entries) Ct(e.first, j) += e.second;
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(Ct);
  const Eigen::MatrixXd Q_basis = qr.householderQ() * Eigen::MatrixXd::Identity(Ct.rows(), Ct.cols());
  for(double omega : {0.0, 10.0})
  {
    TVF::Spline_options options;
    options.omega = omega;
    TVF::Full_spline_solver full(hodge, options);
    full.add(constraints);
    const Eigen::VectorXd x = full.field();
    // A divergence at a point weighs face values by about 1/h (h ~ 0.02 here): its residual
    // reaches 5e-9 relative, where the vector rows are met to 1e-10.
    EXPECT_LT(constraint_residual(*ops, constraints, x), 1e-8) << "omega " << omega;
    const Eigen::SparseMatrix<double> Q = ops->B() + (omega / ops->face_areas().sum()) * ops->S();
    const Eigen::VectorXd Qx = Q * x;
    std::mt19937 rng(3);
    std::normal_distribution<double> normal;
    double worst = 0;
    for(int k = 0; k < 3; ++k)
    {
      Eigen::VectorXd z(x.size());
      for(Eigen::Index i = 0; i < z.size(); ++i) z[i] = normal(rng);
      z -= Q_basis * (Q_basis.transpose() * z); // the constraint rows vanish on z
      ASSERT_LT((Ct.transpose() * z).norm(), 1e-10 * z.norm());
      worst = std::max(worst, std::abs(Qx.dot(z)) / std::sqrt(x.dot(Qx) * z.dot(Q * z)));
    }
    EXPECT_LT(worst, 1e-9) << "omega " << omega; // measured 6e-12 and 2e-12
  }
}
