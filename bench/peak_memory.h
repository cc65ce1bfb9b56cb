// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Resident memory of this process for the benchmarks (Linux: /proc/self/status; -1 where
// unknown).  A measured run starts with reset_peak_memory(), which gives glibc's freed pages
// back first (it keeps them otherwise, and a later run would reuse them unseen) and resets the
// high-water mark (writing 5 to /proc/self/clear_refs) to the current resident size.

#ifndef TVF_BENCH_PEAK_MEMORY_H
#define TVF_BENCH_PEAK_MEMORY_H

#include <cstdlib>
#include <fstream>
#include <string>
#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace tvf_bench {

inline void reset_peak_memory()
{
#ifdef __GLIBC__
  malloc_trim(0);
#endif
  std::ofstream("/proc/self/clear_refs") << "5";
}

/// A field of /proc/self/status given in kB ("VmHWM", "VmRSS"), in bytes.
inline double status_bytes(const std::string& field)
{
  std::ifstream status("/proc/self/status");
  for(std::string line; std::getline(status, line);)
    if(line.rfind(field + ":", 0) == 0) return std::atof(line.c_str() + field.size() + 1) * 1024.;
  return -1;
}

/// Largest resident size since the last reset.
inline double peak_memory_bytes() { return status_bytes("VmHWM"); }
inline double resident_bytes() { return status_bytes("VmRSS"); }

} // namespace tvf_bench

#endif
