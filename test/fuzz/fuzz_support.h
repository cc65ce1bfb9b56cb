// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the fuzz targets share: a small fixed mesh (a torus, so that harmonic fields and
// n-field singularities exist) with its operators and bases, built once per process, and
// files for the readers that take a path.

#ifndef TVF_FUZZ_SUPPORT_H
#define TVF_FUZZ_SUPPORT_H

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Hodge_solver.h>
#include <CGAL/Tangent_vector_fields/N_field_basis.h>
#include <CGAL/Tangent_vector_fields/N_field_operators.h>
#include <CGAL/Tangent_vector_fields/Operator_matrices.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include "tool.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace tvf_fuzz {

namespace TVF = CGAL::Tangent_vector_fields;

/// The fuzzers' mesh: a torus of 8 x 5 quads split into 80 triangles (genus 1).
std::shared_ptr<const TVF::Operator_matrices> torus_operators();
std::shared_ptr<TVF::Hodge_solver> torus_hodge();
/// Its 16 lowest eigenfields.
std::shared_ptr<const TVF::Eigenfield_basis> torus_basis();
/// The n-field operators of the torus (n in [1, 12]; free boundary, no prescribed singularities).
std::shared_ptr<const TVF::N_field_operators> torus_n_field_operators(int n);
/// The 16 lowest elements of the basis of 4-fields.
std::shared_ptr<const TVF::N_field_basis> torus_n_field_basis();

/// The torus as the tool reads it (an OFF file through `Tool_mesh`), for the field readers of
/// `Tool_mesh::read_field`.  Also makes the tool quiet.
const tvf_tool::Tool_mesh& torus_tool_mesh();

/// Writes `data` to a file named `<name>.<extension>` in a folder of this process's own
/// and returns its path (for readers that take a path; the file is rewritten every time).
std::string input_file(const std::uint8_t* data, std::size_t size, const std::string& name,
                       const std::string& extension);

/// The input as a string.
inline std::string input_text(const std::uint8_t* data, std::size_t size)
{
  return std::string(reinterpret_cast<const char*>(data), size);
}

/// Ends the process with a report on stderr: for outcomes no input may cause (a wrong answer
/// accepted silently, an output that does not read back), which libFuzzer then keeps as a crash.
[[noreturn]] void fail(const std::string& what);

} // namespace tvf_fuzz

#endif
