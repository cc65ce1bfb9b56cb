// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The generalized eigensolver behind the spectral basis (SPEC 5): analytic spectra,
// agreement with dense solves, residuals, orthonormality, and the inertia count
// that proves no eigenvalue was skipped.

#include "test_meshes.h"

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>
#include <CGAL/Tangent_vector_fields/Generalized_eigensolver.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;

namespace {

struct Vertex_problem
{
  Eigen::SparseMatrix<double> A;
  Eigen::VectorXd d;
  Eigen::MatrixXd kernel;
};

Vertex_problem vertex_problem(const Mesh& mesh)
{
  TVF::Discrete_operators<Mesh> ops(mesh);
  return {ops.matrices().W(), ops.matrices().vertex_masses(), Eigen::MatrixXd::Ones(mesh.number_of_vertices(), 1)};
}

Vertex_problem edge_problem(const Mesh& mesh)
{
  TVF::Discrete_operators<Mesh> ops(mesh);
  const auto& A = ops.matrices();
  Eigen::MatrixXd kernel(A.mesh().number_of_interior_edges(), 0);
  if(ops.topology().number_of_boundary_loops() == 0) kernel = Eigen::MatrixXd::Ones(kernel.rows(), 1);
  return {A.W_star(), A.all_to_interior_edges(A.edge_masses()), kernel};
}

void expect_orthonormal(const Eigen::MatrixXd& X, const Eigen::VectorXd& d)
{
  const Eigen::MatrixXd K = X.transpose() * d.asDiagonal() * X;
  EXPECT_LT((K - Eigen::MatrixXd::Identity(X.cols(), X.cols())).cwiseAbs().maxCoeff(), 1e-10);
}

} // namespace

TEST(Eigensolver, SphereSpectrumIsLTimesLPlusOneWithMultiplicity)
{
  // Scalar eigenvalues of the unit sphere are l(l+1) with multiplicity 2l+1.  On
  // icospheres with 642 and 2562 vertices (iterative path) the cotan discretisation
  // error for l <= 6 is below 6% and 1.5% (measured 4.9% and 1.2% at l = 6) and
  // shrinks about 4x per refinement (O(h^2)).
  const int count = 48; // l = 1 .. 6
  std::vector<Eigen::VectorXd> errors;
  for(int level : {3, 4})
  {
    SCOPED_TRACE(level);
    Mesh sphere = make_icosphere(level);
    const Vertex_problem p = vertex_problem(sphere);
    TVF::Eigensolver_options options;
    options.allow_dense = false;
    const TVF::Eigenpairs e = TVF::lowest_eigenpairs(p.A, p.d, count, p.kernel, options);
    ASSERT_EQ(e.values.size(), count);
    Eigen::VectorXd error(6);
    int i = 0;
    for(int l = 1; l <= 6; ++l)
    {
      const double exact = l * (l + 1);
      // The 2l+1 copies agree much better than the discretisation error (symmetry).
      const double lo = e.values[i], hi = e.values[i + 2 * l];
      error[l - 1] = std::abs(0.5 * (lo + hi) - exact) / exact;
      EXPECT_LT(error[l - 1], level == 3 ? 6e-2 : 1.5e-2) << "l = " << l;
      if(i + 2 * l + 1 < count) EXPECT_GT(e.values[i + 2 * l + 1] - hi, 10 * (hi - lo)) << "l = " << l;
      i += 2 * l + 1;
    }
    EXPECT_LE(e.residuals.maxCoeff(), 1e-10);
    expect_orthonormal(e.vectors, p.d);
    // Sylvester: count + 1 (with the constant) eigenvalues below the gap before l = 7.
    EXPECT_EQ(TVF::count_eigenvalues_below(p.A, p.d, 0.5 * (42 + 56)), count + 1);
    errors.push_back(error);
  }
  for(int l = 1; l <= 6; ++l) EXPECT_LT(errors[1][l - 1], 0.35 * errors[0][l - 1]) << "l = " << l;
}

TEST(Eigensolver, IterativeAgreesWithDenseOnVertexAndEdgeProblems)
{
  Mesh torus = make_torus(30, 14); // 420 vertices, 1260 edges; genus 1
  Mesh disk = make_curved_disk(12); // with boundary: no kernel for the edge problem
  for(const Mesh* mesh : {&torus, &disk})
    for(int kind = 0; kind < 2; ++kind)
    {
      SCOPED_TRACE(kind == 0 ? "vertex" : "edge");
      const Vertex_problem p = kind == 0 ? vertex_problem(*mesh) : edge_problem(*mesh);
      const int count = 60;
      TVF::Eigensolver_options iterative;
      iterative.allow_dense = false;
      iterative.block_size = 8;
      const TVF::Eigenpairs a = TVF::lowest_eigenpairs(p.A, p.d, count, p.kernel, iterative);
      const TVF::Eigenpairs b = TVF::lowest_eigenpairs(p.A, p.d, count, p.kernel);
      EXPECT_LT(((a.values - b.values).array() / b.values.array()).abs().maxCoeff(), 1e-9);
      EXPECT_LE(a.residuals.maxCoeff(), 1e-10);
      EXPECT_LE(b.residuals.maxCoeff(), 1e-10);
      expect_orthonormal(a.vectors, p.d);
      expect_orthonormal(b.vectors, p.d);
      // Orthogonal to the kernel.
      if(p.kernel.cols() > 0) EXPECT_LT((p.kernel.transpose() * p.d.asDiagonal() * a.vectors).norm(), 1e-9);
    }
}

TEST(Eigensolver, InertiaCountMatchesTheComputedSpectrum)
{
  // Jittered sphere: no exact multiplicities, so every consecutive pair has a gap.
  Mesh sphere = make_icosphere(3);
  jitter_vertices(sphere, 0.1, 3);
  const Vertex_problem p = vertex_problem(sphere);
  const TVF::Eigenpairs e = TVF::lowest_eigenpairs(p.A, p.d, 40, p.kernel);
  for(int k : {1, 10, 25, 39})
  {
    const double tau = 0.5 * (e.values[k - 1] + e.values[k]);
    // k computed eigenvalues below tau, plus the constant.
    EXPECT_EQ(TVF::count_eigenvalues_below(p.A, p.d, tau), k + 1) << "k = " << k;
  }
}

TEST(Eigensolver, SpectrumSlicingAgreesWithDenseAcrossManyWindows)
{
  // Windows of ~30 eigenvalues, blocks of 4: the perfect icosphere has exact
  // multiplicities up to 5 (icosahedral symmetry), more than a block finds at once,
  // so the retry with wider blocks is exercised; the jittered one has none.
  Mesh sphere = make_icosphere(3);
  Mesh jittered = make_icosphere(3);
  jitter_vertices(jittered, 0.1, 5);
  // One chain of windows, and the spectrum cut into 2 and 3 chains solved at once (the
  // pairs on both sides of a cut come from different runs: orthonormality is checked).
  for(const Mesh* mesh : {&sphere, &jittered})
    for(int kind = 0; kind < 2; ++kind)
    {
      const Vertex_problem p = kind == 0 ? vertex_problem(*mesh) : edge_problem(*mesh);
      const int count = 150;
      TVF::Eigensolver_options dense;
      dense.dense_size = 4000; // an exact reference
      const TVF::Eigenpairs b = TVF::lowest_eigenpairs(p.A, p.d, count, p.kernel, dense);
      for(int threads : {1, 2, 3})
      {
        SCOPED_TRACE(std::string(mesh == &sphere ? "sphere " : "jittered ") + (kind == 0 ? "vertex" : "edge") +
                     ", threads " + std::to_string(threads));
        TVF::Eigensolver_options sliced;
        sliced.allow_dense = false;
        sliced.slice_size = 30;
        sliced.threads = threads;
        const TVF::Eigenpairs a = TVF::lowest_eigenpairs(p.A, p.d, count, p.kernel, sliced);
        ASSERT_EQ(a.values.size(), count);
        EXPECT_LT(((a.values - b.values).array() / b.values.array()).abs().maxCoeff(), 1e-9);
        EXPECT_LE(a.residuals.maxCoeff(), 1e-10);
        expect_orthonormal(a.vectors, p.d);
        EXPECT_TRUE(a.completeness.passed());
        EXPECT_GE(a.completeness.expected - static_cast<int>(p.kernel.cols()), count);
        EXPECT_GT(a.complete_below, a.values[count - 1] * (1 - 1e-12));
      }
    }
}

TEST(Eigensolver, SlicingReachesTheToleranceWhereSomeMassesAreTiny)
{
  // A sphere and a second one 1e-3 as large: masses 1e6 below the others, so the standard
  // form's rows there are 1e6 larger.  Roundoff of the size a random start block leaves on
  // every entry kept the true residuals of the Lanczos pairs above 1e-10 however long the
  // basis grew (the same happened on needle triangles: CGAL's camel.off).  Checked against
  // dense LAPACK, with each pair's residual computed here.
  Mesh mesh = make_icosphere(3);
  Mesh small = make_icosphere(2);
  transform(small, 1e-3, {1, 0, 0, 0, 1, 0, 0, 0, 1}, Vector_3(3, 0, 0));
  mesh.join(small);
  Vertex_problem p = vertex_problem(mesh);
  p.kernel.setZero(p.A.rows(), 2); // the constants of each component
  for(Eigen::Index i = 0; i < p.A.rows(); ++i) p.kernel(i, i < 642 ? 0 : 1) = 1;
  const int count = 40;
  TVF::Eigensolver_options dense;
  dense.dense_size = 4000;
  const TVF::Eigenpairs b = TVF::lowest_eigenpairs(p.A, p.d, count, p.kernel, dense);
  TVF::Eigensolver_options sliced;
  sliced.allow_dense = false;
  sliced.slice_size = 20;
  const TVF::Eigenpairs a = TVF::lowest_eigenpairs(p.A, p.d, count, p.kernel, sliced);
  ASSERT_EQ(a.values.size(), count);
  EXPECT_LT(((a.values - b.values).array() / b.values.array()).abs().maxCoeff(), 1e-9);
  for(int i = 0; i < count; ++i)
  {
    const Eigen::VectorXd x = a.vectors.col(i);
    const Eigen::VectorXd r = (p.A * x - a.values[i] * p.d.cwiseProduct(x)).cwiseQuotient(p.d.cwiseSqrt());
    EXPECT_LE(r.norm() / (a.values[i] * p.d.cwiseSqrt().cwiseProduct(x).norm()), 1e-10) << "pair " << i;
  }
  expect_orthonormal(a.vectors, p.d);
}

TEST(Eigensolver, ChainsReportProgressOnTheCallersThreadAndStopOnACancel)
{
  Mesh sphere = make_icosphere(3);
  jitter_vertices(sphere, 0.1, 7);
  const Vertex_problem p = vertex_problem(sphere);
  TVF::Eigensolver_options options;
  options.allow_dense = false;
  options.slice_size = 30;
  options.threads = 2;
  const std::thread::id caller = std::this_thread::get_id();
  int calls = 0, last = 0;
  bool other_thread = false;
  options.progress = [&](const TVF::Eigensolver_progress& e) {
    ++calls;
    other_thread = other_thread || std::this_thread::get_id() != caller;
    last = e.converged;
    EXPECT_LE(e.converged, e.wanted);
  };
  const TVF::Eigenpairs e = TVF::lowest_eigenpairs(p.A, p.d, 150, p.kernel, options);
  EXPECT_GT(calls, 0);
  EXPECT_EQ(last, 150); // the last report says every pair was found
  EXPECT_FALSE(other_thread);
  EXPECT_EQ(e.values.size(), 150);
  // A callback that throws cancels both chains; its exception reaches the caller.
  struct Cancelled
  {
  };
  options.progress = [&](const TVF::Eigensolver_progress&) { throw Cancelled(); };
  EXPECT_THROW(TVF::lowest_eigenpairs(p.A, p.d, 150, p.kernel, options), Cancelled);
}

TEST(Eigensolver, ProblemsSolvedTogetherEachMeetTheirSpectrum)
{
  // One call, one pool of threads: a sphere's vertex problem (analytic spectrum, exact
  // multiplicities), a jittered sphere's edge problem (sliced), a small torus (the dense
  // path) and an empty request.  Each against its own truth: l(l+1) with multiplicity
  // 2l+1 on the sphere, a dense solve of the same matrices for the others.
  Mesh sphere = make_icosphere(4); // 2562 vertices
  Mesh jittered = make_icosphere(3);
  jitter_vertices(jittered, 0.1, 11);
  Mesh torus = make_torus(8, 5);
  const Vertex_problem a = vertex_problem(sphere), b = edge_problem(jittered), c = vertex_problem(torus);
  const int count_a = 48, count_b = 150, count_c = 12; // l = 1 .. 6 on the sphere
  TVF::Eigensolver_options options;
  options.slice_size = 30;
  options.threads = 2;
  int calls = 0, last = 0, wanted = 0;
  options.progress = [&](const TVF::Eigensolver_progress& e) {
    ++calls;
    last = e.converged;
    wanted = e.wanted;
  };
  const std::vector<TVF::Eigenpairs> result = TVF::lowest_eigenpairs_of_each(
      {{a.A, a.d, count_a, a.kernel}, {b.A, b.d, count_b, b.kernel}, {c.A, c.d, count_c, c.kernel}, {c.A, c.d, 0, c.kernel}},
      options);
  ASSERT_EQ(result.size(), 4u);
  EXPECT_GT(calls, 0);
  EXPECT_EQ(wanted, count_a + count_b); // the sliced ones
  EXPECT_EQ(last, wanted);

  const TVF::Eigenpairs& s = result[0];
  ASSERT_EQ(s.values.size(), count_a);
  for(int l = 1, i = 0; l <= 6; i += 2 * l + 1, ++l)
  {
    // Discretisation error below 1.5% at this level (see the test above); the 2l+1 copies
    // far closer to each other than to the next eigenvalue.
    const double exact = l * (l + 1), lo = s.values[i], hi = s.values[i + 2 * l];
    EXPECT_LT(std::abs(0.5 * (lo + hi) - exact) / exact, 1.5e-2) << "l = " << l;
    if(i + 2 * l + 1 < count_a) EXPECT_GT(s.values[i + 2 * l + 1] - hi, 10 * (hi - lo)) << "l = " << l;
  }
  const Vertex_problem* problem[] = {&a, &b, &c};
  const int count[] = {count_a, count_b, count_c};
  for(int k = 0; k < 3; ++k)
  {
    SCOPED_TRACE("problem " + std::to_string(k));
    const Vertex_problem& p = *problem[k];
    const TVF::Eigenpairs& e = result[static_cast<std::size_t>(k)];
    TVF::Eigensolver_options dense;
    dense.dense_size = 4000;
    const TVF::Eigenpairs reference = TVF::lowest_eigenpairs(p.A, p.d, count[k], p.kernel, dense);
    ASSERT_EQ(e.values.size(), count[k]);
    EXPECT_LT(((e.values - reference.values).array() / reference.values.array()).abs().maxCoeff(), 1e-9);
    EXPECT_LE(e.residuals.maxCoeff(), 1e-10);
    expect_orthonormal(e.vectors, p.d);
    EXPECT_TRUE(e.completeness.passed());
    if(k < 2) EXPECT_GT(e.thread_seconds, 0.); // sliced on the pool
  }
  EXPECT_EQ(result[3].values.size(), 0);
  EXPECT_EQ(result[3].vectors.rows(), c.A.rows());

  // A bad request anywhere is refused, with its reason, before any work is done.
  calls = 0;
  try
  {
    TVF::lowest_eigenpairs_of_each({{a.A, a.d, count_a, a.kernel}, {c.A, c.d, 40, c.kernel}}, options);
    ADD_FAILURE() << "a request beyond the space's dimension was accepted";
  }
  catch(const TVF::Invalid_input& e)
  {
    EXPECT_NE(std::string(e.what()).find("asked for 40 eigenpairs but the space has dimension 39"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(calls, 0);
}

TEST(Eigensolver, RefusesImpossibleRequests)
{
  Mesh torus = make_torus(8, 5);
  const Vertex_problem p = vertex_problem(torus);
  EXPECT_THROW(TVF::lowest_eigenpairs(p.A, p.d, 40, p.kernel), TVF::Invalid_input); // space has dimension 39
  EXPECT_NO_THROW(TVF::lowest_eigenpairs(p.A, p.d, 39, p.kernel));
  EXPECT_THROW(TVF::lowest_eigenpairs(p.A, p.d, -1, p.kernel), TVF::Invalid_input);
}

// ---------------------------------------------------------------------------
// Spectral basis (SPEC 5 and 6)

#include <CGAL/Tangent_vector_fields/Spectral_basis.h>
#include <CGAL/Tangent_vector_fields/face_field_io.h>

#include <cstdio>
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
  EXPECT_THROW(Basis(torus, TVF::parameters::number_of_eigenfields(2 * 288 + 1)), TVF::Invalid_input);
  EXPECT_THROW(Basis(torus, TVF::parameters::number_of_exact_eigenfields(144)), TVF::Invalid_input); // 143 available
  EXPECT_THROW(Basis(torus, TVF::parameters::maximum_eigenvalue(std::nan(""))), TVF::Invalid_input);
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

TEST(SpectralBasis, CompletenessCheckCatchesAMissingEigenvalue)
{
  Mesh sphere = make_icosphere(3);
  const Vertex_problem p = vertex_problem(sphere);
  TVF::Eigensolver_options options;
  options.allow_dense = false;
  const TVF::Eigenpairs e = TVF::lowest_eigenpairs(p.A, p.d, 40, p.kernel, options);
  EXPECT_TRUE(e.completeness.passed());
  EXPECT_EQ(e.completeness.inertia, e.completeness.expected);
  EXPECT_GT(e.complete_below, e.values[39]);
  // The 40 values end inside the l = 6 cluster, whose icosahedral sub-multiplets are
  // exact: the shift must go in a real gap (the widest among values 30 on, which is
  // the one between l = 5 and l = 6).
  EXPECT_TRUE(TVF::check_completeness(p.A, p.d, e.values, 1, 30).passed());
  // What Spectra did on spheres: one copy of a repeated eigenvalue missing (l = 3).
  Eigen::VectorXd truncated(39);
  truncated << e.values.head(10), e.values.tail(29);
  const TVF::Completeness_check check = TVF::check_completeness(p.A, p.d, truncated, 1, 30);
  EXPECT_FALSE(check.passed());
  EXPECT_EQ(check.inertia - check.expected, 1);
  // The last copy of l = 5 skipped, the list going on with l = 6.
  Eigen::VectorXd skipped(36);
  skipped << e.values.head(34), e.values.segment(35, 2);
  EXPECT_FALSE(TVF::check_completeness(p.A, p.d, skipped, 1, 30).passed());
}

TEST(SpectralBasis, SaveAndLoadRoundTripAndRefuseOtherMeshes)
{
  Mesh torus = make_torus(16, 9);
  Basis basis(torus, TVF::parameters::number_of_eigenfields(50));
  const std::string path = ::testing::TempDir() + "tvf_basis_test.bin";
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
  EXPECT_THROW(Basis::load(other, path), TVF::Invalid_input);
  Mesh moved = torus;
  jitter_vertices(moved, 0.05, 9);
  EXPECT_THROW(Basis::load(moved, path), TVF::Invalid_input);
  Mesh scaled = torus;
  transform(scaled, 2.0);
  EXPECT_THROW(Basis::load(scaled, path), TVF::Invalid_input);
  // Corrupt and truncated files, and a missing file.
  {
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(path + ".short", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    std::string wrong_version = bytes;
    wrong_version[8] = 9;
    std::ofstream(path + ".version", std::ios::binary) << wrong_version;
  }
  EXPECT_THROW(Basis::load(torus, path + ".short"), TVF::Invalid_input);
  EXPECT_THROW(Basis::load(torus, path + ".version"), TVF::Invalid_input);
  EXPECT_THROW(Basis::load(torus, path + ".missing"), TVF::Invalid_input);
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
