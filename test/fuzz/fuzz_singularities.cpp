// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Directional's .sing singularity files: read_singularity_file, and what it accepts writes
// and reads back the same.

#include "fuzz_support.h"

#include <CGAL/Tangent_vector_fields/n_field_files.h>

#include <set>
#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  namespace TVF = CGAL::Tangent_vector_fields;
  std::istringstream in(tvf_fuzz::input_text(data, size));
  try
  {
    const TVF::Singularity_file file = TVF::read_singularity_file(in);
    std::set<int> vertices;
    for(const auto& [v, k] : file.singularities)
      if(v < 0 || !vertices.insert(v).second) tvf_fuzz::fail("a negative or repeated vertex was accepted");
    if(file.n < 1) tvf_fuzz::fail("n < 1 was accepted");
    std::stringstream again;
    TVF::write_singularity_file(again, file);
    const TVF::Singularity_file back = TVF::read_singularity_file(again);
    if(back.n != file.n || back.singularities != file.singularities)
      tvf_fuzz::fail("an accepted .sing file does not read back the same after writing");
  }
  catch(const TVF::Invalid_input&)
  {
  }
  return 0;
}
