// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The spectral basis (SPEC 5 and 6): the sphere's vector spectrum, agreement with a dense
// solve of the Hodge-Laplacian, requests, filters, compression, storage, scale invariance.
// The eigensolver behind it is tested in test_eigensolver.cpp.

#include "expect_reason.h"
#include "test_meshes.h"
#include "scratch_path.h"

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>
#include <CGAL/Model_reduction/Generalized_eigensolver.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace TVF = CGAL::Tangent_vector_fields;
namespace MR = CGAL::Model_reduction;
using namespace tvf_test;

#include <CGAL/Tangent_vector_fields/Spectral_basis.h>
#include <CGAL/Tangent_vector_fields/face_field_io.h>
#include <CGAL/Tangent_vector_fields/internal/basis_file.h>
#include <CGAL/Tangent_vector_fields/internal/scalar_eigenproblem.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>

namespace {

typedef TVF::Spectral_basis<Mesh> Basis;

// All basis elements as fields (2nf x size).
Eigen::MatrixXd basis_fields(const TVF::Eigenfield_basis& basis)
{
  Eigen::MatrixXd U(2 * basis.operators().mesh().number_of_faces(), basis.size());
  for(int k = 0; k < basis.size(); ++k) U.col(k) = basis.eigenfield(k);
  return U;
}

double mx_norm(const TVF::Eigenfield_basis& basis, const Eigen::VectorXd& v)
{
  return std::sqrt(v.cwiseAbs2().dot(basis.operators().field_masses()));
}

// Eigenvalues of L = MX^-1 S, densely (symmetric form MX^-1/2 S MX^-1/2).
Eigen::VectorXd dense_hodge_laplace_spectrum(const Mesh& mesh)
{
  TVF::Discrete_operators<Mesh> ops(mesh);
  const Eigen::VectorXd s = ops.matrices().field_masses().cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd B = s.asDiagonal() * Eigen::MatrixXd(ops.matrices().S()) * s.asDiagonal();
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(B, Eigen::EigenvaluesOnly).eigenvalues();
}

} // namespace

TEST(SpectralBasis, SphereVectorSpectrumHasMultiplicityTwiceTwoLPlusOneSplitEvenly)
{
  // Vector eigenvalues of the unit sphere are l(l+1), each 2(2l+1) times: 2l+1
  // gradients of spherical harmonics (exact) and 2l+1 rotated ones (coexact).  The
  // coexact problem (1920 interior edges) takes the iterative path, the exact one
  // (642 vertices) the dense one.  Crouzeix-Raviart errors are about twice the cotan
  // ones: below 10% up to l = 5 on this mesh (measured 5.0% at l = 5).
  Mesh sphere = make_icosphere(3);
  const int d = 2 * (3 + 5 + 7 + 9 + 11); // l = 1 .. 5
  Basis basis(sphere, TVF::parameters::number_of_eigenfields(d));
  ASSERT_EQ(basis.size(), d);
  EXPECT_EQ(basis.basis().number_of_harmonic(), 0); // genus 0: none
  int k = 0;
  for(int l = 1; l <= 5; ++l)
  {
    int exact = 0, coexact = 0;
    for(int i = 0; i < 2 * (2 * l + 1); ++i, ++k)
    {
      EXPECT_NEAR(basis.eigenvalue(k), l * (l + 1), 0.1 * l * (l + 1)) << "l = " << l;
      (basis.type(k) == TVF::Eigenfield_type::exact ? exact : coexact)++;
    }
    EXPECT_EQ(exact, 2 * l + 1) << "l = " << l;
    EXPECT_EQ(coexact, 2 * l + 1) << "l = " << l;
    if(k < d) EXPECT_GT(basis.eigenvalue(k), 1.1 * l * (l + 1)); // a clear gap before the next l
  }
  const Eigen::MatrixXd U = basis_fields(basis.basis());
  const Eigen::MatrixXd K = U.transpose() * basis.basis().operators().field_masses().asDiagonal() * U;
  EXPECT_LT((K - Eigen::MatrixXd::Identity(d, d)).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_LE(basis.basis().report().max_residual, 1e-10);
  // Eigenfields of L: L Phi = lambda Phi.
  const Eigen::SparseMatrix<double>& L = basis.basis().operators().L();
  for(int j : {0, 7, 40, d - 1})
  {
    const Eigen::VectorXd phi = U.col(j);
    EXPECT_LT(mx_norm(basis.basis(), L * phi - basis.eigenvalue(j) * phi), 1e-8 * basis.eigenvalue(j)) << j;
  }
}

TEST(SpectralBasis, FullBasisMatchesDenseSolveAndHasTwoElementsPerFace)
{
  struct Case
  {
    const char* name;
    Mesh mesh;
    int harmonic;
  };
  std::vector<Case> cases;
  cases.push_back({"torus", make_torus(16, 9), 2});    // closed, genus 1, 288 faces
  cases.push_back({"disk", make_curved_disk(7), 0});   // one boundary loop
  cases.push_back({"annulus", make_curved_disk(7, 0.35), 1});
  {
    Mesh two = make_torus(10, 6);
    Mesh annulus = make_curved_disk(4, 0.4);
    two.join(annulus);
    two.add_vertex(Point_3(5, 5, 5)); // in no face: ignored
    cases.push_back({"torus + annulus + isolated vertex", std::move(two), 3});
  }
  for(const Case& c : cases)
  {
    SCOPED_TRACE(c.name);
    const int nf = static_cast<int>(c.mesh.number_of_faces());
    const Eigen::VectorXd dense = dense_hodge_laplace_spectrum(c.mesh);
    ASSERT_EQ(dense.size(), 2 * nf);
    Basis full(c.mesh, TVF::parameters::number_of_eigenfields(2 * nf));
    ASSERT_EQ(full.size(), 2 * nf);
    EXPECT_EQ(full.basis().number_of_harmonic(), c.harmonic);
    const double scale = dense[dense.size() - 1];
    for(int k = 0; k < 2 * nf; ++k)
    {
      const double tolerance = 1e-8 * std::max(dense[k], dense[c.harmonic]);
      ASSERT_NEAR(full.eigenvalue(k), dense[k], tolerance) << "k = " << k << " of " << 2 * nf << ", largest " << scale;
    }
    // Round trip through the full basis, and Parseval.
    const Eigen::VectorXd v = random_field(nf, 7);
    const Eigen::VectorXd a = full.basis().coefficients(v);
    EXPECT_LT(mx_norm(full.basis(), full.basis().field(a) - v), 1e-10 * mx_norm(full.basis(), v));
    EXPECT_NEAR(a.norm(), mx_norm(full.basis(), v), 1e-10 * a.norm());
    EXPECT_LT(mx_norm(full.basis(), full.basis().rest(v)), 1e-10 * mx_norm(full.basis(), v));
    // A partial basis is the beginning of the full one.
    Basis part(c.mesh, TVF::parameters::number_of_eigenfields(60));
    ASSERT_EQ(part.size(), 60);
    for(int k = 0; k < 60; ++k)
      EXPECT_NEAR(part.eigenvalue(k), dense[k], 1e-8 * std::max(dense[k], dense[c.harmonic])) << "k = " << k;
  }
}

TEST(SpectralBasis, PerTypeAndBelowEigenvalueRequests)
{
  Mesh torus = make_torus(16, 9);
  const Eigen::VectorXd dense = dense_hodge_laplace_spectrum(torus);
  Basis split(torus, TVF::parameters::number_of_exact_eigenfields(30).number_of_coexact_eigenfields(20));
  EXPECT_EQ(split.basis().number_of_exact(), 30);
  EXPECT_EQ(split.basis().number_of_coexact(), 20);
  EXPECT_EQ(split.size(), 2 + 50);
  // Everything up to a frequency: exactly the dense eigenvalues below it.
  const double bound = 0.5 * (dense[80] + dense[81]);
  Basis below(torus, TVF::parameters::maximum_eigenvalue(bound));
  EXPECT_EQ(below.size(), 81);
  EXPECT_LE(below.eigenvalue(below.size() - 1), bound);
  EXPECT_THROW_REASON(Basis(torus, TVF::parameters::number_of_eigenfields(2 * 288 + 1)),
                      TVF::Invalid_input, "eigenfields but the space of fields has dimension 576");
  EXPECT_THROW_REASON(Basis(torus, TVF::parameters::number_of_exact_eigenfields(144)),
                      TVF::Invalid_input, "asked for 144 exact and 0 coexact eigenfields; the mesh has 143");
  EXPECT_THROW_REASON(Basis(torus, TVF::parameters::maximum_eigenvalue(std::nan(""))),
                      TVF::Invalid_input, "the largest eigenvalue of the basis must be finite and non-negative");
}

TEST(SpectralBasis, FiltersActPerType)
{
  Mesh torus = make_torus(30, 14);
  Basis basis(torus, TVF::parameters::number_of_eigenfields(120));
  const TVF::Eigenfield_basis& b = basis.basis();
  const TVF::Operator_matrices& ops = b.operators();
  // A gradient and a co-gradient of smooth functions, and a mix with a harmonic field.
  Eigen::VectorXd f(ops.mesh().number_of_vertices());
  for(int v = 0; v < f.size(); ++v)
  {
    const auto& p = ops.mesh().position(v);
    f[v] = std::sin(3 * p[0]) + p[1] * p[2];
  }
  Eigen::VectorXd g(ops.mesh().number_of_interior_edges());
  for(int i = 0; i < g.size(); ++i)
  {
    const auto& ends = ops.mesh().edge_vertices(ops.mesh().interior_edges()[i]);
    const auto& p = ops.mesh().position(ends[0]);
    const auto& q = ops.mesh().position(ends[1]);
    g[i] = std::cos(p[0] + q[0]) * (p[2] + q[2]);
  }
  const Eigen::VectorXd gradient = ops.G() * f;
  const Eigen::VectorXd cogradient = ops.rotate(ops.G_star_interior() * g);
  TVF::Spectral_filter no_coexact;
  no_coexact.coexact = [](double) { return 0.; };
  EXPECT_LT(mx_norm(b, b.filter(gradient, no_coexact) - gradient), 1e-10 * mx_norm(b, gradient));
  TVF::Spectral_filter no_exact;
  no_exact.exact = [](double) { return 0.; };
  no_exact.harmonic_factor = 0;
  EXPECT_LT(mx_norm(b, b.filter(cogradient, no_exact) - cogradient), 1e-10 * mx_norm(b, cogradient));
  // The exact-part filter of gradient + cogradient + harmonic keeps the low gradient part only.
  const Eigen::VectorXd h = b.harmonic_fields().col(0);
  const Eigen::VectorXd mix = gradient + cogradient + h;
  const Eigen::VectorXd exact_only = b.filter(mix, TVF::Spectral_filter::exact_part());
  const Eigen::VectorXd low_gradient = b.filter(gradient, TVF::Spectral_filter::exact_part());
  EXPECT_LT(mx_norm(b, exact_only - low_gradient), 1e-10 * mx_norm(b, mix));
  // Identity filter reproduces the field (basis part + rest).
  EXPECT_LT(mx_norm(b, b.filter(mix, TVF::Spectral_filter()) - mix), 1e-12 * mx_norm(b, mix));
  // Low-pass lowers the Dirichlet energy of the basis part, high-pass raises it.
  const Eigen::VectorXd a = b.coefficients(mix);
  const double t = 1.0 / b.eigenvalue(b.size() - 1);
  const Eigen::VectorXd low = b.coefficients(b.filter(mix, TVF::Spectral_filter::low_pass(t)));
  const Eigen::VectorXd high = b.coefficients(b.filter(mix, TVF::Spectral_filter::high_pass(t)));
  EXPECT_LT(b.dirichlet_energy(low), 0.9 * b.dirichlet_energy(a));
  EXPECT_GT(b.dirichlet_energy(high), 1.1 * b.dirichlet_energy(a));
  for(int k = 0; k < b.size(); ++k)
    EXPECT_NEAR(low[k], a[k] * std::exp(-t * b.eigenvalue(k)), 1e-9 * a.norm()) << k;
  // Band energies add up to the energy of the coefficients, harmonic in column 0.
  const Eigen::MatrixXd bands = b.band_energies(a, {0, 1e-300, 10, 1e300});
  EXPECT_NEAR(bands.sum(), a.squaredNorm(), 1e-12 * a.squaredNorm());
  EXPECT_NEAR(bands(0, 0), a.head(2).squaredNorm(), 1e-12 * a.squaredNorm());
  // Energies in the basis: E_D = v^T S v for a field in the span.
  const Eigen::VectorXd in_span = b.field(a);
  EXPECT_NEAR(b.dirichlet_energy(a), in_span.dot(ops.S() * in_span), 1e-8 * b.dirichlet_energy(a));
  EXPECT_NEAR(b.biharmonic_energy(a), in_span.dot(ops.B() * in_span), 1e-8 * b.biharmonic_energy(a));
}

TEST(SpectralBasis, CompressionErrorFallsWithTheNumberOfCoefficients)
{
  Mesh torus = make_torus(24, 12);
  Basis basis(torus, TVF::parameters::number_of_eigenfields(2 * 576));
  const TVF::Eigenfield_basis& b = basis.basis();
  Eigen::MatrixXd fields(2 * 576, 2);
  fields.col(0) = basis.operators().to_frame_coordinates(ambient_field_map(torus, "smooth", 3));
  fields.col(1) = random_field(576, 5);
  double previous_smooth = 2;
  for(int k : {10, 50, 200, 600, 1152})
  {
    const TVF::Compressed_fields c = b.compress(fields, k);
    EXPECT_NEAR(c.ratio, 1152.0 / k, 1e-12);
    EXPECT_LE(c.relative_errors[0], previous_smooth);
    previous_smooth = c.relative_errors[0];
    const Eigen::MatrixXd back = b.decompress(c);
    for(int j = 0; j < 2; ++j)
      EXPECT_NEAR(mx_norm(b, back.col(j) - fields.col(j)) / mx_norm(b, fields.col(j)), c.relative_errors[j], 1e-12);
  }
  EXPECT_LT(b.compress(fields, 1152).relative_errors.maxCoeff(), 1e-10);
  // A smooth field compresses far better than noise (measured 0.096 against 0.95:
  // the piecewise-constant field itself has jumps at every edge).
  const TVF::Compressed_fields c = b.compress(fields, 100);
  EXPECT_LT(c.relative_errors[0], 0.2 * c.relative_errors[1]);
}

TEST(SpectralBasis, SaveAndLoadRoundTripAndRefuseOtherMeshes)
{
  Mesh torus = make_torus(16, 9);
  Basis basis(torus, TVF::parameters::number_of_eigenfields(50));
  const std::string path = scratch_path("basis_test.bin");
  basis.save(path);
  const Basis loaded = Basis::load(torus, path);
  ASSERT_EQ(loaded.size(), basis.size());
  EXPECT_EQ(loaded.basis().eigenvalues(), basis.basis().eigenvalues());
  EXPECT_EQ(loaded.basis().exact_eigenfunctions().to_double(), basis.basis().exact_eigenfunctions().to_double());
  EXPECT_EQ(loaded.basis().coexact_eigenfunctions().to_double(), basis.basis().coexact_eigenfunctions().to_double());
  EXPECT_EQ(loaded.basis().harmonic_fields(), basis.basis().harmonic_fields());
  for(int k = 0; k < basis.size(); ++k) EXPECT_EQ(loaded.type(k), basis.type(k));
  const Eigen::VectorXd v = random_field(288, 2);
  EXPECT_EQ(loaded.basis().coefficients(v), basis.basis().coefficients(v));

  // Other connectivity, other geometry, a scaled copy: refused.
  Mesh other = make_torus(16, 10);
  EXPECT_THROW_REASON(Basis::load(other, path), TVF::Invalid_input, "it belongs to a mesh with other connectivity");
  Mesh moved = torus;
  jitter_vertices(moved, 1e-6, 9);
  EXPECT_THROW_REASON(Basis::load(moved, path), TVF::Invalid_input, "it belongs to a mesh with other edge lengths");
  // Moved further, faces' longest edges change, and with them the corner Intrinsic_mesh starts
  // each face at: still the same connectivity.  (Made to fail: with the version-2 identity,
  // which hashed the corners in that order, this said "other connectivity".)
  jitter_vertices(moved, 0.05, 9);
  EXPECT_THROW_REASON(Basis::load(moved, path), TVF::Invalid_input, "it belongs to a mesh with other edge lengths");
  Mesh scaled = torus;
  transform(scaled, 2.0);
  EXPECT_THROW_REASON(Basis::load(scaled, path), TVF::Invalid_input, "it belongs to a mesh with other edge lengths");
  // Corrupt and truncated files, and a missing file.
  {
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(path + ".short", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    std::string wrong_version = bytes;
    wrong_version[8] = 9;
    std::ofstream(path + ".version", std::ios::binary) << wrong_version;
  }
  // A file of format version 2, which holds the older identity (legacy_mesh_identity), still
  // loads.  (Made to fail: reading every version with the new identity refuses it as "other
  // connectivity".)
  {
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const TVF::Intrinsic_mesh& intrinsic = basis.basis().operators().mesh();
    const std::uint32_t version = 2;
    const std::uint64_t legacy = TVF::internal::legacy_mesh_identity(intrinsic).connectivity;
    ASSERT_NE(legacy, TVF::internal::mesh_identity(intrinsic).connectivity);
    std::memcpy(&bytes[8], &version, sizeof version); // after the magic; then byte order, identity
    std::memcpy(&bytes[16], &legacy, sizeof legacy);
    std::ofstream(path + ".v2", std::ios::binary) << bytes;
  }
  EXPECT_EQ(Basis::load(torus, path + ".v2").basis().eigenvalues(), basis.basis().eigenvalues());
  EXPECT_THROW_REASON(Basis::load(make_torus(16, 10), path + ".v2"), TVF::Invalid_input,
                      "it belongs to a mesh with other connectivity");
  std::remove((path + ".v2").c_str());
  EXPECT_THROW_REASON(Basis::load(torus, path + ".short"), TVF::Invalid_input, "the file is truncated");
  EXPECT_THROW_REASON(Basis::load(torus, path + ".version"), TVF::Invalid_input, "file format version 9");
  EXPECT_THROW_REASON(Basis::load(torus, path + ".missing"), TVF::Invalid_input, "cannot open the spectral basis file");
  std::remove(path.c_str());
  std::remove((path + ".short").c_str());
  std::remove((path + ".version").c_str());
}

TEST(SpectralBasis, SameSpectrumAfterScalingByExtremeFactors)
{
  Mesh reference = make_icosphere(3);
  jitter_vertices(reference, 0.1, 4);
  const Basis base(reference, TVF::parameters::number_of_eigenfields(40));
  for(double s : {1e-8, 1e8})
  {
    SCOPED_TRACE(s);
    Mesh scaled = reference;
    transform(scaled, s, rotation_matrix(Vector_3(1, 2, 3), 0.7));
    const Basis basis(scaled, TVF::parameters::number_of_eigenfields(40));
    ASSERT_EQ(basis.size(), 40);
    for(int k = 0; k < 40; ++k)
    {
      EXPECT_NEAR(basis.eigenvalue(k) * s * s, base.eigenvalue(k), 1e-8 * base.eigenvalue(k)) << k;
      EXPECT_EQ(basis.type(k), base.type(k)) << k;
    }
    EXPECT_LE(basis.basis().report().max_residual, 1e-10);
  }
}

TEST(SpectralBasis, ProgressIsReportedAndPropertyMapsWork)
{
  Mesh torus = make_torus(30, 14);
  std::vector<double> fractions;
  std::function<void(const TVF::Spectral_progress&)> callback = [&](const TVF::Spectral_progress& p) {
    fractions.push_back(p.fraction);
  };
  Basis basis(torus, TVF::parameters::number_of_eigenfields(100).progress_callback(callback));
  ASSERT_GE(fractions.size(), 2u);
  EXPECT_EQ(fractions.back(), 1.0);
  for(std::size_t i = 1; i < fractions.size(); ++i) EXPECT_GE(fractions[i], fractions[i - 1] - 1e-12);
  // Property-map round trip: an eigenfield written to a map has coefficient e_k.
  auto field = torus.add_property_map<Face_index, Vector_3>("f:eigenfield", Vector_3(0, 0, 0)).first;
  basis.eigenfield(17, field);
  const Eigen::VectorXd a = basis.coefficients(field);
  EXPECT_NEAR(a[17], 1, 1e-10);
  EXPECT_NEAR(a.norm(), 1, 1e-10);
  auto filtered = torus.add_property_map<Face_index, Vector_3>("f:filtered", Vector_3(0, 0, 0)).first;
  TVF::filter_tangent_field(torus, field, TVF::Spectral_filter::low_pass(0.0), filtered,
                            TVF::parameters::number_of_eigenfields(30));
  for(Face_index f : torus.faces()) EXPECT_LT(std::sqrt((filtered[f] - field[f]).squared_length()), 1e-9);
}

TEST(SpectralBasis, EveryEigensolverSettingOfTheBasisOptionsReachesTheEigensolver)
{
  // Basis_options::threads once went nowhere: the basis always ran on every core.
  TVF::Basis_options options;
  options.tolerance = 3e-9;
  options.block_size = 7;
  options.restart_per_pair = 2.5;
  options.seed = 99;
  options.threads = 3;
  const MR::Eigensolver_options e = TVF::internal::eigensolver_options(options);
  EXPECT_EQ(e.tolerance, 3e-9);
  EXPECT_EQ(e.block_size, 7);
  EXPECT_EQ(e.restart_per_pair, 2.5);
  EXPECT_EQ(e.seed, 99u);
  EXPECT_EQ(e.threads, 3);
}
