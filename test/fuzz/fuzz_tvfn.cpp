// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Bases of n-fields (.tvfn), loaded for the 4-fields of the torus.

#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  namespace TVF = CGAL::Tangent_vector_fields;
  const auto operators = tvf_fuzz::torus_n_field_operators(4);
  const std::string path = tvf_fuzz::input_file(data, size, "basis", "tvfn");
  try
  {
    const TVF::N_field_basis basis = TVF::N_field_basis::load(operators, path);
    if(basis.size() % 2 != 0 || basis.kernel_dimension() < 0 || basis.kernel_dimension() > basis.size())
      tvf_fuzz::fail("an inconsistent basis of n-fields was loaded");
  }
  catch(const TVF::Invalid_input&)
  {
  }
  return 0;
}
