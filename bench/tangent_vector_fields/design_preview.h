// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// bench_design's table of the editor's preview (issue 36): the fur of a reduced field traced
// through the faces it reaches only, against the whole reduced field and the same fur.

#ifndef TVF_BENCH_DESIGN_PREVIEW_H
#define TVF_BENCH_DESIGN_PREVIEW_H

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Field_constraint.h>
#include <CGAL/Tangent_vector_fields/Operator_matrices.h>
#include <CGAL/Tangent_vector_fields/Refining_spline_solver.h>

#include <memory>
#include <string>
#include <vector>

namespace tvf_bench {

/// The diagonal of the bounding box of the mesh's vertices.
double bounding_box_diagonal(const CGAL::Tangent_vector_fields::Intrinsic_mesh& m);

/// Measures the preview of the reduced field of `constraints` in a basis of size `d` and appends
/// its table rows to `rows` (also printed with their details as measured).  Then the editor's
/// answer to an add with exact answers on: `refining` (holding `constraints`, refining in the
/// background) gets a constraint, the preview's strokes are traced, and the exact field follows
/// as `tvf serve` waits for it after a preview.
void measure_preview(const std::string& mesh_key, const CGAL::Tangent_vector_fields::Operator_matrices& ops,
                     std::shared_ptr<const CGAL::Tangent_vector_fields::Eigenfield_basis> basis, int d,
                     const std::vector<CGAL::Tangent_vector_fields::Field_constraint>& constraints,
                     CGAL::Tangent_vector_fields::Refining_spline_solver& refining, std::vector<std::string>& rows);

/// The table of every mesh's rows, with its legend (nothing if `rows` is empty).
void print_preview_table(const std::vector<std::string>& rows);

} // namespace tvf_bench

#endif
