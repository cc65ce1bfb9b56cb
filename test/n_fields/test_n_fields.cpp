// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// n-direction fields (SPEC 10): the first-order energy against independent formulas
// (Crouzeix-Raviart for n = 1, a frame-free hinge computation for any n), its symmetry,
// kernel and J-invariance, the index and Poincare-Hopf on meshes of every topology, the
// smoothest field of the sphere (2n singularities of index 1/n), the spectrum of L_n
// on icospheres against the continuous operator, the basis and its files, invariance.

#include "test_meshes.h"

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>
#include <CGAL/Tangent_vector_fields/N_field_basis.h>
#include <CGAL/Tangent_vector_fields/N_field_operators.h>
#include <CGAL/Tangent_vector_fields/N_field_singularities.h>
#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/smoothest_n_field.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <numeric>

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;

namespace {

std::shared_ptr<const TVF::N_field_operators> n_field_operators(const Mesh& mesh, int n,
                                                                TVF::N_field_boundary boundary = TVF::N_field_boundary::free)
{
  TVF::Discrete_operators<Mesh> ops(mesh);
  TVF::N_field_options options;
  options.boundary = boundary;
  return std::make_shared<const TVF::N_field_operators>(ops.shared_matrices(), n, options);
}

// A cube [-1, 1]^3 with a k x k grid of squares per side, each split into two triangles.
Mesh make_cube(int k)
{
  std::vector<Point_3> points;
  std::map<std::array<int, 3>, int> index; // lattice point (in units of 2/k) -> vertex
  auto vertex = [&](std::array<int, 3> q) {
    auto it = index.find(q);
    if(it != index.end()) return it->second;
    points.emplace_back(-1 + 2. * q[0] / k, -1 + 2. * q[1] / k, -1 + 2. * q[2] / k);
    index[q] = static_cast<int>(points.size()) - 1;
    return static_cast<int>(points.size()) - 1;
  };
  std::vector<std::array<int, 3>> triangles;
  for(int axis = 0; axis < 3; ++axis)
    for(int side = 0; side < 2; ++side)
    {
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      for(int i = 0; i < k; ++i)
        for(int j = 0; j < k; ++j)
        {
          auto at = [&](int a, int b) {
            std::array<int, 3> q{};
            q[axis] = side * k;
            q[u] = a;
            q[w] = b;
            return vertex(q);
          };
          const int p00 = at(i, j), p10 = at(i + 1, j), p01 = at(i, j + 1), p11 = at(i + 1, j + 1);
          // (u, w, axis) is right-handed: counter-clockwise seen from outside on side 1.
          if(side == 1)
          {
            triangles.push_back({p00, p10, p11});
            triangles.push_back({p00, p11, p01});
          }
          else
          {
            triangles.push_back({p00, p11, p10});
            triangles.push_back({p00, p01, p11});
          }
        }
    }
  return make_mesh(points, triangles);
}

int euler_characteristic(const TVF::Intrinsic_mesh& mesh)
{
  int chi = 0;
  for(const auto& c : mesh.topology().components) chi += c.euler_characteristic();
  return chi;
}

// Random tangent vectors in every face (frame coordinates) of lengths in [0.5, 1.5].
Eigen::VectorXd random_vectors(int nf, unsigned seed)
{
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), length(0.5, 1.5);
  Eigen::VectorXd x(2 * nf);
  for(int f = 0; f < nf; ++f)
  {
    const double a = angle(gen), r = length(gen);
    x[2 * f] = r * std::cos(a);
    x[2 * f + 1] = r * std::sin(a);
  }
  return x;
}

Eigen::Vector3d to_eigen(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

// Rotation about the unit axis `a` by `angle` applied to `v` (Rodrigues).
Eigen::Vector3d rotate(const Eigen::Vector3d& v, const Eigen::Vector3d& a, double angle)
{
  return v * std::cos(angle) + a.cross(v) * std::sin(angle) + a * a.dot(v) * (1 - std::cos(angle));
}

// E_D from 3D data alone: unfold face g onto f about their common edge, measure the angle
// between the two representative vectors in f's plane, and compare n times it.
double hinge_energy(const Mesh& mesh, const std::vector<Eigen::Vector3d>& u, int n)
{
  double energy = 0;
  for(Edge_index e : mesh.edges())
  {
    if(mesh.is_border(e)) continue;
    const auto h = mesh.halfedge(e);
    const Face_index f = mesh.face(h), g = mesh.face(mesh.opposite(h));
    auto point = [&](Vertex_index v) { const Point_3& p = mesh.point(v); return Eigen::Vector3d(p.x(), p.y(), p.z()); };
    auto normal_area = [&](Face_index t, double& area) {
      auto k = mesh.halfedge(t);
      const Eigen::Vector3d p0 = point(mesh.source(k)), p1 = point(mesh.target(k)),
                            p2 = point(mesh.target(mesh.next(k)));
      const Eigen::Vector3d c = (p1 - p0).cross(p2 - p0);
      area = c.norm() / 2;
      return Eigen::Vector3d(c.normalized());
    };
    double area_f, area_g;
    const Eigen::Vector3d nf = normal_area(f, area_f), ng = normal_area(g, area_g);
    const Eigen::Vector3d edge = point(mesh.target(h)) - point(mesh.source(h));
    const Eigen::Vector3d axis = edge.normalized();
    // Dihedral rotation about the edge that takes g's normal to f's normal.
    const double angle = std::atan2(axis.dot(ng.cross(nf)), ng.dot(nf));
    const Eigen::Vector3d ug = rotate(u[g], axis, angle);
    const Eigen::Vector3d uf = u[f];
    const double delta = std::atan2(nf.dot(ug.cross(uf)), ug.dot(uf)); // from ug to uf, about nf
    const double w = 3 * edge.squaredNorm() / (area_f + area_g);
    const double rf = uf.norm(), rg = ug.norm();
    energy += w * (rf * rf + rg * rg - 2 * rf * rg * std::cos(n * delta));
  }
  return energy;
}

} // namespace

TEST(NFieldOperators, FirstOrderEnergyOfVectorFieldsIsTheCrouzeixRaviartHodgeEnergy)
{
  // SPEC 10: for n = 1 the jumps across an interior edge are the nonconforming divergence
  // and curl, so u^T S_1 u = |G*^T MX u|^2_{M*^-1} + |G*^T MX J u|^2_{M*^-1} (interior edges).
  for(const Mesh& mesh : {make_torus(12, 8), make_disk(6, 0.3), make_icosphere(2), make_curved_disk(5)})
  {
    const auto nops = n_field_operators(mesh, 1);
    const TVF::Operator_matrices& A = nops->operators();
    const Eigen::VectorXd m_star = A.all_to_interior_edges(A.edge_masses());
    for(unsigned seed : {1u, 2u})
    {
      const Eigen::VectorXd u = random_field(A.mesh().number_of_faces(), seed);
      const Eigen::VectorXd div = A.G_star_interior().transpose() * A.MX() * u;
      const Eigen::VectorXd curl = A.G_star_interior().transpose() * A.MX() * A.rotate(u);
      const double hodge = div.cwiseAbs2().cwiseQuotient(m_star).sum() + curl.cwiseAbs2().cwiseQuotient(m_star).sum();
      EXPECT_NEAR(nops->dirichlet_energy(u), hodge, 1e-11 * hodge);
    }
  }
}

TEST(NFieldOperators, EnergyMatchesAFrameFreeHingeComputationForEveryN)
{
  // The operator works in the faces' frames; the hinge computation never uses a frame.
  // Agreement for random fields and n = 1..6 shows the energy does not depend on the frames.
  Mesh mesh = make_torus(10, 7);
  jitter_vertices(mesh, 0.05, 3);
  TVF::Discrete_operators<Mesh> ops(mesh);
  const int nf = static_cast<int>(mesh.number_of_faces());
  const Eigen::VectorXd x = random_vectors(nf, 5);
  std::vector<Eigen::Vector3d> u(nf);
  for(int f = 0; f < nf; ++f) u[f] = to_eigen(ops.intrinsic_mesh().from_frame(f, x[2 * f], x[2 * f + 1]));
  for(int n = 1; n <= 6; ++n)
  {
    const TVF::N_field_operators nops(ops.shared_matrices(), n);
    const double expected = hinge_energy(mesh, u, n);
    EXPECT_NEAR(nops.dirichlet_energy(nops.from_vectors(x)), expected, 1e-10 * expected) << "n = " << n;
    // Any of the n vectors of a face represents the same field.
    for(int j = 0; j < n; ++j)
      EXPECT_LT((nops.from_vectors(nops.to_vectors(nops.from_vectors(x), j)) - nops.from_vectors(x)).norm(),
                1e-12 * x.norm());
  }
}

TEST(NFieldOperators, SymmetricPositiveSemidefiniteAndCommutesWithRotation)
{
  const Mesh mesh = make_curved_disk(4, 0.3);
  for(int n : {1, 2, 3, 4, 6})
  {
    const auto nops = n_field_operators(mesh, n);
    const Eigen::MatrixXd S = nops->S();
    EXPECT_EQ((S - S.transpose()).cwiseAbs().maxCoeff(), 0.);
    const Eigen::MatrixXd J = nops->operators().J();
    EXPECT_LT((J * S - S * J).cwiseAbs().maxCoeff(), 1e-13 * S.cwiseAbs().maxCoeff());
    const Eigen::VectorXd d = nops->masses().cwiseSqrt().cwiseInverse();
    const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(d.asDiagonal() * S * d.asDiagonal()).eigenvalues();
    EXPECT_GT(lambda[0], -1e-12 * lambda[lambda.size() - 1]) << "n = " << n;
    // Pairs: every eigenvalue twice.
    for(Eigen::Index k = 0; k + 1 < lambda.size(); k += 2)
      EXPECT_NEAR(lambda[k], lambda[k + 1], 1e-9 * lambda[lambda.size() - 1]);
  }
}

TEST(NFieldOperators, ParallelFieldsExactlyWhereTheHolonomyIsTrivial)
{
  // Cube corners have angle defect pi/2: the holonomy n pi/2 is trivial for n = 4 and 8
  // only.  A flat disk has trivial holonomy for every n; a torus of revolution for none.
  auto kernel_dimension = [](const Mesh& mesh, int n) { return static_cast<int>(n_field_operators(mesh, n)->kernel().cols()); };
  const Mesh cube = make_cube(3);
  for(int n = 1; n <= 8; ++n) EXPECT_EQ(kernel_dimension(cube, n), n % 4 == 0 ? 2 : 0) << "n = " << n;
  const Mesh disk = make_disk(5);
  for(int n : {1, 2, 5}) EXPECT_EQ(kernel_dimension(disk, n), 2);
  EXPECT_EQ(static_cast<int>(n_field_operators(disk, 3, TVF::N_field_boundary::zero)->kernel().cols()), 0);
  const Mesh torus = make_torus(12, 8);
  for(int n : {1, 2, 4}) EXPECT_EQ(kernel_dimension(torus, n), 0);

  // Dense truth: the kernel columns have zero energy and the dimension of the null space
  // of S_n (cube, n = 4) is exactly 2.
  const auto nops = n_field_operators(cube, 4);
  const Eigen::MatrixXd& K = nops->kernel();
  const Eigen::MatrixXd S = nops->S();
  EXPECT_LT((S * K).cwiseAbs().maxCoeff(), 1e-12 * S.cwiseAbs().maxCoeff());
  const Eigen::MatrixXd gram = K.transpose() * nops->masses().asDiagonal() * K;
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(2, 2)).cwiseAbs().maxCoeff(), 1e-12);
  const Eigen::VectorXd d = nops->masses().cwiseSqrt().cwiseInverse();
  const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(d.asDiagonal() * S * d.asDiagonal()).eigenvalues();
  EXPECT_LT(std::abs(lambda[1]), 1e-10 * lambda.maxCoeff());
  EXPECT_GT(lambda[2], 1e-4 * lambda.maxCoeff());
}

TEST(NFieldSingularities, AFieldTurningKTimesAroundAFlatVertexHasIndexKOverN)
{
  // Disk centred at vertex 0 (flat, 6 faces around it): the n-field whose power turns k
  // times counter-clockwise around the centre, first vector at angle k phi / n.  A turning
  // of pi or more between neighbouring faces cannot be told from one the other way round,
  // so around 6 faces |k| <= 2 is what a discrete field can show.
  const Mesh mesh = make_disk(6);
  TVF::Discrete_operators<Mesh> ops(mesh);
  const TVF::Intrinsic_mesh& im = ops.intrinsic_mesh();
  for(int n : {1, 2, 4, 5})
    for(int k = -2; k <= 2; ++k)
    {
      const TVF::N_field_operators nops(ops.shared_matrices(), n);
      Eigen::VectorXd x(2 * im.number_of_faces());
      for(int f = 0; f < im.number_of_faces(); ++f)
      {
        std::array<double, 3> c{0, 0, 0};
        for(int v : im.face_vertices(f))
          for(int i = 0; i < 3; ++i) c[i] += im.position(v)[i] / 3;
        const double phi = std::atan2(c[1], c[0]), theta = k * phi / n;
        const auto ab = im.to_frame(f, {std::cos(theta), std::sin(theta), 0});
        x[2 * f] = ab[0];
        x[2 * f + 1] = ab[1];
      }
      const std::vector<int> index = TVF::n_field_indices(nops, nops.from_vectors(x));
      EXPECT_EQ(index[0], k) << "n = " << n << ", k = " << k;
      const auto& topology = im.topology();
      int interior_nonzero = 0, sum = 0;
      std::vector<char> boundary(im.number_of_vertices(), 0);
      for(int e = 0; e < im.number_of_edges(); ++e)
        if(im.is_boundary_edge(e))
          for(int v : im.edge_vertices(e)) boundary[v] = 1;
      for(int v = 1; v < im.number_of_vertices(); ++v) interior_nonzero += !boundary[v] && index[v] != 0;
      for(int i : index) sum += i;
      EXPECT_EQ(interior_nonzero, 0);
      EXPECT_EQ(sum, n * topology.components[0].euler_characteristic());
    }
}

TEST(NFieldSingularities, PoincareHopfOnMeshesOfEveryTopology)
{
  // Sum of k over all vertices (interior and boundary) = n chi, for random fields (many
  // singularities) and smoothest fields, n = 1..6.
  std::vector<std::pair<std::string, Mesh>> meshes = {{"icosphere", make_icosphere(2)},
                                                      {"torus", make_torus(12, 8)},
                                                      {"disk", make_disk(5)},
                                                      {"annulus", make_disk(5, 0.3)},
                                                      {"curved disk", make_curved_disk(5)},
                                                      {"cube", make_cube(2)}};
  Mesh genus3;
  if(read_mesh(shared_data_dir() + "/3holes.off", genus3)) meshes.emplace_back("3holes", genus3);
  Mesh bunny;
  if(read_mesh(shared_data_dir() + "/stanford-bunny.obj", bunny)) meshes.emplace_back("bunny", bunny);
  for(const auto& [name, mesh] : meshes)
  {
    TVF::Discrete_operators<Mesh> ops(mesh);
    const int chi = euler_characteristic(ops.intrinsic_mesh());
    const int nf = ops.intrinsic_mesh().number_of_faces();
    for(int n = 1; n <= 6; ++n)
    {
      const auto nops = std::make_shared<const TVF::N_field_operators>(ops.shared_matrices(), n);
      const Eigen::VectorXd z = nops->from_vectors(random_vectors(nf, 7 + n));
      const std::vector<int> k = TVF::n_field_indices(*nops, z);
      EXPECT_EQ(std::accumulate(k.begin(), k.end(), 0), n * chi) << name << ", random, n = " << n;
      if(nf <= 10000 && (n == 2 || n == 4))
      {
        const std::vector<int> ks = TVF::n_field_indices(*nops, TVF::smoothest_n_field(*nops));
        EXPECT_EQ(std::accumulate(ks.begin(), ks.end(), 0), n * chi) << name << ", smoothest, n = " << n;
      }
    }
  }
}

TEST(SmoothestNField, SphereHasTwoNSingularitiesOfIndexOneOverN)
{
  // Knoeppel et al. 2013: the smoothest n-field of the round sphere has 2n singularities
  // of index +1/n.
  const Mesh sphere = make_icosphere(3);
  for(int n : {1, 2, 4})
  {
    const auto nops = n_field_operators(sphere, n);
    const auto singular = TVF::n_field_singularities(*nops, TVF::smoothest_n_field(*nops));
    EXPECT_EQ(static_cast<int>(singular.size()), 2 * n) << "n = " << n;
    for(const auto& s : singular) EXPECT_EQ(s.index, 1) << "n = " << n << ", vertex " << s.vertex;
  }
}

TEST(SmoothestNField, CrossFieldOfACubeIsParallelWithItsCornersSingular)
{
  const Mesh cube = make_cube(3);
  const auto nops = n_field_operators(cube, 4);
  const Eigen::VectorXd z = TVF::smoothest_n_field(*nops);
  // Zero energy up to rounding of the terms it sums.
  const Eigen::VectorXd S_diagonal = nops->S().diagonal();
  EXPECT_LT(nops->dirichlet_energy(z), 1e-13 * z.dot(S_diagonal.cwiseProduct(z)));
  const auto singular = TVF::n_field_singularities(*nops, z);
  ASSERT_EQ(singular.size(), 8u);
  for(const auto& s : singular)
  {
    EXPECT_EQ(s.index, 1);
    const auto& p = nops->mesh().position(s.vertex);
    EXPECT_EQ(std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2]), 3.) << "a corner";
  }
}
