// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Benchmark of field design (issue 4), in the thesis' Table 1 set-up: a spectral basis
// (the first d of the lowest 2000 eigenfields; d = 1000 is the 500 + 500 of the thesis
// up to the exact/coexact split), 30 constraints (24 vectors, 3 divergences, 3 curls:
// 54 rows).  Per mesh and basis size d, side by side in one run:
//   reduced TVFS: set-up (solver + 30 constraints), value edit + solve, constraint add
//                 + solve, reconstruction of the full field (and its memory rate);
//   reduced soft: factor (solver + 30 constraints) and solve;
//   full soft:    factor and solve;   full TVFS: factor, pull-backs, solve;
// and the error of the reduced TVFS against the full one: relative L2(MX) error,
// median angle between face vectors, constraint residual, energy ratio (also for a smooth
// constraint set, with and without its constraints near a boundary).  Then exact answers:
// the timeline of one constraint add with Refining_spline_solver (reduced field ready,
// exact field ready, exact value edits), whose exact point ends each error-time curve.  And the
// editor's preview (issue 36): fur strokes of the reduced field traced through the faces they reach
// only (Reduced_face_vectors) against the whole reduced field and the same fur, with the strokes'
// difference (the same roots: identical up to rounding).
//
// Usage: bench_design [data-dir] [--meshes rocker,bunny,armadillo] [--sizes 50,100,...]
//                     [--cache DIR] (saves / loads bases there)
//                     [--chart FILE.svg] (error against time per edit, one curve per mesh and constraint set)
//                     [--default-allocator] (without Model_reduction::keep_freed_memory(), which the tvf tool calls)
//                     [--preview-only] (only the preview strokes against the whole reduced field, and the
//                     exact answers' timeline: the table of issue 36)
//        bench_design [data-dir] --write-meshes DIR [--meshes ...]: writes the benchmark meshes (DIR/<mesh>.off,
//                     as subdivided here) and their 30 table constraints (DIR/<mesh>-constraints.json) for
//                     `tvf serve` and bench/bench_editor.mjs, then stops.


#include "bench_meshes.h"
#include "design_preview.h"

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Full_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Reduced_face_vectors.h>
#include <CGAL/Tangent_vector_fields/Reduced_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Refining_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Soft_field_design.h>
#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>
#include <CGAL/Tangent_vector_fields/constraint_file_io.h>
#include <CGAL/Model_reduction/keep_freed_memory.h>
#include <CGAL/Model_reduction/svg_chart.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>

namespace TVF = CGAL::Tangent_vector_fields;
namespace MR = CGAL::Model_reduction;

namespace {

typedef std::chrono::steady_clock Clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct Source
{
  std::string key, file;
  int subdivisions;
};

std::shared_ptr<TVF::Hodge_solver> load(const std::string& dir, const Source& s, int& faces,
                                        const std::string& save_as = std::string())
{
  return tvf_bench::load_mesh(dir, s.file, s.subdivisions, faces, save_as);
}

// 24 unit tangent vectors in faces spread over the mesh, 3 divergences and 3 curls.
std::vector<TVF::Field_constraint> table_constraints(const TVF::Intrinsic_mesh& m, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI);
  std::uniform_int_distribution<int> face(0, m.number_of_faces() - 1);
  std::vector<TVF::Field_constraint> c;
  for(int i = 0; i < 24; ++i)
  {
    const int f = face(rng);
    const double t = angle(rng);
    c.push_back(TVF::Field_constraint::vector_in_face(f, m.from_frame(f, std::cos(t), std::sin(t))));
  }
  // Divergence and curl values of the size a unit field has over a tenth of the mesh.
  double area = 0;
  for(int f = 0; f < m.number_of_faces(); ++f) area += m.face_area(f);
  const double value = 10 / std::sqrt(area);
  for(int i = 0; i < 3; ++i)
  {
    c.push_back(TVF::Field_constraint::divergence_at_point(face(rng), {{0.2, 0.3, 0.5}}, i == 1 ? -value : value));
    c.push_back(TVF::Field_constraint::curl_at_point(face(rng), {{0.5, 0.25, 0.25}}, i == 2 ? -value : value));
  }
  return c;
}

// 30 vector constraints sampled from a smooth field: a rotation about an axis through
// the centroid plus a constant, projected onto the faces.
std::vector<TVF::Field_constraint> smooth_constraints(const TVF::Intrinsic_mesh& m, unsigned seed)
{
  std::array<double, 3> c{{0, 0, 0}};
  for(int v = 0; v < m.number_of_vertices(); ++v)
    for(int k = 0; k < 3; ++k) c[k] += m.position(v)[k] / m.number_of_vertices();
  double radius = 0;
  for(int v = 0; v < m.number_of_vertices(); ++v)
    radius = std::max(radius, std::hypot(m.position(v)[0] - c[0], m.position(v)[1] - c[1], m.position(v)[2] - c[2]));
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> face(0, m.number_of_faces() - 1);
  std::vector<TVF::Field_constraint> out;
  while(out.size() < 30)
  {
    const int f = face(rng);
    std::array<double, 3> p{{0, 0, 0}};
    for(int k = 0; k < 3; ++k)
      for(int i = 0; i < 3; ++i) p[i] += (m.position(m.face_vertices(f)[k])[i] - c[i]) / 3 / radius;
    // (0.3, 1, 0.2) x p + (0.5, 0.2, 0.1)
    const std::array<double, 3> v{{1 * p[2] - 0.2 * p[1] + 0.5, 0.2 * p[0] - 0.3 * p[2] + 0.2, 0.3 * p[1] - 1 * p[0] + 0.1}};
    const std::array<double, 2> a = m.to_frame(f, v);
    if(std::hypot(a[0], a[1]) < 0.05) continue; // nearly normal to the face
    out.push_back(TVF::Field_constraint::vector_in_face(f, v));
  }
  return out;
}

// The constraints whose face centroid is farther than `distance` from every boundary edge.
std::vector<TVF::Field_constraint> away_from_boundary(const TVF::Intrinsic_mesh& m,
                                                      const std::vector<TVF::Field_constraint>& constraints,
                                                      double distance)
{
  auto midpoint = [&](int a, int b, int k) { return 0.5 * (m.position(a)[k] + m.position(b)[k]); };
  std::vector<std::array<double, 3>> boundary;
  for(int e = 0; e < m.number_of_edges(); ++e)
    if(m.is_boundary_edge(e))
    {
      const auto& v = m.edge_vertices(e);
      boundary.push_back({{midpoint(v[0], v[1], 0), midpoint(v[0], v[1], 1), midpoint(v[0], v[1], 2)}});
    }
  std::vector<TVF::Field_constraint> out;
  for(const auto& c : constraints)
  {
    std::array<double, 3> p{{0, 0, 0}};
    for(int k = 0; k < 3; ++k)
      for(int i = 0; i < 3; ++i) p[i] += m.position(m.face_vertices(c.face)[k])[i] / 3;
    double nearest = HUGE_VAL;
    for(const auto& b : boundary) nearest = std::min(nearest, std::hypot(p[0] - b[0], p[1] - b[1], p[2] - b[2]));
    if(nearest > distance) out.push_back(c);
  }
  return out;
}

double relative_mx_error(const Eigen::VectorXd& masses, const Eigen::VectorXd& x, const Eigen::VectorXd& ref)
{
  const Eigen::VectorXd d = x - ref;
  return std::sqrt(d.dot(masses.cwiseProduct(d)) / ref.dot(masses.cwiseProduct(ref)));
}

double median_angle_degrees(const Eigen::VectorXd& x, const Eigen::VectorXd& ref)
{
  std::vector<double> angles(x.size() / 2);
  for(std::size_t f = 0; f < angles.size(); ++f)
  {
    const double a = std::atan2(x[2 * f + 1], x[2 * f]) - std::atan2(ref[2 * f + 1], ref[2 * f]);
    angles[f] = std::abs(std::remainder(a, 2 * M_PI)) * 180 / M_PI;
  }
  std::nth_element(angles.begin(), angles.begin() + angles.size() / 2, angles.end());
  return angles[angles.size() / 2];
}

double median_of(std::vector<double> v)
{
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

std::vector<int> parse_list(const std::string& s)
{
  std::vector<int> v;
  std::stringstream in(s);
  std::string item;
  while(std::getline(in, item, ',')) v.push_back(std::atoi(item.c_str()));
  return v;
}

} // namespace

int main(int argc, char** argv)
{
  std::string dir = TVF_SHARED_DATA_DIR, which = "rocker,bunny,armadillo", cache, chart_file, write_dir;
  MR::Line_chart chart;
  chart.title = "TVFS: error against the full spline vs. time of a constraint add (d = 100 ... 2000; last point: exact)";
  chart.x_label = "constraint add + solve [s]";
  chart.y_label = "relative L2(MX) error vs full";
  std::vector<int> sizes = {50, 100, 200, 500, 1000, 2000};
  bool default_allocator = false, preview_only = false;
  std::vector<std::string> preview_rows;
  for(int i = 1; i < argc; ++i)
  {
    if(!std::strcmp(argv[i], "--meshes") && i + 1 < argc) which = argv[++i];
    else if(!std::strcmp(argv[i], "--sizes") && i + 1 < argc) sizes = parse_list(argv[++i]);
    else if(!std::strcmp(argv[i], "--cache") && i + 1 < argc) cache = argv[++i];
    else if(!std::strcmp(argv[i], "--chart") && i + 1 < argc) chart_file = argv[++i];
    else if(!std::strcmp(argv[i], "--write-meshes") && i + 1 < argc) write_dir = argv[++i];
    else if(!std::strcmp(argv[i], "--default-allocator")) default_allocator = true;
    else if(!std::strcmp(argv[i], "--preview-only")) preview_only = true;
    else dir = argv[i];
  }
  // As the tvf tool does (Model_reduction::keep_freed_memory.h); --default-allocator measures without it.
  if(!default_allocator) MR::keep_freed_memory();
  const int largest = *std::max_element(sizes.begin(), sizes.end());
  const std::vector<Source> sources = {
      {"rocker", "rocker-arm.obj", 0}, {"bunny", "stanford-bunny.obj", 0}, {"armadillo", "armadillo.obj", 1}};
  std::printf("Field design, 30 constraints (24 vectors, 3 divergences, 3 curls = 54 rows), omega = 0 (TVFS)\n"
              "and omega = 0 (soft, Dirichlet energy), unit soft weights.  Times in milliseconds unless marked.\n\n");
  for(const Source& s : sources)
  {
    if(which.find(s.key) == std::string::npos) continue;
    int faces = 0;
    auto hodge = load(dir, s, faces, write_dir.empty() ? std::string() : write_dir + "/" + s.key + ".off");
    if(!hodge) continue;
    if(!write_dir.empty())
    {
      TVF::Constraint_file file;
      file.constraints = table_constraints(hodge->operators().mesh(), 7);
      std::ofstream out(write_dir + "/" + s.key + "-constraints.json");
      TVF::write_constraint_file(out, file, hodge->operators().mesh());
      std::printf("wrote %s/%s.off (%d faces) and %s-constraints.json\n", write_dir.c_str(), s.key.c_str(), faces, s.key.c_str());
      continue;
    }
    const TVF::Operator_matrices& ops = hodge->operators();
    const Eigen::VectorXd& masses = ops.field_masses();
    // Basis: computed or loaded.
    auto start = Clock::now();
    std::shared_ptr<TVF::Eigenfield_basis> basis;
    const std::string path = cache.empty() ? std::string() : cache + "/" + s.key + "-lowest" + std::to_string(largest) + ".tvfb";
    bool loaded = false;
    if(!path.empty() && std::ifstream(path).good())
    {
      try
      {
        basis = std::make_shared<TVF::Eigenfield_basis>(TVF::Eigenfield_basis::load(hodge, path));
        loaded = basis->size() >= largest;
      }
      catch(const std::exception& e)
      {
        std::cerr << "cache not used: " << e.what() << "\n";
      }
    }
    if(!loaded)
    {
      basis = std::make_shared<TVF::Eigenfield_basis>(hodge, TVF::Basis_request::lowest(largest));
      if(!path.empty()) basis->save(path);
    }
    const double basis_seconds = seconds_since(start);
    // Reduced fields in double, kept to measure what float32 eigenfunctions add (at the end).
    struct Double_reconstruction
    {
      int d;
      double seconds, bytes, reduction_error;
      Eigen::VectorXd field;
    };
    const auto constraints = table_constraints(ops.mesh(), 7);
    const auto smooth = smooth_constraints(ops.mesh(), 5);
    const TVF::Field_constraint extra =
        TVF::Field_constraint::vector_in_face(faces / 2, ops.mesh().from_frame(faces / 2, 0.6, -0.8));

    // Full-resolution references.
    start = Clock::now();
    TVF::Full_spline_solver full(hodge);
    full.add(constraints);
    const Eigen::VectorXd full_field = full.field();
    const double full_total = seconds_since(start);
    start = Clock::now();
    full.add(extra);
    full.field();
    const double full_add = seconds_since(start);
    full.remove(full.constraint_ids().back());
    start = Clock::now();
    auto edited = constraints[0];
    edited.vector = ops.mesh().from_frame(edited.face, 0.0, 1.0);
    full.change(full.constraint_ids().front(), edited);
    full.field();
    const double full_edit = seconds_since(start);
    full.change(full.constraint_ids().front(), constraints[0]);
    std::vector<Double_reconstruction> double_reconstructions;
    MR::Chart_series random_series{s.key + ", random set", {}, {}}, smooth_series{s.key + ", smooth set", {}, {}};
    if(preview_only)
      std::printf("== %s: %d faces, %d harmonic fields; basis of %d: %.1f s (%s)\n", s.key.c_str(), faces,
                  hodge->harmonic_dimension(), basis->size(), basis_seconds, loaded ? "loaded" : "computed");
    if(!preview_only) // the table of every d
    {
      start = Clock::now();
      TVF::Full_soft_design full_soft(hodge);
      for(const auto& c : constraints) full_soft.add(c);
      full_soft.field();
      const double full_soft_total = seconds_since(start);
      start = Clock::now();
      const int soft_extra = full_soft.add(extra);
      full_soft.field();
      const double full_soft_add = seconds_since(start);
      full_soft.remove(soft_extra);
      TVF::Full_spline_solver full_smooth(hodge);
      full_smooth.add(smooth);
      const Eigen::VectorXd full_smooth_field = full_smooth.field();
      // The smooth set without the constraints near a boundary (within 2% of the diagonal):
      // the eigenfields are tangent to the boundary, so a constraint crossing it close by is
      // met only through eigenfields far above any affordable d.
      const auto smooth_away = away_from_boundary(ops.mesh(), smooth, 0.02 * tvf_bench::bounding_box_diagonal(ops.mesh()));
      TVF::Full_spline_solver full_away(hodge);
      full_away.add(smooth_away);
      const Eigen::VectorXd full_away_field = full_away.field();

      std::printf("== %s: %d faces, %d harmonic fields; basis of %d: %.1f s (%s)\n", s.key.c_str(), faces,
                  hodge->harmonic_dimension(), basis->size(), basis_seconds, loaded ? "loaded" : "computed");
      std::printf("full TVFS: factor %.2f s (W, W* shared with the basis computation), 54 pull-backs %.2f s"
                  " (second-order residual %.1e), total %.2f s; add 1 constraint %.3f s; value edit %.1f ms\n",
                  full.statistics().factor_seconds, full.statistics().pull_back_seconds, full.statistics().residual,
                  full_total, full_add, 1e3 * full_edit);
      std::printf("full soft: factor %.2f s (W, W*), 54 pull-backs %.2f s, solve %.3f s, total %.2f s (second-order"
                  " residual %.1e); add 1 constraint %.3f s\n\n",
                  full_soft.factor_seconds(), full_soft.pull_back_seconds(), full_soft.solve_seconds(), full_soft_total,
                  full_soft.residual(), full_soft_add);
      std::printf("%6s | %9s %9s %9s %9s %8s | %9s %9s | %9s %8s %9s %9s %9s | %9s\n", "d", "setup", "edit", "add",
                  "reconstr", "GB/s", "soft fac", "soft sol", "rel L2", "med deg", "c. resid", "E ratio", "speed-up",
                  "full/red");
      std::vector<std::string> smooth_rows;
      for(int d : sizes)
      {
        if(d > basis->size()) continue;
        start = Clock::now();
        TVF::Reduced_spline_solver reduced(basis, d);
        try
        {
          reduced.add(constraints);
        }
        catch(const TVF::Infeasible_constraints& e)
        {
          std::printf("%6d | refused: %s\n", d, e.what());
          continue;
        }
        reduced.coefficients();
        const double setup = seconds_since(start);
        // Value edits: alternate two values of the first vector constraint.
        const int edits = 200;
        auto a = constraints[0], b = constraints[0];
        b.vector = ops.mesh().from_frame(b.face, 0.0, 1.0);
        const TVF::Constraint_id first = reduced.constraint_ids().front();
        start = Clock::now();
        for(int i = 0; i < edits; ++i)
        {
          reduced.change(first, i % 2 ? a : b);
          reduced.coefficients();
        }
        const double edit = seconds_since(start) / edits;
        reduced.change(first, a);
        // Constraint add + solve, then remove (not timed).
        const int adds = 20;
        double add = 0;
        for(int i = 0; i < adds; ++i)
        {
          start = Clock::now();
          const TVF::Constraint_id id = reduced.add(extra);
          reduced.coefficients();
          add += seconds_since(start);
          reduced.remove(id);
        }
        add /= adds;
        reduced.coefficients();
        // Reconstruction of the full field (two dense and two sparse products).
        start = Clock::now();
        const Eigen::VectorXd field = reduced.field();
        const double reconstruction = seconds_since(start);
        int exact = 0, coexact = 0;
        for(int k = 0; k < d; ++k)
          (basis->type(k) == TVF::Eigenfield_type::exact ? exact : coexact) += basis->type(k) != TVF::Eigenfield_type::harmonic;
        const double bytes = 8.0 * (double(exact) * ops.mesh().number_of_vertices() +
                                    double(coexact) * ops.mesh().number_of_interior_edges());
        // Reduced soft design.
        start = Clock::now();
        TVF::Reduced_soft_design soft(basis, d);
        for(const auto& c : constraints) soft.add(c);
        const double soft_factor = seconds_since(start);
        soft.coefficients();
        start = Clock::now();
        for(int i = 0; i < edits; ++i)
        {
          soft.change(0, i % 2 ? a : b);
          soft.coefficients();
        }
        const double soft_solve = seconds_since(start) / edits;
        // Errors against the full spline.
        const double error = relative_mx_error(masses, field, full_field);
        double_reconstructions.push_back({d, reconstruction, bytes, error, field});
        const double angle = median_angle_degrees(field, full_field);
        const double ratio = reduced.report().energy / full.report().energy;
        random_series.x.push_back(add);
        random_series.y.push_back(error);
        std::printf("%6d | %9.3f %9.4f %9.3f %9.2f %8.2f | %9.2f %9.4f | %9.2e %8.3f %9.1e %9.4f %9.0f | %9.0f\n", d,
                    1e3 * setup, 1e3 * edit, 1e3 * add, 1e3 * reconstruction, bytes / reconstruction / 1e9,
                    1e3 * soft_factor, 1e3 * soft_solve, error, angle, reduced.report().constraint_residual, ratio,
                    full_add / add, full_total / setup);
        std::fflush(stdout);
        // The smooth constraint set: errors only.
        TVF::Reduced_spline_solver reduced_smooth(basis, d);
        try
        {
          reduced_smooth.add(smooth);
          const Eigen::VectorXd x = reduced_smooth.field();
          smooth_series.x.push_back(add); // the add time measured on the random set at this d
          smooth_series.y.push_back(relative_mx_error(masses, x, full_smooth_field));
          TVF::Reduced_spline_solver reduced_away(basis, d);
          reduced_away.add(smooth_away);
          char line[256];
          std::snprintf(line, sizeof line, "%6d | %9.2e %8.3f %9.1e %9.4f | %9.2e\n", d,
                        relative_mx_error(masses, x, full_smooth_field), median_angle_degrees(x, full_smooth_field),
                        reduced_smooth.report().constraint_residual,
                        reduced_smooth.report().energy / full_smooth.report().energy,
                        relative_mx_error(masses, reduced_away.field(), full_away_field));
          smooth_rows.push_back(line);
        }
        catch(const TVF::Infeasible_constraints&)
        {
          smooth_rows.push_back(std::to_string(d) + " | refused (basis too small)\n");
        }
      }
      std::printf("\nsmooth constraint set (30 vectors from a smooth ambient field), reduced TVFS against full;\n"
                  "away: the %d of them farther than 2%% of the bounding-box diagonal from every boundary edge:\n"
                  "%6s | %9s %8s %9s %9s | %9s\n", static_cast<int>(smooth_away.size()), "d", "rel L2", "med deg", "c. resid",
                  "E ratio", "away");
      for(const std::string& line : smooth_rows) std::printf("%s", line.c_str());
    }

    // Exact answers: the timeline of one vector constraint added to the 30 with a basis of
    // d = 1000 (or the largest below) and the full solver refining it (Refining_spline_solver).
    int dt = 0;
    for(int d : sizes)
      if(d <= std::min(1000, basis->size())) dt = std::max(dt, d);
    if(dt > 0)
    {
      TVF::Refining_spline_solver refining(std::make_unique<TVF::Reduced_spline_solver>(basis, dt),
                                           std::make_unique<TVF::Full_spline_solver>(hodge));
      refining.add(constraints);
      refining.refine();
      refining.field();
      std::vector<double> reduced_ready, exact_ready, edit_exact, drag_exact;
      double exact_error = 0;
      bool all_exact = true;
      for(int i = 0; i < 5; ++i)
      {
        const int f = (faces / 2 + 7919 * i) % faces;
        auto c = TVF::Field_constraint::vector_in_face(f, ops.mesh().from_frame(f, 0.6, -0.8));
        start = Clock::now();
        const TVF::Constraint_id id = refining.add(c);
        refining.field();
        reduced_ready.push_back(seconds_since(start));
        refining.refine();
        const Eigen::VectorXd exact_field = refining.field();
        exact_ready.push_back(seconds_since(start));
        if(i == 0) // against the one-shot full spline of the 31 constraints
        {
          full.add(c);
          exact_error = relative_mx_error(masses, exact_field, full.field());
          full.remove(full.constraint_ids().back());
        }
        c.vector = ops.mesh().from_frame(f, -0.8, 0.6);
        start = Clock::now();
        refining.change(id, c);
        refining.field();
        edit_exact.push_back(seconds_since(start));
        refining.field_after_value_edit(id); // the responses to this constraint's values, once
        start = Clock::now();
        for(int k = 0; k < 10; ++k)
        {
          c.vector = ops.mesh().from_frame(f, std::cos(k), std::sin(k));
          refining.change(id, c);
          refining.field_after_value_edit(id);
        }
        drag_exact.push_back(seconds_since(start) / 10);
        all_exact = all_exact && refining.is_exact();
        refining.remove(id);
      }
      // As tvf serve does it: the worker thread pulls each new constraint back while this
      // thread makes the first answer (soonest_field: the exact one if the worker is expected
      // to be quicker than the reduced field, else the reduced one); then the exact field.
      std::vector<double> background_first, background_exact;
      int exact_first = 0;
      refining.refine_in_background();
      for(int i = 0; i < 6; ++i)
      {
        const int f = (faces / 3 + 7919 * i) % faces;
        const auto c = TVF::Field_constraint::vector_in_face(f, ops.mesh().from_frame(f, 0.6, -0.8));
        start = Clock::now();
        const TVF::Constraint_id id = refining.add(c);
        TVF::Spline_answer first;
        refining.soonest_field(&first);
        const double first_seconds = seconds_since(start);
        if(!first.exact)
        {
          all_exact = refining.wait_until_exact(std::chrono::minutes(10)) && all_exact;
          refining.field();
        }
        if(i > 0) // the first add measures the times soonest_field decides by
        {
          background_first.push_back(first_seconds);
          background_exact.push_back(seconds_since(start));
          exact_first += first.exact;
        }
        refining.remove(id);
      }
      // The editor's answer to an add when its fur is previewed (issue 36).
      tvf_bench::measure_preview(s.key, ops, basis, dt, constraints, refining, preview_rows);
      refining.stop_background();
      auto median = [](std::vector<double> v) {
        std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
        return v[v.size() / 2];
      };
      std::printf("\nexact answers, one vector constraint added to the 30 (reduced d = %d refined by the full solver;"
                  " medians of 5 adds):\n  reduced field ready %.2f ms | exact field ready %.1f ms (error against the"
                  " one-shot full spline %.1e) | value edit, exact: %.1f ms (field), %.2f ms per drag step"
                  " (field_after_value_edit)%s\n",
                  dt, 1e3 * median(reduced_ready), 1e3 * median(exact_ready), exact_error, 1e3 * median(edit_exact),
                  1e3 * median(drag_exact), all_exact ? "" : "  [NOT EXACT after the edits]");
      std::printf("  the same with the pull-back on a worker thread (as tvf serve): first answer ready %.2f ms (exact in %d"
                  " of 5) | exact field ready %.1f ms\n",
                  1e3 * median(background_first), exact_first, 1e3 * median(background_exact));
      random_series.x.push_back(median(exact_ready)); // the curve's exact endpoint
      random_series.y.push_back(exact_error);
    }
    if(preview_only)
      continue;
    const double double_bytes = static_cast<double>(basis->memory_bytes());
    basis->set_precision(TVF::Eigenfunction_precision::float32);
    std::printf("\nreconstruction of the reduced field with eigenfunctions in double and in float32 (%.2f GB and %.2f GB);\n"
                "f32 error: float32 against double reconstruction; reduction error: double against the full spline:\n"
                "%6s | %9s %8s | %9s %8s | %9s | %9s\n", double_bytes / 1e9, basis->memory_bytes() / 1e9, "d", "f64 ms",
                "GB/s", "f32 ms", "GB/s", "f32 error", "reduction");
    for(const Double_reconstruction& r : double_reconstructions)
    {
      TVF::Reduced_spline_solver reduced32(basis, r.d);
      reduced32.add(constraints);
      reduced32.coefficients();
      start = Clock::now();
      const Eigen::VectorXd field32 = reduced32.field();
      const double seconds32 = seconds_since(start);
      std::printf("%6d | %9.2f %8.2f | %9.2f %8.2f | %9.1e | %9.2e\n", r.d, 1e3 * r.seconds, r.bytes / r.seconds / 1e9,
                  1e3 * seconds32, r.bytes / 2 / seconds32 / 1e9, relative_mx_error(masses, field32, r.field),
                  r.reduction_error);
    }
    chart.series.push_back(random_series);
    chart.series.push_back(smooth_series);
    std::printf("speed-up = full TVFS constraint add (1 pull-back with the factor kept) / reduced constraint add;\n"
                "full/red = full TVFS from scratch (factor + 54 pull-backs) / reduced set-up.\n\n");
  }
  tvf_bench::print_preview_table(preview_rows);
  if(!chart_file.empty() && !chart.series.empty())
  {
    MR::write_svg_line_chart(chart_file, chart);
    std::printf("chart written to %s\n", chart_file.c_str());
  }
  return 0;
}
