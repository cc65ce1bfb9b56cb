// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Directional's .rawfield: read_raw_field, then what a field of degree n becomes (an n-field
// of the torus, or the tool's `--field F.rawfield`, which takes one direction per face).

#include "fuzz_support.h"

#include <CGAL/Tangent_vector_fields/n_field_files.h>

#include <cmath>
#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  namespace TVF = CGAL::Tangent_vector_fields;
  const tvf_tool::Tool_mesh& mesh = tvf_fuzz::torus_tool_mesh();
  std::istringstream in(tvf_fuzz::input_text(data, size));
  try
  {
    const TVF::Raw_field raw = TVF::read_raw_field(in);
    if(raw.degree < 1 || raw.vectors.size() % std::size_t(raw.degree) != 0)
      tvf_fuzz::fail("a raw field of degree " + std::to_string(raw.degree) + " with " +
                     std::to_string(raw.vectors.size()) + " vectors was accepted");
    for(const auto& v : raw.vectors)
      if(!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
        tvf_fuzz::fail("a non-finite raw field was accepted");
    if(raw.degree <= 12)
    {
      const Eigen::VectorXd z = TVF::n_field_from_raw_field(*tvf_fuzz::torus_n_field_operators(raw.degree), raw);
      if(!z.allFinite()) tvf_fuzz::fail("a raw field became a non-finite n-field");
    }
  }
  catch(const TVF::Invalid_input&)
  {
  }
  tvf_tool::Field_source source;
  source.file = tvf_fuzz::input_file(data, size, "field", "rawfield");
  source.direction = size > 0 ? data[size - 1] % 3 : 0;
  try
  {
    if(!mesh.read_field(source).allFinite()) tvf_fuzz::fail("a non-finite field was accepted");
  }
  catch(const tvf_tool::Tool_error&)
  {
  }
  return 0;
}
