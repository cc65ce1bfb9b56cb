// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// n-direction fields (SPEC 10), the field itself: the first-order energy against independent
// formulas (Crouzeix-Raviart for n = 1, a frame-free hinge computation for any n), its symmetry,
// kernel and J-invariance, the index and Poincare-Hopf on meshes of every topology, the smoothest
// field (sphere: 2n singularities of index 1/n; cube: its corners), alignment, invariance; the
// files (.rawfield of degree n, .sing, .vtp) written and read back.

#include "n_field_test_support.h"
#include "scratch_path.h"

#include <CGAL/Tangent_vector_fields/N_field_basis.h>
#include <CGAL/Tangent_vector_fields/N_field_singularities.h>
#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/n_field_files.h>
#include <CGAL/Tangent_vector_fields/smoothest_n_field.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <numeric>
#include <set>
#include <sstream>

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;
using namespace nfield_test;

namespace {


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
    // The complex form (assembled on its own) acts as the real one, free and zero boundary.
    for(auto boundary : {TVF::N_field_boundary::free, TVF::N_field_boundary::zero})
    {
      const auto o = n_field_operators(mesh, n, boundary);
      const Eigen::VectorXd x = random_field(o->mesh().number_of_faces(), 71);
      Eigen::VectorXcd c(x.size() / 2);
      for(Eigen::Index f = 0; f < c.size(); ++f) c[f] = std::complex<double>(x[2 * f], x[2 * f + 1]);
      const Eigen::VectorXd real = o->S() * x;
      const Eigen::VectorXcd complex = o->complex_S() * c;
      for(Eigen::Index f = 0; f < c.size(); ++f)
        EXPECT_LT(std::abs(complex[f] - std::complex<double>(real[2 * f], real[2 * f + 1])), 1e-12 * real.norm());
    }
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

TEST(SmoothestNField, WhereLanczosFailsTheSlicingSolverAnswers)
{
  // A tolerance below what double precision reaches: the Lanczos run of the smoothest field
  // cannot meet it and gives up (the space closes on these 80 faces), and the slicing
  // eigensolver's complex Hermitian path answers (its floor is the rounding floor).  The answer
  // must be a lowest eigenvector: its Rayleigh quotient the lowest eigenvalue of the real form,
  // computed densely here.
  const Mesh sphere = make_icosphere(1);
  for(int n : {1, 3})
  {
    const auto nops = n_field_operators(sphere, n);
    TVF::Smoothest_n_field_options options;
    options.tolerance = 1e-15;
    const Eigen::VectorXd z = TVF::smoothest_n_field(*nops, options);
    const Eigen::MatrixXd S = Eigen::MatrixXd(nops->S());
    const Eigen::MatrixXd M = nops->masses().asDiagonal();
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(S, M);
    const double lowest = dense.eigenvalues()[0];
    ASSERT_GT(z.norm(), 0) << "n = " << n;
    const double rayleigh = z.dot(S * z) / z.dot(M * z);
    EXPECT_NEAR(rayleigh, lowest, 1e-10 * lowest) << "n = " << n;
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

TEST(SmoothestNField, InvariantToScaleAndRigidMotion)
{
  // A jittered torus: its lowest eigenvalue is one pair, so the smoothest field is unique
  // up to a rotation by a constant angle; scaled by 1e-8 and 1e8 and moved it must have the
  // same singularities, the same field up to that angle, and eigenvalues scaled by 1/s^2.
  Mesh reference = make_torus(24, 16);
  jitter_vertices(reference, 0.05, 13);
  const auto reference_ops = n_field_operators(reference, 4);
  const Eigen::VectorXd z0 = TVF::smoothest_n_field(*reference_ops);
  const std::vector<int> k0 = TVF::n_field_indices(*reference_ops, z0);
  const double lambda0 = reference_ops->dirichlet_energy(z0) / z0.dot(reference_ops->masses().cwiseProduct(z0));
  for(double s : {1e-8, 1e8})
  {
    Mesh mesh = reference;
    transform(mesh, s, rotation_matrix(Vector_3(1, 2, 3), 0.7), Vector_3(5 * s, -3 * s, 1 * s));
    const auto ops = n_field_operators(mesh, 4);
    const Eigen::VectorXd z = TVF::smoothest_n_field(*ops);
    EXPECT_EQ(TVF::n_field_indices(*ops, z), k0) << "scale " << s;
    const Eigen::VectorXd& m = ops->masses();
    // |<z, z0>| in the power representation's complex inner product, per unit norm.
    std::complex<double> inner(0, 0);
    for(int f = 0; f < static_cast<int>(z.size() / 2); ++f)
      inner += m[2 * f] * std::complex<double>(z[2 * f], z[2 * f + 1]) * std::conj(std::complex<double>(z0[2 * f], z0[2 * f + 1]));
    const double cosine = std::abs(inner) / std::sqrt(z.dot(m.cwiseProduct(z)) * z0.dot(m.cwiseProduct(z0)));
    EXPECT_NEAR(cosine, 1., 1e-6) << "scale " << s;
    const double lambda = ops->dirichlet_energy(z) / z.dot(m.cwiseProduct(z));
    EXPECT_NEAR(lambda * s * s, lambda0, 1e-8 * lambda0) << "scale " << s;
  }
}

TEST(SmoothestNField, AlignedFieldMinimisesItsEnergy)
{
  // E(z) = E_D(z) + s |z - g|^2_MX is minimal at the aligned field.  Truth: its optimality
  // condition (S + s MX) z = s MX g, assembled here from S and the masses and solved densely
  // (E_D(x) = x^T S x is checked first, so that the condition is the right one).  A light
  // weight tends to the smooth field, a heavy one reproduces the guide.
  Mesh mesh = make_curved_disk(6, 0.3);
  const auto nops = n_field_operators(mesh, 2);
  const int nf = nops->mesh().number_of_faces();
  double area = 0;
  for(int f = 0; f < nf; ++f) area += nops->mesh().face_area(f);
  TVF::Smoothest_n_field_options options;
  options.alignment = nops->from_vectors(random_vectors(nf, 17));
  const Eigen::MatrixXd S = nops->S();
  const Eigen::VectorXd& m = nops->masses();
  const Eigen::VectorXd probe = random_field(nf, 3);
  EXPECT_NEAR(nops->dirichlet_energy(probe), probe.dot(S * probe), 1e-12 * probe.dot(S * probe));
  for(double weight : {3., 0.01, 300.})
  {
    options.alignment_weight = weight;
    const Eigen::VectorXd z = TVF::smoothest_n_field(*nops, options);
    const double s = weight / area;
    const Eigen::MatrixXd system = S + s * Eigen::MatrixXd(m.asDiagonal());
    const Eigen::VectorXd truth = system.ldlt().solve(Eigen::VectorXd(s * m.cwiseProduct(options.alignment)));
    // The system's condition number (max eigenvalue of S over s, about 1e4 at the light weight)
    // times rounding: 1e-9 leaves room for it, and a several-percent error fails by far.
    EXPECT_LT(relative_difference(z, truth, m), 1e-9) << "weight " << weight;
  }
  // The energy at the truth is lower than at any nearby field (the condition is a minimum).
  options.alignment_weight = 3;
  const Eigen::VectorXd z = TVF::smoothest_n_field(*nops, options);
  const double s = options.alignment_weight / area;
  auto energy = [&](const Eigen::VectorXd& x) {
    const Eigen::VectorXd d = x - options.alignment;
    return nops->dirichlet_energy(x) + s * d.dot(nops->masses().cwiseProduct(d));
  };
  const double e0 = energy(z);
  for(unsigned seed = 1; seed <= 5; ++seed)
  {
    const Eigen::VectorXd delta = 1e-3 * random_field(nf, seed) * std::sqrt(z.squaredNorm() / nf);
    EXPECT_GT(energy(z + delta), e0);
    EXPECT_GT(energy(z - delta), e0);
  }
  options.alignment_weight = 1e9;
  const Eigen::VectorXd heavy = TVF::smoothest_n_field(*nops, options);
  EXPECT_LT((heavy - options.alignment).norm(), 1e-4 * options.alignment.norm());

  options.alignment = Eigen::VectorXd::Zero(3);
  try
  {
    TVF::smoothest_n_field(*nops, options);
    ADD_FAILURE() << "a guide of the wrong size was accepted";
  }
  catch(const TVF::Invalid_input& e)
  {
    EXPECT_NE(std::string(e.what()).find("alignment field has 3 values"), std::string::npos) << e.what();
  }
}

TEST(SmoothestNField, GenericInterfaceOnASurfaceMesh)
{
  Mesh sphere = make_icosphere(3);
  auto field = sphere.add_property_map<Face_index, Vector_3>("f:cross", Vector_3(0, 0, 0)).first;
  const auto singular = TVF::smoothest_n_field(sphere, 4, field);
  EXPECT_EQ(singular.size(), 8u);
  for(Face_index f : sphere.faces())
  {
    const Vector_3 n = CGAL::Polygon_mesh_processing::compute_face_normal(f, sphere);
    EXPECT_NEAR(std::sqrt(field[f].squared_length()), 1., 1e-12);
    EXPECT_NEAR(field[f] * n, 0., 1e-12);
  }
  auto index = sphere.add_property_map<Vertex_index, int>("v:index", 0).first;
  const auto again = TVF::n_field_singularities(sphere, 4, field, index);
  EXPECT_EQ(again, singular);
  int sum = 0;
  for(Vertex_index v : sphere.vertices()) sum += index[v];
  EXPECT_EQ(sum, 8);
}


TEST(NFieldFiles, RawFieldsAndSingularitiesRoundTripAndBadFilesAreRefused)
{
  Mesh torus = make_torus(20, 12);
  for(int n : {2, 4})
  {
    const auto ops = n_field_operators(torus, n);
    const TVF::Intrinsic_mesh& mesh = ops->mesh();
    const Eigen::VectorXd z = ops->from_vectors(random_vectors(mesh.number_of_faces(), 7 + n));
    const TVF::Raw_field raw = TVF::n_field_to_raw_field(*ops, z);
    ASSERT_EQ(raw.degree, n);
    // The n vectors, counter-clockwise about the face normal, at 2 pi / n of each other.
    for(int f = 0; f < mesh.number_of_faces(); f += 37)
      for(int j = 1; j < n; ++j)
      {
        const Eigen::Vector3d a = to_eigen(raw.vectors[f * n + j - 1]), b = to_eigen(raw.vectors[f * n + j]);
        const Eigen::Vector3d normal = to_eigen(mesh.normal(f));
        EXPECT_LT((b - rotate(a, normal, 2 * M_PI / n)).norm(), 1e-12 * a.norm()) << "face " << f;
      }
    // File round trip bit for bit; the n-field read back within rounding.
    std::stringstream text;
    TVF::write_raw_field(text, raw);
    const TVF::Raw_field again = TVF::read_raw_field(text);
    EXPECT_EQ(again.degree, n);
    EXPECT_EQ(again.vectors, raw.vectors);
    EXPECT_LT((TVF::n_field_from_raw_field(*ops, again) - z).cwiseAbs().maxCoeff(), 1e-13);

    const TVF::Singularity_file sing = TVF::n_field_singularity_file(*ops, z);
    int sum = 0;
    for(const auto& s : sing.singularities) sum += s.second;
    EXPECT_EQ(sum, 0); // n chi on the torus
    EXPECT_GT(sing.singularities.size(), 4u);
    std::stringstream sing_text;
    TVF::write_singularity_file(sing_text, sing);
    const TVF::Singularity_file sing_again = TVF::read_singularity_file(sing_text);
    EXPECT_EQ(sing_again.n, n);
    EXPECT_EQ(sing_again.singularities, sing.singularities);

    // The .vtp: n vector arrays, and the index k / n at every vertex.
    const TVF::Vtk_polydata vtp = TVF::n_field_polydata(*ops, z, "cross");
    std::stringstream vtp_text;
    TVF::write_vtk_polydata(vtp_text, vtp);
    const TVF::Vtk_polydata read = TVF::read_vtk_polydata(vtp_text);
    const auto* index = read.find_point_array("cross_index");
    ASSERT_TRUE(index);
    const std::vector<int> k = TVF::n_field_indices(*ops, z);
    for(int v = 0; v < mesh.number_of_vertices(); ++v) EXPECT_EQ(index->values[v], double(k[v]) / n);
    for(int j = 0; j < n; ++j)
    {
      const auto* arm = read.find_cell_array("cross_" + std::to_string(j));
      ASSERT_TRUE(arm);
      for(int f = 0; f < mesh.number_of_faces(); f += 53)
        for(int c = 0; c < 3; ++c) EXPECT_EQ(arm->values[3 * f + c], raw.vectors[f * n + j][c]);
    }
  }

  const auto ops = n_field_operators(torus, 4);
  const int nf = ops->mesh().number_of_faces();
  auto raw_error = [&](const TVF::Raw_field& raw) {
    try
    {
      TVF::n_field_from_raw_field(*ops, raw);
    }
    catch(const TVF::Invalid_input& e)
    {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  TVF::Raw_field lines = TVF::n_field_to_raw_field(*n_field_operators(torus, 2), random_vectors(nf, 3));
  EXPECT_NE(raw_error(lines).find("2 vectors per face where an n-field with n = 4 has 4"), std::string::npos);
  TVF::Raw_field crosses = TVF::n_field_to_raw_field(*ops, ops->from_vectors(random_vectors(nf, 4)));
  std::swap(crosses.vectors[4 * 9 + 1], crosses.vectors[4 * 9 + 3]); // clockwise in face 9
  EXPECT_NE(raw_error(crosses).find("face 9 is not an n-field with n = 4: vector 1 is 180 degrees"), std::string::npos)
      << raw_error(crosses);
  crosses.vectors.pop_back();
  EXPECT_NE(raw_error(crosses).find("faces, the mesh has"), std::string::npos) << raw_error(crosses);

  auto sing_error = [](const std::string& text) {
    std::istringstream in(text);
    try
    {
      TVF::read_singularity_file(in);
    }
    catch(const TVF::Invalid_input& e)
    {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(sing_error("").find("no header"), std::string::npos);
  EXPECT_NE(sing_error("0 1\n3 1\n").find("N must be at least 1"), std::string::npos);
  EXPECT_NE(sing_error("4 2\n3 1\n").find("2 singularities announced, 1 found"), std::string::npos);
  EXPECT_NE(sing_error("4 2\n3 1\n3 -1\n").find("vertex 3 listed twice"), std::string::npos);
  EXPECT_NE(sing_error("4 1\n3 1.5\n").find("'1.5' is not an integer"), std::string::npos);
  EXPECT_NE(sing_error("4 1\n-3 1\n").find("bad vertex -3"), std::string::npos);
  EXPECT_NE(sing_error("4 1\n3 1\n7\n").find("unexpected '7'"), std::string::npos);
}

TEST(NFieldOperators, EnergyDensityIntegratesToTheEnergyAndVanishesForParallelFields)
{
  const Mesh disk = make_disk(8, 0.3);
  for(auto boundary : {TVF::N_field_boundary::free, TVF::N_field_boundary::zero})
  {
    const auto ops = n_field_operators(disk, 3, boundary);
    const Eigen::VectorXd z = ops->from_vectors(random_vectors(ops->mesh().number_of_faces(), 17));
    const Eigen::VectorXd density = ops->energy_density(z);
    EXPECT_NEAR(density.dot(ops->face_areas()), ops->dirichlet_energy(z), 1e-12 * ops->dirichlet_energy(z));
    EXPECT_GE(density.minCoeff(), 0.);
  }
  // A flat annulus has parallel fields: zero density (free boundary).
  const auto ops = n_field_operators(disk, 3);
  ASSERT_EQ(ops->kernel().cols(), 2);
  EXPECT_LT(ops->energy_density(ops->kernel().col(0)).cwiseAbs().maxCoeff(), 1e-20);
}

// Like a .tvfb file (fuzz_tvfb found a corrupt one that loaded): a number of a field changed
// with sizes, mesh identity and end marker intact is refused, with the element named.
TEST(NFieldBasis, LoadRefusesAFieldThatIsNotOfUnitNorm)
{
  const Mesh cube = make_cube(4);
  const auto nops = n_field_operators(cube, 4);
  const TVF::N_field_basis basis(nops, 12);
  const std::string path = scratch_path("corrupt_cube4.tvfn");
  basis.save(path);
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  // A 64-byte header; n, boundary, singularity count (none), kernel dimension; the eigenvalues
  // (16 bytes of sizes, 12 doubles); the fields' sizes, then their first double (element 0).
  const std::size_t first_field = 64 + 16 + 16 + 8 * 12 + 16;
  double x;
  std::memcpy(&x, &bytes[first_field], 8);
  x = 1000 * x + 1;
  std::memcpy(&bytes[first_field], &x, 8);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  try
  {
    TVF::N_field_basis::load(nops, path);
    FAIL() << "loaded";
  }
  catch(const TVF::Invalid_input& e)
  {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("cannot load the n-field basis from '" + path + "': element 0 has norm ", 0), 0u) << message;
    EXPECT_NE(message.find(" instead of 1 (the file is corrupt)"), std::string::npos) << message;
  }
  std::remove(path.c_str());
}
