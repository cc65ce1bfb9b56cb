// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Bad and extreme input to field design (SPEC 7): malformed, duplicate, contradictory
// and nearly dependent constraints, bad tensions and weights, impossible basis sizes, and
// degenerate meshes.  A refused constraint leaves the solver as it was; an accepted
// one is met by a finite field.

#include "bad_input_support.h"

#include <CGAL/Tangent_vector_fields/Full_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Reduced_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Refining_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Soft_field_design.h>
#include <CGAL/Tangent_vector_fields/Vector_field_spline.h>

#include <limits>

using namespace bad_input;

namespace {

typedef TVF::Vector_field_spline<Mesh> Spline;
typedef TVF::Field_constraint Constraint;

struct Full_setup
{
  std::shared_ptr<const TVF::Operator_matrices> ops;
  std::shared_ptr<const TVF::Hodge_solver> hodge;
  explicit Full_setup(const Mesh& mesh, bool mollify = false)
    : ops(TVF::Discrete_operators<Mesh>(mesh, TVF::parameters::use_intrinsic_mollification(mollify)).shared_matrices()),
      hodge(std::make_shared<TVF::Hodge_solver>(ops))
  {}
};

// Largest |C~ x - c| over the rows of `constraints`, relative to the largest |c| (or absolute).
double residual(const TVF::Operator_matrices& ops, const std::vector<Constraint>& constraints, const Eigen::VectorXd& x)
{
  double worst = 0, largest = 0;
  for(const Constraint& c : constraints)
    for(const TVF::Constraint_row& r : TVF::constraint_rows(ops, c))
    {
      worst = std::max(worst, std::abs(r.dot(x) - r.value));
      largest = std::max(largest, std::abs(r.value));
    }
  return largest > 0 ? worst / largest : worst;
}

// The frame coordinates of the projection of `v` onto face `f`.
Eigen::Vector2d projected(const TVF::Operator_matrices& ops, int f, const std::array<double, 3>& v)
{
  const auto a = ops.mesh().to_frame(f, v);
  return Eigen::Vector2d(a[0], a[1]);
}

} // namespace

TEST(BadDesign, MalformedConstraintsAreRefusedAndLeaveTheSolverUnchanged)
{
  Mesh mesh = make_icosphere(1);
  const Vertex_index lonely = mesh.add_vertex(Point_3(5, 5, 5));
  Full_setup s(mesh);
  TVF::Full_spline_solver solver(s.hodge);
  const int nf = 80, nv = 43, ne = 120;
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  const std::vector<std::pair<Constraint, std::string>> bad = {
      {Constraint::vector_in_face(-1, {1, 0, 0}), "face index -1 out of range"},
      {Constraint::vector_in_face(nf, {1, 0, 0}), "face index 80 out of range"},
      {Constraint::divergence_at_vertex(nv, 1), "vertex index 43 out of range"},
      {Constraint::divergence_at_vertex(-5, 1), "vertex index -5 out of range"},
      {Constraint::curl_at_edge(ne, 1), "edge index 120 out of range"},
      {Constraint::vector_in_face(3, {nan, 0, 0}), "non-finite number"},
      {Constraint::divergence_at_vertex(3, inf), "non-finite number"},
      {Constraint::curl_at_point(3, {0.2, nan, 0.3}, 1), "non-finite number"},
      {Constraint::direction_in_face(3, {0, 0, 0}), "non-zero direction"},
      {Constraint::divergence_at_point(3, {0.5, 0.6, 0}, 1), "barycentric"},
      {Constraint::divergence_at_point(3, {-0.1, 0.6, 0.5}, 1), "barycentric"},
      {Constraint::divergence_at_vertex(static_cast<int>(lonely), 1), "in no face"},
  };
  for(const auto& [c, phrase] : bad)
    expect_error<TVF::Invalid_input>([&] { solver.add(c); }, phrase);
  // A vector normal to its face has no tangent part to ask for.
  const auto& n = s.ops->mesh().normal(7);
  expect_error<TVF::Invalid_input>([&] { solver.add(Constraint::vector_in_face(7, {n[0], n[1], n[2]})); },
                                   "normal to its face");
  // A batch with one bad constraint adds none.
  expect_error<TVF::Invalid_input>(
      [&] { solver.add(std::vector<Constraint>{Constraint::vector_in_face(1, {1, 0, 0}), bad[0].first}); },
      "out of range");
  EXPECT_EQ(solver.number_of_constraints(), 0);
  EXPECT_EQ(solver.field().norm(), 0.);
  // Edits: an unknown id, a NaN value; the constraint keeps its old value.
  const TVF::Constraint_id id = solver.add(Constraint::divergence_at_vertex(0, 1));
  expect_error<TVF::Invalid_input>([&] { solver.remove(id + 1); }, "no constraint with id");
  expect_error<TVF::Invalid_input>([&] { solver.change(id, Constraint::divergence_at_vertex(0, nan)); }, "non-finite");
  EXPECT_EQ(solver.constraint(id).value, 1.);
  EXPECT_NEAR(s.ops->divergence(solver.field())[0], 1., 1e-9);
}

TEST(BadDesign, ZeroVectorConstraintGivesAVanishingFaceNotANaN)
{
  // A zero vector is a valid value (a sink of the field's magnitude): met exactly.
  const Mesh mesh = make_torus(12, 8);
  Full_setup s(mesh);
  TVF::Full_spline_solver solver(s.hodge);
  const std::vector<Constraint> cs = {Constraint::vector_in_face(0, {0, 0, 0}),
                                      Constraint::vector_in_face(40, {0.3, 0.1, 0.2})};
  solver.add(cs);
  const Eigen::VectorXd x = solver.field();
  ASSERT_TRUE(x.allFinite());
  EXPECT_LT(x.segment<2>(0).norm(), 1e-12);
  EXPECT_LT((x.segment<2>(80) - projected(*s.ops, 40, {0.3, 0.1, 0.2})).norm(), 1e-9);
  EXPECT_GT(x.norm(), 0.);
}

TEST(BadDesign, DuplicateContradictoryAndNearlyDependentConstraintsAreInfeasible)
{
  const Mesh mesh = make_icosphere(2);
  Full_setup s(mesh);
  const std::array<double, 3> v = {0.4, -0.2, 0.7};
  auto refused = [&](const std::vector<Constraint>& cs, double min_residual, double max_residual) {
    TVF::Full_spline_solver solver(s.hodge);
    try
    {
      solver.add(cs);
      ADD_FAILURE() << "accepted " << cs.back().describe();
    }
    catch(const TVF::Infeasible_constraints& e)
    {
      EXPECT_NE(std::string(e.what()).find("depends on the constraints already set"), std::string::npos) << e.what();
      EXPECT_LT(e.independence(), 1e-10);
      EXPECT_GE(e.residual(), min_residual) << e.what();
      EXPECT_LE(e.residual(), max_residual) << e.what();
    }
    EXPECT_EQ(solver.number_of_constraints(), 0);
  };
  // The same constraint twice: dependent, and consistent (residual ~0).
  refused({Constraint::vector_in_face(5, v), Constraint::vector_in_face(5, v)}, 0, 1e-12);
  // Values 1e-14 apart: as dependent; the residual shows the difference, not a swing.
  const std::array<double, 3> w = {v[0] * (1 + 1e-14), v[1], v[2]};
  refused({Constraint::vector_in_face(5, v), Constraint::vector_in_face(5, w)}, 0, 1e-12);
  // Contradictory vectors in one face: the residual is their (projected) difference.
  const double gap = (projected(*s.ops, 5, v) - projected(*s.ops, 5, {0, 1, 0})).norm();
  refused({Constraint::vector_in_face(5, v), Constraint::vector_in_face(5, {0, 1, 0})}, 1e-3 * gap, 1.01 * gap);
  // A direction in a face whose vector is already set.
  refused({Constraint::vector_in_face(5, v), Constraint::direction_in_face(5, {1, 0, 0})}, 0, 10);
}

TEST(BadDesign, DivergencesAtEveryVertexOfAClosedMeshConflictWithGauss)
{
  // sum_v M_v div_v = 0 on a closed surface: divergence 1 at all 42 vertices is refused
  // (all or nothing); at 41 of them it is met and the last vertex takes what Gauss leaves.
  const Mesh mesh = make_icosphere(1);
  Full_setup s(mesh);
  std::vector<Constraint> all;
  for(int v = 0; v < 42; ++v) all.push_back(Constraint::divergence_at_vertex(v, 1));
  TVF::Full_spline_solver solver(s.hodge);
  try
  {
    solver.add(all);
    ADD_FAILURE() << "42 divergences accepted";
  }
  catch(const TVF::Infeasible_constraints& e)
  {
    EXPECT_NE(std::string(e.what()).find("vertex 41"), std::string::npos) << e.what();
    EXPECT_GT(e.residual(), 1.) << e.what(); // it implies about -41 where 1 is asked
  }
  EXPECT_EQ(solver.number_of_constraints(), 0);
  all.pop_back();
  solver.add(all);
  const Eigen::VectorXd div = s.ops->divergence(solver.field());
  const Eigen::VectorXd& mass = s.ops->vertex_masses();
  for(int v = 0; v < 41; ++v) EXPECT_NEAR(div[v], 1., 1e-8) << v;
  EXPECT_NEAR(div[41], -mass.head(41).sum() / mass[41], 1e-6 * mass.head(41).sum() / mass[41]);
}

TEST(BadDesign, BadTensionsWeightsAndBasisSizesAreRefused)
{
  Mesh mesh = make_icosphere(1);
  const double nan = std::nan("");
  for(double omega : {-1., nan, std::numeric_limits<double>::infinity()})
  {
    expect_error<TVF::Invalid_input>([&] { Spline s(mesh, TVF::parameters::spline_tension(omega)); }, "omega");
    expect_error<TVF::Invalid_input>([&] { Spline s(mesh, TVF::parameters::harmonic_eigenvalue(omega)); },
                                     "harmonic eigenvalue");
  }
  Spline spline(mesh);
  spline.add_vector(Face_index(2), Vector_3(1, 0, 0));
  expect_error<TVF::Invalid_input>([&] { spline.set_tension(nan); }, "omega");
  EXPECT_EQ(spline.solver().options().omega, 0.);

  const TVF::Spectral_basis<Mesh> basis(mesh, TVF::parameters::number_of_eigenfields(8));
  expect_error<TVF::Invalid_input>([&] { Spline s(basis, TVF::parameters::number_of_eigenfields(9)); }, "9");
  expect_error<TVF::Invalid_input>([&] { Spline s(basis, TVF::parameters::number_of_eigenfields(-1)); }, "-1");
  // A basis of 8 fields meets at most 8 independent rows: the fifth vector is refused, with the reason.
  Spline reduced(basis);
  for(int f = 0; f < 4; ++f) reduced.add_vector(Face_index(10 * f), Vector_3(0.1 * f, 1, 0));
  expect_error<TVF::Infeasible_constraints>([&] { reduced.add_vector(Face_index(50), Vector_3(1, 0, 0)); },
                                            "use a larger basis");

  // Soft design: weights that are not positive and finite, a bad omega.
  const auto ops = TVF::Discrete_operators<Mesh>(mesh).shared_matrices();
  TVF::Full_soft_design soft(std::make_shared<TVF::Hodge_solver>(ops));
  for(double weight : {0., -1., nan, std::numeric_limits<double>::infinity()})
    expect_error<TVF::Invalid_input>([&] { soft.add(Constraint::vector_in_face(0, {1, 0, 0}), weight); },
                                     "positive finite weight");
  EXPECT_EQ(soft.number_of_constraints(), 0);
  TVF::Soft_design_options bad_omega;
  bad_omega.omega = nan;
  expect_error<TVF::Invalid_input>([&] { TVF::Full_soft_design d(std::make_shared<TVF::Hodge_solver>(ops), bad_omega); },
                                   "omega");
}

TEST(BadDesign, ContradictorySoftConstraintsGiveTheirWeightedMean)
{
  // Soft constraints never conflict: two contradictory vectors of equal weight in one
  // face cost 2w |x_f - mean|^2 + const, so the design equals that of their mean at
  // weight 2w.
  const Mesh mesh = make_icosphere(2);
  const auto ops = TVF::Discrete_operators<Mesh>(mesh).shared_matrices();
  const auto hodge = std::make_shared<TVF::Hodge_solver>(ops);
  TVF::Full_soft_design both(hodge), mean(hodge);
  both.add(Constraint::vector_in_face(9, {1, 0, 0}), 3);
  both.add(Constraint::vector_in_face(9, {0, 1, 0}), 3);
  both.add(Constraint::vector_in_face(100, {0, 0, 1}), 1);
  mean.add(Constraint::vector_in_face(9, {0.5, 0.5, 0}), 6);
  mean.add(Constraint::vector_in_face(100, {0, 0, 1}), 1);
  const Eigen::VectorXd a = both.field(), b = mean.field();
  ASSERT_TRUE(a.allFinite());
  EXPECT_GT(a.norm(), 0.);
  EXPECT_LT((a - b).norm(), 1e-8 * b.norm());
}

TEST(BadDesign, DegenerateMeshesAreRefusedOrDesignedExactly)
{
  Mesh empty;
  expect_defect(TVF::Mesh_defect::empty, [&] { Spline s(empty); });
  Mesh nan_mesh = make_icosphere(1);
  nan_mesh.point(Vertex_index(3)) = Point_3(0, 0, std::nan(""));
  expect_defect(TVF::Mesh_defect::non_finite_coordinate, [&] { Spline s(nan_mesh); }, "vertex 3");

  // One triangle: a vector constraint is the whole field; full and reduced agree.
  Mesh triangle = single_triangle();
  auto out = triangle.add_property_map<Face_index, Vector_3>("f:out", Vector_3(7, 7, 7)).first;
  TVF::vector_field_spline(triangle, {Constraint::vector_in_face(0, {1, 1, 1})}, out);
  const auto ops = TVF::Discrete_operators<Mesh>(triangle).shared_matrices();
  const Eigen::Vector2d want = projected(*ops, 0, {1, 1, 1});
  const auto back = ops->mesh().to_frame(0, {out[Face_index(0)].x(), out[Face_index(0)].y(), out[Face_index(0)].z()});
  EXPECT_LT((Eigen::Vector2d(back[0], back[1]) - want).norm(), 1e-12);
  EXPECT_NEAR(out[Face_index(0)] * Vector_3(ops->mesh().normal(0)[0], ops->mesh().normal(0)[1], ops->mesh().normal(0)[2]),
              0., 1e-12); // tangent
  const TVF::Spectral_basis<Mesh> basis(triangle, TVF::parameters::number_of_eigenfields(2));
  Spline reduced(basis);
  reduced.add_vector(Face_index(0), Vector_3(1, 1, 1));
  EXPECT_LT((reduced.solver().field() - want).norm(), 1e-10);
  // A second constraint in the only face asks for more rows than there are unknowns.
  expect_error<TVF::Infeasible_constraints>([&] { reduced.add_direction(Face_index(0), Vector_3(0, 1, 0)); },
                                            "depends on");
  // No constraints at all: the zero field, not a NaN.
  TVF::vector_field_spline(triangle, {}, out);
  EXPECT_EQ(out[Face_index(0)], Vector_3(0, 0, 0));
}

TEST(BadDesign, AwkwardButValidMeshesMeetTheirConstraints)
{
  // Boundary only (annulus band), genus 3, a component 1e-6 as large, a needle
  // (short edge 1e-7), a zero-area face under mollification with a constraint on it:
  // constraints met, field finite, harmonic dimension that of the topology counted here.
  Mesh needle = make_disk(4);
  {
    const auto h = needle.halfedge(Face_index(5));
    needle.point(needle.target(h)) = needle.point(needle.source(h)) + 1e-7 * (needle.point(needle.target(h)) -
                                                                              needle.point(needle.source(h)));
  }
  Mesh flat = make_disk(3);
  {
    const auto h = flat.halfedge(Face_index(0));
    flat.point(flat.target(flat.next(h))) = CGAL::midpoint(flat.point(flat.source(h)), flat.point(flat.target(h)));
  }
  const Mesh band = boundary_only_band(10), slab = holed_slab(7, 3), pair = sphere_with_tiny_companion(1e-6);
  struct Case
  {
    const Mesh* mesh;
    int harmonic;
    bool mollify;
    std::vector<Constraint> constraints;
  };
  // The topology, counted here: (chi, boundary loops).
  EXPECT_EQ(euler_and_boundary_loops(band), std::make_pair(0, 2));  // annulus: 2g + b - 1 = 1
  EXPECT_EQ(euler_and_boundary_loops(slab), std::make_pair(-4, 0)); // genus 3: 2g = 6
  EXPECT_EQ(euler_and_boundary_loops(pair), std::make_pair(4, 0));  // two spheres: 0
  const int tiny_face = 320 + 7; // a face of the small sphere
  const std::vector<Case> cases = {
      {&band, 1, false, {Constraint::vector_in_face(0, {0, 0, 1}), Constraint::divergence_at_vertex(3, 0.5)}},
      {&slab, 6, false, {Constraint::vector_in_face(0, {1, 0, 0}), Constraint::curl_at_edge(17, 2)}},
      {&pair, 0, false, {Constraint::vector_in_face(3, {0, 1, 0}), Constraint::vector_in_face(tiny_face, {1, 0, 0})}},
      {&needle, 0, false, {Constraint::vector_in_face(5, {1, 0, 0}), Constraint::divergence_at_vertex(0, 1)}},
      {&flat, 0, true, {Constraint::vector_in_face(0, {0, 1, 0}), Constraint::vector_in_face(9, {1, 0, 0})}}};
  for(const Case& c : cases)
  {
    SCOPED_TRACE(c.mesh->number_of_faces());
    Full_setup s(*c.mesh, c.mollify);
    TVF::Full_spline_solver solver(s.hodge);
    EXPECT_EQ(solver.harmonic_dimension(), c.harmonic);
    solver.add(c.constraints);
    const Eigen::VectorXd x = solver.field();
    ASSERT_TRUE(x.allFinite());
    EXPECT_LT(residual(*s.ops, c.constraints, x), 1e-8);
    // The first constraint is a vector: it fixes two harmonic directions, the others none.
    EXPECT_EQ(solver.report().undetermined_harmonic, std::max(0, c.harmonic - 2));
  }
}

TEST(BadDesign, RefiningSolverRefusesMismatchedSolversAndBadEditsAndRefinesOnMultiScaleMeshes)
{
  // A sphere with a companion 1e-6 as large: the reduced answer at once, then the exact one,
  // both meeting the constraints; bad edits change neither.
  const Mesh pair = sphere_with_tiny_companion(1e-6);
  const TVF::Spectral_basis<Mesh> basis(pair, TVF::parameters::number_of_eigenfields(60));
  Full_setup s(pair);
  auto reduced = [&](double omega) {
    TVF::Spline_options o;
    o.omega = omega;
    return std::make_unique<TVF::Reduced_spline_solver>(basis.shared_basis(), 0, o);
  };
  auto full = [&](double omega) {
    TVF::Spline_options o;
    o.omega = omega;
    return std::make_unique<TVF::Full_spline_solver>(s.hodge, o);
  };
  expect_error<TVF::Invalid_input>([&] { TVF::Refining_spline_solver r(nullptr, full(0)); },
                                   "both a reduced and a full solver are needed");
  expect_error<TVF::Invalid_input>([&] { TVF::Refining_spline_solver r(reduced(0), full(1)); }, "different tensions");
  auto used = full(0);
  used->add(Constraint::vector_in_face(0, {1, 0, 0}));
  expect_error<TVF::Invalid_input>([&] { TVF::Refining_spline_solver r(reduced(0), std::move(used)); },
                                   "must start without constraints");

  TVF::Refining_spline_solver solver(reduced(0), full(0));
  const std::vector<Constraint> cs = {Constraint::vector_in_face(3, {0, 1, 0}), Constraint::vector_in_face(100, {1, 0, 0})};
  solver.add(cs);
  // The lowest 60 eigenfields all live on the big sphere (the small one's eigenvalues are
  // 1e12 larger): the basis cannot represent a vector on the small sphere.
  expect_error<TVF::Infeasible_constraints>([&] { solver.add(Constraint::vector_in_face(327, {1, 0, 0})); },
                                            "in face 327");
  expect_error<TVF::Invalid_input>([&] { solver.add(Constraint::vector_in_face(400, {1, 0, 0})); }, "out of range");
  expect_error<TVF::Invalid_input>([&] { solver.set_omega(std::nan("")); }, "omega");
  EXPECT_EQ(solver.number_of_constraints(), 2);
  TVF::Spline_answer answer;
  const Eigen::VectorXd quick = solver.field(&answer);
  EXPECT_FALSE(answer.exact);
  ASSERT_TRUE(quick.allFinite());
  solver.refine();
  const Eigen::VectorXd exact = solver.field(&answer);
  EXPECT_TRUE(answer.exact);
  ASSERT_TRUE(exact.allFinite());
  EXPECT_LT(residual(*s.ops, cs, exact), 1e-8);
}
