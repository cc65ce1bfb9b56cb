// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mesh path of the tool: a file (the first byte picks OFF, OBJ, PLY, STL or GOCAD and
// --mollify; the rest is the file) through CGAL's readers, Model_reduction::polygon_soup_to_mesh's repair and
// the package's checks to the operators (Tool_mesh), then a Hodge decomposition on small
// meshes.  A mesh is refused with Tool_error, or gives finite operators and parts.

#include "fuzz_support.h"

#include <CGAL/Tangent_vector_fields/errors.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  namespace TVF = CGAL::Tangent_vector_fields;
  if(size == 0) return 0;
  tvf_tool::set_quiet(true);
  static const char* formats[] = {"off", "obj", "ply", "stl", "ts"};
  const std::string path = tvf_fuzz::input_file(data + 1, size - 1, "mesh", formats[(data[0] & 0x7f) % 5]);
  const bool mollify = (data[0] & 0x80) != 0;
  try
  {
    const tvf_tool::Tool_mesh mesh(path, mollify);
    const TVF::Operator_matrices& m = mesh.matrices();
    if(!m.face_areas().allFinite() || !(m.face_areas().minCoeff() > 0))
      tvf_fuzz::fail("a mesh with non-finite or non-positive face areas was accepted");
    if(mesh.number_of_faces() <= 200)
    {
      TVF::Hodge_solver hodge(mesh.shared_matrices());
      const Eigen::VectorXd field = Eigen::VectorXd::LinSpaced(2 * mesh.number_of_faces(), -1, 1);
      const TVF::Hodge_parts parts = hodge.decompose(field, TVF::hodge_exact | TVF::hodge_coexact | TVF::hodge_harmonic);
      if(!parts.exact.allFinite() || !parts.coexact.allFinite() || !parts.harmonic.allFinite())
        tvf_fuzz::fail("the Hodge decomposition of an accepted mesh is not finite");
    }
  }
  catch(const tvf_tool::Tool_error&)
  {
  }
  catch(const TVF::Numerical_failure&) // a mesh the checks pass but whose harmonic space is not what topology says
  {
  }
  return 0;
}
