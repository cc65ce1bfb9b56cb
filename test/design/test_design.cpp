// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Field design (SPEC 7): tangent vector field splines, reduced and full, and their
// constraints: constraints met, energies nested in the basis size, reduced against
// full, sources and vortices, harmonic parts, edits, scale invariance, and the
// refusals of constraint sets that cannot be met.

#include "test_meshes.h"

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>
#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Full_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Reduced_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Soft_field_design.h>
#include <CGAL/Tangent_vector_fields/Vector_field_spline.h>
#include <CGAL/Tangent_vector_fields/constraint_file_io.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <gtest/gtest.h>

#include <random>
#include <sstream>

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;

namespace {

struct Design_setup
{
  std::shared_ptr<const TVF::Operator_matrices> ops;
  std::shared_ptr<TVF::Hodge_solver> hodge;
  std::shared_ptr<TVF::Eigenfield_basis> basis;
  int nf = 0;
};

// Operators, Hodge solver and a basis of `basis_size` eigenfields (0: all 2nf).
Design_setup setup(const Mesh& mesh, int basis_size)
{
  Design_setup s;
  TVF::Discrete_operators<Mesh> operators(mesh);
  s.ops = operators.shared_matrices();
  s.nf = s.ops->mesh().number_of_faces();
  s.hodge = std::make_shared<TVF::Hodge_solver>(s.ops);
  const int d = basis_size == 0 ? 2 * s.nf : basis_size;
  s.basis = std::make_shared<TVF::Eigenfield_basis>(s.hodge, TVF::Basis_request::lowest(d));
  return s;
}

// A tangent vector of face f: a fixed combination of its frame.
std::array<double, 3> tangent(const TVF::Intrinsic_mesh& m, int f, double a, double b)
{
  const auto& e1 = m.frame_e1(f);
  const auto& e2 = m.frame_e2(f);
  return {{a * e1[0] + b * e2[0], a * e1[1] + b * e2[1], a * e1[2] + b * e2[2]}};
}

// A mixed constraint set: vectors in spread-out faces, a direction, a divergence at
// a vertex and at a point, a curl at an edge and at a point.
std::vector<TVF::Field_constraint> mixed_constraints(const TVF::Intrinsic_mesh& m, int vectors, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<TVF::Field_constraint> c;
  const int nf = m.number_of_faces();
  for(int i = 0; i < vectors; ++i)
    c.push_back(TVF::Field_constraint::vector_in_face((i * 7919 + 13) % nf, tangent(m, (i * 7919 + 13) % nf, u(rng), u(rng))));
  c.push_back(TVF::Field_constraint::direction_in_face((nf / 2 + 3) % nf, tangent(m, (nf / 2 + 3) % nf, 1, 2)));
  c.push_back(TVF::Field_constraint::divergence_at_vertex(m.face_vertices(nf / 3)[0], 0.7));
  c.push_back(TVF::Field_constraint::divergence_at_point(nf / 5, {{0.2, 0.3, 0.5}}, -0.4));
  int interior = m.interior_edges()[m.number_of_interior_edges() / 2];
  c.push_back(TVF::Field_constraint::curl_at_edge(interior, 0.9));
  c.push_back(TVF::Field_constraint::curl_at_point((2 * nf) / 3, {{0.6, 0.1, 0.3}}, -0.5));
  return c;
}

// How far x is from each constraint, measured through the operators (not the solvers'
// constraint rows): the face's vector, its cross product with a direction, the divergence
// at vertices and the curl at edges (interpolated at points: barycentric weights for the
// divergence, Crouzeix-Raviart weights 1 - 2 b_k for the curl at the edge opposite corner k).
// Relative to the largest value asked for (1 for directions).
double constraint_residual(const TVF::Operator_matrices& ops, const std::vector<TVF::Field_constraint>& constraints,
                           const Eigen::VectorXd& x)
{
  const TVF::Intrinsic_mesh& m = ops.mesh();
  const Eigen::VectorXd divergence = ops.divergence(x), curl = ops.nonconforming_curl(x);
  double worst = 0, largest = 1e-300;
  for(const auto& c : constraints)
  {
    switch(c.kind)
    {
    case TVF::Constraint_kind::vector:
    {
      const auto a = m.to_frame(c.face, c.vector);
      worst = std::max({worst, std::abs(x[2 * c.face] - a[0]), std::abs(x[2 * c.face + 1] - a[1])});
      largest = std::max({largest, std::abs(a[0]), std::abs(a[1])});
      break;
    }
    case TVF::Constraint_kind::direction:
    {
      const auto a = m.to_frame(c.face, c.vector);
      const double cross = (x[2 * c.face] * a[1] - x[2 * c.face + 1] * a[0]) / std::hypot(a[0], a[1]);
      worst = std::max(worst, std::abs(cross));
      largest = std::max(largest, 1.);
      break;
    }
    case TVF::Constraint_kind::divergence:
    case TVF::Constraint_kind::curl:
    {
      const bool div = c.kind == TVF::Constraint_kind::divergence;
      double measured = 0;
      if(c.vertex >= 0) measured = divergence[c.vertex];
      else if(c.edge >= 0) measured = curl[c.edge];
      else
        for(int k = 0; k < 3; ++k)
          measured += div ? c.barycentric[k] * divergence[m.face_vertices(c.face)[k]]
                          : (1 - 2 * c.barycentric[k]) * curl[m.face_edges(c.face)[k]];
      worst = std::max(worst, std::abs(measured - c.value));
      largest = std::max(largest, std::abs(c.value));
      break;
    }
    }
  }
  return worst / largest;
}

double relative_mx_error(const TVF::Operator_matrices& ops, const Eigen::VectorXd& x, const Eigen::VectorXd& reference)
{
  const Eigen::VectorXd& m = ops.field_masses();
  const Eigen::VectorXd d = x - reference;
  return std::sqrt(d.dot(m.cwiseProduct(d)) / reference.dot(m.cwiseProduct(reference)));
}

} // namespace

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
  const std::vector<TVF::Field_constraint> bad = {
      TVF::Field_constraint::vector_in_face(-1, {{1, 0, 0}}),
      TVF::Field_constraint::vector_in_face(m.number_of_faces(), {{1, 0, 0}}),
      TVF::Field_constraint::vector_in_face(0, {{nan, 0, 0}}),
      TVF::Field_constraint::vector_in_face(0, m.normal(0)),           // normal to the face
      TVF::Field_constraint::direction_in_face(0, {{0, 0, 0}}),        // no direction
      TVF::Field_constraint::divergence_at_vertex(m.number_of_vertices(), 1),
      TVF::Field_constraint::divergence_at_point(0, {{0.5, 0.6, 0.1}}, 1), // sum 1.2
      TVF::Field_constraint::curl_at_point(0, {{-0.5, 1.0, 0.5}}, 1),      // negative
      TVF::Field_constraint::curl_at_edge(m.number_of_edges(), 1),
      TVF::Field_constraint::curl_at_edge(0, std::numeric_limits<double>::infinity())};
  for(const auto& c : bad) EXPECT_THROW(full.add(c), TVF::Invalid_input) << c.describe();
  EXPECT_EQ(full.number_of_constraints(), 0);
  // Boundary alignment: only on boundary edges; the field is then parallel to the edge.
  EXPECT_THROW(TVF::Field_constraint::boundary_alignment(m, m.interior_edges()[0]), TVF::Invalid_input);
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

TEST(SoftDesign, ApproachesTheHardSplineAsTheWeightGrows)
{
  // min E_D + w_s E_B + w |C~x - c|^2 tends to the spline of E_B + (1/w_s) E_D as
  // w grows (same minimiser up to the factor w_s); the gap shrinks like 1/w.
  const Mesh mesh = make_torus(16, 10);
  Design_setup s = setup(mesh, 200);
  const auto constraints = mixed_constraints(s.ops->mesh(), 5, 21);
  TVF::Spline_options spline_options;
  spline_options.omega = 10;
  TVF::Full_spline_solver hard(s.hodge, spline_options);
  hard.add(constraints);
  TVF::Reduced_spline_solver hard_reduced(s.basis, 0, spline_options);
  hard_reduced.add(constraints);
  TVF::Soft_design_options options;
  options.omega = 0.1;
  std::vector<double> errors, reduced_errors;
  for(double weight : {1e2, 1e4, 1e6})
  {
    TVF::Full_soft_design soft(s.hodge, options);
    TVF::Reduced_soft_design soft_reduced(s.basis, 0, options);
    for(const auto& c : constraints)
    {
      soft.add(c, weight);
      soft_reduced.add(c, weight);
    }
    errors.push_back(relative_mx_error(*s.ops, soft.field(), hard.field()));
    reduced_errors.push_back(relative_mx_error(*s.ops, soft_reduced.field(), hard_reduced.field()));
    EXPECT_LT(soft.residual(), 1e-10);
  }
  for(std::size_t i = 1; i < errors.size(); ++i)
  {
    EXPECT_LT(errors[i], errors[i - 1] / 30) << i;
    EXPECT_LT(reduced_errors[i], reduced_errors[i - 1] / 30) << i;
  }
  EXPECT_LT(errors.back(), 1e-4);
  EXPECT_LT(reduced_errors.back(), 1e-4);
}

TEST(SoftDesign, ReducedEqualsFullOnTheWholeBasisAndEditsEqualAFreshSolve)
{
  for(int genus : {0, 1})
  {
    const Mesh mesh = genus == 0 ? make_icosphere(2) : make_torus(14, 8);
    Design_setup s = setup(mesh, 0);
    const auto constraints = mixed_constraints(s.ops->mesh(), 5, 4);
    TVF::Soft_design_options options;
    options.omega = 0.05;
    TVF::Full_soft_design full(s.hodge, options);
    TVF::Reduced_soft_design reduced(s.basis, 0, options);
    std::vector<int> ids;
    for(const auto& c : constraints)
    {
      full.add(c, 3.0);
      ids.push_back(reduced.add(c, 3.0));
    }
    EXPECT_LT(relative_mx_error(*s.ops, reduced.field(), full.field()), 1e-8) << "genus " << genus;
    EXPECT_NEAR(reduced.energy() / full.energy(), 1, 1e-8);
    // Rank-one downdates and updates against a fresh factorisation.
    reduced.remove(ids[2]);
    auto changed = constraints[7];
    changed.value = -3;
    reduced.change(ids[7], changed, 3.0);
    reduced.change(ids[0], constraints[0], 10.0); // a new weight: a replacement
    TVF::Reduced_soft_design fresh(s.basis, 0, options);
    for(std::size_t i = 0; i < constraints.size(); ++i)
      if(i != 2) fresh.add(i == 7 ? changed : constraints[i], i == 0 ? 10.0 : 3.0);
    EXPECT_LT(relative_mx_error(*s.ops, reduced.field(), fresh.field()), 1e-10);
  }
}

TEST(SoftDesign, UndeterminedHarmonicPartAndScaleInvariance)
{
  const Mesh base = make_torus(16, 10);
  Design_setup s0 = setup(base, 100);
  const TVF::Intrinsic_mesh& m = s0.ops->mesh();
  {
    TVF::Full_soft_design full(s0.hodge);
    TVF::Reduced_soft_design reduced(s0.basis);
    for(TVF::Soft_field_design* design : {static_cast<TVF::Soft_field_design*>(&full), static_cast<TVF::Soft_field_design*>(&reduced)})
    {
      design->add(TVF::Field_constraint::divergence_at_vertex(5, 1.0));
      design->add(TVF::Field_constraint::curl_at_edge(m.interior_edges()[40], -1.0));
      EXPECT_TRUE(design->field().allFinite());
      EXPECT_GT(design->field().norm(), 0);
      EXPECT_EQ(design->undetermined_harmonic(), 2);
    }
    // The undetermined harmonic part is zero: both fields are MX-orthogonal to the harmonic fields.
    const Eigen::MatrixXd& H = s0.hodge->harmonic_basis();
    const Eigen::VectorXd& masses = s0.ops->field_masses();
    for(const Eigen::VectorXd& x : {full.field(), reduced.field()})
      EXPECT_LT((H.transpose() * masses.asDiagonal() * x).norm(), 1e-9 * std::sqrt(x.dot(masses.cwiseProduct(x))));
  }
  const auto constraints0 = mixed_constraints(m, 5, 8);
  TVF::Soft_design_options options;
  options.omega = 0.2;
  TVF::Full_soft_design f0(s0.hodge, options);
  TVF::Reduced_soft_design r0(s0.basis, 0, options);
  for(const auto& c : constraints0)
  {
    f0.add(c, 5);
    r0.add(c, 5);
  }
  for(double scale : {1e-8, 1e8})
  {
    Mesh mesh = base;
    transform(mesh, scale, rotation_matrix(Vector_3(0, 1, 1), 1.1));
    Design_setup s = setup(mesh, 100);
    TVF::Full_soft_design f(s.hodge, options);
    TVF::Reduced_soft_design r(s.basis, 0, options);
    for(auto c : constraints0)
    {
      if(c.kind == TVF::Constraint_kind::vector || c.kind == TVF::Constraint_kind::direction)
      {
        const std::array<double, 2> a = m.to_frame(c.face, c.vector);
        c.vector = s.ops->mesh().from_frame(c.face, a[0], a[1]);
      }
      else
        c.value /= scale;
      f.add(c, 5);
      r.add(c, 5);
    }
    EXPECT_LT(relative_mx_error(*s0.ops, f.field(), f0.field()), 1e-7) << scale;
    EXPECT_LT(relative_mx_error(*s0.ops, r.field(), r0.field()), 1e-7) << scale;
  }
}

TEST(DesignInterface, GenericSplineOnPropertyMapsAndOneShotFunction)
{
  // Constraints by mesh elements and 3D vectors; the field comes back as 3D vectors
  // that meet them; reduced on a Spectral_basis and full on the mesh.
  Mesh mesh = make_torus(16, 10);
  const Face_index f0(7), f1(100);
  const Vector_3 v0(0.3, -0.2, 0.5);
  TVF::Spectral_basis<Mesh> basis(mesh, TVF::parameters::number_of_eigenfields(120));
  TVF::Vector_field_spline<Mesh> reduced(basis, TVF::parameters::spline_tension(2.0));
  TVF::Vector_field_spline<Mesh> full(mesh, TVF::parameters::spline_tension(2.0));
  const Point_3 p = mesh.point(mesh.target(mesh.halfedge(f1)));
  for(TVF::Vector_field_spline<Mesh>* s : {&reduced, &full})
  {
    const TVF::Constraint_id id = s->add_vector(f0, v0);
    s->add_divergence(Vertex_index(30), 0.5);
    s->add_curl(f1, p, -0.25);
    auto out = mesh.add_property_map<Face_index, Vector_3>("f:spline", Vector_3(0, 0, 0)).first;
    s->field(out);
    // The projection of v0 onto face f0.
    const TVF::Intrinsic_mesh& m = s->solver().operators().mesh();
    const auto a = m.to_frame(0 + 7, {{v0.x(), v0.y(), v0.z()}});
    const auto w = m.from_frame(7, a[0], a[1]);
    EXPECT_NEAR(out[f0].x(), w[0], 1e-9);
    EXPECT_NEAR(out[f0].y(), w[1], 1e-9);
    EXPECT_NEAR(out[f0].z(), w[2], 1e-9);
    s->set_vector(id, Vector_3(0, 0, 0)); // a zero vector: the field vanishes there
    s->field(out);
    EXPECT_LT(std::sqrt(out[f0].squared_length()), 1e-9);
    EXPECT_LT(s->report().constraint_residual, 1e-9);
    mesh.remove_property_map(out);
  }
  // One-shot: the same as the full editor.
  const std::vector<TVF::Field_constraint> constraints = {
      TVF::Field_constraint::vector_in_face(7, {{0.3, -0.2, 0.5}}), TVF::Field_constraint::divergence_at_vertex(30, 0.5)};
  auto one_shot = mesh.add_property_map<Face_index, Vector_3>("f:one_shot", Vector_3(0, 0, 0)).first;
  const TVF::Spline_report report = TVF::vector_field_spline(mesh, constraints, one_shot);
  EXPECT_EQ(report.constraints, 2);
  TVF::Full_spline_solver check(std::make_shared<TVF::Hodge_solver>(TVF::Discrete_operators<Mesh>(mesh).shared_matrices()));
  check.add(constraints);
  const Eigen::VectorXd x = check.field();
  const TVF::Intrinsic_mesh& m = check.operators().mesh();
  double worst = 0;
  for(Face_index f : mesh.faces())
  {
    const auto w = m.from_frame(int(f), x[2 * int(f)], x[2 * int(f) + 1]);
    worst = std::max(worst, std::abs(one_shot[f].x() - w[0]) + std::abs(one_shot[f].y() - w[1]) + std::abs(one_shot[f].z() - w[2]));
  }
  EXPECT_LT(worst, 1e-12);
}

TEST(DesignInterface, ConstraintFileRoundTripAndErrors)
{
  const Mesh mesh = make_disk(8);
  TVF::Discrete_operators<Mesh> operators(mesh);
  const TVF::Intrinsic_mesh& m = operators.intrinsic_mesh();
  int boundary_edge = -1;
  for(int e = 0; e < m.number_of_edges() && boundary_edge < 0; ++e)
    if(m.is_boundary_edge(e)) boundary_edge = e;
  const auto& fv = m.face_vertices(4);
  std::ostringstream json;
  json << "{\"omega\": 2.5, \"constraints\": ["
       << "{\"type\": \"vector\", \"face\": 3, \"vector\": [1, 0.5, 0]},"
       << "{\"type\": \"direction\", \"face\": 9, \"direction\": [0, 1, 0], \"weight\": 4},"
       << "{\"type\": \"divergence\", \"vertex\": 5, \"value\": 1.5},"
       << "{\"type\": \"divergence\", \"face\": 4, \"vertices\": [" << fv[2] << ", " << fv[0] << ", " << fv[1]
       << "], \"barycentric\": [0.5, 0.3, 0.2], \"value\": -1},"
       << "{\"type\": \"curl\", \"edge\": 11, \"value\": 0.25},"
       << "{\"type\": \"curl\", \"face\": 6, \"point\": [0, 0, 0], \"value\": 2},"
       << "{\"type\": \"boundary_alignment\", \"edge\": " << boundary_edge << "}]}";
  std::istringstream in(json.str());
  const TVF::Constraint_file file = TVF::read_constraint_file(in, operators.matrices());
  ASSERT_EQ(file.constraints.size(), 7u);
  EXPECT_EQ(file.omega, 2.5);
  EXPECT_EQ(file.weights[1], 4);
  EXPECT_EQ(file.constraints[2].vertex, 5);
  // Barycentric coordinates follow the listed vertices into the face's order.
  EXPECT_DOUBLE_EQ(file.constraints[3].barycentric[2], 0.5);
  EXPECT_DOUBLE_EQ(file.constraints[3].barycentric[0], 0.3);
  EXPECT_EQ(file.constraints[6].kind, TVF::Constraint_kind::direction);
  // Written and read back: the same constraints (to the last bit).
  std::stringstream again;
  TVF::write_constraint_file(again, file, m);
  const TVF::Constraint_file back = TVF::read_constraint_file(again, operators.matrices());
  ASSERT_EQ(back.constraints.size(), file.constraints.size());
  for(std::size_t i = 0; i < back.constraints.size(); ++i)
  {
    EXPECT_EQ(back.constraints[i].describe(), file.constraints[i].describe());
    EXPECT_EQ(back.constraints[i].barycentric, file.constraints[i].barycentric);
    EXPECT_EQ(back.constraints[i].vector, file.constraints[i].vector);
    EXPECT_EQ(back.weights[i], file.weights[i]);
  }
  // Bad files: one clear reason each.
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"{\"constraints\": [ {\"type\": \"vector\", \"face\": 3, ", "line"},
      {"{\"constraints\": [{\"type\": \"swirl\", \"face\": 3}]}", "unknown type"},
      {"{\"constraints\": [{\"type\": \"vector\", \"face\": 100000, \"vector\": [1, 0, 0]}]}", "out of range"},
      {"{\"constraints\": [{\"type\": \"vector\", \"face\": 2}]}", "missing \"vector\""},
      {"{\"constraints\": [{\"type\": \"vector\", \"face\": 2, \"vector\": [1, 0]}]}", "3 numbers"},
      {"{\"constraints\": [{\"type\": \"divergence\", \"vertex\": 2, \"value\": \"x\"}]}", "\"value\" must be a number"},
      {"{\"constraints\": [{\"type\": \"divergence\", \"vertex\": 2, \"value\": 1e999}]}", "number overflow"},
      {"{\"constraints\": [{\"type\": \"vector\", \"face\": 2, \"vector\": [1, 0, 0], \"weigth\": 2}]}",
       "unknown key \"weigth\" for a vector constraint"},
      {"{\"constraints\": [{\"type\": \"vector\", \"face\": 2, \"face\": 3, \"vector\": [1, 0, 0]}]}",
       "the key \"face\" appears twice"},
      {"{\"constraints\": [{\"type\": \"divergence\", \"vertex\": 2, \"face\": 3, \"value\": 1}]}", "not both"},
      {"{\"omega\": 0}", "missing \"constraints\""},
      {"{\"constraints\": {}}", "\"constraints\" must be an array"},
      {"{\"constraints\": [{\"type\": \"curl\", \"face\": 2, \"value\": 1}]}", "point"},
      {"{\"omega\": -1, \"constraints\": []}", "omega"},
      {"{\"items\": []}", "unknown key \"items\""}};
  for(const auto& b : bad)
  {
    std::istringstream s(b.first);
    try
    {
      TVF::read_constraint_file(s, operators.matrices());
      ADD_FAILURE() << "accepted: " << b.first;
    }
    catch(const TVF::Invalid_input& e)
    {
      EXPECT_NE(std::string(e.what()).find(b.second), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(TVF::read_constraint_file("/nonexistent/constraints.json", operators.matrices()), TVF::Invalid_input);
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
