// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Block classical Gram-Schmidt against a tall Krylov basis, for blocks of 4 columns.
// With so few columns the products are memory-bound, and the BLAS's general GEMM
// copies (packs) the whole basis into a buffer before multiplying: three passes over
// it from memory instead of one (the packing routines took as long as the arithmetic
// in the eigensolver's profile).  Here the basis is read once per product, in panels
// of rows for which the block stays in the first-level cache.

#include <CGAL/Tangent_vector_fields/internal/Lanczos_window.h>

#include <algorithm>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

namespace {

constexpr Eigen::Index panel_rows = 8192; // a panel of the block: 256 KB, in the second-level cache

// C = Q^T Z and then Z -= Q C, Q column-major (stride ldq), Z row-major (n x 4), C
// row-major (m x 4).  Plain loops over 4 columns of Q at once with 4-wide inner loops,
// which the compiler vectorises; compiled for AVX2 + FMA too and chosen at run time.
__attribute__((target_clones("arch=haswell", "default"))) void
project_out(const double* Q, Eigen::Index ldq, Eigen::Index n, Eigen::Index m, double* Z, double* C)
{
  std::fill(C, C + 4 * m, 0.);
  for(Eigen::Index r = 0; r < n; r += panel_rows)
  {
    const Eigen::Index end = std::min(n, r + panel_rows);
    // Eight columns at once: eight independent accumulators hide the latency of the
    // fused multiply-adds (four left the loop latency-bound at a quarter of the speed).
    Eigen::Index j = 0;
    for(; j + 8 <= m; j += 8)
    {
      const double* q = Q + j * ldq;
      double a[8][4] = {};
      for(Eigen::Index i = r; i < end; ++i)
      {
        const double* z = Z + 4 * i;
        for(int k = 0; k < 8; ++k)
          for(int c = 0; c < 4; ++c) a[k][c] += q[k * ldq + i] * z[c];
      }
      for(int k = 0; k < 8; ++k)
        for(int c = 0; c < 4; ++c) C[4 * (j + k) + c] += a[k][c];
    }
    for(; j < m; ++j)
    {
      const double* q = Q + j * ldq;
      double a[4] = {0, 0, 0, 0};
      for(Eigen::Index i = r; i < end; ++i)
        for(int c = 0; c < 4; ++c) a[c] += q[i] * Z[4 * i + c];
      for(int c = 0; c < 4; ++c) C[4 * j + c] += a[c];
    }
  }
  for(Eigen::Index r = 0; r < n; r += panel_rows)
  {
    const Eigen::Index end = std::min(n, r + panel_rows);
    Eigen::Index j = 0;
    for(; j + 4 <= m; j += 4)
    {
      const double *q0 = Q + j * ldq, *q1 = q0 + ldq, *q2 = q1 + ldq, *q3 = q2 + ldq;
      const double *c0 = C + 4 * j, *c1 = c0 + 4, *c2 = c1 + 4, *c3 = c2 + 4;
      for(Eigen::Index i = r; i < end; ++i)
      {
        double* z = Z + 4 * i;
        for(int c = 0; c < 4; ++c) z[c] -= q0[i] * c0[c] + q1[i] * c1[c] + q2[i] * c2[c] + q3[i] * c3[c];
      }
    }
    for(; j < m; ++j)
    {
      const double* q = Q + j * ldq;
      const double* cj = C + 4 * j;
      for(Eigen::Index i = r; i < end; ++i)
        for(int c = 0; c < 4; ++c) Z[4 * i + c] -= q[i] * cj[c];
    }
  }
}

} // namespace

Eigen::MatrixXd project_out_of_columns(const Eigen::Ref<const Eigen::MatrixXd>& Q, Eigen::Index first,
                                       Eigen::Index count, Eigen::MatrixXd& Z)
{
  if(Z.cols() != 4)
  {
    const Eigen::MatrixXd C = Q.middleCols(first, count).transpose() * Z;
    Z.noalias() -= Q.middleCols(first, count) * C;
    return C;
  }
  Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor> rows = Z;
  Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor> C(count, 4);
  project_out(Q.data() + first * Q.outerStride(), Q.outerStride(), Q.rows(), count, rows.data(), C.data());
  Z = rows;
  return C;
}

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL
