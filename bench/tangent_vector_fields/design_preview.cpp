// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The editor's preview (issue 36): the fur of the reduced field of the 30 constraints, traced
// through the faces it reaches only, against the whole reduced field and the same fur; with
// eigenfunction rows in float32 (the editor's) and, where they fit, in double; on one thread and
// on every core, alternated in one run.

#include "design_preview.h"

#include <CGAL/Tangent_vector_fields/Reduced_face_vectors.h>
#include <CGAL/Tangent_vector_fields/Reduced_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>
#include <CGAL/Model_reduction/internal/Thread_pool.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace TVF = CGAL::Tangent_vector_fields;

namespace tvf_bench {

namespace {

typedef std::chrono::steady_clock Clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

double median_of(std::vector<double> v)
{
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// The editor's fur (Display_settings' defaults, as Field_design::lines draws it).
TVF::Fur_options editor_fur(int threads)
{
  TVF::Fur_options fur;
  fur.number_of_strokes = 4000;
  fur.length = 0.02;
  fur.scale_length_by_magnitude = true;
  fur.magnitude_reference = TVF::Fur_options::Magnitude_reference::roots;
  fur.threads = threads;
  return fur;
}

// The preview's strokes against those of the whole field: the largest distance between
// corresponding points (relative to the diagonal) and the strokes whose point or face lists
// differ (a different walk, not only rounding).
struct Stroke_difference
{
  double largest = 0;
  int differing = 0;
  bool same_count = true;
};

Stroke_difference compare_strokes(const std::vector<TVF::Streamline>& a, const std::vector<TVF::Streamline>& b,
                                  double diagonal)
{
  Stroke_difference d;
  d.same_count = a.size() == b.size();
  for(std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
  {
    if(a[i].points.size() != b[i].points.size() || a[i].faces != b[i].faces)
    {
      ++d.differing;
      continue;
    }
    for(std::size_t j = 0; j < a[i].points.size(); ++j)
    {
      const auto& p = a[i].points[j];
      const auto& q = b[i].points[j];
      d.largest = std::max(d.largest, std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]) / diagonal);
    }
  }
  return d;
}

// `tvf serve`'s answer to an add with exact answers on and fur shown: the preview's strokes, then
// `soonest_field` worth waiting 0.5 s (the exact field if the worker has it by then, else the
// reduced one and the exact one later).
void editor_answer(const TVF::Operator_matrices& ops, const TVF::Streamline_surface& surface,
                   std::shared_ptr<const TVF::Eigenfield_rows> rows, TVF::Refining_spline_solver& refining)
{
  const int faces = ops.mesh().number_of_faces();
  const auto source = std::make_shared<TVF::Reduced_face_vectors>(rows);
  std::vector<double> strokes_ready, exact_ready;
  int exact_first = 0, runs = 0;
  for(int i = 0; i < 6; ++i)
  {
    const int f = (faces / 5 + 7919 * i) % faces;
    const auto c = TVF::Field_constraint::vector_in_face(f, ops.mesh().from_frame(f, -0.6, 0.8));
    const Clock::time_point start = Clock::now();
    const TVF::Constraint_id id = refining.add(c);
    source->set_coefficients(refining.reduced().coefficients());
    const std::vector<TVF::Streamline> strokes = TVF::Streamline_tracer(surface, source).fur(editor_fur(0));
    const double strokes_seconds = seconds_since(start);
    TVF::Spline_answer first;
    refining.soonest_field(&first, 0.5);
    if(!first.exact)
    {
      refining.wait_until_exact(std::chrono::minutes(10));
      refining.field();
    }
    const double exact_seconds = seconds_since(start);
    if(i > 0) // the first add measures the pull-back time soonest_field decides by
    {
      strokes_ready.push_back(strokes_seconds);
      exact_ready.push_back(exact_seconds);
      exact_first += first.exact;
      ++runs;
    }
    refining.remove(id);
  }
  std::printf("\nthe editor's answer to an add, fur previewed, exact answers on (tvf serve: the preview's strokes,\n"
              "then the exact field if the worker has it within 0.5 s, not the whole reduced field; medians of %d\n"
              "adds): strokes ready %.1f ms | exact field ready %.1f ms (the first field exact in %d of %d)\n",
              runs, 1e3 * median_of(strokes_ready), 1e3 * median_of(exact_ready), exact_first, runs);
}

} // namespace

double bounding_box_diagonal(const TVF::Intrinsic_mesh& m)
{
  std::array<double, 3> lo{{HUGE_VAL, HUGE_VAL, HUGE_VAL}}, hi{{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}};
  for(int v = 0; v < m.number_of_vertices(); ++v)
    for(int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], m.position(v)[k]), hi[k] = std::max(hi[k], m.position(v)[k]);
  return std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

void measure_preview(const std::string& mesh_key, const TVF::Operator_matrices& ops,
                     std::shared_ptr<const TVF::Eigenfield_basis> basis, int d,
                     const std::vector<TVF::Field_constraint>& constraints, TVF::Refining_spline_solver& refining,
                     std::vector<std::string>& rows)
{
  const int faces = ops.mesh().number_of_faces();
  TVF::Reduced_spline_solver reduced(basis, d);
  reduced.add(constraints);
  Clock::time_point start = Clock::now();
  const TVF::Streamline_surface surface(ops.shared_mesh());
  const double surface_seconds = seconds_since(start);
  const double diagonal = bounding_box_diagonal(ops.mesh());
  // One thread, then every core (as the editor runs it).
  const int cores = CGAL::Model_reduction::internal::thread_count(0);
  const std::vector<int> thread_counts = cores > 1 ? std::vector<int>{1, cores} : std::vector<int>{1};
  const int runs = 5;
  std::vector<std::vector<double>> whole_field(thread_counts.size()), whole_lines(thread_counts.size());
  std::vector<TVF::Streamline> whole;
  for(int i = 0; i < runs; ++i)
    for(std::size_t c = 0; c < thread_counts.size(); ++c)
    {
      // As the editor's field message does it: the whole reduced field, then the fur on it.
      start = Clock::now();
      const Eigen::VectorXd x = reduced.field();
      whole_field[c].push_back(seconds_since(start));
      start = Clock::now();
      whole = TVF::Streamline_tracer(ops.shared_mesh(), x).fur(editor_fur(thread_counts[c]));
      whole_lines[c].push_back(seconds_since(start));
    }
  for(const TVF::Eigenfunction_precision precision :
      {TVF::Eigenfunction_precision::float32, TVF::Eigenfunction_precision::float64})
  {
    const bool single = precision == TVF::Eigenfunction_precision::float32;
    // Double rows only where they fit beside the basis (the armadillo's would be 5.5 GB).
    if(!single && 16.0 * faces * d > 2e9)
    {
      std::printf("\n(no double eigenfield rows for %s: %.1f GB)\n", mesh_key.c_str(), 16.0 * faces * d / 1e9);
      continue;
    }
    start = Clock::now();
    auto eigenfield_rows = std::make_shared<const TVF::Eigenfield_rows>(basis, d, precision);
    const double rows_seconds = seconds_since(start);
    std::vector<std::vector<double>> preview_lines(thread_counts.size());
    std::vector<std::vector<TVF::Streamline>> preview(thread_counts.size());
    std::vector<std::size_t> faces_read(thread_counts.size());
    // As the editor does: one source per basis size, given each edit's coefficients.
    const auto source = std::make_shared<TVF::Reduced_face_vectors>(eigenfield_rows);
    for(int i = 0; i < runs; ++i)
      for(std::size_t c = 0; c < thread_counts.size(); ++c)
      {
        start = Clock::now();
        source->set_coefficients(reduced.coefficients());
        preview[c] = TVF::Streamline_tracer(surface, source).fur(editor_fur(thread_counts[c]));
        preview_lines[c].push_back(seconds_since(start));
        faces_read[c] = source->faces_asked();
      }
    std::printf("\npreview strokes (d = %d; 4000 fur strokes of 0.02 diagonal scaled by the magnitude at the roots;"
                " medians of %d, thread counts alternated): eigenfield rows by face in %s, %.2f GB, made in %.2f s"
                " (once per d), streamline surface %.1f ms (once)\n",
                d, runs, single ? "float32" : "double", eigenfield_rows->bytes() / 1e9, rows_seconds,
                1e3 * surface_seconds);
    for(std::size_t c = 0; c < thread_counts.size(); ++c)
    {
      const Stroke_difference difference = compare_strokes(preview[c], whole, diagonal);
      const bool same = difference.same_count && difference.differing == 0 && difference.largest < 1e-6;
      char line[512];
      std::snprintf(line, sizeof line,
                    "%-9s %7d %4s %7d | %9.1f %9.1f %9.1f | %9.2f %7zu %5.1f%% | %7zu %7zu %9.1e %7d%s\n",
                    mesh_key.c_str(), faces, single ? "f32" : "f64", thread_counts[c], 1e3 * median_of(whole_field[c]),
                    1e3 * median_of(whole_lines[c]), 1e3 * (median_of(whole_field[c]) + median_of(whole_lines[c])),
                    1e3 * median_of(preview_lines[c]), faces_read[c], 100.0 * faces_read[c] / faces,
                    preview[c].size(), whole.size(), difference.largest, difference.differing,
                    same ? "  same strokes" : "  DIFFERENT");
      std::printf("%s", line);
      rows.push_back(line);
    }
    if(single) // the editor's rows
      editor_answer(ops, surface, eigenfield_rows, refining);
    eigenfield_rows.reset(); // before the next copy
  }
}

void print_preview_table(const std::vector<std::string>& rows)
{
  if(rows.empty()) return;
  std::printf("\nThe editor's preview (issue 36): whole = the reduced field U a of every face, then fur on it\n"
              "(as the field message); preview = the same fur through the faces it reaches, U_f a per face from\n"
              "the face's block of eigenfield rows (Eigenfield_rows, f32: float32 entries, the editor's; f64: double);\n"
              "threads: Fur_options::threads for both furs.  Same roots and lengths: the same strokes up to the\n"
              "rounding of the face vectors (distance: largest between corresponding points / diagonal; differ:\n"
              "strokes whose walks differ; each thread reads its strokes' faces, so a face may be read twice).\n"
              "Milliseconds.\n"
              "%-9s %7s %4s %7s | %9s %9s %9s | %9s %7s %6s | %7s %7s %9s %7s\n",
              "mesh", "faces", "rows", "threads", "whole U a", "fur", "total", "preview", "faces", "", "strokes",
              "(whole)", "distance", "differ");
  for(const std::string& line : rows) std::printf("%s", line.c_str());
}

} // namespace tvf_bench
