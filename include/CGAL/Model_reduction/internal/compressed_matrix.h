// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_INTERNAL_COMPRESSED_MATRIX_H
#define CGAL_MODEL_REDUCTION_INTERNAL_COMPRESSED_MATRIX_H

#include <Eigen/SparseCore>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace Model_reduction {
namespace internal {

// A column-major sparse matrix from its compressed arrays (rows sorted within
// each column): assembling these arrays directly beats triplets several times.
inline Eigen::SparseMatrix<double> compressed_matrix(Eigen::Index rows, Eigen::Index cols,
                                                     const std::vector<int>& outer,
                                                     const std::vector<int>& inner,
                                                     const std::vector<double>& values)
{
  Eigen::SparseMatrix<double> A(rows, cols);
  A.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), A.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), A.innerIndexPtr());
  std::copy(values.begin(), values.end(), A.valuePtr());
  return A;
}

} // namespace internal
} // namespace Model_reduction
} // namespace CGAL

#endif
