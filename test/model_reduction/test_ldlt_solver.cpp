// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The indefinite LDL^T behind spectrum slicing: its inertia against the analytic spectrum of a
// grid graph, with either ordering and with an analysis copied from another solver; the same
// for the complex Hermitian LDL^H, on a torus graph with a magnetic flux.

#include <CGAL/Model_reduction/Sparse_ldlt_solver.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

namespace {

namespace MR = CGAL::Model_reduction;

// Graph Laplacian of an m x m grid: the sum of two path Laplacians, with eigenvalues
// (2 - 2 cos(pi i / m)) + (2 - 2 cos(pi j / m)), i, j = 0 .. m - 1.
Eigen::SparseMatrix<double> grid_laplacian(int m)
{
  std::vector<Eigen::Triplet<double>> t;
  auto id = [m](int i, int j) { return i * m + j; };
  for(int i = 0; i < m; ++i)
    for(int j = 0; j < m; ++j)
    {
      if(i + 1 < m) t.insert(t.end(), {{id(i, j), id(i, j), 1.}, {id(i + 1, j), id(i + 1, j), 1.},
                                       {id(i, j), id(i + 1, j), -1.}, {id(i + 1, j), id(i, j), -1.}});
      if(j + 1 < m) t.insert(t.end(), {{id(i, j), id(i, j), 1.}, {id(i, j + 1), id(i, j + 1), 1.},
                                       {id(i, j), id(i, j + 1), -1.}, {id(i, j + 1), id(i, j), -1.}});
    }
  Eigen::SparseMatrix<double> L(m * m, m * m);
  L.setFromTriplets(t.begin(), t.end());
  return L;
}

// Magnetic Laplacian of an m x m torus graph, sum over its edges (i, j) of
// (e_i - rho e_j)(e_i - rho e_j)^H with rho = e^{i phi / m} along the first axis and
// e^{i psi / m} along the second: a flux phi (psi) through each cycle, so that no gauge makes
// it real.  The Kronecker sum of two cycles', with eigenvalues
// (2 - 2 cos((2 pi k + phi) / m)) + (2 - 2 cos((2 pi l + psi) / m)), k, l = 0 .. m - 1.
Eigen::SparseMatrix<std::complex<double>> magnetic_torus_laplacian(int m, double phi, double psi)
{
  typedef std::complex<double> Complex;
  std::vector<Eigen::Triplet<Complex>> t;
  auto id = [m](int i, int j) { return (i % m) * m + j % m; };
  auto edge = [&](int a, int b, Complex rho) {
    t.insert(t.end(), {{a, a, 1.}, {b, b, 1.}, {a, b, -std::conj(rho)}, {b, a, -rho}});
  };
  for(int i = 0; i < m; ++i)
    for(int j = 0; j < m; ++j)
    {
      edge(id(i, j), id(i + 1, j), std::polar(1., phi / m));
      edge(id(i, j), id(i, j + 1), std::polar(1., psi / m));
    }
  Eigen::SparseMatrix<Complex> L(m * m, m * m);
  L.setFromTriplets(t.begin(), t.end());
  return L;
}

// The number of `spectrum`'s values below a shift in the middle of a gap near 0.5 (so that no
// pivot is near zero), and that shift.
int count_below_a_gap(std::vector<double> spectrum, double& sigma)
{
  std::sort(spectrum.begin(), spectrum.end());
  const int below = static_cast<int>(std::lower_bound(spectrum.begin(), spectrum.end(), 0.5) - spectrum.begin());
  int k = below;
  while(spectrum[k + 1] - spectrum[k] < 1e-6) ++k;
  sigma = (spectrum[k] + spectrum[k + 1]) / 2;
  return k + 1;
}

// K's negative pivots, with nested dissection, minimum degree and a copied analysis, are
// `expected`; its solves are accurate.
template <class Scalar>
void expect_inertia_and_solves(const Eigen::SparseMatrix<Scalar>& K, int expected)
{
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> Matrix;
  const Matrix b = Matrix::Random(K.rows(), 4);
  MR::Basic_sparse_ldlt_solver<Scalar> nested, minimum_degree, copied;
  nested.analyze(K, true);
  minimum_degree.analyze(K);
  copied.copy_analysis(nested);
  for(MR::Basic_sparse_ldlt_solver<Scalar>* s : {&nested, &minimum_degree, &copied})
  {
    s->factor(K, "the shifted grid Laplacian");
    EXPECT_EQ(s->negative_pivots(), expected);
    // Twice, so that a solve reusing its workspace is checked too.  Indefinite LDL^T without
    // pivoting solves to about 1e-10 relative here; 1e-8 leaves room and still catches a wrong
    // factor (a residual of order 1).
    for(int repeat = 0; repeat < 2; ++repeat)
    {
      const Matrix x = s->solve(b);
      EXPECT_LT((K * x - b).norm() / b.norm(), 1e-8);
    }
  }
}

} // namespace

// 160 x 160 = 25,600 unknowns: above the size where many factorisations use nested dissection.
TEST(SparseLdlt, InertiaIsTheAnalyticCountWithEitherOrderingAndACopiedAnalysis)
{
  const int m = 160;
  std::vector<double> spectrum;
  for(int i = 0; i < m; ++i)
    for(int j = 0; j < m; ++j) spectrum.push_back(4 - 2 * std::cos(M_PI * i / m) - 2 * std::cos(M_PI * j / m));
  double sigma = 0;
  const int expected = count_below_a_gap(spectrum, sigma);
  Eigen::SparseMatrix<double> K = grid_laplacian(m);
  K.diagonal().array() -= sigma;
  expect_inertia_and_solves(K, expected);
}

// A Hermitian matrix with genuinely complex entries: its pivots (D of L D L^H, real) counted,
// not their imaginary parts, and its solves with the conjugate transpose.
TEST(SparseLdlt, HermitianInertiaIsTheAnalyticCount)
{
  const int m = 160;
  const double phi = 1.0, psi = 2.3;
  std::vector<double> spectrum;
  for(int k = 0; k < m; ++k)
    for(int l = 0; l < m; ++l)
      spectrum.push_back(4 - 2 * std::cos((2 * M_PI * k + phi) / m) - 2 * std::cos((2 * M_PI * l + psi) / m));
  double sigma = 0;
  const int expected = count_below_a_gap(spectrum, sigma);
  Eigen::SparseMatrix<std::complex<double>> K = magnetic_torus_laplacian(m, phi, psi);
  K.diagonal().array() -= sigma;
  expect_inertia_and_solves(K, expected);
}
