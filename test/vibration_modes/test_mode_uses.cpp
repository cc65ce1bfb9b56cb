// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The uses of modes against independent truth: the linear simulation against the closed form
// of one mode (with the integrator's derived period error), the reduced simulation on every
// mode against the full one, energy conservation, error falling with k; elastic modelling on
// every mode against the full KKT solution, handles met, rigid translations reproduced;
// segmentation of a dumbbell into its two spheres; saved modes read back exactly and refused
// on another mesh, position, pins or stiffness with the reason.

#include "expect_reason.h"
#include "scratch_path.h"
#include "shell_test_meshes.h"

#include <CGAL/Vibration_modes/Elastic_deformer.h>
#include <CGAL/Vibration_modes/compressed_modes.h>
#include <CGAL/Vibration_modes/errors.h>
#include <CGAL/Vibration_modes/linear_simulation.h>
#include <CGAL/Vibration_modes/lowest_vibration_modes.h>
#include <CGAL/Vibration_modes/mode_segmentation.h>
#include <CGAL/Vibration_modes/modes_file.h>
#include <CGAL/Vibration_modes/vibration_modes.h>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <fstream>
#include <set>

using namespace shell_test;
namespace VM = CGAL::Vibration_modes;

namespace {

const DS::Shell_stiffness stiffness{1, 1, 0.01};

VM::Mode_problem problem_of(const Mesh& mesh, const std::vector<int>& pinned = {})
{
  return VM::shell_mode_problem(DS::Shell_energy(DS::stacked_positions(mesh), triangles_of(mesh), stiffness), pinned);
}

// Every generalised eigenpair of a small problem by Eigen's dense solver (independent of the
// package's eigensolver); the first kernel.cols() are the rigid motions.
Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense_pairs(const VM::Mode_problem& p)
{
  return Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(p.H), Eigen::MatrixXd(p.mass.asDiagonal()));
}

double m_norm(const VM::Mode_problem& p, const Eigen::VectorXd& u) { return std::sqrt(u.dot(p.mass.cwiseProduct(u))); }

} // namespace

// ---------------------------------------------------------------- linear simulation

TEST(LinearSimulation, OneModeOscillatesWithTheDerivedDiscreteFrequency)
{
  const VM::Mode_problem p = problem_of(lumpy_sphere(1));
  const auto dense = dense_pairs(p);
  const double lambda = dense.eigenvalues()[8], omega = std::sqrt(lambda);
  const Eigen::VectorXd phi = dense.eigenvectors().col(8);
  VM::Linear_simulation_options o;
  o.time_step = 0.5 / omega; // h omega = 0.5: a period error of 2 %, far above rounding
  o.steps = 200;
  o.initial_displacement = phi;
  const VM::Linear_trajectory t = VM::full_linear_simulation(p, o);
  ASSERT_EQ(t.displacements.cols(), 201);
  // Derived (linear_simulation.h): u_n = cos(n h Omega) phi, tan(h Omega / 2) = h omega / 2.
  const double Omega = 2 / o.time_step * std::atan(0.5 * o.time_step * omega);
  double worst = 0, against_exact = 0;
  for(Eigen::Index n = 0; n < t.displacements.cols(); ++n)
  {
    worst = std::max(worst, m_norm(p, t.displacements.col(n) - std::cos(t.times[n] * Omega) * phi));
    against_exact = std::max(against_exact, m_norm(p, t.displacements.col(n) - std::cos(t.times[n] * omega) * phi));
  }
  // Each step solves with CHOLMOD (relative error ~1e-15 times the condition of the step
  // matrix, here ~1e4): 1e-9 after 200 steps leaves room; the undiscretised cos(omega t) is
  // off by the period error (about 2 radians after 200 steps).
  EXPECT_LT(worst, 1e-9);
  EXPECT_GT(against_exact, 0.5);
}

TEST(LinearSimulation, ReducedOnEveryModeEqualsFull)
{
  const VM::Mode_problem p = problem_of(lumpy_sphere(1));
  const auto dense = dense_pairs(p);
  const Eigen::Index n = p.H.rows(), kernel = p.kernel.cols();
  ASSERT_EQ(kernel, 6);
  VM::Linear_simulation_options o;
  o.time_step = 0.05;
  o.steps = 100;
  o.output_every = 5;
  o.rayleigh_mass = 0.1;
  o.rayleigh_stiffness = 1e-3;
  o.initial_displacement = random_vector(n, 3, 0.01);
  o.initial_velocity = random_vector(n, 4, 0.01);
  o.force = random_vector(n, 5, 0.1); // with a net force and torque: the body drifts and turns
  o.force_at_time = [](double t, Eigen::VectorXd& f) { f[7] = std::sin(3 * t); };
  const VM::Linear_trajectory full = VM::full_linear_simulation(p, o);
  const VM::Linear_trajectory reduced = VM::reduced_linear_simulation(p, dense.eigenvectors().rightCols(n - kernel), o);
  EXPECT_LT(VM::relative_trajectory_error(p, reduced, full), 1e-9);
  // Without the rigid motions the drift is lost.
  const VM::Linear_trajectory no_kernel =
      VM::reduced_linear_simulation(p, dense.eigenvectors().rightCols(n - kernel), o, false);
  EXPECT_GT(VM::relative_trajectory_error(p, no_kernel, full), 1e-2);
}

TEST(LinearSimulation, UndampedEnergyIsConservedAndDampingDissipates)
{
  const VM::Mode_problem p = problem_of(lumpy_sphere(2));
  const VM::Modes modes = VM::lowest_vibration_modes(p, 20);
  VM::Linear_simulation_options o;
  o.time_step = 0.3; // large steps: the rule is unconditionally stable
  o.steps = 300;
  o.initial_displacement = random_vector(p.H.rows(), 7, 0.01);
  o.initial_velocity = random_vector(p.H.rows(), 8, 0.01);
  for(const VM::Linear_trajectory& t :
      {VM::full_linear_simulation(p, o), VM::reduced_linear_simulation(p, modes, 20, o)})
  {
    // Exact for the trapezoidal rule on a linear system; rounding of 300 solves.
    EXPECT_LT((t.energies.array() - t.energies[0]).abs().maxCoeff(), 1e-10 * t.energies[0]);
  }
  o.rayleigh_mass = 0.05;
  const VM::Linear_trajectory damped = VM::full_linear_simulation(p, o);
  for(Eigen::Index i = 1; i < damped.energies.size(); ++i) EXPECT_LE(damped.energies[i], damped.energies[i - 1] * (1 + 1e-12));
  EXPECT_LT(damped.energies[damped.energies.size() - 1], 0.5 * damped.energies[0]);
}

TEST(LinearSimulation, ReducedErrorFallsAsModesAreAdded)
{
  // A shell held at one cap, pushed by a force on the other: a step load.
  const Mesh mesh = lumpy_sphere(3);
  const Eigen::VectorXd x = DS::stacked_positions(mesh);
  std::vector<int> pinned;
  Eigen::VectorXd force = Eigen::VectorXd::Zero(x.size());
  for(Eigen::Index v = 0; v < x.size() / 3; ++v)
  {
    if(x[3 * v + 2] < -0.8) pinned.push_back(int(v));
    if(x[3 * v + 2] > 0.7) force.segment<3>(3 * v) = Eigen::Vector3d(0.3, 0.1, -1) * 1e-2;
  }
  const VM::Mode_problem p = problem_of(mesh, pinned);
  ASSERT_EQ(p.kernel.cols(), 0);
  const VM::Modes modes = VM::lowest_vibration_modes(p, 80);
  VM::Linear_simulation_options o;
  o.time_step = 0.5 / std::sqrt(modes.energies[0]);
  o.steps = 100;
  o.force = force;
  const VM::Linear_trajectory full = VM::full_linear_simulation(p, o);
  double last = 1;
  for(int k : {5, 20, 80})
  {
    const double error = VM::relative_trajectory_error(p, VM::reduced_linear_simulation(p, modes, k, o), full);
    EXPECT_LT(error, last) << "k = " << k;
    last = error;
  }
  EXPECT_LT(last, 0.2);
}

TEST(LinearSimulation, ForcesAndFramesAsVertexMaps)
{
  Mesh mesh = lumpy_sphere(1);
  auto force = mesh.add_property_map<Vertex_index, Vector_3>("v:force", Vector_3(0, 0, 0)).first;
  force[Vertex_index(4)] = Vector_3(0, 0, -0.5);
  force[Vertex_index(9)] = Vector_3(0.25, 0, 0);
  const VM::Mode_problem p = VM::mesh_mode_problem(mesh, VM::parameters::bending_stiffness(0.01));
  VM::Linear_simulation_options o;
  o.steps = 10;
  o.force = VM::stacked_vertex_vectors(mesh, force);
  EXPECT_EQ(o.force[14], -0.5);
  EXPECT_EQ(o.force[27], 0.25);
  EXPECT_EQ(o.force.norm(), std::sqrt(0.3125));
  const VM::Linear_trajectory t = VM::full_linear_simulation(p, o);
  auto frame = mesh.add_property_map<Vertex_index, Vector_3>("v:displacement").first;
  VM::copy_displacement_to_vertex_map(mesh, t.displacements.col(10), frame);
  for(auto v : vertices(mesh))
    for(int c = 0; c < 3; ++c) EXPECT_EQ(frame[v][c], t.displacements(3 * Eigen::Index(v) + c, 10));
  EXPECT_THROW_REASON(VM::copy_displacement_to_vertex_map(mesh, Eigen::VectorXd::Zero(5), frame), VM::Invalid_input,
                      "not 3 per vertex");
  force[Vertex_index(2)] = Vector_3(0, std::nan(""), 0);
  EXPECT_THROW_REASON(VM::stacked_vertex_vectors(mesh, force), VM::Invalid_input, "vertex 2 is not finite");
}

TEST(LinearSimulation, RefusesBadInputWithTheReason)
{
  const VM::Mode_problem p = problem_of(lumpy_sphere(1));
  const VM::Modes modes = VM::lowest_vibration_modes(p, 5);
  VM::Linear_simulation_options o;
  o.time_step = -1;
  EXPECT_THROW_REASON(VM::full_linear_simulation(p, o), VM::Invalid_input, "time step must be finite and positive");
  o.time_step = std::nan("");
  EXPECT_THROW_REASON(VM::full_linear_simulation(p, o), VM::Invalid_input, "time step must be finite and positive");
  o.time_step = 0.1;
  o.rayleigh_stiffness = -1;
  EXPECT_THROW_REASON(VM::full_linear_simulation(p, o), VM::Invalid_input, "Rayleigh damping");
  o.rayleigh_stiffness = 0;
  o.initial_displacement = Eigen::VectorXd::Zero(p.H.rows());
  o.initial_displacement[3] = std::nan("");
  EXPECT_THROW_REASON(VM::full_linear_simulation(p, o), VM::Invalid_input, "initial displacement has a non-finite entry");
  o.initial_displacement = Eigen::VectorXd::Zero(7);
  EXPECT_THROW_REASON(VM::full_linear_simulation(p, o), VM::Invalid_input, "initial displacement has 7 rows");
  o.initial_displacement.resize(0);
  EXPECT_THROW_REASON(VM::reduced_linear_simulation(p, modes, 6, o), VM::Invalid_input, "6 modes asked for, 5 computed");
  Eigen::MatrixXd twice(p.H.rows(), 2);
  twice << modes.vectors.col(0), modes.vectors.col(0);
  EXPECT_THROW_REASON(VM::reduced_linear_simulation(p, twice, o), VM::Invalid_input, "linearly dependent");
}

// ---------------------------------------------------------------- elastic modelling

namespace {

std::vector<std::vector<int>> some_handles() { return {{0}, {5}, {17, 18, 19}, {30}}; }

} // namespace

TEST(ElasticModelling, OnEveryModeEqualsTheFullSolutionAndMeetsTheHandles)
{
  const VM::Mode_problem p = problem_of(lumpy_sphere(1));
  const auto dense = dense_pairs(p);
  const Eigen::Index n = p.H.rows();
  Eigen::MatrixXd targets = Eigen::Map<Eigen::MatrixXd>(random_vector(12, 9, 0.1).data(), 3, 4);
  VM::Full_elastic_deformer full(p, some_handles());
  VM::Reduced_elastic_deformer reduced(p, dense.eigenvectors().rightCols(n - 6), some_handles());
  const Eigen::VectorXd u = full.deform(targets);
  reduced.drag(targets);
  EXPECT_LT(m_norm(p, reduced.displacement() - u), 1e-8 * m_norm(p, u));
  // Truth for the full answer: the dense KKT system [2H C^T; C 0] solved by LU.
  const VM::Handle_constraints hc = VM::handle_constraints(p, some_handles());
  const Eigen::Index m = hc.C.rows();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + m, n + m);
  K.topLeftCorner(n, n) = 2 * Eigen::MatrixXd(p.H);
  K.topRightCorner(n, m) = Eigen::MatrixXd(hc.C).transpose();
  K.bottomLeftCorner(m, n) = Eigen::MatrixXd(hc.C);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + m);
  rhs.tail(m) = Eigen::Map<const Eigen::VectorXd>(targets.data(), m);
  const Eigen::VectorXd kkt = K.fullPivLu().solve(rhs).head(n);
  EXPECT_LT(m_norm(p, u - kkt), 1e-8 * m_norm(p, kkt));
  // Handles met exactly, also by a small basis; a one-vertex handle moves by its target.
  const VM::Modes modes = VM::lowest_vibration_modes(p, 10);
  VM::Reduced_elastic_deformer small(p, modes.vectors, some_handles());
  EXPECT_EQ(small.dimension(), 16);
  small.drag(targets);
  const Eigen::VectorXd us = small.displacement();
  EXPECT_LT((hc.C * us - rhs.tail(m)).norm(), 1e-12 * targets.norm());
  EXPECT_LT((us.segment<3>(0) - targets.col(0)).norm(), 1e-12 * targets.norm());
  // ... with more energy than the full answer (a smaller space), and its own energy reported.
  EXPECT_GE(us.dot(p.H * us), u.dot(p.H * u) * (1 - 1e-12));
  EXPECT_NEAR(small.energy(), us.dot(p.H * us), 1e-10 * small.energy());
}

TEST(ElasticModelling, TranslatingEveryHandleTranslatesTheBody)
{
  const Mesh mesh = lumpy_sphere(2);
  const VM::Mode_problem p = VM::mesh_mode_problem(mesh, VM::parameters::bending_stiffness(0.01));
  // Handles given as vertex descriptors.
  const std::vector<std::vector<Vertex_index>> descriptors = {
      {Vertex_index(0)}, {Vertex_index(5)}, {Vertex_index(17), Vertex_index(18), Vertex_index(19)}, {Vertex_index(30)}};
  ASSERT_EQ(VM::handle_vertex_indices(mesh, descriptors), some_handles());
  const VM::Modes modes = VM::lowest_vibration_modes(p, 10);
  VM::Reduced_elastic_deformer reduced(p, modes.vectors, some_handles());
  VM::Full_elastic_deformer full(p, some_handles());
  const Eigen::Vector3d t(0.3, -0.2, 0.5);
  const Eigen::MatrixXd targets = t.replicate(1, 4);
  reduced.drag(targets);
  for(const Eigen::VectorXd& u : {reduced.displacement(), full.deform(targets)})
    for(Eigen::Index v = 0; v < u.size() / 3; ++v) EXPECT_LT((u.segment<3>(3 * v) - t).norm(), 1e-9) << "vertex " << v;
  EXPECT_LT(reduced.energy(), 1e-12);
}

TEST(ElasticModelling, RefusesBadHandlesWithTheReason)
{
  const VM::Mode_problem p = problem_of(lumpy_sphere(1));
  const VM::Modes modes = VM::lowest_vibration_modes(p, 4);
  EXPECT_THROW_REASON(VM::Full_elastic_deformer(p, {{0}, {1000}}), VM::Invalid_input, "vertex 1000 of handle 1 is outside the mesh");
  EXPECT_THROW_REASON(VM::Full_elastic_deformer(p, {{0}, {}}), VM::Invalid_input, "handle 1 has no vertices");
  EXPECT_THROW_REASON(VM::Full_elastic_deformer(p, {{0}}), VM::Invalid_input, "zero-energy motion(s) free");
  EXPECT_THROW_REASON(VM::Reduced_elastic_deformer(p, modes.vectors, {{0}, {3}, {9}, {12}}), VM::Invalid_input,
                      "need 12 independent directions, the basis has only 10");
  const VM::Mode_problem pinned = problem_of(lumpy_sphere(1), {2, 3, 4});
  EXPECT_THROW_REASON(VM::Full_elastic_deformer(pinned, {{0}, {3}}), VM::Invalid_input, "vertex 3 of handle 1 is pinned");
  VM::Reduced_elastic_deformer d(p, modes.vectors, {{0}, {5}, {30}});
  EXPECT_THROW_REASON(d.drag(Eigen::MatrixXd::Zero(3, 2)), VM::Invalid_input, "for 3 handles");
  Eigen::MatrixXd bad = Eigen::MatrixXd::Zero(3, 3);
  bad(1, 1) = std::nan("");
  EXPECT_THROW_REASON(d.drag(bad), VM::Invalid_input, "not finite");
}

// ---------------------------------------------------------------- segmentation

TEST(ModeSegmentation, SeparatesTheSpheresOfADumbbell)
{
  // Compressed manifold modes (the scalar problem, constants allowed in a mode): at this mu
  // the two cheapest local functions are a bump on each sphere, cut at the neck (mu from 2x to
  // 3x this scale gives the same two regions; 1x spreads both modes over the whole surface,
  // 4x shrinks them inside the spheres).
  Mesh mesh = make_dumbbell();
  const VM::Mode_problem p = VM::laplacian_mode_problem(DS::stacked_positions(mesh), triangles_of(mesh));
  const VM::Modes ordinary = VM::lowest_vibration_modes(p, 2);
  VM::Compressed_mode_options o;
  o.orthogonal_to_kernel = false;
  o.sparsity_weight = 2.5 * ordinary.energies[1] / std::sqrt(p.mass.sum());
  const VM::Modes modes = VM::compressed_modes(p, 2, o);
  auto label = mesh.add_property_map<Vertex_index, int>("v:segment", -7).first;
  ASSERT_EQ(VM::segment_by_modes(mesh, modes, label), 2);
  // Every vertex of a sphere's body (beyond the neck's ends, |z| > c) is in its sphere's region.
  int region_of[2] = {-1, -1};
  for(auto v : vertices(mesh))
  {
    EXPECT_GE(label[v], -1);
    const double z = mesh.point(v).z();
    if(std::abs(z) <= 1.6) continue;
    int& r = region_of[z > 0];
    if(r < 0) r = label[v];
    EXPECT_EQ(label[v], r) << "vertex " << v << " at z = " << z;
    EXPECT_GE(label[v], 0);
  }
  EXPECT_NE(region_of[0], region_of[1]);
}

TEST(ModeSegmentation, RegionsAreConnectedAndThresholdsUnassign)
{
  const Mesh mesh = lumpy_sphere(2);
  const std::vector<DS::Shell_energy::Triangle> triangles = triangles_of(mesh);
  // Two "modes" on the vertex index: mode 0 large on two separate caps, mode 1 small elsewhere.
  const Eigen::VectorXd x = DS::stacked_positions(mesh);
  const Eigen::Index n = x.size() / 3;
  Eigen::MatrixXd U = Eigen::MatrixXd::Zero(3 * n, 2);
  for(Eigen::Index v = 0; v < n; ++v)
  {
    const double z = x[3 * v + 2];
    if(std::abs(z) > 0.6) U(3 * v, 0) = 1;
    else U(3 * v + 1, 1) = 0.1 + 0.2 * std::abs(z);
  }
  const VM::Mode_segmentation s = VM::segment_by_modes(U, 3, triangles);
  ASSERT_EQ(s.number_of_regions(), 3); // two caps of mode 0, the belt of mode 1
  EXPECT_EQ(std::count(s.region_mode.begin(), s.region_mode.end(), 0), 2);
  // A threshold of 0.5 of mode 1's peak unassigns the belt's middle, splitting it in two.
  const VM::Mode_segmentation t = VM::segment_by_modes(U, 3, triangles, 0.5);
  EXPECT_GT(std::count(t.region.begin(), t.region.end(), -1), 0);
  EXPECT_THROW_REASON(VM::segment_by_modes(U, 3, triangles, 1.5), VM::Invalid_input, "threshold must be in [0, 1)");
  U(4, 1) = std::nan("");
  EXPECT_THROW_REASON(VM::segment_by_modes(U, 3, triangles), VM::Invalid_input, "non-finite");
  U(4, 1) = 0;
  EXPECT_THROW_REASON(VM::segment_by_modes(U.topRows(30), 3, triangles), VM::Invalid_input, "but the modes have 10 vertices");
}

// ---------------------------------------------------------------- save and load

TEST(ModesFile, RoundTripOfOrdinaryAndCompressedModes)
{
  const Mesh mesh = lumpy_sphere(2);
  const Eigen::VectorXd x = DS::stacked_positions(mesh);
  const auto triangles = triangles_of(mesh);
  const VM::Mode_problem p = VM::shell_mode_problem(DS::Shell_energy(x, triangles, stiffness), {3, 1});
  const VM::Modes ordinary = VM::lowest_vibration_modes(p, 5);
  VM::Compressed_mode_options o;
  o.sparsity_weight = 2 * ordinary.energies[2] / std::sqrt(p.mass.sum() / 3);
  VM::Modes compressed = VM::compressed_modes(p, 3, o);
  ASSERT_EQ(compressed.converged, (std::vector<int>{1, 1, 1}));
  compressed.converged[1] = 0; // a mixed list, so that a dropped or shifted flag shows
  VM::Mode_settings settings;
  settings.pinned_vertices = {3, 1};
  settings.stiffness = stiffness;
  for(const VM::Modes* m : {&ordinary, static_cast<const VM::Modes*>(&compressed)})
  {
    const std::string path = scratch_path("modes.vmb");
    VM::save_modes(path, *m, settings, x, triangles);
    VM::Mode_settings found;
    const VM::Modes back = VM::load_modes(path, x, triangles, &settings, &found);
    EXPECT_EQ(back.vectors, m->vectors);
    EXPECT_EQ(back.energies, m->energies);
    EXPECT_EQ(back.residuals, m->residuals);
    EXPECT_EQ(back.objectives, m->objectives);
    EXPECT_EQ(back.l1_norms, m->l1_norms);
    EXPECT_EQ(back.support_fractions, m->support_fractions);
    EXPECT_EQ(back.outer_iterations, m->outer_iterations);
    EXPECT_EQ(back.inner_iterations, m->inner_iterations);
    EXPECT_EQ(back.converged, m->converged);
    EXPECT_EQ(back.sparsity_weight, m->sparsity_weight);
    EXPECT_EQ(back.kernel_dimension, m->kernel_dimension);
    EXPECT_EQ(back.complete_below, m->complete_below);
    EXPECT_EQ(back.completeness.inertia, m->completeness.inertia);
    EXPECT_EQ(found.pinned_vertices, (std::vector<int>{1, 3}));
    EXPECT_EQ(found.stiffness.bending, stiffness.bending);
    EXPECT_EQ(found.group_size, 3);
  }
  // The mesh front: the named parameters of the computation are stored and checked.
  Mesh copy = mesh;
  const std::vector<Vertex_index> pins = {Vertex_index(1), Vertex_index(3)};
  const auto np = VM::parameters::pinned_vertices(pins).bending_stiffness(0.01);
  const std::string path = scratch_path("front.vmb");
  VM::save_vibration_modes(copy, compressed, path, np);
  EXPECT_EQ(VM::load_vibration_modes(copy, path, np).vectors, compressed.vectors);
  EXPECT_THROW_REASON(VM::load_vibration_modes(copy, path, VM::parameters::pinned_vertices(pins)), VM::Invalid_input,
                      "computed with other stiffnesses");
  EXPECT_THROW_REASON(VM::load_vibration_modes(copy, path, VM::parameters::bending_stiffness(0.01)), VM::Invalid_input,
                      "computed with other pinned vertices");
}

TEST(ModesFile, RefusesAnotherMeshWithTheReason)
{
  const Mesh mesh = lumpy_sphere(2);
  const Eigen::VectorXd x = DS::stacked_positions(mesh);
  auto triangles = triangles_of(mesh);
  const VM::Modes modes = VM::lowest_vibration_modes(problem_of(mesh), 3);
  const std::string path = scratch_path("refused.vmb");
  VM::save_modes(path, modes, {}, x, triangles);
  // The same connectivity with every face started at another corner is the same mesh.
  auto rotated = triangles;
  for(auto& t : rotated) t = {t[1], t[2], t[0]};
  EXPECT_EQ(VM::load_modes(path, x, rotated).vectors, modes.vectors);

  const Mesh other = lumpy_sphere(1);
  EXPECT_THROW_REASON(VM::load_modes(path, DS::stacked_positions(other), triangles_of(other)), VM::Invalid_input,
                      "other connectivity");
  auto flipped = triangles;
  std::swap(flipped[0][1], flipped[0][2]);
  EXPECT_THROW_REASON(VM::load_modes(path, x, flipped), VM::Invalid_input, "other connectivity");
  Eigen::VectorXd bent = x;
  bent[5] += 1e-3;
  EXPECT_THROW_REASON(VM::load_modes(path, bent, triangles), VM::Invalid_input, "other edge lengths");
  EXPECT_THROW_REASON(VM::load_modes(path, moved(x, 1, Eigen::Matrix3d::Identity(), {0.5, 0, 0}), triangles),
                      VM::Invalid_input, "in another position");
  EXPECT_THROW_REASON(VM::load_modes(path, moved(x, 1, rotation({1, 2, 3}, 0.3), {0, 0, 0}), triangles),
                      VM::Invalid_input, "in another position");
  VM::Mode_settings scalar;
  scalar.group_size = 1;
  EXPECT_THROW_REASON(VM::load_modes(path, x, triangles, &scalar), VM::Invalid_input, "computed for group size 3");
  // Not a modes file; a truncated one.
  {
    std::ofstream out(scratch_path("junk.vmb"), std::ios::binary);
    out << "this is not a binary file of modes at all";
  }
  EXPECT_THROW_REASON(VM::load_modes(scratch_path("junk.vmb"), x, triangles), VM::Invalid_input,
                      "not a vibration modes file");
  {
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream out(scratch_path("cut.vmb"), std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size() / 2));
  }
  EXPECT_THROW_REASON(VM::load_modes(scratch_path("cut.vmb"), x, triangles), VM::Invalid_input, "truncated");
  EXPECT_THROW_REASON(VM::load_modes(scratch_path("absent.vmb"), x, triangles), VM::Invalid_input, "cannot open");
}

TEST(ModesFile, CorruptFilesAreRefusedOrLoadFinite)
{
  // A small deterministic fuzz of the reader (the libFuzzer targets cover the other formats):
  // every corrupted or cut copy either loads with finite values of the right sizes or is
  // refused with Invalid_input.
  const Mesh mesh = lumpy_sphere(1);
  const Eigen::VectorXd x = DS::stacked_positions(mesh);
  const auto triangles = triangles_of(mesh);
  const VM::Mode_problem p = problem_of(mesh);
  VM::Compressed_mode_options o;
  o.sparsity_weight = 0.5;
  const VM::Modes modes = VM::compressed_modes(p, 2, o);
  const std::string path = scratch_path("fuzzed.vmb");
  VM::save_modes(path, modes, {}, x, triangles);
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }
  std::mt19937 rng(5);
  int loaded = 0, refused = 0;
  for(int trial = 0; trial < 400; ++trial)
  {
    std::string copy = bytes;
    if(trial % 4 == 0)
      copy.resize(rng() % copy.size());
    else
      for(int flips = 1 + int(rng() % 3); flips > 0; --flips) copy[rng() % copy.size()] ^= char(1 + rng() % 255);
    {
      std::ofstream out(path, std::ios::binary | std::ios::trunc);
      out.write(copy.data(), std::streamsize(copy.size()));
    }
    try
    {
      const VM::Modes m = VM::load_modes(path, x, triangles);
      EXPECT_EQ(m.vectors.rows(), x.size());
      EXPECT_TRUE(m.vectors.allFinite() && m.energies.allFinite());
      EXPECT_EQ(m.energies.size(), m.vectors.cols());
      ++loaded;
    }
    catch(const VM::Invalid_input& e)
    {
      EXPECT_NE(std::string(e.what()).find("cannot load the vibration modes"), std::string::npos) << e.what();
      ++refused;
    }
  }
  EXPECT_GT(refused, 100); // cut files and flips in the header and sizes
  EXPECT_GT(loaded, 0);    // flips inside the values load (the format has no checksum)
}
