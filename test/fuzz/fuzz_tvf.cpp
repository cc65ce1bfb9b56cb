// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// .tvf face fields, read as the tool reads `--field F.tvf` (read_face_vectors, then one
// vector per face or per polygon of the mesh file).

#include "fuzz_support.h"

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const tvf_tool::Tool_mesh& mesh = tvf_fuzz::torus_tool_mesh();
  tvf_tool::Field_source source;
  source.file = tvf_fuzz::input_file(data, size, "field", "tvf");
  try
  {
    const Eigen::VectorXd x = mesh.read_field(source);
    if(x.size() != 2 * mesh.number_of_faces() || !x.allFinite()) tvf_fuzz::fail("a malformed field was accepted");
  }
  catch(const tvf_tool::Tool_error&)
  {
  }
  return 0;
}
