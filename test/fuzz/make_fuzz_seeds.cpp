// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Writes the seeds that the package's own writers make for the fuzzers' torus: the binary
// bases (.tvfb, .tvfn), a .tvfc file, face fields (.tvf, .rawfield, .vtp), n-fields
// (.rawfield, .vtp, .sing) and constraint files.  Usage: make_fuzz_seeds <corpus folder>.
// The other seeds of the editor and the mesh path are written by hand.

#include "fuzz_support.h"

#include "coefficient_file.h"

#include <CGAL/Tangent_vector_fields/constraint_file_io.h>
#include <CGAL/Tangent_vector_fields/n_field_constraint_file_io.h>
#include <CGAL/Tangent_vector_fields/n_field_files.h>

#include <cstdio>
#include <fstream>

namespace {

namespace TVF = CGAL::Tangent_vector_fields;

std::ofstream open(const std::string& path)
{
  std::ofstream out(path, std::ios::binary);
  if(!out) tvf_fuzz::fail("cannot write " + path);
  return out;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc != 2)
  {
    std::fprintf(stderr, "usage: make_fuzz_seeds <corpus folder>\n");
    return 2;
  }
  const std::string corpus = argv[1];
  const auto operators = tvf_fuzz::torus_operators();
  const TVF::Intrinsic_mesh& mesh = operators->mesh();
  const tvf_tool::Tool_mesh& tool_mesh = tvf_fuzz::torus_tool_mesh();

  // Bases.
  const auto basis = tvf_fuzz::torus_basis();
  basis->save(corpus + "/tvfb/torus16.tvfb");
  const auto n_basis = tvf_fuzz::torus_n_field_basis();
  n_basis->save(corpus + "/tvfn/torus16.n4.tvfn");

  // A field of the basis, compressed to its 8 lowest coefficients.
  const Eigen::VectorXd field = basis->eigenfield(3) + 0.5 * basis->eigenfield(7);
  tvf_tool::Coefficient_file compressed;
  compressed.faces = static_cast<std::uint64_t>(mesh.number_of_faces());
  compressed.coefficients = basis->coefficients(field).head(8);
  compressed.signature = {{1, -2, 3, -4}};
  compressed.relative_error = 0.125;
  tvf_tool::write_coefficient_file(corpus + "/tvfc/field8.tvfc", compressed);

  // Face fields, as the tool writes them.
  tool_mesh.write_fields(corpus + "/tvf/field.tvf", {{"field", field}});
  tool_mesh.write_fields(corpus + "/rawfield/field.rawfield", {{"field", field}});
  tool_mesh.write_fields(corpus + "/vtp/field.vtp", {{"field", field}, {"other", 2 * field}});

  // A 4-field: all four vectors per face, its singularities, and the mesh with its vectors.
  const auto ops4 = tvf_fuzz::torus_n_field_operators(4);
  const Eigen::VectorXd z = n_basis->fields().col(2) + 0.3 * n_basis->fields().col(5);
  {
    std::ofstream out = open(corpus + "/rawfield/four.rawfield");
    TVF::write_raw_field(out, TVF::n_field_to_raw_field(*ops4, z));
  }
  {
    std::ofstream out = open(corpus + "/vtp/four.vtp");
    TVF::write_vtk_polydata(out, TVF::n_field_polydata(*ops4, z, "cross"));
  }
  {
    std::ofstream out = open(corpus + "/singularities/four.sing");
    TVF::write_singularity_file(out, TVF::n_field_singularity_file(*ops4, z));
  }
  {
    TVF::Singularity_file file;
    file.n = 4;
    file.singularities = {{0, 1}, {7, -1}, {12, 2}};
    std::ofstream out = open(corpus + "/singularities/three.sing");
    TVF::write_singularity_file(out, file);
  }

  // Constraint files of every kind of entry.
  {
    TVF::Constraint_file file;
    file.omega = 10;
    file.has_omega = true;
    file.constraints = {TVF::Field_constraint::vector_in_face(3, mesh.from_frame(3, 1, 0.5)),
                        TVF::Field_constraint::direction_in_face(40, mesh.from_frame(40, 0, 1)),
                        TVF::Field_constraint::divergence_at_vertex(5, 0.25),
                        TVF::Field_constraint::divergence_at_point(9, {{0.2, 0.3, 0.5}}, -1),
                        TVF::Field_constraint::curl_at_edge(17, 2),
                        TVF::Field_constraint::curl_at_point(60, {{0.6, 0.2, 0.2}}, 0.5)};
    file.weights = {1, 2, 1, 1, 0.5, 1};
    std::ofstream out = open(corpus + "/constraints/vector.json");
    TVF::write_constraint_file(out, file, mesh);
  }
  {
    TVF::N_field_constraint_file file;
    file.n = 4;
    file.omega = 1;
    file.order = 3;
    file.singularities = {{2, 1}};
    file.constraints = {TVF::N_field_constraint::vector_in_face(3, mesh.from_frame(3, 1, 0.5)),
                        TVF::N_field_constraint::direction_at_point(20, {{0.2, 0.3, 0.5}}, mesh.from_frame(20, 0, 1)),
                        TVF::N_field_constraint::singularity_at_vertex(30, -1),
                        TVF::N_field_constraint::singularity_at_vertex(12, 1, 50, mesh.from_frame(50, 1, 0))};
    std::ofstream out = open(corpus + "/constraints/cross.json");
    TVF::write_n_field_constraint_file(out, file, mesh);
  }
  // The torus as an OFF file for the mesh path (first byte 0: OFF).
  {
    std::ifstream in(tool_mesh.path(), std::ios::binary);
    std::ofstream out = open(corpus + "/mesh/torus.off");
    out << '\0' << in.rdbuf();
  }
  return 0;
}
