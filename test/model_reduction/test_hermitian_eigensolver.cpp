// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The generalized eigensolver on complex Hermitian problems (the n-field basis's): sliced and
// dense pairs against a dense Hermitian solve of the same matrices, residuals and Hermitian
// D-orthonormality computed here, the kernel deflated, completeness by the inertia of LDL^H.

#include <CGAL/Model_reduction/Generalized_eigensolver.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <string>
#include <vector>

namespace MR = CGAL::Model_reduction;

namespace {

typedef std::complex<double> Complex;

// `A x = lambda D x` on two components.  A torus graph of m1 x m1 vertices whose edges carry
// random weights w and random phases rho, A = sum w (e_i - rho e_j)(e_i - rho e_j)^H: a
// genuinely complex matrix (no gauge makes it real; a transpose for an adjoint changes its
// spectrum), positive definite.  And an m2 x m2 grid whose phases are a gauge,
// rho_ij = conj(g_i) g_j with |g| = 1: its kernel is g (complex), the one column of `kernel`.
// D: random masses in [0.5, 2].
struct Hermitian_problem
{
  Eigen::SparseMatrix<Complex> A;
  Eigen::VectorXd d;
  Eigen::MatrixXcd kernel;
};

Hermitian_problem random_hermitian_problem(int m1, int m2, unsigned seed)
{
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> weight(0.5, 1.5), angle(-M_PI, M_PI), mass(0.5, 2);
  const int n1 = m1 * m1, n = n1 + m2 * m2;
  std::vector<Eigen::Triplet<Complex>> t;
  auto edge = [&](int a, int b, Complex rho) {
    const double w = weight(generator);
    t.insert(t.end(), {{a, a, w}, {b, b, w}, {a, b, -w * std::conj(rho)}, {b, a, -w * rho}});
  };
  for(int i = 0; i < m1; ++i)
    for(int j = 0; j < m1; ++j)
    {
      edge(i * m1 + j, (i + 1) % m1 * m1 + j, std::polar(1., angle(generator)));
      edge(i * m1 + j, i * m1 + (j + 1) % m1, std::polar(1., angle(generator)));
    }
  Hermitian_problem p;
  p.kernel = Eigen::MatrixXcd::Zero(n, 1);
  for(int v = n1; v < n; ++v) p.kernel(v, 0) = std::polar(1., angle(generator));
  auto gauge_edge = [&](int a, int b) { edge(a, b, std::conj(p.kernel(a, 0)) * p.kernel(b, 0)); };
  for(int i = 0; i < m2; ++i)
    for(int j = 0; j < m2; ++j)
    {
      const int v = n1 + i * m2 + j;
      if(i + 1 < m2) gauge_edge(v, v + m2);
      if(j + 1 < m2) gauge_edge(v, v + 1);
    }
  p.A.resize(n, n);
  p.A.setFromTriplets(t.begin(), t.end());
  p.d.resize(n);
  for(int v = 0; v < n; ++v) p.d[v] = mass(generator);
  return p;
}

// All eigenvalues of the problem (the kernel's 0 first), by Eigen's dense Hermitian solver.
Eigen::VectorXd dense_spectrum(const Hermitian_problem& p)
{
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXcd> dense(
      Eigen::MatrixXcd(p.A), Eigen::MatrixXcd(p.d.cast<Complex>().asDiagonal()), Eigen::EigenvaluesOnly);
  EXPECT_EQ(dense.info(), Eigen::Success);
  return dense.eigenvalues();
}

// The pairs `e` are the `count` lowest outside the kernel: their values those of `spectrum`
// after its 0, their residuals |D^-1/2 (A x - l D x)| / (l |D^1/2 x|) (the tolerance's
// definition) computed here, their vectors D-orthonormal in the Hermitian product and
// D-orthogonal to the kernel.
void expect_lowest_pairs(const Hermitian_problem& p, const Eigen::VectorXd& spectrum, const MR::Complex_eigenpairs& e,
                         const Eigen::MatrixXcd& X, int count)
{
  ASSERT_EQ(e.values.size(), count);
  ASSERT_EQ(X.cols(), count);
  EXPECT_LT(std::abs(spectrum[0]), 1e-12); // the kernel
  const Eigen::VectorXd truth = spectrum.segment(1, count);
  EXPECT_LT(((e.values - truth).array() / truth.array()).abs().maxCoeff(), 1e-9);
  const Eigen::VectorXd inv_sqrt_d = p.d.cwiseSqrt().cwiseInverse();
  for(int i = 0; i < count; ++i)
  {
    const Eigen::VectorXcd r = p.A * X.col(i) - e.values[i] * p.d.cwiseProduct(X.col(i));
    EXPECT_LE(inv_sqrt_d.cwiseProduct(r).norm() / (e.values[i] * p.d.cwiseSqrt().cwiseProduct(X.col(i)).norm()), 1e-10)
        << "pair " << i;
  }
  const Eigen::MatrixXcd gram = X.adjoint() * p.d.asDiagonal() * X;
  EXPECT_LT((gram - Eigen::MatrixXcd::Identity(count, count)).cwiseAbs().maxCoeff(), 1e-10);
  const Eigen::VectorXd kernel_mass = p.kernel.col(0).cwiseAbs2().cwiseProduct(p.d);
  EXPECT_LT((p.kernel.adjoint() * p.d.asDiagonal() * X).cwiseAbs().maxCoeff() / std::sqrt(kernel_mass.sum()), 1e-9);
}

int count_below(const Eigen::VectorXd& spectrum, double tau) { return static_cast<int>((spectrum.array() < tau).count()); }

} // namespace

TEST(HermitianEigensolver, SlicedPairsMatchADenseHermitianSolve)
{
  // 1,076 unknowns, 120 pairs in windows of about 20 (sliced although small), on one chain
  // and cut into chains on two and three threads (the pairs next to a cut joined by a
  // Hermitian Rayleigh-Ritz step).
  const Hermitian_problem p = random_hermitian_problem(26, 20, 3);
  ASSERT_GT(p.A.coeffs().imag().cwiseAbs().maxCoeff(), 0.5);
  const Eigen::VectorXd spectrum = dense_spectrum(p);
  const int count = 120;
  for(int threads : {1, 2, 3})
  {
    SCOPED_TRACE("threads " + std::to_string(threads));
    MR::Eigensolver_options options;
    options.allow_dense = false;
    options.slice_size = 20;
    options.threads = threads;
    const MR::Complex_eigenpairs e = MR::lowest_eigenpairs(p.A, p.d, count, p.kernel, options);
    expect_lowest_pairs(p, spectrum, e, e.vectors, count);
    EXPECT_LE(e.residuals.maxCoeff(), 1e-10);
    // The inertia of LDL^H at the check's shift is the dense count below it (kernel included).
    EXPECT_TRUE(e.completeness.passed());
    EXPECT_EQ(e.completeness.inertia, count_below(spectrum, e.completeness.shift));
    EXPECT_GE(e.completeness.expected, count + 1);
    EXPECT_GT(e.complete_below, e.values[count - 1] * (1 - 1e-12));
  }
  // Counts at shifts between consecutive eigenvalues (of the whole spectrum, up to the top).
  for(int k : {1, 2, 40, 121, 600, 1075})
  {
    const double tau = 0.5 * (spectrum[k - 1] + spectrum[k]);
    EXPECT_EQ(MR::count_eigenvalues_below(p.A, p.d, tau), k) << "k = " << k;
  }
}

TEST(HermitianEigensolver, DensePathAndFloat32VectorsOfComplexProblems)
{
  // A small problem takes the dense path (LAPACK zheevd); its float32 vectors are the double
  // ones rounded, both parts.
  const Hermitian_problem small = random_hermitian_problem(9, 6, 5);
  const Eigen::VectorXd spectrum = dense_spectrum(small);
  MR::Eigensolver_options options;
  const MR::Complex_eigenpairs e = MR::lowest_eigenpairs(small.A, small.d, 30, small.kernel, options);
  // Dense: no shift-invert solve.  (Dense pairs that miss the tolerance are handed to slicing,
  // which would hide a wrong dense solve.)
  EXPECT_EQ(e.operator_applications, 0);
  expect_lowest_pairs(small, spectrum, e, e.vectors, 30);
  EXPECT_TRUE(e.completeness.passed());
  EXPECT_EQ(e.completeness.inertia, count_below(spectrum, e.completeness.shift));
  options.float32_vectors = true;
  const MR::Complex_eigenpairs f = MR::lowest_eigenpairs(small.A, small.d, 30, small.kernel, options);
  EXPECT_EQ(f.vectors.size(), 0);
  EXPECT_TRUE(f.vectors_float32 == e.vectors.cast<std::complex<float>>());

  // Sliced and rounded as the chains go: the values and residuals of the double solve; the
  // rounded vectors D-orthonormal to float32 accuracy (n entries rounded by 2^-24: inner
  // products move by about 1e-7), their Rayleigh quotients the values (rounding moves a
  // quotient to second order only).
  const Hermitian_problem p = random_hermitian_problem(26, 20, 7);
  const Eigen::VectorXd full = dense_spectrum(p);
  options.allow_dense = false;
  options.slice_size = 20;
  options.threads = 2;
  const MR::Complex_eigenpairs g = MR::lowest_eigenpairs(p.A, p.d, 100, p.kernel, options);
  ASSERT_EQ(g.vectors_float32.cols(), 100);
  const Eigen::VectorXd truth = full.segment(1, 100);
  EXPECT_LT(((g.values - truth).array() / truth.array()).abs().maxCoeff(), 1e-9);
  EXPECT_LE(g.residuals.maxCoeff(), 1e-10);
  const Eigen::MatrixXcd X = g.vectors_float32.cast<Complex>();
  const Eigen::MatrixXcd K = X.adjoint() * p.d.asDiagonal() * X;
  EXPECT_LT((K - Eigen::MatrixXcd::Identity(100, 100)).cwiseAbs().maxCoeff(), 1e-6);
  const Eigen::VectorXd quotients = (X.adjoint() * (p.A * X)).diagonal().real().cwiseQuotient(K.diagonal().real());
  EXPECT_LT(((quotients - truth).array() / truth.array()).abs().maxCoeff(), 1e-9);
}
