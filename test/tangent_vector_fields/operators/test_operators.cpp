// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Identities of SPEC section 2 on irregular meshes, the property-map interface,
// frames, and named parameters.

#include "test_meshes.h"

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;

namespace {

typedef Eigen::SparseMatrix<double> Sparse;

// Relative size of `x` against `scale` (both norms), for identities that should be roundoff.
double relative(double x, double scale) { return scale > 0 ? x / scale : x; }

struct Named_mesh
{
  std::string name;
  Mesh mesh;
};

std::vector<Named_mesh> irregular_meshes()
{
  std::vector<Named_mesh> meshes;
  Mesh sphere = make_icosphere(2);
  jitter_vertices(sphere, 0.2, 7);
  meshes.push_back({"jittered icosphere", sphere});
  meshes.push_back({"irregular torus", make_torus(14, 9)});
  meshes.push_back({"curved disk", make_curved_disk(5)});
  meshes.push_back({"curved annulus", make_curved_disk(4, 0.35)});
  return meshes;
}

// Classical cotan matrix from 3D positions: w_ij = (cot alpha + cot beta) / 2.
Eigen::MatrixXd classical_cotan_matrix(const Mesh& mesh)
{
  const int nv = static_cast<int>(mesh.number_of_vertices());
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(nv, nv);
  for(Face_index f : mesh.faces())
  {
    std::vector<Vertex_index> v;
    for(Vertex_index w : vertices_around_face(mesh.halfedge(f), mesh)) v.push_back(w);
    for(int k = 0; k < 3; ++k)
    {
      const Point_3& p = mesh.point(v[k]);
      const Vector_3 a = mesh.point(v[(k + 1) % 3]) - p, b = mesh.point(v[(k + 2) % 3]) - p;
      const double cot = (a * b) / std::sqrt(CGAL::cross_product(a, b).squared_length());
      const int i = static_cast<int>(v[(k + 1) % 3]), j = static_cast<int>(v[(k + 2) % 3]);
      W(i, j) -= cot / 2;
      W(j, i) -= cot / 2;
      W(i, i) += cot / 2;
      W(j, j) += cot / 2;
    }
  }
  return W;
}

} // namespace

TEST(Operators, CotanMatrixEqualsClassicalFormulaAndGtMxG)
{
  for(const auto& m : irregular_meshes())
  {
    SCOPED_TRACE(m.name);
    TVF::Discrete_operators<Mesh> ops(m.mesh);
    const auto& A = ops.matrices();
    const Eigen::MatrixXd W = Eigen::MatrixXd(A.W());
    const Eigen::MatrixXd reference = classical_cotan_matrix(m.mesh);
    EXPECT_LT(relative((W - reference).norm(), reference.norm()), 1e-12);
    const Eigen::MatrixXd GtMG = Eigen::MatrixXd(Sparse(A.G().transpose() * A.MX() * A.G()));
    EXPECT_LT(relative((W - GtMG).norm(), W.norm()), 1e-12);
    // W* (interior) equals G*^T MX G* on interior edges.
    const Sparse& Gi = A.G_star_interior();
    const Eigen::MatrixXd Ws = Eigen::MatrixXd(A.W_star());
    const Eigen::MatrixXd GsMGs = Eigen::MatrixXd(Sparse(Gi.transpose() * A.MX() * Gi));
    EXPECT_LT(relative((Ws - GsMGs).norm(), Ws.norm()), 1e-12);
    // Constants: in the kernel of W always, of W* only on closed meshes.
    EXPECT_LT((W * Eigen::VectorXd::Ones(W.rows())).norm(), 1e-12 * W.norm());
  }
}

TEST(Operators, GradientOfLinearFunctionIsExactOnFlatMesh)
{
  // On a planar mesh the gradient of the hat interpolant of x + 2y is (1, 2, 0) in every face.
  Mesh mesh = make_disk(5);
  TVF::Discrete_operators<Mesh> ops(mesh);
  auto f = mesh.add_property_map<Vertex_index, double>("v:f", 0).first;
  for(Vertex_index v : mesh.vertices()) f[v] = mesh.point(v).x() + 2 * mesh.point(v).y();
  auto grad = mesh.add_property_map<Face_index, Vector_3>("f:grad", Vector_3(0, 0, 0)).first;
  ops.gradient(f, grad);
  for(Face_index t : mesh.faces()) EXPECT_LT((grad[t] - Vector_3(1, 2, 0)).squared_length(), 1e-24);
  // The Crouzeix-Raviart gradient of the midpoint values of the same function agrees.
  auto g = mesh.add_property_map<Edge_index, double>("e:g", 0).first;
  for(Edge_index e : mesh.edges()) g[e] = (f[mesh.vertex(e, 0)] + f[mesh.vertex(e, 1)]) / 2;
  auto grad_star = mesh.add_property_map<Face_index, Vector_3>("f:grad_star", Vector_3(0, 0, 0)).first;
  ops.nonconforming_gradient(g, grad_star);
  for(Face_index t : mesh.faces()) EXPECT_LT((grad_star[t] - Vector_3(1, 2, 0)).squared_length(), 1e-24);
}

TEST(Operators, CurlOfGradientAndDivergenceOfCogradientVanish)
{
  for(const auto& m : irregular_meshes())
  {
    SCOPED_TRACE(m.name);
    TVF::Discrete_operators<Mesh> ops(m.mesh);
    const auto& A = ops.matrices();
    const auto& im = ops.intrinsic_mesh();
    // curl*_h G = 0 on the rows of interior edges.
    const Eigen::MatrixXd curlG = Eigen::MatrixXd(Sparse(A.G_star().transpose() * A.J() * A.MX() * A.G()));
    const double scale = Eigen::MatrixXd(A.G()).norm() * A.field_masses().maxCoeff() * Eigen::MatrixXd(A.G_star()).norm();
    for(int e = 0; e < im.number_of_edges(); ++e)
      if(!im.is_boundary_edge(e)) EXPECT_LT(curlG.row(e).norm(), 1e-13 * scale) << "edge " << e;
    // div_h J G* = 0 on the columns of interior edges.
    const Eigen::MatrixXd divJGs = Eigen::MatrixXd(Sparse(A.G().transpose() * A.MX() * A.J() * A.G_star()));
    for(int e = 0; e < im.number_of_edges(); ++e)
      if(!im.is_boundary_edge(e)) EXPECT_LT(divJGs.col(e).norm(), 1e-13 * scale) << "edge " << e;
    // (G f)^T MX (J G* g) = 0 for all f and all g vanishing on the boundary.
    const Eigen::MatrixXd cross = Eigen::MatrixXd(Sparse(A.G().transpose() * A.MX() * A.J() * A.G_star_interior()));
    EXPECT_LT(cross.norm(), 1e-13 * scale);
  }
}

TEST(Operators, DirichletEnergyIsSymmetricSemidefiniteWithHarmonicKernel)
{
  for(const auto& m : irregular_meshes())
  {
    SCOPED_TRACE(m.name);
    TVF::Discrete_operators<Mesh> ops(m.mesh);
    const auto& A = ops.matrices();
    const Eigen::MatrixXd S = Eigen::MatrixXd(A.S());
    EXPECT_LT((S - S.transpose()).norm(), 1e-13 * S.norm());
    // The directly assembled S equals the product formula of SPEC 2 (interior edges).
    const Eigen::MatrixXd MX = Eigen::MatrixXd(A.MX()), G = Eigen::MatrixXd(A.G()), J = Eigen::MatrixXd(A.J());
    const Eigen::MatrixXd Gs = Eigen::MatrixXd(A.G_star_interior());
    Eigen::VectorXd interior_mass(Gs.cols());
    for(int i = 0; i < Gs.cols(); ++i) interior_mass[i] = A.edge_masses()[ops.intrinsic_mesh().interior_edges()[i]];
    const Eigen::MatrixXd formula =
        MX * (G * A.vertex_masses().cwiseInverse().asDiagonal() * G.transpose() -
              J * Gs * interior_mass.cwiseInverse().asDiagonal() * Gs.transpose() * J) * MX;
    EXPECT_LT((S - formula).norm(), 1e-13 * S.norm());
    // Generalised eigenvalues of S x = lambda MX x: all >= 0, exactly dim H of them zero.
    const Eigen::VectorXd inv_sqrt_mass = A.field_masses().cwiseSqrt().cwiseInverse();
    const Eigen::MatrixXd Sn = inv_sqrt_mass.asDiagonal() * S * inv_sqrt_mass.asDiagonal();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(Sn);
    const Eigen::VectorXd lambda = eig.eigenvalues();
    const double top = lambda.maxCoeff();
    EXPECT_GT(lambda.minCoeff(), -1e-10 * top);
    int zeros = 0;
    while(zeros < lambda.size() && lambda[zeros] < 1e-9 * top) ++zeros;
    EXPECT_EQ(zeros, ops.topology().harmonic_dimension());
    EXPECT_GT(lambda[zeros], 1e-6 * top); // a clear gap after the kernel
    // L = MX^-1 S is self-adjoint in MX: MX L = (MX L)^T.
    const Eigen::MatrixXd ML = Eigen::MatrixXd(Sparse(A.MX() * A.L()));
    EXPECT_LT((ML - ML.transpose()).norm(), 1e-13 * ML.norm());
    // B = S MX^-1 S.
    const Eigen::MatrixXd B = Eigen::MatrixXd(A.B());
    const Eigen::MatrixXd reference = S * A.field_masses().cwiseInverse().asDiagonal() * S;
    EXPECT_LT((B - reference).norm(), 1e-12 * reference.norm());
  }
}

TEST(Operators, DivergenceAndCurlAreAdjointsOfGradients)
{
  // <div v, f>_M = -<v, G f>_MX and <curl v, f>_M = -<v, J G f>_MX (thesis (1.4), (1.5)).
  Mesh mesh = make_torus(12, 8);
  TVF::Discrete_operators<Mesh> ops(mesh);
  const auto& A = ops.matrices();
  const Eigen::VectorXd v = Eigen::VectorXd::Random(2 * mesh.number_of_faces());
  const Eigen::VectorXd f = Eigen::VectorXd::Random(mesh.number_of_vertices());
  const Eigen::VectorXd g = Eigen::VectorXd::Random(mesh.number_of_edges());
  const Eigen::VectorXd& mx = A.field_masses();
  const double s = v.norm() * f.norm() * mx.maxCoeff() * 10;
  EXPECT_NEAR(A.divergence(v).dot(A.vertex_masses().cwiseProduct(f)), -(A.G() * f).dot(mx.cwiseProduct(v)), 1e-12 * s);
  EXPECT_NEAR(A.curl(v).dot(A.vertex_masses().cwiseProduct(f)), -A.rotate(A.G() * f).dot(mx.cwiseProduct(v)), 1e-12 * s);
  EXPECT_NEAR(A.nonconforming_divergence(v).dot(A.edge_masses().cwiseProduct(g)),
              -(A.G_star() * g).dot(mx.cwiseProduct(v)), 1e-12 * s);
  EXPECT_NEAR(A.nonconforming_curl(v).dot(A.edge_masses().cwiseProduct(g)),
              -A.rotate(A.G_star() * g).dot(mx.cwiseProduct(v)), 1e-12 * s);
  // J J = -1 and the sparse J agrees with rotate().
  EXPECT_LT((A.rotate(A.rotate(v)) + v).norm(), 1e-15 * v.norm());
  EXPECT_LT((A.J() * v - A.rotate(v)).norm(), 1e-15 * v.norm());
}

TEST(Operators, MassesAddUpToTheArea)
{
  Mesh mesh = make_curved_disk(6, 0.3);
  TVF::Discrete_operators<Mesh> ops(mesh);
  const auto& A = ops.matrices();
  double area = 0;
  for(Face_index f : mesh.faces())
  {
    auto h = mesh.halfedge(f);
    const Point_3 &a = mesh.point(mesh.source(h)), &b = mesh.point(mesh.target(h)),
                  &c = mesh.point(mesh.target(mesh.next(h)));
    area += std::sqrt(CGAL::cross_product(b - a, c - a).squared_length()) / 2;
  }
  EXPECT_NEAR(A.face_areas().sum(), area, 1e-13 * area);
  EXPECT_NEAR(A.vertex_masses().sum(), area, 1e-13 * area);
  EXPECT_NEAR(A.edge_masses().sum(), area, 1e-13 * area);
  EXPECT_NEAR(A.field_masses().sum(), 2 * area, 1e-13 * area);
  // The property-map versions give the same numbers.
  auto vm = mesh.add_property_map<Vertex_index, double>("v:mass", 0).first;
  ops.vertex_masses(vm);
  double total = 0;
  for(Vertex_index v : mesh.vertices()) total += vm[v];
  EXPECT_NEAR(total, area, 1e-13 * area);
}

TEST(Operators, FramesAreOrthonormalTangentAndRoundTripIsExact)
{
  Mesh mesh = make_torus(10, 7);
  TVF::Discrete_operators<Mesh> ops(mesh);
  auto e1 = mesh.add_property_map<Face_index, Vector_3>("f:e1").first;
  auto e2 = mesh.add_property_map<Face_index, Vector_3>("f:e2").first;
  auto n = mesh.add_property_map<Face_index, Vector_3>("f:n").first;
  ops.face_frames(e1, e2, n);
  auto in = mesh.add_property_map<Face_index, Vector_3>("f:in").first;
  auto out = mesh.add_property_map<Face_index, Vector_3>("f:out").first;
  std::mt19937 gen(3);
  std::normal_distribution<double> N;
  for(Face_index f : mesh.faces())
  {
    EXPECT_NEAR(e1[f].squared_length(), 1, 1e-14);
    EXPECT_NEAR(e2[f].squared_length(), 1, 1e-14);
    EXPECT_NEAR(e1[f] * e2[f], 0, 1e-14);
    EXPECT_LT((CGAL::cross_product(e1[f], e2[f]) - n[f]).squared_length(), 1e-28);
    // The normal agrees with the face orientation.
    auto h = mesh.halfedge(f);
    const Vector_3 geometric = CGAL::cross_product(mesh.point(mesh.target(h)) - mesh.point(mesh.source(h)),
                                                   mesh.point(mesh.target(mesh.next(h))) - mesh.point(mesh.source(h)));
    EXPECT_GT(geometric * n[f], 0);
    in[f] = Vector_3(N(gen), N(gen), N(gen));
  }
  const Eigen::VectorXd x = ops.to_frame_coordinates(in);
  ops.from_frame_coordinates(x, out);
  for(Face_index f : mesh.faces())
  {
    // out is the orthogonal projection of in onto the face plane.
    const Vector_3 projected = in[f] - (in[f] * n[f]) * n[f];
    EXPECT_LT((out[f] - projected).squared_length(), 1e-28 * (1 + in[f].squared_length()));
  }
  // Tangent vectors survive the round trip exactly (to roundoff).
  const Eigen::VectorXd y = ops.to_frame_coordinates(out);
  EXPECT_LT((x - y).norm(), 1e-14 * x.norm());
  // Rotation by J turns e1 into e2.
  for(Face_index f : mesh.faces()) in[f] = e1[f];
  ops.rotate(in, out);
  for(Face_index f : mesh.faces()) EXPECT_LT((out[f] - e2[f]).squared_length(), 1e-28);
}

TEST(Operators, LayoutAgreesWithTheEmbedding)
{
  // The intrinsic layout of each face equals its 3D vertices in the face frame.
  Mesh mesh = make_torus(9, 6);
  TVF::Discrete_operators<Mesh> ops(mesh);
  const auto& im = ops.intrinsic_mesh();
  for(int f = 0; f < im.number_of_faces(); ++f)
  {
    const auto& p0 = im.position(im.face_vertices(f)[0]);
    const auto& p2 = im.position(im.face_vertices(f)[2]);
    const auto ab = im.to_frame(f, {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]});
    EXPECT_NEAR(ab[0], im.corner2_layout(f)[0], 1e-14);
    EXPECT_NEAR(ab[1], im.corner2_layout(f)[1], 1e-14);
  }
}

TEST(Operators, NamedParametersMixOursAndCgals)
{
  // A vertex point map that doubles the mesh: areas scale by 4.
  Mesh mesh = make_icosphere(1);
  auto doubled = mesh.add_property_map<Vertex_index, Point_3>("v:doubled").first;
  for(Vertex_index v : mesh.vertices()) doubled[v] = CGAL::ORIGIN + 2 * (mesh.point(v) - CGAL::ORIGIN);
  TVF::Discrete_operators<Mesh> plain(mesh);
  TVF::Discrete_operators<Mesh> ours(mesh, TVF::parameters::vertex_point_map(doubled).use_intrinsic_mollification(false));
  TVF::Discrete_operators<Mesh> theirs(mesh, CGAL::parameters::vertex_point_map(doubled));
  TVF::Discrete_operators<Mesh> mixed(mesh, TVF::parameters::use_intrinsic_mollification(true).vertex_point_map(doubled));
  TVF::Discrete_operators<Mesh> combined(
      mesh, TVF::parameters::combine(CGAL::parameters::vertex_point_map(doubled),
                                     TVF::parameters::mollification_epsilon(1e-9).use_intrinsic_mollification(true)));
  const double a = plain.matrices().face_areas().sum();
  for(const auto* ops : {&ours, &theirs, &mixed, &combined})
    EXPECT_NEAR(ops->matrices().face_areas().sum(), 4 * a, 1e-12 * a);
  EXPECT_EQ(mixed.intrinsic_mesh().mollification_delta(), 0.); // nothing to mollify on a good mesh
}

// The editor's sessions share one set of operators, each session on its own thread, and the
// matrices are built on first use: whichever threads ask at once, each matrix is built once
// (every thread gets the same object) and equals the one built by a single thread.  Before,
// two threads building a matrix at once crashed the editor's server.
TEST(Operators, MatricesAskedForByManyThreadsAtOnceAreBuiltOnce)
{
  const Mesh mesh = make_torus(60, 40);
  typedef const Sparse& (TVF::Operator_matrices::*Accessor)() const;
  const std::vector<Accessor> accessors = {
      &TVF::Operator_matrices::G,  &TVF::Operator_matrices::G_star, &TVF::Operator_matrices::G_star_interior,
      &TVF::Operator_matrices::M,  &TVF::Operator_matrices::M_star, &TVF::Operator_matrices::MX,
      &TVF::Operator_matrices::J,  &TVF::Operator_matrices::W,      &TVF::Operator_matrices::W_star,
      &TVF::Operator_matrices::S,  &TVF::Operator_matrices::L,      &TVF::Operator_matrices::B};
  const TVF::Discrete_operators<Mesh> alone(mesh);
  for(int round = 0; round < 20; ++round)
  {
    const TVF::Discrete_operators<Mesh> shared(mesh);
    const TVF::Operator_matrices& ops = shared.matrices();
    const int threads = 8;
    std::vector<std::vector<const Sparse*>> seen(threads);
    std::vector<Eigen::VectorXd> divergences(threads);
    const Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(2 * mesh.number_of_faces(), -1, 1);
    std::atomic<int> waiting{threads};
    std::vector<std::thread> pool;
    for(int t = 0; t < threads; ++t)
      pool.emplace_back([&, t] {
        for(--waiting; waiting.load() > 0;) // all start together
          ;
        for(std::size_t k = 0; k < accessors.size(); ++k) // in a different order per thread
          seen[t].push_back(&(ops.*accessors[(k + 5 * t) % accessors.size()])());
        divergences[t] = ops.divergence(v);
      });
    for(std::thread& t : pool) t.join();
    for(std::size_t k = 0; k < accessors.size(); ++k)
    {
      const Sparse& reference = (alone.matrices().*accessors[k])();
      for(int t = 0; t < threads; ++t)
      {
        const Sparse* got = seen[t][(k + accessors.size() - (5 * t) % accessors.size()) % accessors.size()];
        ASSERT_EQ(got, &(ops.*accessors[k])()) << "matrix " << k << " built more than once (thread " << t << ")";
        ASSERT_EQ(got->nonZeros(), reference.nonZeros()) << "matrix " << k;
        EXPECT_EQ((*got - reference).norm(), 0.) << "matrix " << k;
      }
    }
    for(int t = 0; t < threads; ++t) EXPECT_EQ((divergences[t] - alone.matrices().divergence(v)).norm(), 0.);
  }
}
