// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_KEEP_FREED_MEMORY_H
#define CGAL_MODEL_REDUCTION_KEEP_FREED_MEMORY_H

/// \file keep_freed_memory.h
/// A process-wide setting for interactive programs (editors, servers, benchmarks): freed
/// blocks of a few MB stay in the heap for the next allocation.

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace CGAL {
namespace Model_reduction {

/// \brief Keeps freed blocks of up to 32 MB, and up to 256 MB of free heap, for reuse.
///
/// Every solve at full resolution allocates blocks of one double per unknown (a few MB).
/// glibc returns such blocks to the system when they are freed, so the next one is fresh
/// memory again: one page fault per 4 KB page.  On a virtual machine a page fault costs
/// about 10 microseconds; on this project's 2-core VM one constraint added to an exact
/// solve with 692k unknowns faulted 42 MB of pages, 120 ms of its 380 ms.  Call this once at
/// the start of an interactive program (the `tvf` tool and the benchmarks do).  The price is
/// memory held after a peak: `malloc_trim(0)` gives it back where the program knows it is
/// idle (`tvf serve` does when a page closes).  Returns false where it has no effect (not
/// glibc, or glibc refused the setting).
///
/// This is a process-wide allocator setting; the library never changes it by itself.
inline bool keep_freed_memory()
{
#ifdef __GLIBC__
  // 32 MB is the largest mmap threshold glibc accepts on 64-bit systems.
  return mallopt(M_MMAP_THRESHOLD, 32 << 20) == 1 && mallopt(M_TRIM_THRESHOLD, 256 << 20) == 1;
#else
  return false;
#endif
}

} // namespace Model_reduction
} // namespace CGAL

#endif
