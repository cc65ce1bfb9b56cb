// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_INTERNAL_HUGE_PAGES_H
#define CGAL_MODEL_REDUCTION_INTERNAL_HUGE_PAGES_H

/// \file huge_pages.h
/// Large dense matrices (Krylov bases, eigenfunctions) backed by 2 MB pages where the
/// system allows it.  Fresh memory costs one page fault per 4 KB page on first touch,
/// about 10 microseconds each on a virtual machine: filling a new 104k x 504 matrix of
/// doubles took 1.12 s in 4 KB pages and 0.04 s in 2 MB pages (2-core VM, Linux with
/// transparent huge pages in `madvise` mode, the usual default).

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace CGAL {
namespace Model_reduction {
namespace internal {

#if defined(__linux__)
/// `madvise(advice)` on the whole `unit`-sized pages inside `[data, data + bytes)`.
inline void advise_whole_pages(void* data, std::size_t bytes, std::uintptr_t unit, int advice)
{
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(data) + unit - 1) & ~(unit - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(unit - 1);
  if(end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, advice);
}
#endif

/// Asks the kernel to back the whole 2 MB pages inside `[data, data + bytes)` with huge
/// pages.  Only pages not touched yet gain; a hint, so failure is ignored.
inline void advise_huge_pages(void* data, std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t huge = std::uintptr_t(2) << 20;
  if(bytes >= 2 * huge) advise_whole_pages(data, bytes, huge, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

/// Gives the 4 KB pages wholly inside `[data, data + bytes)` back to the system (their
/// contents are lost; the range stays mapped and reads as zeros after).  Elsewhere a no-op.
inline void discard_pages(void* data, std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_DONTNEED)
  advise_whole_pages(data, bytes, 4096, MADV_DONTNEED);
#else
  (void)data;
  (void)bytes;
#endif
}

/// `m.resize(rows, cols)`, with fresh storage advised to use huge pages (contents undefined).
template <class Matrix>
void resize_in_huge_pages(Matrix& m, Eigen::Index rows, Eigen::Index cols)
{
  if(m.rows() == rows && m.cols() == cols) return;
  m.resize(rows, cols);
  advise_huge_pages(m.data(), sizeof(typename Matrix::Scalar) * static_cast<std::size_t>(m.size()));
}

/// Entries of type `T` (double, float) mapped straight from the system (Linux: `mmap`,
/// advised to use huge pages), so that freeing them gives the memory back at once whatever
/// the allocator's settings (`keep_freed_memory` keeps blocks up to 32 MB in the heap, where
/// the converged vectors of the rocker arm's eigensolver stayed next to their copy: 0.50 GB
/// peak against 0.36 GB).
template <class T>
class Mapped_array
{
public:
  explicit Mapped_array(std::size_t count) : bytes_(sizeof(T) * std::max<std::size_t>(count, 1))
  {
#if defined(__linux__)
    void* p = mmap(nullptr, bytes_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if(p == MAP_FAILED) throw std::bad_alloc();
    data_ = static_cast<T*>(p);
    advise_huge_pages(data_, bytes_);
#else
    data_ = new T[bytes_ / sizeof(T)];
#endif
  }
  ~Mapped_array()
  {
#if defined(__linux__)
    munmap(data_, bytes_);
#else
    delete[] data_;
#endif
  }
  Mapped_array(const Mapped_array&) = delete;
  Mapped_array& operator=(const Mapped_array&) = delete;
  T* data() const { return data_; }

private:
  std::size_t bytes_;
  T* data_ = nullptr;
};

} // namespace internal
} // namespace Model_reduction
} // namespace CGAL

#endif
