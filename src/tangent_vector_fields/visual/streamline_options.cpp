// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The checks of streamline options shared by every way of tracing.

#include "streamline_walker.h"

#include <CGAL/Tangent_vector_fields/errors.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

std::string short_number(double x)
{
  std::ostringstream s;
  s << std::setprecision(3) << x;
  return s.str();
}

void check_streamline_options(const Streamline_options& o)
{
  // NaN would pass every comparison unnoticed: no length limit, no zero faces, no loop test.
  if(std::isnan(o.maximum_length)) throw Invalid_input("streamlines: maximum_length is NaN (0 or less: no limit)");
  if(o.maximum_segments < 1)
    throw Invalid_input("streamlines: maximum_segments must be at least 1 (got " + std::to_string(o.maximum_segments) +
                        ")");
  if(!(o.zero_field_tolerance >= 0) || !std::isfinite(o.zero_field_tolerance))
    throw Invalid_input("streamlines: zero_field_tolerance must be finite and non-negative");
  if(!(o.loop_closure_tolerance >= 0) || !std::isfinite(o.loop_closure_tolerance))
    throw Invalid_input("streamlines: loop_closure_tolerance must be finite and non-negative (0: no loop test)");
}

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL
