// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Field design (SPEC 7), continued: soft-constrained design (Fisher et al.) against the
// hard spline, and the generic interface (property maps, named parameters, constraint files).

#include "expect_reason.h"
#include "design_test_support.h"

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
using namespace design_test;

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

// The full soft design goes through pull-backs and a small system; here its answer is
// checked against the normal equations formed from S, B and the rows directly:
// (S + omega B) x + sum_i w_i r_i^T (r_i x - c_i) = 0.  Then edits in any order against a
// fresh design.
TEST(SoftDesign, FullDesignMeetsTheNormalEquationsAndEditsEqualAFreshOne)
{
  for(int shape = 0; shape < 2; ++shape)
  {
    const Mesh mesh = shape == 0 ? make_torus(14, 8) : make_disk(7, 0.3); // genus 1; an annulus
    Design_setup s = setup(mesh, 10);
    const auto constraints = mixed_constraints(s.ops->mesh(), 5, 11);
    for(double omega : {0.0, 0.05})
    {
      TVF::Soft_design_options options;
      options.omega = omega;
      TVF::Full_soft_design design(s.hodge, options);
      std::vector<int> ids;
      std::vector<double> weights;
      for(std::size_t i = 0; i < constraints.size(); ++i)
      {
        weights.push_back(i % 3 == 0 ? 40.0 : 2.0);
        ids.push_back(design.add(constraints[i], weights.back()));
      }
      const Eigen::VectorXd x = design.field();
      ASSERT_TRUE(x.allFinite());
      const double area = s.ops->face_areas().sum();
      const Eigen::SparseMatrix<double> Q = s.ops->S() + (omega * area) * s.ops->B();
      Eigen::VectorXd gradient = Q * x, pull = Eigen::VectorXd::Zero(x.size());
      for(std::size_t i = 0; i < constraints.size(); ++i)
        for(const TVF::Constraint_row& r : TVF::constraint_rows(*s.ops, constraints[i]))
        {
          const double w = weights[i] * r.unit_area_scale * r.unit_area_scale;
          double rx = 0;
          for(const auto& e : r.entries) rx += e.second * x[e.first];
          for(const auto& e : r.entries)
          {
            gradient[e.first] += w * e.second * (rx - r.value);
            pull[e.first] += w * e.second * r.value;
          }
        }
      // Relative to the size of the right-hand side; B's condition (~nf^2) limits the products.
      EXPECT_LT(gradient.norm(), 1e-9 * pull.norm()) << "shape " << shape << " omega " << omega;
      EXPECT_NEAR(design.energy(), x.dot(Q * x), 1e-9 * std::abs(design.energy()));
      EXPECT_LT(design.residual(), 1e-10);

      // Edits: a removal, a value change, a new weight (a replacement), an addition.
      design.remove(ids[3]);
      auto changed = constraints[5];
      if(changed.kind == TVF::Constraint_kind::vector) changed.vector = {{-changed.vector[0], -changed.vector[1], -changed.vector[2]}};
      else changed.value = -2 * changed.value - 1;
      design.change(ids[5], changed, weights[5]);
      design.change(ids[0], constraints[0], 7.0);
      const auto extra = TVF::Field_constraint::divergence_at_vertex(3, 0.5);
      design.add(extra, 1.0);
      TVF::Full_soft_design fresh(s.hodge, options);
      for(std::size_t i = 0; i < constraints.size(); ++i)
        if(i != 3) fresh.add(i == 5 ? changed : constraints[i], i == 0 ? 7.0 : weights[i]);
      fresh.add(extra, 1.0);
      EXPECT_LT(relative_mx_error(*s.ops, design.field(), fresh.field()), 1e-10) << "shape " << shape;
    }
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
  EXPECT_THROW_REASON(TVF::read_constraint_file("/nonexistent/constraints.json", operators.matrices()), TVF::Invalid_input,
                      "cannot open constraint file /nonexistent/constraints.json");
}
