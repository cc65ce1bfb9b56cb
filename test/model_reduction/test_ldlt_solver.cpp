// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The indefinite LDL^T behind spectrum slicing: its inertia against the analytic spectrum of a
// grid graph, with either ordering and with an analysis copied from another solver.

#include <CGAL/Model_reduction/Sparse_ldlt_solver.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

} // namespace

// 160 x 160 = 25,600 unknowns: above the size where many factorisations use nested dissection.
TEST(SparseLdlt, InertiaIsTheAnalyticCountWithEitherOrderingAndACopiedAnalysis)
{
  const int m = 160;
  std::vector<double> spectrum;
  for(int i = 0; i < m; ++i)
    for(int j = 0; j < m; ++j) spectrum.push_back(4 - 2 * std::cos(M_PI * i / m) - 2 * std::cos(M_PI * j / m));
  std::sort(spectrum.begin(), spectrum.end());
  // A shift in the middle of a gap near 0.5, so no pivot is near zero.
  const int below = static_cast<int>(std::lower_bound(spectrum.begin(), spectrum.end(), 0.5) - spectrum.begin());
  int k = below;
  while(spectrum[k + 1] - spectrum[k] < 1e-6) ++k;
  const double sigma = (spectrum[k] + spectrum[k + 1]) / 2;
  const int expected = k + 1;

  Eigen::SparseMatrix<double> K = grid_laplacian(m);
  K.diagonal().array() -= sigma;
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(m * m, 4);

  MR::Sparse_ldlt_solver nested, minimum_degree, copied;
  nested.analyze(K, true);
  minimum_degree.analyze(K);
  copied.copy_analysis(nested);
  for(MR::Sparse_ldlt_solver* s : {&nested, &minimum_degree, &copied})
  {
    s->factor(K, "the shifted grid Laplacian");
    EXPECT_EQ(s->negative_pivots(), expected);
    // Twice, so that a solve reusing its workspace is checked too.  Indefinite LDL^T without
    // pivoting solves to about 1e-10 relative here; 1e-8 leaves room and still catches a wrong
    // factor (a residual of order 1).
    for(int repeat = 0; repeat < 2; ++repeat)
    {
      const Eigen::MatrixXd x = s->solve(b);
      EXPECT_LT((K * x - b).norm() / b.norm(), 1e-8);
    }
  }
}
