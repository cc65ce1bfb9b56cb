// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Reduced and hyper-reduced Projective Dynamics against independent truth: the position
// subspace reproduces affine maps exactly; the rest state stays still; the identity basis with
// every element projected reproduces the full Simulator; the PCA keeps the leading directions
// of a dense eigen-decomposition done here; g (recomputed here) never increases per iteration;
// linear momentum is conserved (also hyper-reduced); huge steps and scrambled starts stay
// finite; the error against full PD falls as k grows; bad input is refused with its reason;
// a saved precomputation loads to the same trajectory, bit for bit, and is refused for another
// model or other reduction options, or when truncated or corrupt; the precomputation reports its
// progress and can be cancelled.

#include "expect_reason.h"
#include "pd_test_support.h"
#include "scratch_path.h"

#include <CGAL/Projective_dynamics/Position_subspace.h>
#include <CGAL/Projective_dynamics/Projection_subspace.h>
#include <CGAL/Projective_dynamics/Reduced_simulator.h>
#include <CGAL/Projective_dynamics/Simulator.h>
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

PD::Tet_mesh small_box() { return PD::make_tet_box(6, 3, 3, {0, 0, 0}, {1.2, .6, .6}); }

PD::Elastic_model box_model(double stiffness = 1e4)
{
  return PD::make_solid_model(small_box(), params::strain_stiffness(stiffness).density(1e3));
}

// Hyper-reduction sized for the small box (216 tetrahedra... 324): l = 40, s = 80.
PD::Reduction_options small_hyper(int samples = 12)
{
  PD::Reduction_options r;
  r.samples = samples;
  r.constraint_samples = 20;
  r.projection_columns = 40;
  r.sampled_elements = 80;
  return r;
}

PD::Positions jittered(const PD::Positions& x, double amount, std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(-amount, amount);
  PD::Positions y = x;
  for(Eigen::Index i = 0; i < y.size(); ++i) y.data()[i] += u(rng);
  return y;
}

double m_norm2(const PD::Positions& d, const Eigen::VectorXd& m)
{
  double s = 0;
  for(Eigen::Index i = 0; i < d.rows(); ++i) s += m[i] * d.row(i).squaredNorm();
  return s;
}

// dist^2(F, SO(3)) from the signed singular values via the eigenvalues of F^T F.
double squared_distance_to_rotations(const Eigen::Matrix3d& F)
{
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(F.transpose() * F);
  Eigen::Vector3d s = eig.eigenvalues().cwiseMax(0).cwiseSqrt();
  if(F.determinant() < 0) s[0] = -s[0];
  return (s - Eigen::Vector3d::Ones()).squaredNorm();
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
  for(bool hyper : {false, true})
  {
    PD::Reduction_options r = small_hyper();
    r.hyper_reduction = hyper;
    const PD::Elastic_model model = box_model();
    PD::Reduced_simulator sim(model, PD::Simulator_options(), r);
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
    // Every collision vertex on or above the floor after each step, up to what ten rounds of
    // pushes leave (a push of some vertices can move others below; 1e-5 m here).
    EXPECT_GT(lowest, -0.3 - 1e-5) << "hyper " << hyper;
    EXPECT_LT(lowest, -0.3 + 1e-3) << "hyper " << hyper << ": it never reached the floor";
    // A grabbed corner follows its target (soft: within a few millimetres of 5 cm).
    const PD::Positions start = sim.positions_of({0});
    PD::Positions target = start;
    target(0, 2) += 0.05;
    sim.grab({0}, target);
    for(int t = 0; t < 30; ++t) sim.step();
    EXPECT_LT((sim.positions_of({0}) - target).norm(), 0.01) << "hyper " << hyper << ": " << start << " -> " << sim.positions_of({0}) << " target " << target;
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

namespace {

std::vector<char> file_bytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write_bytes(const std::string& path, const std::vector<char>& bytes, std::size_t count)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(count));
}

// A scene: gravity, a floor the box falls onto, one pinned corner; `steps` steps.
std::vector<PD::Positions> trajectory(PD::Reduced_simulator& sim, int steps)
{
  sim.set_pinned_vertices({0});
  sim.add_floor({0, 0, -0.1}, {0, 0, 1});
  std::vector<PD::Positions> out;
  for(int t = 0; t < steps; ++t) sim.step(), out.push_back(sim.positions());
  return out;
}

PD::Elastic_model model_of(const PD::Tet_mesh& mesh)
{
  return PD::make_solid_model(mesh, params::strain_stiffness(1e4).density(1e3));
}

// The box's tetrahedra in two groups (halves of 162), of stiffness 1e4 and 2e4.
PD::Elastic_model two_group_box()
{
  const PD::Tet_mesh mesh = small_box();
  PD::Positions x(Eigen::Index(mesh.points.size()), 3);
  for(std::size_t i = 0; i < mesh.points.size(); ++i)
    for(int c = 0; c < 3; ++c) x(Eigen::Index(i), c) = mesh.points[i][std::size_t(c)];
  PD::Elastic_model model(x, PD::lumped_masses(mesh.points, mesh.tetrahedra, 1e3));
  const std::size_t half = mesh.tetrahedra.size() / 2;
  model.add_tet_strain({mesh.tetrahedra.begin(), mesh.tetrahedra.begin() + std::ptrdiff_t(half)}, 1e4);
  model.add_tet_strain({mesh.tetrahedra.begin() + std::ptrdiff_t(half), mesh.tetrahedra.end()}, 2e4);
  return model;
}

} // namespace

TEST(ProjectiveDynamicsReduced, SavedPrecomputationLoadsToTheSameTrajectory)
{
  for(bool hyper : {false, true})
  {
    PD::Reduction_options r = small_hyper();
    r.hyper_reduction = hyper;
    PD::Simulator_options o;
    o.time_step = 1.0 / 60;
    const std::string path = tvf_test::scratch_path(hyper ? "hyper.pdr" : "reduced.pdr");
    PD::Reduced_simulator made(box_model(), o, r);
    made.save(path);
    // Loaded with another time step, iterations and stiffness, then given the saved ones: only
    // K depends on them.
    PD::Simulator_options other = o;
    other.time_step = 1.0 / 30, other.iterations = 3;
    PD::Reduced_simulator loaded = PD::Reduced_simulator::load(box_model(5e3), path, other, r);
    EXPECT_EQ(loaded.dimension(), made.dimension());
    EXPECT_EQ(loaded.samples(), made.samples());
    EXPECT_EQ(loaded.sampled_elements(), made.sampled_elements());
    EXPECT_EQ(loaded.used_vertices(), made.used_vertices());
    loaded.set_time_step(o.time_step);
    loaded.set_iterations(o.iterations);
    loaded.set_stiffness(0, 1e4);
    const std::vector<PD::Positions> a = trajectory(made, 40), b = trajectory(loaded, 40);
    double largest = 0;
    for(std::size_t t = 0; t < a.size(); ++t) largest = std::max(largest, (a[t] - b[t]).cwiseAbs().maxCoeff());
    EXPECT_EQ(largest, 0.0) << "hyper " << hyper << ": the loaded simulator's trajectory differs";
    // It moved (fell onto the floor), so the comparison says something.
    EXPECT_GT((a.back() - box_model().rest_positions()).norm(), 0.01) << "hyper " << hyper;
    // Two element groups, each with its own stiffness, saved and loaded.
    {
      PD::Reduced_simulator two(two_group_box(), o, r);
      two.save(path);
      PD::Reduced_simulator again = PD::Reduced_simulator::load(two_group_box(), path, o, r);
      EXPECT_EQ(trajectory(two, 10).back(), trajectory(again, 10).back()) << "hyper " << hyper << ", two groups";
      EXPECT_THROW_REASON(PD::Reduced_simulator::load(box_model(), path, o, r), PD::Invalid_input, "made for 2 element groups, the model has 1");
      made.save(path);
    }
    // The named-parameter form, and its own stiffness and density (masses are not saved).
    if(hyper)
      EXPECT_NO_THROW(PD::Reduced_simulator::load(
          PD::make_solid_model(small_box(), params::strain_stiffness(2e4).density(500)), path,
          params::number_of_samples(12).number_of_constraint_samples(20).number_of_projection_columns(40)
              .number_of_sampled_elements(80).pin_stiffness(10).time_step(0.01)));
  }
}

TEST(ProjectiveDynamicsReduced, SavedExplicitBasisLoadsToTheSameTrajectory)
{
  // An explicit basis (the identity, every element projected) is saved as well; its samples
  // option is not compared.
  const PD::Elastic_model model = box_model();
  const int n = model.number_of_vertices();
  Eigen::SparseMatrix<double, Eigen::RowMajor> identity(n, n);
  identity.setIdentity();
  PD::Reduction_options r = small_hyper();
  r.hyper_reduction = false;
  const PD::Simulator_options o;
  const std::string path = tvf_test::scratch_path("identity.pdr");
  PD::Reduced_simulator made(model, identity, o, r);
  made.save(path);
  r.samples = 3;
  PD::Reduced_simulator loaded = PD::Reduced_simulator::load(model, path, o, r);
  EXPECT_TRUE(loaded.samples().empty());
  EXPECT_EQ(trajectory(made, 10).back(), trajectory(loaded, 10).back());
  r.hyper_reduction = true;
  EXPECT_THROW_REASON(PD::Reduced_simulator::load(model, path, o, r), PD::Invalid_input, "hyper_reduction false in the file, true given");
}

TEST(ProjectiveDynamicsReduced, LoadRefusesAnotherModelOrOptions)
{
  const std::string path = tvf_test::scratch_path("box.pdr");
  const PD::Simulator_options o;
  const PD::Reduction_options r = small_hyper();
  PD::Reduced_simulator(box_model(), o, r).save(path);
  auto load = [&](const PD::Elastic_model& model, const PD::Reduction_options& options) {
    PD::Reduced_simulator::load(model, path, o, options);
  };
  EXPECT_NO_THROW(load(box_model(), r));
  // One vertex moved by 1 mm.
  PD::Tet_mesh moved = small_box();
  moved.points[7][1] += 1e-3;
  EXPECT_THROW_REASON(load(model_of(moved), r), PD::Invalid_input, "it belongs to a mesh with other edge lengths");
  // Another mesh.
  EXPECT_THROW_REASON(load(model_of(PD::make_tet_box(5, 3, 3, {0, 0, 0}, {1.2, .6, .6})), r), PD::Invalid_input,
                      "it belongs to a mesh with other connectivity");
  // The same mesh moved as a whole (the basis holds rest coordinates).
  PD::Tet_mesh shifted = small_box();
  for(auto& p : shifted.points) p[0] += 1;
  EXPECT_THROW_REASON(load(model_of(shifted), r), PD::Invalid_input, "its rest positions are elsewhere");
  // Other strain limits: other projections, other projection subspaces.
  EXPECT_THROW_REASON(load(PD::make_solid_model(small_box(), params::strain_stiffness(1e4).density(1e3).strain_limits(std::make_pair(0.9, 1.1))), r),
                      PD::Invalid_input, "element group 0 has other constraint sets");
  // A second element group.
  {
    PD::Elastic_model two = box_model();
    two.add_springs(std::vector<PD::Edge>{PD::Edge{{0, 1}}}, 10);
    EXPECT_THROW_REASON(load(two, r), PD::Invalid_input, "connectivity");
  }
  // Other reduction options, each named.
  PD::Reduction_options other = r;
  other.samples = 10;
  EXPECT_THROW_REASON(load(box_model(), other), PD::Invalid_input,
                      "made with other reduction options: number_of_samples 12 in the file, 10 given");
  other = r, other.radius_multiplier = 1.2;
  EXPECT_THROW_REASON(load(box_model(), other), PD::Invalid_input, "radius_multiplier 1.1 in the file, 1.2 given");
  other = r, other.projection_columns = 30;
  EXPECT_THROW_REASON(load(box_model(), other), PD::Invalid_input, "number_of_projection_columns 40 in the file, 30 given");
  other = r, other.sampled_elements = 90;
  EXPECT_THROW_REASON(load(box_model(), other), PD::Invalid_input, "number_of_sampled_elements 80 in the file, 90 given");
  other = r, other.constraint_samples = 21;
  EXPECT_THROW_REASON(load(box_model(), other), PD::Invalid_input, "number_of_constraint_samples 20 in the file, 21 given");
  other = r, other.hyper_reduction = false;
  EXPECT_THROW_REASON(load(box_model(), other), PD::Invalid_input, "hyper_reduction true in the file, false given");
  // The pin stiffness is a run-time parameter.
  other = r, other.pin_stiffness = 5;
  EXPECT_NO_THROW(load(box_model(), other));
  // No file, and a file of something else.
  EXPECT_THROW_REASON(PD::Reduced_simulator::load(box_model(), path + ".missing", o, r), PD::Invalid_input,
                      "cannot open the reduced simulator file");
  const std::string text = tvf_test::scratch_path("not.pdr");
  std::ofstream(text) << "MeshVersionFormatted 2\nDimension 3\nVertices\n0\nEnd\n";
  EXPECT_THROW_REASON(PD::Reduced_simulator::load(box_model(), text, o, r), PD::Invalid_input, "not a reduced simulator file");
}

TEST(ProjectiveDynamicsReduced, TruncatedOrCorruptFileRefused)
{
  const std::string path = tvf_test::scratch_path("whole.pdr"), bad = tvf_test::scratch_path("bad.pdr");
  const PD::Simulator_options o;
  const PD::Reduction_options r = small_hyper();
  const PD::Elastic_model model = box_model();
  PD::Reduced_simulator(model, o, r).save(path);
  const std::vector<char> bytes = file_bytes(path);
  ASSERT_GT(bytes.size(), 1000u);
  auto load_bad = [&] { PD::Reduced_simulator::load(model, bad, o, r); };
  // Truncated anywhere: refused, "truncated" (or no end marker when only it is cut).
  for(std::size_t cut : {std::size_t(0), std::size_t(5), std::size_t(64), std::size_t(200), bytes.size() / 2, bytes.size() - 9})
  {
    write_bytes(bad, bytes, cut);
    EXPECT_THROW_REASON(load_bad(), PD::Invalid_input, "the file is truncated");
  }
  write_bytes(bad, bytes, bytes.size() - 1);
  EXPECT_THROW_REASON(load_bad(), PD::Invalid_input, "cannot load the reduced simulator from");
  // A basis column index out of range (the first one: after the header of 64 bytes, the
  // position signature, one group, the options, U's size and its row starts).
  const int n = model.number_of_vertices();
  const std::size_t first_column = 64 + 32 + 4 + 20 + 34 + 16 + 8 + 4 * (std::size_t(n) + 1) + 8;
  std::vector<char> corrupt = bytes;
  const std::int32_t huge = 1 << 30;
  std::memcpy(corrupt.data() + first_column, &huge, 4);
  write_bytes(bad, corrupt, corrupt.size());
  EXPECT_THROW_REASON(load_bad(), PD::Invalid_input, "the file is corrupt (a basis column index)");
  // A NaN in the first basis value (after the column indices and the values' matrix size).
  corrupt = bytes;
  std::int64_t nonzeros = 0;
  std::memcpy(&nonzeros, bytes.data() + first_column - 8, 8);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::memcpy(corrupt.data() + first_column + 4 * std::size_t(nonzeros) + 16, &nan, 8);
  write_bytes(bad, corrupt, corrupt.size());
  EXPECT_THROW_REASON(load_bad(), PD::Invalid_input, "non-finite");
  // Bytes flipped, densely in the structure before the numbers (header, groups, options, U's
  // sizes, row starts and first column indices) and sparsely in the numbers: refused with a
  // reason or loaded (a changed number can be a valid one), never a crash or another exception.
  std::vector<std::size_t> places;
  for(std::size_t at = 0; at < first_column + 64; at += 7) places.push_back(at);
  for(std::size_t at = first_column + 64; at < bytes.size(); at += bytes.size() / 60) places.push_back(at);
  int refused = 0;
  for(std::size_t at : places)
  {
    corrupt = bytes;
    corrupt[at] = char(corrupt[at] ^ 0x5a);
    write_bytes(bad, corrupt, corrupt.size());
    try
    {
      load_bad();
    }
    catch(const PD::Invalid_input& e)
    {
      ++refused;
      EXPECT_NE(std::string(e.what()).find("cannot load the reduced simulator from"), std::string::npos) << e.what();
    }
  }
  // Most flips in the structure are caught (a flip in a low bit of a signature is rounding).
  EXPECT_GT(refused, int(places.size()) / 3) << places.size() << " flips";
}

TEST(ProjectiveDynamicsReduced, PrecomputationReportsProgressAndCanBeCancelled)
{
  for(bool hyper : {false, true})
  {
    std::vector<PD::Reduced_precomputation_progress> seen;
    PD::Reduction_options r = small_hyper();
    r.hyper_reduction = hyper;
    r.progress = [&](const PD::Reduced_precomputation_progress& p) { return seen.push_back(p), true; };
    // Two element groups: progress within the stages, per group.
    PD::Reduced_simulator sim(two_group_box(), PD::Simulator_options(), r);
    ASSERT_GE(seen.size(), hyper ? 7u : 4u);
    EXPECT_EQ(seen.front().fraction, 0.0);
    EXPECT_EQ(seen.front().stage, "position subspace");
    for(std::size_t q = 1; q < seen.size(); ++q)
      EXPECT_GE(seen[q].fraction, seen[q - 1].fraction) << seen[q - 1].stage << " -> " << seen[q].stage;
    EXPECT_EQ(seen.back().fraction, 1.0);
    EXPECT_EQ(seen.back().stage, "done");
    bool projected = false, subspaces = false;
    for(const auto& p : seen) projected |= p.stage == "projected matrices", subspaces |= p.stage == "projection subspaces";
    EXPECT_TRUE(projected);
    EXPECT_EQ(subspaces, hyper);
  }
  // The named parameter, void form.
  int calls = 0;
  double last = -1;
  PD::Reduced_simulator sim(box_model(), params::number_of_samples(12).number_of_constraint_samples(20)
                                             .number_of_projection_columns(40).number_of_sampled_elements(80)
                                             .progress_callback([&](const PD::Reduced_precomputation_progress& p) {
                                               ++calls, last = p.fraction;
                                             }));
  EXPECT_GT(calls, 2);
  EXPECT_EQ(last, 1.0);
  // False cancels.
  EXPECT_THROW_REASON(PD::Reduced_simulator(box_model(), params::number_of_samples(12).number_of_constraint_samples(20)
                                                             .number_of_projection_columns(40).number_of_sampled_elements(80)
                                                             .progress_callback([](const PD::Reduced_precomputation_progress& p) {
                                                               return p.stage != "projection subspaces";
                                                             })),
                      PD::Cancelled, "cancelled (at \"projection subspaces\")");
}
