// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Block classical Gram-Schmidt against a tall Krylov basis, for blocks of 4 columns.
// With so few columns the products are memory-bound, and the BLAS's general GEMM
// copies (packs) the whole basis into a buffer before multiplying: three passes over
// it from memory instead of one (the packing routines took as long as the arithmetic
// in the eigensolver's profile).  Here the basis is read once per product, in panels
// of rows for which the block stays in the second-level cache.

#include <CGAL/Model_reduction/internal/Lanczos_window.h>

#include <algorithm>
#include <complex>
#include <functional>

namespace CGAL {
namespace Model_reduction {
namespace internal {

namespace {

constexpr Eigen::Index panel_rows = 8192; // a panel of the block: 256 KB, in the second-level cache

// C = Q^T Z and then Z -= Q C, all column-major: Q (n x m, stride ldq), Z (n x 4, stride
// n), C (m x 4, stride m).  Both loops run along the rows, four columns of Q at a time,
// so that the compiler vectorises them over rows with 16 independent accumulators (the
// reduction order is relaxed by `omp simd`); compiled for AVX-512 and AVX2 + FMA too and
// chosen at run time.  Measured at 104k rows and m = 170 on this project's 2-core
// machine: 8.3 GB/s of Q read, against 6.0 GB/s for a kernel vectorised across the four
// columns of a row-major block (and 10 GB/s for a plain sum of the same memory).
__attribute__((target_clones("arch=skylake-avx512", "arch=haswell", "default"))) void
project_out(const double* Q, Eigen::Index ldq, Eigen::Index n, Eigen::Index m, double* Z, double* C)
{
  std::fill(C, C + 4 * m, 0.);
  double *z0 = Z, *z1 = Z + n, *z2 = Z + 2 * n, *z3 = Z + 3 * n;
  double *c0 = C, *c1 = C + m, *c2 = C + 2 * m, *c3 = C + 3 * m;
  for(Eigen::Index r = 0; r < n; r += panel_rows)
  {
    const Eigen::Index end = std::min(n, r + panel_rows);
    Eigen::Index j = 0;
    for(; j + 4 <= m; j += 4)
    {
      const double *q0 = Q + j * ldq, *q1 = q0 + ldq, *q2 = q1 + ldq, *q3 = q2 + ldq;
      double a00 = 0, a01 = 0, a02 = 0, a03 = 0, a10 = 0, a11 = 0, a12 = 0, a13 = 0;
      double a20 = 0, a21 = 0, a22 = 0, a23 = 0, a30 = 0, a31 = 0, a32 = 0, a33 = 0;
#pragma omp simd reduction(+ : a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, a30, a31, a32, a33)
      for(Eigen::Index i = r; i < end; ++i)
      {
        const double x0 = z0[i], x1 = z1[i], x2 = z2[i], x3 = z3[i];
        a00 += q0[i] * x0, a01 += q0[i] * x1, a02 += q0[i] * x2, a03 += q0[i] * x3;
        a10 += q1[i] * x0, a11 += q1[i] * x1, a12 += q1[i] * x2, a13 += q1[i] * x3;
        a20 += q2[i] * x0, a21 += q2[i] * x1, a22 += q2[i] * x2, a23 += q2[i] * x3;
        a30 += q3[i] * x0, a31 += q3[i] * x1, a32 += q3[i] * x2, a33 += q3[i] * x3;
      }
      c0[j] += a00, c1[j] += a01, c2[j] += a02, c3[j] += a03;
      c0[j + 1] += a10, c1[j + 1] += a11, c2[j + 1] += a12, c3[j + 1] += a13;
      c0[j + 2] += a20, c1[j + 2] += a21, c2[j + 2] += a22, c3[j + 2] += a23;
      c0[j + 3] += a30, c1[j + 3] += a31, c2[j + 3] += a32, c3[j + 3] += a33;
    }
    for(; j < m; ++j)
    {
      const double* q = Q + j * ldq;
      double a0 = 0, a1 = 0, a2 = 0, a3 = 0;
#pragma omp simd reduction(+ : a0, a1, a2, a3)
      for(Eigen::Index i = r; i < end; ++i) a0 += q[i] * z0[i], a1 += q[i] * z1[i], a2 += q[i] * z2[i], a3 += q[i] * z3[i];
      c0[j] += a0, c1[j] += a1, c2[j] += a2, c3[j] += a3;
    }
  }
  for(Eigen::Index r = 0; r < n; r += panel_rows)
  {
    const Eigen::Index end = std::min(n, r + panel_rows);
    Eigen::Index j = 0;
    for(; j + 4 <= m; j += 4)
    {
      const double *q0 = Q + j * ldq, *q1 = q0 + ldq, *q2 = q1 + ldq, *q3 = q2 + ldq;
#pragma omp simd
      for(Eigen::Index i = r; i < end; ++i)
      {
        const double y0 = q0[i], y1 = q1[i], y2 = q2[i], y3 = q3[i];
        z0[i] -= y0 * c0[j] + y1 * c0[j + 1] + y2 * c0[j + 2] + y3 * c0[j + 3];
        z1[i] -= y0 * c1[j] + y1 * c1[j + 1] + y2 * c1[j + 2] + y3 * c1[j + 3];
        z2[i] -= y0 * c2[j] + y1 * c2[j + 1] + y2 * c2[j + 2] + y3 * c2[j + 3];
        z3[i] -= y0 * c3[j] + y1 * c3[j + 1] + y2 * c3[j + 2] + y3 * c3[j + 3];
      }
    }
    for(; j < m; ++j)
    {
      const double* q = Q + j * ldq;
#pragma omp simd
      for(Eigen::Index i = r; i < end; ++i)
        z0[i] -= q[i] * c0[j], z1[i] -= q[i] * c1[j], z2[i] -= q[i] * c2[j], z3[i] -= q[i] * c3[j];
    }
  }
}

// The same step through the BLAS.
template <class Scalar>
Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>
project_out_by_blas(const Eigen::Ref<const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>>& Q,
                    Eigen::Index first, Eigen::Index count, Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& Z)
{
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> C(count, Z.cols());
  C.noalias() = Q.middleCols(first, count).adjoint() * Z;
  Z.noalias() -= Q.middleCols(first, count) * C;
  return C;
}

} // namespace

Eigen::MatrixXd project_out_of_columns(const Eigen::Ref<const Eigen::MatrixXd>& Q, Eigen::Index first,
                                       Eigen::Index count, Eigen::MatrixXd& Z)
{
  if(Z.cols() != 4) return project_out_by_blas<double>(Q, first, count, Z);
  Eigen::MatrixXd C(count, Z.cols());
  project_out(Q.data() + first * Q.outerStride(), Q.outerStride(), Q.rows(), count, Z.data(), C.data());
  return C;
}

// Complex blocks through the BLAS (zgemm): four times the arithmetic per entry read, so that
// packing costs less.  Measured (4 columns against 100 of 20k rows, one thread): 5.0 ms, where
// the real kernel on the interleaved parts, four passes (Z and -i Z, projection and update),
// took 9.5 ms.
Eigen::MatrixXcd project_out_of_columns(const Eigen::Ref<const Eigen::MatrixXcd>& Q, Eigen::Index first,
                                        Eigen::Index count, Eigen::MatrixXcd& Z)
{
  return project_out_by_blas<std::complex<double>>(Q, first, count, Z);
}

template <class Scalar>
Locked_columns<Scalar>::Locked_columns(const std::vector<const Scalar*>& columns, Eigen::Index rows) : rows_(rows)
{
  // In address order, adjacent columns join a run (the order of a Gram-Schmidt step's
  // columns does not matter).
  std::vector<const Scalar*> sorted = columns;
  std::sort(sorted.begin(), sorted.end(), std::less<const Scalar*>());
  for(const Scalar* column : sorted)
  {
    if(!runs_.empty() && runs_.back().first + runs_.back().second * rows == column) ++runs_.back().second;
    else runs_.push_back({column, 1});
  }
  count_ = static_cast<Eigen::Index>(columns.size());
}

template <class Scalar>
void Locked_columns<Scalar>::project_out(Matrix& Z) const
{
  for(const auto& run : runs_)
  {
    const Eigen::Map<const Matrix> V(run.first, rows_, run.second);
    project_out_of_columns(V, 0, run.second, Z);
  }
}

template class Locked_columns<double>;
template class Locked_columns<std::complex<double>>;

} // namespace internal
} // namespace Model_reduction
} // namespace CGAL
