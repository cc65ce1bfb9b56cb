// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Extreme sizes and positions: meshes scaled by 1e-150 to 1e150 (and moved far from the
// origin) give, through every entry point (geometry, Hodge, basis, design, streamlines),
// the results of the unit-size mesh with their units (lengths s, areas s^2, eigenvalues
// 1/s^2, fields of given vectors unchanged); sizes beyond the double range are refused
// with the reason; constraint vectors near the largest double are accepted.

#include "test_meshes.h"

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>
#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Full_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Hodge_solver.h>
#include <CGAL/Tangent_vector_fields/N_field_constraint.h>
#include <CGAL/Tangent_vector_fields/N_field_operators.h>
#include <CGAL/Tangent_vector_fields/N_field_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Reduced_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Soft_field_design.h>
#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;

namespace {

const double scales[] = {1e-150, 1e-100, 1e-50, 1e50, 1e100, 1e150};

std::shared_ptr<const TVF::Operator_matrices> operators_of(const Mesh& mesh)
{
  return TVF::Discrete_operators<Mesh>(mesh).shared_matrices();
}

// The mesh scaled by s and moved by (3, -1, 0.5) s: far from the origin relative to
// nothing, so every coordinate keeps its digits.
Mesh scaled(const Mesh& mesh, double s)
{
  Mesh m = mesh;
  transform(m, s, {1, 0, 0, 0, 1, 0, 0, 0, 1}, Vector_3(3 * s, -s, 0.5 * s));
  return m;
}

double relative_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b)
{
  return (a - b).norm() / b.norm();
}

// The largest relative difference from scale 1 per entry point and scale; printed as a table
// when the suite ends (the measured side of the tolerances below).
std::map<std::string, std::map<double, double>>& sweep()
{
  static std::map<std::string, std::map<double, double>> table;
  return table;
}
double record(const std::string& entry, double scale, double difference)
{
  double& largest = sweep()[entry][scale];
  largest = std::max(largest, difference);
  return difference;
}
struct Print_sweep : ::testing::Environment
{
  void TearDown() override
  {
    if(sweep().empty()) return;
    std::printf("\nlargest relative difference from scale 1 (mesh scaled and moved by s):\n%-28s", "entry point");
    for(double s : scales) std::printf(" %9.0e", s);
    std::printf("\n");
    for(const auto& row : sweep())
    {
      std::printf("%-28s", row.first.c_str());
      for(double s : scales) std::printf(" %9.1e", row.second.count(s) ? row.second.at(s) : NAN);
      std::printf("\n");
    }
  }
};
::testing::Environment* const print_sweep = ::testing::AddGlobalTestEnvironment(new Print_sweep);

// A fixed field in frame coordinates: the frames of a scaled mesh are those of the
// unit one (to rounding), so the same numbers are the same field.
Eigen::VectorXd test_field(int nf)
{
  Eigen::VectorXd x(2 * nf);
  for(int i = 0; i < 2 * nf; ++i) x[i] = std::sin(0.37 * i + 1) + 0.5 * std::cos(1.3 * i);
  return x;
}

} // namespace

TEST(ExtremeScale, GeometryKeepsItsUnits)
{
  const Mesh base = make_torus(16, 8);
  const auto ops1 = operators_of(base);
  const TVF::Intrinsic_mesh& m1 = ops1->mesh();
  for(double s : scales)
  {
    SCOPED_TRACE(s);
    const auto ops = operators_of(scaled(base, s));
    const TVF::Intrinsic_mesh& m = ops->mesh();
    // Areas scale as s^2 and cotangents not at all (the input rounding of the scaled
    // coordinates, ~1e-16 relative, is all that differs).
    EXPECT_NEAR(ops->face_areas().sum() / (s * s), ops1->face_areas().sum(), 1e-12 * ops1->face_areas().sum());
    for(int f = 0; f < m.number_of_faces(); f += 17)
      for(int k = 0; k < 3; ++k) EXPECT_NEAR(m.cotangent(f, k), m1.cotangent(f, k), 1e-11);
    // The length unit is the power of two just below the mean edge length.
    EXPECT_LE(m.length_unit(), m.mean_edge_length());
    EXPECT_GT(2 * m.length_unit(), m.mean_edge_length());
    EXPECT_EQ(std::ldexp(1., std::ilogb(m.length_unit())), m.length_unit());
    // Gradients scale as 1/s: G of the function x/s (the first coordinate in units of s).
    Eigen::VectorXd x(m.number_of_vertices()), x1(m.number_of_vertices());
    for(int v = 0; v < m.number_of_vertices(); ++v)
    {
      x[v] = m.position(v)[0];
      x1[v] = m1.position(v)[0];
    }
    EXPECT_LT(relative_difference(ops->G() * x, ops1->G() * x1), 1e-11);
  }
}

TEST(ExtremeScale, HodgePartsAreThoseOfTheUnitMesh)
{
  // A torus: exact, coexact and harmonic parts all present.
  const Mesh base = make_torus(20, 10);
  const TVF::Hodge_solver hodge1(operators_of(base));
  const Eigen::VectorXd v = test_field(static_cast<int>(base.number_of_faces()));
  const unsigned all = TVF::hodge_exact | TVF::hodge_coexact | TVF::hodge_harmonic | TVF::hodge_potential;
  const TVF::Hodge_parts p1 = hodge1.decompose(v, all);
  for(double s : scales)
  {
    SCOPED_TRACE(s);
    const TVF::Hodge_solver hodge(operators_of(scaled(base, s)));
    const TVF::Hodge_parts p = hodge.decompose(v, all);
    // Tolerance: the conditioning of W (~1e4 here) times the input rounding.
    EXPECT_LT(record("Hodge: exact part", s, relative_difference(p.exact, p1.exact)), 1e-10);
    EXPECT_LT(record("Hodge: coexact part", s, relative_difference(p.coexact, p1.coexact)), 1e-10);
    EXPECT_LT(record("Hodge: harmonic part", s, relative_difference(p.harmonic, p1.harmonic)), 1e-10);
    // The potential has units of length times the field: s times the unit one.
    EXPECT_LT(record("Hodge: potential / s", s, relative_difference(p.potential / s, p1.potential)), 1e-10);
    // The harmonic basis is orthonormal in MX (~s^2): its fields scale as 1/s.
    const Eigen::MatrixXd& H = hodge.harmonic_basis();
    const Eigen::MatrixXd gram = H.transpose() * hodge.operators().field_masses().asDiagonal() * H;
    EXPECT_LT((gram - Eigen::MatrixXd::Identity(H.cols(), H.cols())).norm(), 1e-10);
  }
}

TEST(ExtremeScale, EigenvaluesScaleAsTheInverseArea)
{
  // The unit sphere: the lowest exact eigenvalue is l(l+1) = 2 for l = 1 (three of them),
  // up to the discretisation error of a level-2 icosphere (measured 2.7%).
  const Mesh base = make_icosphere(2);
  const auto basis1 = std::make_shared<TVF::Eigenfield_basis>(std::make_shared<TVF::Hodge_solver>(operators_of(base)),
                                                              TVF::Basis_request::lowest(12));
  EXPECT_NEAR(basis1->exact_eigenvalues()[0], 2., 0.06);
  for(double s : scales)
  {
    SCOPED_TRACE(s);
    const TVF::Eigenfield_basis basis(std::make_shared<TVF::Hodge_solver>(operators_of(scaled(base, s))),
                                      TVF::Basis_request::lowest(12));
    ASSERT_EQ(basis.size(), basis1->size());
    // Eigenvalues in 1/s^2: products with s^2 equal the unit ones to the solver's tolerance.
    for(int k = 0; k < basis.size(); ++k)
    {
      const double lambda = basis.eigenvalue(k) * s * s, lambda1 = basis1->eigenvalue(k);
      record("basis: eigenvalues * s^2", s, lambda1 > 0 ? std::abs(lambda - lambda1) / lambda1 : std::abs(lambda));
      EXPECT_NEAR(lambda, lambda1, 1e-8 * lambda1) << k;
    }
    EXPECT_NEAR(basis.exact_eigenvalues()[0] * s * s, 2., 0.06);
  }
}

TEST(ExtremeScale, DesignedFieldsAreThoseOfTheUnitMesh)
{
  const Mesh base = make_torus(14, 8);
  const int nf = static_cast<int>(base.number_of_faces());
  TVF::Spline_options options;
  options.omega = 5;
  auto design = [&](const Mesh& mesh, double s) {
    const auto ops = operators_of(mesh);
    const TVF::Intrinsic_mesh& m = ops->mesh();
    // Vectors given in the face frames (the same numbers at every scale); a divergence
    // and a curl in units of 1/s.
    std::vector<TVF::Field_constraint> constraints = {
        TVF::Field_constraint::vector_in_face(0, m.from_frame(0, 1, 0.5)),
        TVF::Field_constraint::vector_in_face(nf / 2, m.from_frame(nf / 2, -0.3, 1)),
        TVF::Field_constraint::divergence_at_vertex(7, 2 / s),
        TVF::Field_constraint::curl_at_edge(40, -1 / s)};
    const auto hodge = std::make_shared<TVF::Hodge_solver>(ops);
    TVF::Full_spline_solver full(hodge, options);
    full.add(constraints);
    const auto basis = std::make_shared<TVF::Eigenfield_basis>(hodge, TVF::Basis_request::lowest(80));
    TVF::Reduced_spline_solver reduced(basis, 0, options);
    reduced.add(constraints);
    TVF::Soft_design_options soft_options;
    soft_options.omega = 0.1;
    TVF::Full_soft_design soft(hodge, soft_options);
    for(const auto& c : constraints) soft.add(c, 1.);
    // The spline's energy has units 1/s^2 (E_B dominates with omega = 5 on this mesh
    // no more than the data decide: both scale alike).
    return std::array<Eigen::VectorXd, 4>{full.field(), reduced.field(), soft.field(),
                                           Eigen::VectorXd::Constant(1, full.report().energy * s * s)};
  };
  const auto unit = design(base, 1);
  for(double s : scales)
  {
    SCOPED_TRACE(s);
    const auto other = design(scaled(base, s), s);
    EXPECT_LT(record("design: full spline", s, relative_difference(other[0], unit[0])), 1e-9);
    EXPECT_LT(record("design: reduced spline", s, relative_difference(other[1], unit[1])), 1e-9);
    EXPECT_LT(record("design: full soft", s, relative_difference(other[2], unit[2])), 1e-8);
    EXPECT_NEAR(other[3][0], unit[3][0], 1e-9 * unit[3][0]);
  }
}

TEST(ExtremeScale, StreamlinesScaleWithTheMesh)
{
  const Mesh base = make_icosphere(3);
  // A rotation about the z axis, in frame coordinates of the unit mesh (those of every
  // scaled copy): streamlines are long circles.
  const auto ops1 = operators_of(base);
  const TVF::Intrinsic_mesh& m1 = ops1->mesh();
  Eigen::VectorXd v(2 * m1.number_of_faces());
  for(int f = 0; f < m1.number_of_faces(); ++f)
  {
    std::array<double, 3> c = {0, 0, 0};
    for(int corner : m1.face_vertices(f))
      for(int k = 0; k < 3; ++k) c[k] += m1.position(corner)[k] / 3;
    const std::array<double, 2> a = m1.to_frame(f, {-c[1], c[0], 0.3});
    v[2 * f] = a[0];
    v[2 * f + 1] = a[1];
  }
  TVF::Streamline_options options;
  options.maximum_length = 2; // absolute (the default unit), in units of the unit mesh
  const TVF::Streamline_tracer tracer1(ops1->shared_mesh(), v);
  const TVF::Streamline line1 = tracer1.trace(100, {0.2, 0.3, 0.5}, options);
  ASSERT_GT(line1.points.size(), 10u);
  for(double s : scales)
  {
    SCOPED_TRACE(s);
    options.maximum_length = 2 * s;
    const TVF::Streamline_tracer tracer(operators_of(scaled(base, s))->shared_mesh(), v);
    const TVF::Streamline line = tracer.trace(100, {0.2, 0.3, 0.5}, options);
    ASSERT_EQ(line.points.size(), line1.points.size());
    EXPECT_NEAR(line.length() / s, line1.length(), 1e-9 * line1.length());
    record("streamline: length / s", s, std::abs(line.length() / s - line1.length()) / line1.length());
    // Points: s times the unit ones, plus the translation.
    for(std::size_t i = 0; i < line.points.size(); i += 7)
      EXPECT_NEAR((line.points[i][0] - 3 * s) / s, line1.points[i][0], 1e-9) << i;
  }
}

TEST(ExtremeScale, SizesBeyondTheDoubleRangeAreRefusedWithTheReason)
{
  const Mesh base = make_icosphere(2);
  for(double s : {1e-160, 1e-200, 1e160, 1e200})
  {
    SCOPED_TRACE(s);
    Mesh mesh = base;
    transform(mesh, s);
    try
    {
      TVF::Discrete_operators<Mesh> ops(mesh);
      ADD_FAILURE() << "accepted";
    }
    catch(const TVF::Invalid_mesh& e)
    {
      EXPECT_EQ(e.defect(), TVF::Mesh_defect::unrepresentable_size);
      EXPECT_NE(std::string(e.what()).find(s < 1 ? "too small" : "too large"), std::string::npos) << e.what();
    }
  }
  // A unit mesh at 1e17 from the origin: its coordinates cannot tell its vertices apart.
  Mesh far = base;
  transform(far, 1., {1, 0, 0, 0, 1, 0, 0, 0, 1}, Vector_3(1e17, 0, 0));
  try
  {
    TVF::Discrete_operators<Mesh> ops(far);
    ADD_FAILURE() << "accepted";
  }
  catch(const TVF::Invalid_mesh& e)
  {
    EXPECT_EQ(e.defect(), TVF::Mesh_defect::degenerate_face);
    EXPECT_NE(std::string(e.what()).find("too small for its distance from the origin"), std::string::npos) << e.what();
  }
  // n-field splines of order 3 have energies ~ area^-3: refused beyond the double range.
  const auto ops = operators_of(scaled(base, 1e-150));
  const auto n_ops = std::make_shared<TVF::N_field_operators>(ops, 4);
  try
  {
    TVF::Full_n_field_spline_solver solver(n_ops, TVF::Spline_options(), 3);
    ADD_FAILURE() << "accepted";
  }
  catch(const TVF::Invalid_input& e)
  {
    EXPECT_NE(std::string(e.what()).find("leave the range of double precision"), std::string::npos) << e.what();
  }
}

TEST(ExtremeScale, ConstraintVectorsNearTheLargestDoubleAreAccepted)
{
  // [1e300, 1e300, 0]: its squared length overflows, its length does not.  The spline is
  // linear in the values: 1e300 times the field of the vector (1, 1, 0).
  const Mesh mesh = make_icosphere(2);
  const auto ops = operators_of(mesh);
  const auto hodge = std::make_shared<TVF::Hodge_solver>(ops);
  const std::array<double, 3> v = ops->mesh().from_frame(3, 1, 1);
  TVF::Full_spline_solver unit(hodge), huge(hodge);
  unit.add(TVF::Field_constraint::vector_in_face(3, v));
  huge.add(TVF::Field_constraint::vector_in_face(3, {v[0] * 1e300, v[1] * 1e300, v[2] * 1e300}));
  const Eigen::VectorXd x = huge.field();
  ASSERT_TRUE(x.allFinite());
  EXPECT_LT(relative_difference(x / 1e300, unit.field()), 1e-12);
  // The n-field constraint of the same vector: its direction, not "normal to its face".
  const auto n_ops = std::make_shared<TVF::N_field_operators>(ops, 4);
  TVF::Full_n_field_spline_solver n_unit(n_ops), n_huge(n_ops);
  n_unit.add(TVF::N_field_constraint::vector_in_face(3, v));
  n_huge.add(TVF::N_field_constraint::vector_in_face(3, {v[0] * 1e300, v[1] * 1e300, v[2] * 1e300}));
  EXPECT_LT(relative_difference(n_huge.field() / 1e300, n_unit.field()), 1e-12);
  // A vector whose projection exceeds the largest double: refused with that reason.
  try
  {
    TVF::Full_spline_solver overflowing(hodge);
    overflowing.add(TVF::Field_constraint::vector_in_face(3, {1.7e308, 1.7e308, 1.7e308}));
    (void)overflowing.field();
    ADD_FAILURE() << "accepted";
  }
  catch(const std::exception& e)
  {
    EXPECT_NE(std::string(e.what()).find("not finite"), std::string::npos) << e.what();
  }
}
