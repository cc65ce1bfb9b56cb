// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// VTK XML PolyData (.vtp): read_vtk_polydata, what it accepts must write and read back the
// same, and the tool's `--field F.vtp`.

#include "fuzz_support.h"

#include <CGAL/Tangent_vector_fields/field_files.h>

#include <sstream>

namespace {

namespace TVF = CGAL::Tangent_vector_fields;

bool same_arrays(const std::vector<TVF::Vtk_polydata::Array>& a, const std::vector<TVF::Vtk_polydata::Array>& b)
{
  if(a.size() != b.size()) return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(a[i].name != b[i].name || a[i].components != b[i].components || a[i].values != b[i].values) return false;
  return true;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const tvf_tool::Tool_mesh& mesh = tvf_fuzz::torus_tool_mesh();
  std::istringstream in(tvf_fuzz::input_text(data, size));
  try
  {
    const TVF::Vtk_polydata polydata = TVF::read_vtk_polydata(in);
    // What was accepted is consistent: the writer takes it and the reader gives it back.
    std::stringstream again;
    TVF::write_vtk_polydata(again, polydata);
    const TVF::Vtk_polydata back = TVF::read_vtk_polydata(again);
    if(back.points != polydata.points || back.lines != polydata.lines || back.polygons != polydata.polygons ||
       !same_arrays(back.point_data, polydata.point_data) || !same_arrays(back.cell_data, polydata.cell_data))
      tvf_fuzz::fail("an accepted .vtp file does not read back the same after writing");
  }
  catch(const TVF::Invalid_input&)
  {
  }
  tvf_tool::Field_source source;
  source.file = tvf_fuzz::input_file(data, size, "field", "vtp");
  try
  {
    if(!mesh.read_field(source).allFinite()) tvf_fuzz::fail("a non-finite field was accepted");
  }
  catch(const tvf_tool::Tool_error&)
  {
  }
  return 0;
}
