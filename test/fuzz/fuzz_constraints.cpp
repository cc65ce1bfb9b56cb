// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// JSON constraint files, vector fields and n-fields, on the torus: what a reader accepts
// writes and reads back with the same number of entries.

#include "fuzz_support.h"

#include <CGAL/Tangent_vector_fields/constraint_file_io.h>
#include <CGAL/Tangent_vector_fields/n_field_constraint_file_io.h>

#include <cmath>
#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  namespace TVF = CGAL::Tangent_vector_fields;
  const auto operators = tvf_fuzz::torus_operators();
  const std::string text = tvf_fuzz::input_text(data, size);
  try
  {
    std::istringstream in(text);
    const TVF::Constraint_file file = TVF::read_constraint_file(in, *operators);
    if(file.weights.size() != file.constraints.size() || !std::isfinite(file.omega) || file.omega < 0)
      tvf_fuzz::fail("an inconsistent constraint file was accepted");
    std::stringstream again;
    TVF::write_constraint_file(again, file, operators->mesh());
    const TVF::Constraint_file back = TVF::read_constraint_file(again, *operators);
    if(back.constraints.size() != file.constraints.size() || back.omega != file.omega || back.weights != file.weights)
      tvf_fuzz::fail("an accepted constraint file does not read back the same after writing");
  }
  catch(const TVF::Invalid_input&)
  {
  }
  try
  {
    std::istringstream in(text);
    const TVF::N_field_constraint_file file = TVF::read_n_field_constraint_file(in, operators);
    if(file.n < 1 || !std::isfinite(file.omega) || file.omega < 0)
      tvf_fuzz::fail("an inconsistent n-field constraint file was accepted");
    std::stringstream again;
    TVF::write_n_field_constraint_file(again, file, operators->mesh());
    const TVF::N_field_constraint_file back = TVF::read_n_field_constraint_file(again, operators);
    if(back.n != file.n || back.constraints.size() != file.constraints.size() || back.omega != file.omega ||
       back.order != file.order || back.singularities != file.singularities)
      tvf_fuzz::fail("an accepted n-field constraint file does not read back the same after writing");
  }
  catch(const TVF::Invalid_input&)
  {
  }
  return 0;
}
