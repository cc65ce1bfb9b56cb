// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_INTERNAL_ONE_BLAS_THREAD_H
#define CGAL_MODEL_REDUCTION_INTERNAL_ONE_BLAS_THREAD_H

namespace CGAL {
namespace Model_reduction {
namespace internal {

/// Sets OpenBLAS (where it is the BLAS) to one thread for this object's lifetime, and back
/// afterwards.  For loops of small BLAS calls (a triangular solve with one vector per
/// iteration), where OpenBLAS's threads spend their time waking and yielding, and for
/// thread pools that run one BLAS call per thread.
class One_blas_thread
{
public:
  One_blas_thread();
  ~One_blas_thread();
  One_blas_thread(const One_blas_thread&) = delete;
  One_blas_thread& operator=(const One_blas_thread&) = delete;

private:
  int before_ = 0;
};

} // namespace internal
} // namespace Model_reduction
} // namespace CGAL

#endif
