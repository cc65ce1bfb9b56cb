// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Spectral basis files (.tvfb), loaded for the torus: a basis that loads gives finite
// coefficients and fields.

#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  namespace TVF = CGAL::Tangent_vector_fields;
  const auto hodge = tvf_fuzz::torus_hodge();
  const std::string path = tvf_fuzz::input_file(data, size, "basis", "tvfb");
  try
  {
    const TVF::Eigenfield_basis basis = TVF::Eigenfield_basis::load(hodge, path);
    const Eigen::VectorXd probe = Eigen::VectorXd::Ones(2 * hodge->operators().mesh().number_of_faces());
    const Eigen::VectorXd a = basis.coefficients(probe);
    if(a.size() != basis.size() || !a.allFinite()) tvf_fuzz::fail("a loaded basis gives non-finite coefficients");
    if(basis.size() > 0 && !basis.eigenfield(basis.size() - 1).allFinite())
      tvf_fuzz::fail("a loaded basis has a non-finite element");
  }
  catch(const TVF::Invalid_input&)
  {
  }
  return 0;
}
