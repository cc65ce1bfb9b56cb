// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Compressed fields (.tvfc) as `tvf decompress` reads them.

#include "fuzz_support.h"

#include "coefficient_file.h"

#include <cmath>
#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::istringstream in(tvf_fuzz::input_text(data, size));
  try
  {
    const tvf_tool::Coefficient_file file = tvf_tool::read_coefficient_file(in, size, "input.tvfc");
    if(!file.coefficients.allFinite() || !std::isfinite(file.relative_error))
      tvf_fuzz::fail("a .tvfc file with non-finite numbers was accepted");
  }
  catch(const tvf_tool::Tool_error&)
  {
  }
  return 0;
}
