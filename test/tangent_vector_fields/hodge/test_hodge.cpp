// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Hodge decomposition (SPEC 3 and 4): orthogonality, reconstruction, recovery of
// pure parts, harmonic dimensions from the topology, invariance, pay-for-what-you-use.

#include "test_meshes.h"

#include <CGAL/Tangent_vector_fields/hodge_decomposition.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;

namespace {

typedef Mesh::Property_map<Face_index, Vector_3> Field;

Field field_map(Mesh& mesh, const std::string& name)
{
  return mesh.add_property_map<Face_index, Vector_3>("f:" + name, Vector_3(0, 0, 0)).first;
}

double mx_dot(const TVF::Operator_matrices& A, const Eigen::VectorXd& a, const Eigen::VectorXd& b)
{
  return a.dot(A.field_masses().cwiseProduct(b));
}

double mx_norm(const TVF::Operator_matrices& A, const Eigen::VectorXd& a) { return std::sqrt(mx_dot(A, a, a)); }

// Checks the three parts of `v` (frame coordinates) for orthogonality and sum.
void expect_valid_decomposition(const TVF::Hodge_solver& solver, const Eigen::VectorXd& v)
{
  const auto& A = solver.operators();
  const TVF::Hodge_parts p = solver.decompose(v, TVF::hodge_exact | TVF::hodge_coexact | TVF::hodge_harmonic);
  const double n = mx_norm(A, v);
  EXPECT_LT(mx_norm(A, p.exact + p.coexact + p.harmonic - v), 1e-12 * n);
  EXPECT_LT(std::abs(mx_dot(A, p.exact, p.coexact)), 1e-10 * n * n);
  EXPECT_LT(std::abs(mx_dot(A, p.exact, p.harmonic)), 1e-10 * n * n);
  EXPECT_LT(std::abs(mx_dot(A, p.coexact, p.harmonic)), 1e-10 * n * n);
  // The harmonic part has no conforming divergence and no nonconforming curl on interior edges.
  const Eigen::VectorXd div = A.divergence(p.harmonic);
  const Eigen::VectorXd curl = A.nonconforming_curl(p.harmonic);
  const double scale = n / std::sqrt(A.field_masses().sum() / 2) / A.mesh().mean_edge_length();
  EXPECT_LT(div.cwiseAbs().maxCoeff(), 1e-9 * scale);
  const auto& im = A.mesh();
  for(int e = 0; e < im.number_of_edges(); ++e)
    if(!im.is_boundary_edge(e)) EXPECT_LT(std::abs(curl[e]), 1e-9 * scale);
  // Each part is what it claims, through the operators (the sum above holds by construction:
  // one part is the remainder): the exact part has no curl, the coexact part no divergence...
  const Eigen::VectorXd exact_curl = A.nonconforming_curl(p.exact);
  for(int e = 0; e < im.number_of_edges(); ++e)
    if(!im.is_boundary_edge(e)) EXPECT_LT(std::abs(exact_curl[e]), 1e-9 * scale);
  EXPECT_LT(A.divergence(p.coexact).cwiseAbs().maxCoeff(), 1e-9 * scale);
  // ... and the harmonic part lies in the span of the harmonic basis.
  const Eigen::MatrixXd& H = solver.harmonic_basis();
  if(H.cols() == 0)
    EXPECT_LT(mx_norm(A, p.harmonic), 1e-12 * n);
  else
  {
    const Eigen::MatrixXd MH = A.field_masses().asDiagonal() * H;
    const Eigen::VectorXd c = (H.transpose() * MH).ldlt().solve(MH.transpose() * p.harmonic);
    EXPECT_LT(mx_norm(A, H * c - p.harmonic), 1e-9 * n);
  }
}

struct Case
{
  std::string name;
  Mesh mesh;
  int dim;
};

std::vector<Case> generated_cases()
{
  std::vector<Case> cases;
  Mesh sphere = make_icosphere(3);
  jitter_vertices(sphere, 0.1, 4);
  cases.push_back({"sphere", sphere, 0});
  cases.push_back({"torus", make_torus(30, 14), 2});
  cases.push_back({"disk", make_curved_disk(8), 0});
  cases.push_back({"annulus", make_curved_disk(6, 0.4), 1});
  return cases;
}

} // namespace

TEST(Hodge, PartsAreOrthogonalAndAddUpOnGeneratedMeshes)
{
  for(auto& c : generated_cases())
  {
    SCOPED_TRACE(c.name);
    TVF::Hodge_decomposition<Mesh> hodge(c.mesh);
    EXPECT_EQ(hodge.harmonic_dimension(), c.dim);
    expect_valid_decomposition(hodge.solver(), random_field(c.mesh.number_of_faces(), 11));
    // A smooth field too (large harmonic content on the torus).
    Field v = ambient_field_map(c.mesh, "v", 5);
    expect_valid_decomposition(hodge.solver(), hodge.operators().to_frame_coordinates(v));
  }
}

TEST(Hodge, PureGradientsCogradientsAndHarmonicFieldsComeBackUnchanged)
{
  for(auto& c : generated_cases())
  {
    SCOPED_TRACE(c.name);
    TVF::Hodge_decomposition<Mesh> hodge(c.mesh);
    const auto& A = hodge.solver().operators();
    std::mt19937 gen(9);
    std::normal_distribution<double> N;
    Eigen::VectorXd f(A.mesh().number_of_vertices()), g(A.mesh().number_of_edges());
    for(int i = 0; i < f.size(); ++i) f[i] = N(gen);
    for(int i = 0; i < g.size(); ++i) g[i] = A.mesh().is_boundary_edge(i) ? 0. : N(gen);
    const Eigen::VectorXd gradient = A.G() * f;
    const Eigen::VectorXd cogradient = A.rotate(A.G_star() * g);
    const unsigned all = TVF::hodge_exact | TVF::hodge_coexact | TVF::hodge_harmonic;

    TVF::Hodge_parts p = hodge.solver().decompose(gradient, all);
    EXPECT_LT(mx_norm(A, p.exact - gradient), 1e-10 * mx_norm(A, gradient));
    EXPECT_LT(mx_norm(A, p.coexact), 1e-10 * mx_norm(A, gradient));
    EXPECT_LT(mx_norm(A, p.harmonic), 1e-10 * mx_norm(A, gradient));

    p = hodge.solver().decompose(cogradient, all);
    EXPECT_LT(mx_norm(A, p.coexact - cogradient), 1e-10 * mx_norm(A, cogradient));
    EXPECT_LT(mx_norm(A, p.exact), 1e-10 * mx_norm(A, cogradient));
    EXPECT_LT(mx_norm(A, p.harmonic), 1e-10 * mx_norm(A, cogradient));

    // The potential is recovered up to a constant per component (zero mean).
    p = hodge.solver().decompose(gradient, TVF::hodge_potential);
    Eigen::VectorXd centred = f.array() - f.dot(A.vertex_masses()) / A.vertex_masses().sum();
    EXPECT_LT((p.potential - centred).norm(), 1e-9 * centred.norm());

    const Eigen::MatrixXd& H = hodge.solver().harmonic_basis();
    ASSERT_EQ(H.cols(), c.dim);
    for(int k = 0; k < H.cols(); ++k)
    {
      p = hodge.solver().decompose(H.col(k), all);
      EXPECT_LT(mx_norm(A, p.harmonic - H.col(k)), 1e-10);
    }
  }
}

TEST(Hodge, HarmonicBasisIsOrthonormalHarmonicAndHasTheTopologicalDimension)
{
  for(auto& c : generated_cases())
  {
    SCOPED_TRACE(c.name);
    TVF::Hodge_decomposition<Mesh> hodge(c.mesh);
    const auto& A = hodge.solver().operators();
    const Eigen::MatrixXd& H = hodge.solver().harmonic_basis();
    ASSERT_EQ(H.cols(), c.dim);
    if(c.dim == 0) continue;
    const Eigen::MatrixXd K = H.transpose() * A.field_masses().asDiagonal() * H;
    EXPECT_LT((K - Eigen::MatrixXd::Identity(c.dim, c.dim)).norm(), 1e-12);
    // Harmonic: zero Dirichlet energy.
    EXPECT_LT((H.transpose() * A.S() * H).norm(), 1e-9 * A.S().diagonal().maxCoeff());
    // Rank spectrum: dim values well above the cut, two far below.
    const Eigen::VectorXd& sigma = hodge.solver().harmonic_rank_spectrum();
    EXPECT_GT(sigma[c.dim - 1], 1e-4);
    EXPECT_LT(sigma[c.dim], 1e-9);
  }
}

namespace {
// Harmonic dimension check on a real mesh of CGAL's data tree.
void check_real_mesh(const std::string& file, int expected_dim, int expected_components = 1)
{
  const std::string dir = cgal_data_dir();
  if(dir.empty()) GTEST_SKIP() << cgal_data_missing();
  Mesh mesh;
  ASSERT_TRUE(read_mesh(dir + "/meshes/" + file, mesh)) << file;
  TVF::Hodge_decomposition<Mesh> hodge(mesh);
  EXPECT_EQ(hodge.topology().number_of_components(), expected_components);
  EXPECT_EQ(hodge.harmonic_dimension(), expected_dim) << hodge.topology().summary();
  const Eigen::MatrixXd& H = hodge.solver().harmonic_basis(); // throws if the numerical rank differs
  EXPECT_EQ(H.cols(), expected_dim);
  const Eigen::VectorXd& sigma = hodge.solver().harmonic_rank_spectrum();
  if(expected_dim > 0)
  {
    std::cout << file << ": smallest harmonic singular value " << sigma[expected_dim - 1]
              << ", largest spurious " << sigma[expected_dim] << std::endl;
    EXPECT_LT(sigma[expected_dim], 1e-9);
  }
  const auto& A = hodge.solver().operators();
  const Eigen::MatrixXd K = H.transpose() * A.field_masses().asDiagonal() * H;
  EXPECT_LT((K - Eigen::MatrixXd::Identity(H.cols(), H.cols())).norm(), 1e-10);
  expect_valid_decomposition(hodge.solver(), random_field(mesh.number_of_faces(), 3));
}
} // namespace

TEST(HodgeRealMeshes, ElephantGenus3) { check_real_mesh("elephant.off", 6); }
TEST(HodgeRealMeshes, CheeseGenus133) { check_real_mesh("cheese.off", 266); }
TEST(HodgeRealMeshes, ElephantWithHolesGenus3And106Loops) { check_real_mesh("elephant-with-holes.off", 111); }

TEST(HodgeRealMeshes, BonesPerComponent)
{
  const std::string dir = cgal_data_dir();
  if(dir.empty()) GTEST_SKIP() << cgal_data_missing();
  Mesh mesh;
  ASSERT_TRUE(read_mesh(dir + "/meshes/bones.off", mesh));
  TVF::Hodge_decomposition<Mesh> hodge(mesh);
  const auto& topology = hodge.topology();
  EXPECT_EQ(topology.number_of_components(), 26);
  // Each component's dimension follows from its own Euler characteristic and loops.
  int sum = 0;
  for(const auto& c : topology.components)
  {
    EXPECT_EQ(c.euler_characteristic(), 2 - 2 * c.genus - c.number_of_boundary_loops);
    sum += c.harmonic_dimension();
  }
  EXPECT_EQ(hodge.harmonic_dimension(), sum);
  EXPECT_EQ(hodge.solver().harmonic_basis().cols(), sum);
  expect_valid_decomposition(hodge.solver(), random_field(mesh.number_of_faces(), 5));
}

TEST(Hodge, InvariantUnderScalingAndRigidMotion)
{
  Mesh reference = make_torus(24, 12);
  const auto ambient = ambient_linear_field(reference, 2);
  auto decompose = [&](Mesh mesh, double scale, const std::array<double, 9>& R) {
    transform(mesh, scale, R, Vector_3(scale * 3, -scale, scale * 0.5));
    Field v = field_map(mesh, "v"), e = field_map(mesh, "e"), c = field_map(mesh, "c"), h = field_map(mesh, "h");
    // The same field, carried along by the motion.
    for(Face_index f : mesh.faces())
    {
      const Vector_3& w = ambient[f];
      v[f] = Vector_3(R[0] * w.x() + R[1] * w.y() + R[2] * w.z(), R[3] * w.x() + R[4] * w.y() + R[5] * w.z(),
                      R[6] * w.x() + R[7] * w.y() + R[8] * w.z());
    }
    TVF::hodge_decomposition(mesh, v, TVF::parameters::exact_part_map(e).coexact_part_map(c).harmonic_part_map(h));
    std::vector<Vector_3> out;
    for(Face_index f : mesh.faces())
    {
      // Rotate back to compare in the reference orientation.
      for(const Vector_3& w : {e[f], c[f], h[f]})
        out.emplace_back(R[0] * w.x() + R[3] * w.y() + R[6] * w.z(), R[1] * w.x() + R[4] * w.y() + R[7] * w.z(),
                         R[2] * w.x() + R[5] * w.y() + R[8] * w.z());
    }
    return out;
  };
  const std::array<double, 9> I = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  const auto base = decompose(reference, 1, I);
  double norm = 0;
  for(const auto& w : base) norm += w.squared_length();
  for(const auto& [scale, R] : {std::make_pair(1e-8, I), std::make_pair(1e8, I),
                                std::make_pair(1.0, rotation_matrix(Vector_3(1, 2, 3), 0.7)),
                                std::make_pair(1e8, rotation_matrix(Vector_3(-1, 0.5, 2), 2.1))})
  {
    SCOPED_TRACE(scale);
    const auto other = decompose(reference, scale, R);
    double diff = 0;
    for(std::size_t i = 0; i < base.size(); ++i) diff += (base[i] - other[i]).squared_length();
    EXPECT_LT(std::sqrt(diff / norm), 1e-10);
  }
}

TEST(Hodge, ComputesOnlyWhatIsAskedFor)
{
  Mesh mesh = make_torus(16, 8);
  Field v = ambient_field_map(mesh, "v", 1), c = field_map(mesh, "c"), e = field_map(mesh, "e");
  TVF::Hodge_decomposition<Mesh> hodge(mesh);
  hodge(v, TVF::parameters::coexact_part_map(c));
  EXPECT_TRUE(hodge.solver().has_copotential_factorization());
  EXPECT_FALSE(hodge.solver().has_potential_factorization());
  hodge(v, TVF::parameters::exact_part_map(e));
  EXPECT_TRUE(hodge.solver().has_potential_factorization());
  // Nothing asked for: nothing computed, nothing written.
  TVF::Hodge_decomposition<Mesh> idle(mesh);
  idle(v);
  EXPECT_FALSE(idle.solver().has_potential_factorization());
  EXPECT_FALSE(idle.solver().has_copotential_factorization());
}

TEST(Hodge, PotentialMapsReproduceTheParts)
{
  Mesh mesh = make_curved_disk(7, 0.3);
  Field v = ambient_field_map(mesh, "v", 8), e = field_map(mesh, "e"), c = field_map(mesh, "c");
  auto f = mesh.add_property_map<Vertex_index, double>("v:f", 0).first;
  auto g = mesh.add_property_map<Edge_index, double>("e:g", 0).first;
  TVF::hodge_decomposition(
      mesh, v, TVF::parameters::exact_part_map(e).coexact_part_map(c).potential_map(f).copotential_map(g));
  TVF::Discrete_operators<Mesh> ops(mesh);
  Field grad = field_map(mesh, "grad"), cograd = field_map(mesh, "cograd");
  ops.gradient(f, grad);
  ops.nonconforming_gradient(g, cograd);
  ops.rotate(cograd, cograd);
  double norm = 0, diff = 0;
  for(Face_index t : mesh.faces())
  {
    norm += v[t].squared_length();
    diff += (grad[t] - e[t]).squared_length() + (cograd[t] - c[t]).squared_length();
  }
  EXPECT_LT(std::sqrt(diff / norm), 1e-12);
  for(Edge_index ed : mesh.edges())
    if(mesh.is_border(ed)) EXPECT_EQ(g[ed], 0.);
}

TEST(Hodge, CustomIndexMapsGiveTheSameParts)
{
  // Reversed vertex, edge and face numberings through named parameters: the same
  // field must decompose into the same parts, element by element.
  Mesh mesh = make_torus(12, 7);
  Field v = ambient_field_map(mesh, "v", 4), h1 = field_map(mesh, "h1"), h2 = field_map(mesh, "h2");
  auto f1 = mesh.add_property_map<Vertex_index, double>("v:f1", 0).first;
  auto f2 = mesh.add_property_map<Vertex_index, double>("v:f2", 0).first;
  auto vim = mesh.add_property_map<Vertex_index, std::size_t>("v:rev").first;
  auto eim = mesh.add_property_map<Edge_index, std::size_t>("e:rev").first;
  auto fim = mesh.add_property_map<Face_index, std::size_t>("f:rev").first;
  for(Vertex_index x : mesh.vertices()) vim[x] = mesh.number_of_vertices() - 1 - std::size_t(x);
  for(Edge_index x : mesh.edges()) eim[x] = mesh.number_of_edges() - 1 - std::size_t(x);
  for(Face_index x : mesh.faces()) fim[x] = mesh.number_of_faces() - 1 - std::size_t(x);
  TVF::hodge_decomposition(mesh, v, TVF::parameters::harmonic_part_map(h1).potential_map(f1));
  TVF::hodge_decomposition(mesh, v,
                           TVF::parameters::harmonic_part_map(h2).potential_map(f2).vertex_index_map(vim)
                               .edge_index_map(eim).face_index_map(fim));
  double norm = 0, diff = 0;
  for(Face_index f : mesh.faces())
  {
    norm += h1[f].squared_length();
    diff += (h1[f] - h2[f]).squared_length();
  }
  EXPECT_GT(norm, 0);
  EXPECT_LT(std::sqrt(diff / norm), 1e-10);
  for(Vertex_index x : mesh.vertices()) EXPECT_NEAR(f1[x], f2[x], 1e-10);
}
