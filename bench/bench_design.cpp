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
// median angle between face vectors, constraint residual, energy ratio.
//
// Usage: bench_design [data-dir] [--meshes rocker,bunny,armadillo] [--sizes 50,100,...]
//                     [--cache DIR] (saves / loads bases there)
//                     [--chart FILE.svg] (error against time per edit, one curve per mesh and constraint set)
//        bench_design [data-dir] --write-meshes DIR [--meshes ...]: writes the benchmark meshes (DIR/<mesh>.off,
//                     as subdivided here) and their 30 table constraints (DIR/<mesh>-constraints.json) for
//                     `tvf serve` and bench/bench_editor.mjs, then stops.


#include "bench_meshes.h"

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Full_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Reduced_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Soft_field_design.h>
#include <CGAL/Tangent_vector_fields/constraint_file_io.h>
#include <CGAL/Tangent_vector_fields/svg_chart.h>

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
  TVF::Line_chart chart;
  chart.title = "Reduced TVFS: error against the full spline vs. time of a constraint add (d = 100 ... 2000)";
  chart.x_label = "constraint add + solve [s]";
  chart.y_label = "relative L2(MX) error vs full";
  std::vector<int> sizes = {50, 100, 200, 500, 1000, 2000};
  for(int i = 1; i < argc; ++i)
  {
    if(!std::strcmp(argv[i], "--meshes") && i + 1 < argc) which = argv[++i];
    else if(!std::strcmp(argv[i], "--sizes") && i + 1 < argc) sizes = parse_list(argv[++i]);
    else if(!std::strcmp(argv[i], "--cache") && i + 1 < argc) cache = argv[++i];
    else if(!std::strcmp(argv[i], "--chart") && i + 1 < argc) chart_file = argv[++i];
    else if(!std::strcmp(argv[i], "--write-meshes") && i + 1 < argc) write_dir = argv[++i];
    else dir = argv[i];
  }
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
    start = Clock::now();
    TVF::Full_soft_design full_soft(hodge);
    for(const auto& c : constraints) full_soft.add(c);
    full_soft.field();
    const double full_soft_total = seconds_since(start);
    TVF::Full_spline_solver full_smooth(hodge);
    full_smooth.add(smooth);
    const Eigen::VectorXd full_smooth_field = full_smooth.field();

    std::printf("== %s: %d faces, %d harmonic fields; basis of %d: %.1f s (%s)\n", s.key.c_str(), faces,
                hodge->harmonic_dimension(), basis->size(), basis_seconds, loaded ? "loaded" : "computed");
    std::printf("full TVFS: factor %.2f s (W, W* shared with the basis computation), 54 pull-backs %.2f s"
                " (second-order residual %.1e), total %.2f s; add 1 constraint %.3f s; value edit %.1f ms\n",
                full.statistics().factor_seconds, full.statistics().pull_back_seconds, full.statistics().residual,
                full_total, full_add, 1e3 * full_edit);
    std::printf("full soft: factor %.2f s (W, W*), 54 pull-backs %.2f s, solve %.3f s, total %.2f s (second-order residual %.1e)\n\n",
                full_soft.factor_seconds(), full_soft.pull_back_seconds(), full_soft.solve_seconds(), full_soft_total,
                full_soft.residual());
    std::printf("%6s | %9s %9s %9s %9s %8s | %9s %9s | %9s %8s %9s %9s %9s | %9s\n", "d", "setup", "edit", "add",
                "reconstr", "GB/s", "soft fac", "soft sol", "rel L2", "med deg", "c. resid", "E ratio", "speed-up",
                "full/red");
    std::vector<std::string> smooth_rows;
    TVF::Chart_series random_series{s.key + ", random set", {}, {}}, smooth_series{s.key + ", smooth set", {}, {}};
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
        char line[256];
        std::snprintf(line, sizeof line, "%6d | %9.2e %8.3f %9.1e %9.4f\n", d, relative_mx_error(masses, x, full_smooth_field),
                      median_angle_degrees(x, full_smooth_field), reduced_smooth.report().constraint_residual,
                      reduced_smooth.report().energy / full_smooth.report().energy);
        smooth_rows.push_back(line);
      }
      catch(const TVF::Infeasible_constraints&)
      {
        smooth_rows.push_back(std::to_string(d) + " | refused (basis too small)\n");
      }
    }
    std::printf("\nsmooth constraint set (30 vectors from a smooth ambient field), reduced TVFS against full:\n"
                "%6s | %9s %8s %9s %9s\n", "d", "rel L2", "med deg", "c. resid", "E ratio");
    for(const std::string& line : smooth_rows) std::printf("%s", line.c_str());
    chart.series.push_back(random_series);
    chart.series.push_back(smooth_series);
    std::printf("speed-up = full TVFS constraint add (1 pull-back with the factor kept) / reduced constraint add;\n"
                "full/red = full TVFS from scratch (factor + 54 pull-backs) / reduced set-up.\n\n");
  }
  if(!chart_file.empty() && !chart.series.empty())
  {
    TVF::write_svg_line_chart(chart_file, chart);
    std::printf("chart written to %s\n", chart_file.c_str());
  }
  return 0;
}
