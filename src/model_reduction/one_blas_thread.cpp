// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Model_reduction/internal/One_blas_thread.h>

// OpenBLAS's thread count, where OpenBLAS is the BLAS (weak: absent with another BLAS).
extern "C" void openblas_set_num_threads(int) __attribute__((weak));
extern "C" int openblas_get_num_threads(void) __attribute__((weak));

namespace CGAL {
namespace Model_reduction {
namespace internal {

One_blas_thread::One_blas_thread()
{
  if(openblas_get_num_threads && openblas_set_num_threads)
  {
    before_ = openblas_get_num_threads();
    openblas_set_num_threads(1);
  }
}

One_blas_thread::~One_blas_thread()
{
  if(before_ > 0) openblas_set_num_threads(before_);
}

} // namespace internal
} // namespace Model_reduction
} // namespace CGAL
