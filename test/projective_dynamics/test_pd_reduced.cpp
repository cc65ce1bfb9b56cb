// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Reduced and hyper-reduced Projective Dynamics against independent truth: the position
// subspace reproduces affine maps exactly; the rest state stays still; the identity basis with
// every element projected reproduces the full Simulator; the PCA keeps the leading directions
// of a dense eigen-decomposition done here; g (recomputed here) never increases per iteration;
// linear momentum is conserved (also hyper-reduced); huge steps and scrambled starts stay
// finite; the error against full PD falls as k grows; bad input is refused with its reason.
// The saved precomputation's tests are in test_pd_reduced_file.cpp.

#include "expect_reason.h"
#include "pd_reduced_test_support.h"
#include "pd_test_support.h"
#include "scratch_path.h"

#include <CGAL/Projective_dynamics/Position_subspace.h>
#include <CGAL/Projective_dynamics/Projection_subspace.h>
#include <CGAL/Projective_dynamics/Reduced_simulator.h>
#include <CGAL/Projective_dynamics/Simulator.h>
#include <CGAL/Projective_dynamics/internal/projection_subspace_factors.h>
#include <CGAL/Projective_dynamics/make_models.h>
#include <CGAL/Projective_dynamics/mesh_generators.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace PD = CGAL::Projective_dynamics;
namespace params = PD::parameters;

namespace {

using pd_test::jittered;
using pd_test::squared_distance_to_rotations;

using pd_test::box_model;
using pd_test::small_box;
using pd_test::small_hyper;

double m_norm2(const PD::Positions& d, const Eigen::VectorXd& m)
{
  double s = 0;
  for(Eigen::Index i = 0; i < d.rows(); ++i) s += m[i] * d.row(i).squaredNorm();
  return s;
}

} // namespace

TEST(ProjectiveDynamicsReduced, SubspaceReproducesAffineMapsExactly)
{
  const PD::Elastic_model model = box_model();
  std::mt19937 rng(3);
  for(int m : {1, 7, 30})
  {
    const PD::Position_subspace P = PD::make_position_subspace(model, m, 1.1);
    ASSERT_EQ(P.basis.cols(), 4 * m); // four columns per sample, no extra constant column
    ASSERT_EQ(P.samples.size(), std::size_t(m));
    const Eigen::Matrix3d A = pd_test::random_matrix<3, 3>(rng);
    const Eigen::Vector3d t = pd_test::random_matrix<3, 1>(rng);
    // Truth: the affine map of the rest shape; coefficients from the columns' definition.
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(4 * m, 3);
    for(int j = 0; j < m; ++j)
    {
      for(int c = 0; c < 3; ++c) a.row(4 * j + c) = A.col(c).transpose();
      a.row(4 * j + 3) = t.transpose();
    }
    const PD::Positions x = model.rest_positions();
    PD::Positions expected(x.rows(), 3);
    for(Eigen::Index i = 0; i < x.rows(); ++i) expected.row(i) = (A * x.row(i).transpose() + t).transpose();
    const PD::Positions q = P.basis * a;
    // Rounding only: sums of a few weights normalised to 1 times O(1) coordinates.
    EXPECT_LT((q - expected).cwiseAbs().maxCoeff(), 1e-12) << m << " samples";
    EXPECT_LT((PD::Positions(P.basis * P.rest_coordinates()) - x).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(ProjectiveDynamicsReduced, FarthestPointSamplesCoverBetterAsTheyGrow)
{
  const PD::Elastic_model model = box_model();
  double previous = 1e300;
  for(int m : {2, 8, 32})
  {
    std::vector<double> d;
    const std::vector<int> s = PD::farthest_point_samples(model, m, &d);
    std::vector<int> sorted = s;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(std::unique(sorted.begin(), sorted.end()), sorted.end()) << "repeated sample";
    const double covering = *std::max_element(d.begin(), d.end());
    EXPECT_LT(covering, previous);
    previous = covering;
    for(int v : s) EXPECT_EQ(d[std::size_t(v)], 0.0);
  }
}

TEST(ProjectiveDynamicsReduced, PcaKeepsTheLeadingEigenvectors)
{
  // C = Q diag(sigma) R^T with distinct sigma; the truth is a dense eigen-decomposition of the
  // weighted C C^T done here (rows x rows), not the c x c Gram matrix the package uses.
  std::mt19937 rng(11);
  const int rows = 60, cols = 25, l = 8;
  Eigen::VectorXd w(rows);
  std::uniform_real_distribution<double> u(0.5, 2.0);
  for(int i = 0; i < rows; ++i) w[i] = u(rng);
  Eigen::MatrixXd C(rows, cols);
  for(int i = 0; i < rows; ++i)
    for(int j = 0; j < cols; ++j) C(i, j) = std::normal_distribution<double>()(rng) * std::pow(0.7, j);
  const Eigen::MatrixXd V = PD::mass_weighted_pca(C, w, l);
  ASSERT_EQ(V.cols(), l);
  const Eigen::VectorXd root = w.cwiseSqrt();
  const Eigen::MatrixXd B = root.asDiagonal() * C;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(B * B.transpose());
  const Eigen::MatrixXd leading = eig.eigenvectors().rightCols(l);   // Eigen: increasing order
  const Eigen::MatrixXd trailing = eig.eigenvectors().leftCols(rows - l);
  const Eigen::MatrixXd Vs = root.asDiagonal() * V;
  // Weighted-orthonormal columns, spanning the leading eigenspace: the tolerances are rounding
  // of eigen-decompositions of O(1) matrices with well separated eigenvalues.
  EXPECT_LT((Vs.transpose() * Vs - Eigen::MatrixXd::Identity(l, l)).norm(), 1e-9);
  EXPECT_LT((trailing.transpose() * Vs).norm(), 1e-8);
  EXPECT_NEAR((leading.transpose() * Vs).squaredNorm(), double(l), 1e-8);
  EXPECT_THROW_REASON(PD::mass_weighted_pca(C.leftCols(3) * Eigen::MatrixXd::Ones(3, 10), w, 5), PD::Invalid_input,
                      "numerical rank");
}

TEST(ProjectiveDynamicsReduced, ProjectionSubspaceHoldsTheRestProjectionsAndItsFactorsAgree)
{
  // The box's tets (one group): V is orthonormal for the element measures, its span holds the
  // rest projections (recomputed here element by element), and the factored form the simulator
  // uses gives V's rows and F = U^T S^T D V as the dense products done here.
  const PD::Elastic_model model = box_model();
  const int l = 40;
  const Eigen::MatrixXd V = PD::projection_subspace(model, 0, 20, 2.2, l);
  const auto& S = model.selection_matrix();
  ASSERT_EQ(V.rows(), S.rows());
  Eigen::VectorXd measure(S.rows());
  Eigen::MatrixXd P(S.rows(), 3);
  for(int e = 0; e < model.number_of_elements(); ++e)
  {
    const PD::Element& el = model.elements()[std::size_t(e)];
    double value[9], out[9];
    for(int r = 0; r < el.rows; ++r)
    {
      const Eigen::RowVector3d v = S.row(el.first_row + r) * model.rest_positions();
      for(int c = 0; c < 3; ++c) value[3 * r + c] = v[c];
      measure[el.first_row + r] = el.measure;
    }
    model.project(e, value, out);
    for(int r = 0; r < el.rows; ++r)
      for(int c = 0; c < 3; ++c) P(el.first_row + r, c) = out[3 * r + c];
  }
  // Rounding of O(1) eigen-decompositions and QR over ~2,000 rows.
  EXPECT_LT((V.transpose() * measure.asDiagonal() * V - Eigen::MatrixXd::Identity(l, l)).cwiseAbs().maxCoeff(), 1e-9);
  const Eigen::MatrixXd coefficients = V.transpose() * measure.asDiagonal() * P; // D-orthogonal projection onto V
  EXPECT_LT((V * coefficients - P).norm(), 1e-10 * P.norm());

  const PD::internal::Projection_subspace_factors f = PD::internal::projection_subspace_factors(model, 0, 20, 2.2, l);
  const std::vector<int> rows = {0, 7, 100, int(S.rows()) - 1};
  const Eigen::MatrixXd some = f.rows_of_V(rows);
  for(std::size_t q = 0; q < rows.size(); ++q)
    EXPECT_LT((some.row(Eigen::Index(q)) - V.row(rows[q])).norm(), 1e-12 * V.norm()) << "row " << rows[q];
  const PD::Position_subspace U = PD::make_position_subspace(model, 10);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> Ut = U.basis.transpose();
  const Eigen::MatrixXd F = Eigen::MatrixXd(U.basis).transpose() * Eigen::MatrixXd(S).transpose() * measure.asDiagonal() * V;
  EXPECT_LT((f.projected(S, Ut) - F).norm(), 1e-12 * F.norm());
}

TEST(ProjectiveDynamicsReduced, RestStateStaysAtRest)
{
  for(bool hyper : {false, true})
  {
    PD::Simulator_options o;
    o.gravity.setZero();
    PD::Reduction_options r = small_hyper();
    r.hyper_reduction = hyper;
    PD::Reduced_simulator sim(box_model(), o, r);
    for(int t = 0; t < 20; ++t) sim.step();
    // Rest projections are exact at rest (F = I is its own projection) and in V exactly:
    // only rounding of k x k solves of a matrix with entries ~ m/h^2 moves anything.
    EXPECT_LT((sim.positions() - sim.model().rest_positions()).cwiseAbs().maxCoeff(), 1e-10) << "hyper " << hyper;
  }
}

TEST(ProjectiveDynamicsReduced, RigidlyMovedRestStateStaysStill)
{
  // U spans rigid motions exactly, the projections rotate with F, and the projection subspace
  // holds the rest projections times any 3x3 mixing: a rotated and shifted rest shape is an
  // equilibrium of reduced and hyper-reduced PD alike.
  std::mt19937 rng(17);
  for(bool hyper : {false, true})
  {
    PD::Simulator_options o;
    o.gravity.setZero();
    PD::Reduction_options r = small_hyper();
    r.hyper_reduction = hyper;
    const PD::Elastic_model model = box_model();
    PD::Reduced_simulator sim(model, o, r);
    const Eigen::Matrix3d R = pd_test::random_rotation(rng);
    const Eigen::RowVector3d t(0.3, -1.2, 2.0);
    PD::Positions moved = model.rest_positions() * R.transpose();
    moved.rowwise() += t;
    sim.set_positions(moved); // exact: the rigid motion is in the subspace
    for(int step = 0; step < 20; ++step) sim.step();
    // Rounding of k x k solves with entries ~ m/h^2 over 20 steps.
    EXPECT_LT((sim.positions() - moved).cwiseAbs().maxCoeff(), 1e-9) << "hyper " << hyper;
  }
}

TEST(ProjectiveDynamicsReduced, IdentityBasisReproducesFullSimulator)
{
  const PD::Elastic_model model = box_model(3e3);
  const int n = model.number_of_vertices();
  Eigen::SparseMatrix<double, Eigen::RowMajor> I(n, n);
  I.setIdentity();
  PD::Simulator_options o;
  PD::Reduction_options r;
  r.hyper_reduction = false; // every element projected
  PD::Simulator full(model, o);
  PD::Reduced_simulator reduced(model, I, o, r);
  std::mt19937 rng(5);
  const PD::Positions start = jittered(model.rest_positions(), 0.05, rng);
  full.set_positions(start);
  reduced.set_positions(start);
  for(int t = 0; t < 30; ++t)
  {
    full.step();
    reduced.step();
  }
  // Same arithmetic up to summation order and the dense versus sparse Cholesky: rounding.
  const double scale = full.positions().cwiseAbs().maxCoeff();
  EXPECT_LT((reduced.positions() - full.positions()).cwiseAbs().maxCoeff(), 1e-9 * scale);
}

TEST(ProjectiveDynamicsReduced, ObjectiveNeverIncreasesPerIteration)
{
  const PD::Elastic_model model = box_model(1e4);
  PD::Simulator_options o;
  o.iterations = 15;
  PD::Reduction_options r;
  r.samples = 15;
  r.hyper_reduction = false;
  PD::Reduced_simulator sim(model, o, r);
  std::mt19937 rng(9);
  sim.set_positions(jittered(model.rest_positions(), 0.1, rng));
  const PD::Tet_mesh mesh = small_box();
  const PD::Positions x = model.rest_positions();
  const Eigen::VectorXd& m = model.masses();
  const double h = o.time_step, k = 1e4;
  for(int t = 0; t < 5; ++t)
  {
    const PD::Positions s = [&] {
      PD::Positions p = sim.positions() + h * sim.velocities();
      for(Eigen::Index i = 0; i < p.rows(); ++i) p.row(i) += h * h * o.gravity.transpose();
      return p;
    }();
    std::vector<double> g;
    sim.step([&](int, const Eigen::MatrixXd& a) {
      const PD::Positions q = sim.basis() * a;
      double value = m_norm2(q - s, m) / (2 * h * h);
      for(const auto& tet : mesh.tetrahedra)
      {
        Eigen::Matrix3d Dm, Ds;
        for(int c = 0; c < 3; ++c)
        {
          Dm.col(c) = (x.row(tet[c + 1]) - x.row(tet[0])).transpose();
          Ds.col(c) = (q.row(tet[c + 1]) - q.row(tet[0])).transpose();
        }
        value += k * std::abs(Dm.determinant()) / 6 / 2 * squared_distance_to_rotations(Ds * Dm.inverse());
      }
      g.push_back(value);
    });
    for(std::size_t i = 1; i < g.size(); ++i)
      EXPECT_LE(g[i], g[i - 1] * (1 + 1e-10)) << "step " << t << " iteration " << i; // rounding of sums of ~1e3 terms
  }
}

TEST(ProjectiveDynamicsReduced, LinearMomentumConserved)
{
  for(bool hyper : {false, true})
  {
    PD::Simulator_options o;
    o.gravity.setZero();
    PD::Reduction_options r = small_hyper();
    r.hyper_reduction = hyper;
    const PD::Elastic_model model = box_model();
    PD::Reduced_simulator sim(model, o, r);
    std::mt19937 rng(21);
    sim.set_positions(jittered(model.rest_positions(), 0.08, rng));
    PD::Positions v = jittered(PD::Positions::Zero(model.number_of_vertices(), 3), 1.0, rng);
    sim.set_velocities(v);
    const Eigen::VectorXd& m = model.masses();
    const Eigen::RowVector3d p0 = m.transpose() * sim.velocities();
    for(int t = 0; t < 20; ++t) sim.step();
    const Eigen::RowVector3d p1 = m.transpose() * sim.velocities();
    // Exact in exact arithmetic (S 1 = 0, U spans the constants); rounding relative to the
    // largest momentum of a vertex times the count.
    EXPECT_LT((p1 - p0).norm(), 1e-9 * (m.sum() * 1.0)) << "hyper " << hyper << ": " << p0 << " -> " << p1;
  }
}

TEST(ProjectiveDynamicsReduced, HugeStepsAndScrambledStartsStayFinite)
{
  for(bool hyper : {false, true})
  {
    PD::Simulator_options o;
    o.time_step = 1e3;
    PD::Reduction_options r = small_hyper();
    r.hyper_reduction = hyper;
    const PD::Elastic_model model = box_model();
    PD::Reduced_simulator sim(model, o, r);
    std::mt19937 rng(2);
    sim.set_positions(jittered(model.rest_positions(), 2.0, rng));
    sim.add_floor({0, 0, -1}, {0, 0, 1});
    for(int t = 0; t < 10; ++t) ASSERT_NO_THROW(sim.step());
    EXPECT_TRUE(sim.positions().allFinite());
    EXPECT_TRUE(sim.velocities().allFinite());
  }
}

TEST(ProjectiveDynamicsReduced, FloorHoldsAtCollisionVerticesAndGrabsPull)
{
  // Hyper-reduced or not; the samples' basis (pushed by its translations) or the same basis
  // handed in as an explicit one (pushed by all its columns near the contact).
  for(int variant = 0; variant < 3; ++variant)
  {
    const bool hyper = variant != 0;
    PD::Reduction_options r = small_hyper();
    r.hyper_reduction = hyper;
    const PD::Elastic_model model = box_model();
    PD::Reduced_simulator sim = variant < 2 ? PD::Reduced_simulator(model, PD::Simulator_options(), r)
                                            : PD::Reduced_simulator(model, PD::make_position_subspace(model, r.samples, r.radius_multiplier).basis,
                                                                    PD::Simulator_options(), r);
    std::vector<int> all(std::size_t(model.number_of_vertices()));
    for(std::size_t i = 0; i < all.size(); ++i) all[i] = int(i);
    sim.set_collision_vertices(all);
    sim.add_floor({0, 0, -0.3}, {0, 0, 1});
    double lowest = 1e300;
    for(int t = 0; t < 60; ++t)
    {
      sim.step();
      lowest = std::min(lowest, sim.positions().col(2).minCoeff());
    }
    // Every collision vertex on or above the floor after each step (the push leaves them at
    // least a relative 1e-10 of the extent above it, far more than the rounding of U a).
    EXPECT_GE(lowest, -0.3) << "variant " << variant;
    EXPECT_LT(lowest, -0.3 + 1e-3) << "variant " << variant << ": it never reached the floor";
    // A grabbed corner follows its target (soft: within a few millimetres of 5 cm).
    const PD::Positions start = sim.positions_of({0});
    PD::Positions target = start;
    target(0, 2) += 0.05;
    sim.grab({0}, target);
    for(int t = 0; t < 30; ++t) sim.step();
    EXPECT_LT((sim.positions_of({0}) - target).norm(), 0.01) << "variant " << variant << ": " << start << " -> " << sim.positions_of({0}) << " target " << target;
  }
}

TEST(ProjectiveDynamicsReduced, StiffnessAndTimeStepRefactorOnlyK)
{
  PD::Reduced_simulator sim(box_model(), params::number_of_samples(10).hyper_reduction(false));
  sim.step();
  EXPECT_EQ(sim.number_of_factorizations(), 1);
  sim.set_stiffness(0, 2e4);
  sim.set_time_step(1.0 / 60);
  sim.step();
  EXPECT_EQ(sim.number_of_factorizations(), 2);
  EXPECT_EQ(sim.positions_of({3, 5}).row(1), sim.positions().row(5));
}

TEST(ProjectiveDynamicsReduced, ErrorAgainstFullFallsAsKGrows)
{
  // A cantilever (1 x .2 x .2 m, 1e5 Pa, 1e3 kg/m^3) pinned at x = 0, sagging for 100 frames.
  const PD::Tet_mesh mesh = PD::make_tet_rod(15, 3, 1.0, 0.2);
  const PD::Elastic_model model = PD::make_solid_model(mesh, params::strain_stiffness(1e5).density(1e3));
  std::vector<int> pinned;
  for(std::size_t v = 0; v < mesh.points.size(); ++v)
    if(mesh.points[v][0] == 0) pinned.push_back(int(v));
  PD::Simulator_options o;
  o.time_step = 1.0 / 60;
  PD::Simulator full(model, o);
  full.set_pinned_vertices(pinned);
  std::vector<PD::Positions> truth;
  for(int t = 0; t < 100; ++t) full.step(), truth.push_back(full.positions());
  const Eigen::VectorXd& m = model.masses();
  double motion = 0;
  for(const auto& q : truth) motion += m_norm2(q - model.rest_positions(), m);
  auto error = [&](PD::Reduced_simulator sim) {
    sim.set_pinned_vertices(pinned);
    double e = 0;
    for(int t = 0; t < 100; ++t) sim.step(), e += m_norm2(sim.positions() - truth[std::size_t(t)], m);
    return std::sqrt(e / motion);
  };
  std::vector<double> errors;
  for(int samples : {4, 8, 16, 32})
  {
    PD::Reduction_options r;
    r.samples = samples;
    r.hyper_reduction = false;
    errors.push_back(error(PD::Reduced_simulator(model, o, r)));
    PD::Reduction_options hr = r;
    hr.hyper_reduction = true, hr.constraint_samples = 30, hr.projection_columns = 60, hr.sampled_elements = 300;
    const double hyper = error(PD::Reduced_simulator(model, o, hr));
    std::printf("  k = %3d: relative M-norm error, reduced %.4f, hyper-reduced (l 60, s 300) %.4f\n", 4 * samples,
                errors.back(), hyper);
  }
  // The largest subspace clearly better than the smallest, and its trajectory within a third of
  // the motion (a loose bound: 128 columns for 256 vertices; what remains we read as mostly
  // phase -- the subspace stiffens the rod, so it swings a little faster, and over 100 frames the
  // difference accumulates -- and the soft pins; measured 0.21).  (64 samples on this
  // coarse rod leave some samples a support too small to span affine maps: refused.)
  EXPECT_LT(errors.back(), 0.5 * errors.front());
  EXPECT_LT(errors.back(), 0.35);
}

TEST(ProjectiveDynamicsReduced, BadInputRefusedWithReason)
{
  const PD::Elastic_model model = box_model();
  const int n = model.number_of_vertices();
  PD::Simulator_options o;
  PD::Reduction_options r;
  r.samples = n + 1;
  EXPECT_THROW_REASON(PD::Reduced_simulator(model, o, r), PD::Invalid_input, "number of position samples");
  r = small_hyper();
  r.sampled_elements = r.projection_columns + 19;
  EXPECT_THROW_REASON(PD::Reduced_simulator(model, o, r), PD::Invalid_input, "fewer than l + 20");
  r = small_hyper();
  r.radius_multiplier = 1.0;
  EXPECT_THROW_REASON(PD::Reduced_simulator(model, o, r), PD::Invalid_input, "above 1");
  o.time_step = -1;
  EXPECT_THROW_REASON(PD::Reduced_simulator(model, o, small_hyper()), PD::Invalid_input, "time step");
  o = PD::Simulator_options();
  r = small_hyper();
  r.constraint_samples = 5; // 20 candidate columns for l = 40
  EXPECT_THROW_REASON(PD::Reduced_simulator(model, o, r), PD::Invalid_input, "exceeds the 4 candidate columns");
  {
    // A basis that cannot reproduce the rest shape (only translations).
    Eigen::SparseMatrix<double, Eigen::RowMajor> T(n, 1);
    for(int i = 0; i < n; ++i) T.insert(i, 0) = 1;
    EXPECT_THROW_REASON(PD::Reduced_simulator(model, T, o, small_hyper()), PD::Invalid_input, "does not reproduce the rest positions");
  }
  PD::Reduced_simulator sim(model, o, small_hyper());
  EXPECT_THROW_REASON(sim.set_stiffness(0, -1), PD::Invalid_input, "stiffness");
  EXPECT_THROW_REASON(sim.positions_of({n}), PD::Invalid_input, "outside");
  // Two separate boxes and one sample: the second is reached by no sample.
  PD::Tet_mesh two = small_box();
  const PD::Tet_mesh other = PD::make_tet_box(2, 2, 2, {5, 0, 0}, {6, 1, 1});
  const int offset = int(two.points.size());
  two.points.insert(two.points.end(), other.points.begin(), other.points.end());
  for(auto t : other.tetrahedra)
  {
    for(int& v : t) v += offset;
    two.tetrahedra.push_back(t);
  }
  two.triangles.clear();
  const PD::Elastic_model split = PD::make_solid_model(two);
  EXPECT_THROW_REASON(PD::make_position_subspace(split, 1), PD::Invalid_input, "reached by no sample");
  EXPECT_NO_THROW(PD::make_position_subspace(split, 2));
}
