// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Ordinary vibration modes against independent truth: a dense generalised eigensolver,
// inertia counts of the rigid motions left by pins, rotation and the scaling law, and the
// reasons of refused problems.

#include "shell_test_meshes.h"

#include <CGAL/Vibration_modes/errors.h>
#include <CGAL/Vibration_modes/lowest_vibration_modes.h>
#include <CGAL/Vibration_modes/vibration_modes.h>
#include <CGAL/Vibration_modes/mode_export.h>

#include "expect_reason.h"
#include "scratch_path.h"

#include <fstream>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

using namespace shell_test;
namespace VM = CGAL::Vibration_modes;

namespace {

DS::Shell_energy shell_of(const Mesh& mesh, DS::Shell_stiffness k = {1, 1, 0.01})
{
  return DS::Shell_energy(DS::stacked_positions(mesh), triangles_of(mesh), k);
}

std::string failure_of(const VM::Mode_problem& p, int count)
{
  try { VM::lowest_vibration_modes(p, count); }
  catch(const std::exception& e) { return e.what(); }
  return "solved";
}

} // namespace

TEST(VibrationModes, MatchTheDenseGeneralisedEigensolver)
{
  const DS::Shell_energy W = shell_of(lumpy_sphere());
  const VM::Mode_problem p = VM::shell_mode_problem(W);
  EXPECT_EQ(p.kernel.cols(), 6);
  CGAL::Model_reduction::Eigensolver_options options;
  options.allow_dense = false; // the sparse Lanczos path, not LAPACK on the same matrix
  const int k = 20;
  const VM::Modes modes = VM::lowest_vibration_modes(p, k, options);
  // Truth: Eigen's dense generalised solver on all of H and M; the first six are the rigid motions.
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(Eigen::MatrixXd(p.H),
                                                                   Eigen::MatrixXd(p.mass.asDiagonal()));
  const Eigen::VectorXd lambda = dense.eigenvalues();
  EXPECT_LT(std::abs(lambda[5]), 1e-9 * lambda[6]);
  for(int i = 0; i < k; ++i) EXPECT_NEAR(modes.energies[i], lambda[6 + i], 1e-8 * lambda[6 + i]) << "mode " << i;
  // The modes span the same space (simple eigenvalues: each mode is the eigenvector).
  EXPECT_LT(largest_angle_sine(modes.vectors, dense.eigenvectors().middleCols(6, k), p.mass), 1e-6);
  // M-orthonormal and M-orthogonal to the rigid motions.
  const Eigen::MatrixXd G = modes.vectors.transpose() * p.mass.asDiagonal() * modes.vectors;
  EXPECT_LT((G - Eigen::MatrixXd::Identity(k, k)).norm(), 1e-10);
  EXPECT_LT((p.kernel.transpose() * p.mass.asDiagonal() * modes.vectors).norm(), 1e-9 * p.kernel.norm());
  EXPECT_TRUE(modes.completeness.passed());
}

TEST(VibrationModes, PinsLeaveTheRigidMotionsAboutThem)
{
  // Inertia of H - tau M on the free unknowns counts what still moves for free: 3 rotations
  // about one pin, 1 about the line through two (or through collinear pins), 0 otherwise.
  const Mesh mesh = lumpy_sphere();
  const DS::Shell_energy W = shell_of(mesh);
  // Vertices 0 and 1 are antipodal on the icosahedron... jittered, so choose by index only.
  struct Pins { std::vector<int> pins; int expected; };
  const std::vector<Pins> cases = {{{}, 6}, {{3}, 3}, {{3, 40}, 1}, {{3, 40, 77}, 0}};
  for(const Pins& c : cases)
  {
    const VM::Mode_problem p = VM::shell_mode_problem(W, c.pins);
    EXPECT_EQ(p.kernel.cols(), c.expected);
    EXPECT_EQ(VM::count_modes_below(p, VM::zero_mode_threshold(p)), c.expected) << c.pins.size() << " pins";
    const VM::Modes modes = VM::lowest_vibration_modes(p, 4);
    for(int v : c.pins) EXPECT_EQ(modes.vectors.middleRows(3 * v, 3).norm(), 0.0);
  }
  // Collinear pins: three points on one line leave the rotation about it.
  Eigen::VectorXd x(18);
  x << 0, 0, 0, 1, 0, 0, 2, 0, 0, 0.5, 1, 0.1, 1.5, 1, -0.1, 1, -1, 0.2;
  const std::vector<DS::Shell_energy::Triangle> t = {{0, 1, 3}, {1, 4, 3}, {1, 2, 4}, {1, 0, 5}, {2, 1, 5}};
  const DS::Shell_energy strip(x, t, {1, 1, 0.1});
  EXPECT_EQ(VM::rigid_motions(x, t, {0, 1, 2}).cols(), 1);
  EXPECT_EQ(VM::rigid_motions(x, t, {0, 2, 3}).cols(), 0);
}

TEST(VibrationModes, RotateWithTheShellAndScaleAsDerived)
{
  const Mesh mesh = lumpy_sphere();
  const Eigen::VectorXd x = DS::stacked_positions(mesh);
  const VM::Modes modes = VM::lowest_vibration_modes(VM::shell_mode_problem(shell_of(mesh)), 8);
  const Eigen::Matrix3d R = rotation(Eigen::Vector3d(-1, 2, 0.5), 2.0);
  const DS::Shell_energy rotated(moved(x, 1, R, Eigen::Vector3d(5, 0, -1)), triangles_of(mesh), {1, 1, 0.01});
  const VM::Mode_problem pr = VM::shell_mode_problem(rotated);
  const VM::Modes turned = VM::lowest_vibration_modes(pr, 8);
  for(int i = 0; i < 8; ++i) EXPECT_NEAR(turned.energies[i], modes.energies[i], 1e-9 * modes.energies[i]);
  // Each (simple) mode rotates with the shell: R u_i is +-u'_i.
  for(int i = 0; i < 8; ++i)
  {
    const Eigen::VectorXd Ru = moved(modes.vectors.col(i), 1, R, Eigen::Vector3d::Zero());
    EXPECT_NEAR(std::abs(Ru.dot(pr.mass.cwiseProduct(turned.vectors.col(i)))), 1.0, 1e-7) << "mode " << i;
  }
  // Scaled by s with k_b scaled by s^2: H keeps its scale (energy s^2, two derivatives
  // 1/s^2), the mass grows by s^2, so every eigenvalue is divided by s^2.
  const double s = 1e3;
  const DS::Shell_energy big(s * x, triangles_of(mesh), {1, 1, 0.01 * s * s});
  const VM::Modes scaled = VM::lowest_vibration_modes(VM::shell_mode_problem(big), 8);
  for(int i = 0; i < 8; ++i) EXPECT_NEAR(scaled.energies[i] * s * s, modes.energies[i], 1e-8 * modes.energies[i]);
}

TEST(VibrationModes, SeveralComponentsEachKeepTheirRigidMotions)
{
  Mesh two = make_icosphere(1);
  Mesh other = make_torus(8, 6);
  transform(other, 1.0, {1, 0, 0, 0, 1, 0, 0, 0, 1}, Vector_3(4, 0, 0));
  two.join(other);
  const VM::Mode_problem p = VM::shell_mode_problem(shell_of(two));
  EXPECT_EQ(p.kernel.cols(), 12);
  EXPECT_EQ(VM::count_modes_below(p, VM::zero_mode_threshold(p)), 12);
  const VM::Modes modes = VM::lowest_vibration_modes(p, 5);
  EXPECT_GT(modes.energies[0], 1e-6 * modes.energies[4]);
}

TEST(VibrationModes, RefuseBadProblemsWithTheReason)
{
  const Mesh disk = make_disk(4);
  const VM::Mode_problem flat = VM::shell_mode_problem(shell_of(disk, {1, 1, 0}));
  EXPECT_NE(failure_of(flat, 3).find("a mechanism moves without energy"), std::string::npos);
  const VM::Mode_problem p = VM::shell_mode_problem(shell_of(make_icosphere(1)));
  EXPECT_NE(failure_of(p, 0).find("at least 1"), std::string::npos);
  EXPECT_NE(failure_of(p, int(p.H.rows())).find("only 120 exist outside the 6 rigid motions"), std::string::npos);
  VM::Mode_problem wrong_kernel = p;
  wrong_kernel.kernel = p.kernel.leftCols(5);
  EXPECT_NE(failure_of(wrong_kernel, 3).find("6 zero modes but 5 rigid motions"), std::string::npos);
  VM::Mode_problem no_mass = p;
  no_mass.mass[7] = 0;
  EXPECT_NE(failure_of(no_mass, 3).find("the mass of unknown 7 is 0"), std::string::npos);
  try { VM::shell_mode_problem(shell_of(make_icosphere(1)), {42}); ADD_FAILURE(); }
  catch(const VM::Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("pinned vertex 42 is outside the mesh (42 vertices)"), std::string::npos);
  }
}

TEST(VibrationModes, MeshFrontTakesNamedParametersAndFillsPropertyMaps)
{
  Mesh mesh = lumpy_sphere();
  const std::vector<Vertex_index> pins = {Vertex_index(3), Vertex_index(40)};
  // The shell's stiffnesses (Discrete_shells' tags) and the pins through one chain.
  const VM::Modes modes = VM::vibration_modes(
      mesh, 5, VM::parameters::bending_stiffness(0.02).area_stiffness(0.5).pinned_vertices(pins).random_seed(3));
  const VM::Modes direct =
      VM::lowest_vibration_modes(VM::shell_mode_problem(shell_of(mesh, {1, 0.5, 0.02}), {3, 40}), 5);
  for(int i = 0; i < 5; ++i) EXPECT_NEAR(modes.energies[i], direct.energies[i], 1e-10 * direct.energies[i]);
  EXPECT_EQ(modes.kernel_dimension, 1);
  auto u = mesh.add_property_map<Vertex_index, Vector_3>("v:mode").first;
  VM::copy_mode_to_vertex_map(mesh, modes, 2, u);
  for(Vertex_index v : vertices(mesh))
    for(int c = 0; c < 3; ++c) EXPECT_EQ(u[v][c], modes.vectors(3 * Eigen::Index(v) + c, 2));
  EXPECT_EQ(u[Vertex_index(40)], Vector_3(0, 0, 0));
  try { VM::copy_mode_to_vertex_map(mesh, modes, 5, u); ADD_FAILURE(); }
  catch(const VM::Invalid_input& e) { EXPECT_NE(std::string(e.what()).find("mode 5 asked for, 5 computed"), std::string::npos); }
}

TEST(ModeExport, EveryModeIsAPointArrayOfTheMeshReadBackExactly)
{
  // Written through the mesh front, read back by the VTK reader: the points are the mesh's
  // vertices in index order, the polygons its faces, mode_i the i-th column to the last bit,
  // and mode_support counts the modes that are non-zero at each vertex (pins: none).
  Mesh mesh = lumpy_sphere();
  const VM::Modes modes = VM::vibration_modes(mesh, 4, VM::parameters::pinned_vertices(std::vector<Vertex_index>{Vertex_index(5)}));
  const std::string path = scratch_path("modes.vtp");
  VM::write_modes_vtp(path, mesh, modes);
  std::ifstream in(path);
  const CGAL::Model_reduction::Vtk_polydata data = CGAL::Model_reduction::read_vtk_polydata(in);
  ASSERT_EQ(data.points.size(), num_vertices(mesh));
  for(Vertex_index v : vertices(mesh))
    for(int c = 0; c < 3; ++c) EXPECT_EQ(data.points[std::size_t(v)][std::size_t(c)], mesh.point(v)[c]);
  ASSERT_EQ(data.polygons.size(), num_faces(mesh));
  for(int i = 0; i < 4; ++i)
  {
    const auto* a = data.find_point_array("mode_" + std::to_string(i + 1));
    ASSERT_NE(a, nullptr) << "mode " << i + 1;
    ASSERT_EQ(a->components, 3);
    for(Eigen::Index j = 0; j < modes.vectors.rows(); ++j) ASSERT_EQ(a->values[std::size_t(j)], modes.vectors(j, i));
  }
  const auto* support = data.find_point_array("mode_support");
  ASSERT_NE(support, nullptr);
  for(Vertex_index v : vertices(mesh)) EXPECT_EQ(support->values[std::size_t(v)], v == Vertex_index(5) ? 0 : 4);
  const Eigen::VectorXd x = DS::stacked_positions(mesh);
  const Eigen::VectorXd moved = VM::displaced_positions(x, modes, 2, 0.5);
  EXPECT_EQ((moved - (x + 0.5 * modes.vectors.col(2))).cwiseAbs().maxCoeff(), 0);

  VM::Modes scalar;
  scalar.vectors = Eigen::MatrixXd::Ones(x.size() / 3, 1);
  EXPECT_THROW_REASON(VM::displaced_positions(x, scalar, 0, 1), VM::Invalid_input, "a scalar mode does not move the vertices");
  EXPECT_THROW_REASON(VM::displaced_positions(x, modes, 4, 1), VM::Invalid_input, "mode 4 asked for, 4 modes exist");
  VM::Modes wrong;
  wrong.vectors = Eigen::MatrixXd::Ones(x.size() + 1, 1);
  EXPECT_THROW_REASON(VM::write_modes_vtp(path, mesh, wrong), VM::Invalid_input, "(1 or 3 per vertex expected)");
  EXPECT_THROW_REASON(VM::write_modes_vtp("/nonexistent-folder/modes.vtp", mesh, modes), VM::Invalid_input,
                      "cannot be opened for writing");
}
