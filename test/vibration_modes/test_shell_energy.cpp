// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The shell energy against independent truth: finite differences of the energy and of the
// gradient, closed forms (a uniformly stretched shell, a folded hinge), invariance to
// rigid motions and the scaling law, the rigid kernel by an inertia count, and the
// reasons of refused input.

#include "shell_test_meshes.h"

#include <CGAL/Model_reduction/Generalized_eigensolver.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace shell_test;

namespace {

struct Shell_case
{
  std::string name;
  Mesh mesh;
};

std::vector<Shell_case> shell_cases()
{
  std::vector<Shell_case> cases;
  Mesh sphere = make_icosphere(1);
  jitter_vertices(sphere, 0.1, 3);
  cases.push_back({"jittered icosphere", sphere});
  cases.push_back({"torus", make_torus(8, 6)});
  cases.push_back({"curved disk with a hole", make_curved_disk(4, 0.3)});
  return cases;
}

DS::Shell_stiffness all_terms() { return {1.0, 0.7, 0.05}; }

// Central differences: truncation O(h^2) = 1e-12 and rounding O(eps / h) = 1e-10 relative
// at h = 1e-6 of unit-size coordinates, so 1e-6 relative leaves room and still catches any
// wrong term (a wrong factor or a missing term is an O(1) relative error).
constexpr double fd_step = 1e-6;
constexpr double fd_tolerance = 1e-6;

} // namespace

TEST(ShellEnergy, GradientMatchesFiniteDifferencesOfTheEnergy)
{
  for(const Shell_case& c : shell_cases())
  {
    SCOPED_TRACE(c.name);
    const DS::Shell_energy W(DS::stacked_positions(c.mesh), triangles_of(c.mesh), all_terms());
    const Eigen::VectorXd y = W.rest_positions() + random_vector(W.rest_positions().size(), 5, 0.05);
    const Eigen::VectorXd g = W.gradient(y);
    ASSERT_GT(g.norm(), 1e-3); // deformed: a real gradient
    for(unsigned d = 0; d < 6; ++d)
    {
      const Eigen::VectorXd dir = random_vector(y.size(), 100 + d);
      const double fd = (W.energy(y + fd_step * dir) - W.energy(y - fd_step * dir)) / (2 * fd_step);
      EXPECT_NEAR(g.dot(dir), fd, fd_tolerance * g.norm() * dir.norm());
    }
  }
}

TEST(ShellEnergy, HessianMatchesFiniteDifferencesOfTheGradient)
{
  for(const Shell_case& c : shell_cases())
  {
    SCOPED_TRACE(c.name);
    const DS::Shell_energy W(DS::stacked_positions(c.mesh), triangles_of(c.mesh), all_terms());
    const Eigen::VectorXd y = W.rest_positions() + random_vector(W.rest_positions().size(), 6, 0.05);
    const Eigen::SparseMatrix<double> H = W.hessian(y);
    EXPECT_LT((Eigen::MatrixXd(H) - Eigen::MatrixXd(H).transpose()).norm(), 1e-12 * H.norm());
    double worst = 0;
    for(Eigen::Index j = 0; j < y.size(); ++j)
    {
      Eigen::VectorXd e = Eigen::VectorXd::Zero(y.size());
      e[j] = fd_step;
      const Eigen::VectorXd fd = (W.gradient(y + e) - W.gradient(y - e)) / (2 * fd_step);
      const Eigen::VectorXd column = H.col(j);
      worst = std::max(worst, (column - fd).norm() / column.norm());
    }
    EXPECT_LT(worst, fd_tolerance);
  }
}

TEST(ShellEnergy, RestHessianMatchesFiniteDifferencesAndIsSemiDefinite)
{
  for(const Shell_case& c : shell_cases())
  {
    SCOPED_TRACE(c.name);
    const DS::Shell_energy W(DS::stacked_positions(c.mesh), triangles_of(c.mesh), all_terms());
    const Eigen::VectorXd& x = W.rest_positions();
    EXPECT_LT(W.energy(x), 1e-24);
    EXPECT_LT(W.gradient(x).norm(), 1e-12);
    const Eigen::SparseMatrix<double> H = W.rest_hessian();
    for(Eigen::Index j = 0; j < x.size(); j += 7)
    {
      Eigen::VectorXd e = Eigen::VectorXd::Zero(x.size());
      e[j] = fd_step;
      const Eigen::VectorXd fd = (W.gradient(x + e) - W.gradient(x - e)) / (2 * fd_step);
      EXPECT_LT((Eigen::VectorXd(H.col(j)) - fd).norm(), fd_tolerance * H.col(j).norm()) << "column " << j;
    }
    const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(H)).eigenvalues();
    EXPECT_GT(lambda[0], -1e-12 * lambda[lambda.size() - 1]);
  }
}

TEST(ShellEnergy, NonManifoldEdgeBendsAtEveryPairOfItsFaces)
{
  // Three fins on the edge (0, 1): three hinges; derivatives still exact.
  Eigen::VectorXd x(15);
  x << 0, 0, 0, 1, 0, 0, 0.4, 1, 0, 0.5, -0.7, 0.6, 0.6, -0.5, -0.8;
  const std::vector<DS::Shell_energy::Triangle> t = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const DS::Shell_energy W(x, t, all_terms());
  EXPECT_EQ(W.hinges().size(), 3u);
  const Eigen::VectorXd y = x + random_vector(15, 9, 0.1);
  const Eigen::SparseMatrix<double> H = W.hessian(y);
  for(Eigen::Index j = 0; j < 15; ++j)
  {
    Eigen::VectorXd e = Eigen::VectorXd::Zero(15);
    e[j] = fd_step;
    const Eigen::VectorXd fd = (W.gradient(y + e) - W.gradient(y - e)) / (2 * fd_step);
    EXPECT_LT((Eigen::VectorXd(H.col(j)) - fd).norm(), fd_tolerance * H.col(j).norm());
  }
}

TEST(ShellEnergy, UniformStretchHasTheClosedFormEnergy)
{
  // y = (1 + e) x: every edge strain is e and every area ratio (1 + e)^2, no angle changes:
  // W = k_s e^2 sum_e a_e + k_a ((1 + e)^2 - 1)^2 sum_t A_t, and sum_e a_e = sum_t A_t = A.
  const Mesh mesh = make_torus(10, 7);
  const DS::Shell_energy W(DS::stacked_positions(mesh), triangles_of(mesh), all_terms());
  const double area = W.lumped_mass().sum() / 3;
  const double e = 0.03;
  const double expected = 1.0 * e * e * area + 0.7 * std::pow((1 + e) * (1 + e) - 1, 2) * area;
  EXPECT_NEAR(W.energy((1 + e) * W.rest_positions()), expected, 1e-12 * expected);
}

TEST(ShellEnergy, FoldedHingeHasTheClosedFormBendingEnergy)
{
  // Two unit right triangles on the edge (0,1) of length 1, areas 1/2 each: a_e = 1/3.
  // Folding one by phi about the edge costs k_b l^2 / a_e phi^2 = 3 k_b phi^2 and nothing else.
  Eigen::VectorXd x(12);
  x << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0;
  const DS::Shell_energy W(x, {{0, 1, 2}, {1, 0, 3}}, {1, 1, 0.25});
  for(double phi : {0.1, 1.0, 2.5, -2.0})
  {
    Eigen::VectorXd y = x;
    y.segment<3>(9) = Eigen::Vector3d(0, -std::cos(phi), std::sin(phi));
    EXPECT_NEAR(W.energy(y), 3 * 0.25 * phi * phi, 1e-13) << "phi " << phi;
  }
}

TEST(ShellEnergy, InvariantToRigidMotionAndScalesAsDerived)
{
  const Mesh mesh = make_curved_disk(5);
  const Eigen::VectorXd x = DS::stacked_positions(mesh);
  const DS::Shell_energy W(x, triangles_of(mesh), all_terms());
  const Eigen::VectorXd y = x + random_vector(x.size(), 11, 0.05);
  const Eigen::Matrix3d R = rotation(Eigen::Vector3d(1, 2, 3), 0.8);
  const Eigen::Vector3d t(3, -1, 2);
  EXPECT_NEAR(W.energy(moved(y, 1, R, t)), W.energy(y), 1e-12 * W.energy(y));
  // Both shapes scaled by s: the membrane terms scale by s^2, bending by 1; so with
  // k_b scaled by s^2 too, the whole energy scales by s^2.
  for(double s : {1e-4, 1e3})
  {
    DS::Shell_stiffness k = all_terms();
    k.bending *= s * s;
    const DS::Shell_energy Ws(s * x, triangles_of(mesh), k);
    EXPECT_NEAR(Ws.energy(s * y), s * s * W.energy(y), 1e-10 * s * s * W.energy(y)) << "s " << s;
  }
}

TEST(ShellEnergy, RigidKernelByInertia)
{
  // Closed surfaces: exactly the six rigid motions cost nothing (Sylvester's inertia of
  // H - tau M counts the eigenvalues below tau, independently of how the kernel is built).
  for(const Mesh& mesh : {make_icosphere(2), make_torus(9, 7)})
  {
    const DS::Shell_energy W(DS::stacked_positions(mesh), triangles_of(mesh), all_terms());
    const Eigen::SparseMatrix<double> H = W.rest_hessian();
    const double tau = 1e-9 * Eigen::MatrixXd(H).diagonal().maxCoeff();
    EXPECT_EQ(CGAL::Model_reduction::count_eigenvalues_below(H, W.lumped_mass(), tau), 6);
  }
  // A flat sheet without bending: each vertex moves out of plane freely (to first order),
  // plus the three rigid motions in the plane: n + 3.
  const Mesh disk = make_disk(4);
  const DS::Shell_energy W(DS::stacked_positions(disk), triangles_of(disk), {1, 1, 0});
  const Eigen::SparseMatrix<double> H = W.rest_hessian();
  const double tau = 1e-9 * Eigen::MatrixXd(H).diagonal().maxCoeff();
  EXPECT_EQ(CGAL::Model_reduction::count_eigenvalues_below(H, W.lumped_mass(), tau),
            int(num_vertices(disk)) + 3);
}

TEST(ShellEnergy, LumpedMassIsTheArea)
{
  const Mesh sphere = make_icosphere(3);
  const DS::Shell_energy W(DS::stacked_positions(sphere), triangles_of(sphere));
  // A level-3 icosphere's area is within 2% below the sphere's 4 pi.
  const double area = W.lumped_mass().sum() / 3;
  EXPECT_GT(area, 0.98 * 4 * M_PI);
  EXPECT_LT(area, 4 * M_PI);
}

TEST(ShellEnergy, RefusesBadInputWithTheReason)
{
  Eigen::VectorXd x(12);
  x << 0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0;
  auto message = [&](const Eigen::VectorXd& p, const std::vector<DS::Shell_energy::Triangle>& t,
                     const DS::Shell_stiffness& k) -> std::string {
    try { DS::Shell_energy W(p, t, k); }
    catch(const std::exception& e) { return e.what(); }
    return "accepted";
  };
  EXPECT_NE(message(x, {{0, 1, 2}, {0, 1, 3}}, {}).find("face 1 is degenerate"), std::string::npos);
  EXPECT_NE(message(x, {{0, 1, 7}}, {}).find("face 0 has vertex index 7"), std::string::npos);
  EXPECT_NE(message(x, {{0, 1, 1}}, {}).find("repeats a vertex"), std::string::npos);
  EXPECT_NE(message(x, {{0, 1, 2}}, {1, -1, 1}).find("must be finite and >= 0"), std::string::npos);
  EXPECT_NE(message(x, {{0, 1, 2}}, {0, 0, 0}).find("all three stiffnesses are 0"), std::string::npos);
  Eigen::VectorXd bad = x;
  bad[4] = std::nan("");
  EXPECT_NE(message(bad, {{0, 1, 2}}, {}).find("vertex 1 has a non-finite coordinate"), std::string::npos);
  const DS::Shell_energy W(x, {{0, 1, 2}});
  EXPECT_THROW(
      {
        try { W.energy(Eigen::VectorXd::Zero(5)); }
        catch(const DS::Invalid_input& e) {
          EXPECT_NE(std::string(e.what()).find("5 values for 12 unknowns"), std::string::npos);
          throw;
        }
      },
      DS::Invalid_input);
  // A quad is not a triangle: the mesh front names the face.
  Mesh quad;
  auto v0 = quad.add_vertex(Point_3(0, 0, 0)), v1 = quad.add_vertex(Point_3(1, 0, 0)),
       v2 = quad.add_vertex(Point_3(1, 1, 0)), v3 = quad.add_vertex(Point_3(0, 1, 0));
  quad.add_face(v0, v1, v2, v3);
  try { DS::make_shell_energy(quad); ADD_FAILURE() << "a quad was accepted"; }
  catch(const DS::Invalid_mesh& e) {
    EXPECT_EQ(e.defect(), DS::Mesh_defect::non_triangle_face);
    EXPECT_NE(std::string(e.what()).find("face 0 has 4 vertices"), std::string::npos);
  }
}

TEST(ShellEnergy, MeshFrontReadsStiffnessesAsNamedParameters)
{
  const Mesh sphere = make_icosphere(1);
  const DS::Shell_energy W = DS::make_shell_energy(
      sphere, DS::parameters::stretching_stiffness(2.0).area_stiffness(0.0).bending_stiffness(0.5));
  EXPECT_EQ(W.stiffness().stretching, 2.0);
  EXPECT_EQ(W.stiffness().area, 0.0);
  EXPECT_EQ(W.stiffness().bending, 0.5);
  EXPECT_EQ(W.number_of_vertices(), Eigen::Index(num_vertices(sphere)));
}
