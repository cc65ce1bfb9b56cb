// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Benchmark of n-direction fields (issue 12).  Per mesh and n, side by side in one run:
//   smoothest field: operators, eigenpair, singularities (interior, boundary, Poincare-Hopf);
//   basis of L_n: set-up of the largest d, residual, inertia check;
//   full spline (m = 2, omega = 0, 30 unit vector constraints = 60 rows): factor + pull-backs + solve;
//   reduced spline per d: set-up (solver + 30 constraints), value edit + solve, constraint
//   add + solve, reconstruction, and its error against the full spline (relative L2 in MX,
//   median and 95th-percentile angle between the fields' nearest vectors, energy ratio).
//
// Usage: bench_n_fields [data-dir] [--meshes rocker,bunny,armadillo] [--n 2,4] [--sizes 100,300,1000]
//                       [--cache DIR] (saves / loads bases there) [--chart FILE.svg]
//                       [--smoothest-only] [--write-meshes DIR] (the meshes as OFF for side-by-side runs)

#include "bench_meshes.h"

#include <CGAL/Tangent_vector_fields/N_field_basis.h>
#include <CGAL/Tangent_vector_fields/N_field_singularities.h>
#include <CGAL/Tangent_vector_fields/N_field_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Smoothest_n_field_solver.h>
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

std::vector<int> parse_list(const char* s)
{
  std::vector<int> v;
  std::stringstream in(s);
  std::string item;
  while(std::getline(in, item, ',')) v.push_back(std::stoi(item));
  return v;
}

std::vector<TVF::N_field_constraint> table_constraints(const TVF::Intrinsic_mesh& m, int count, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI);
  std::uniform_int_distribution<int> face(0, m.number_of_faces() - 1);
  std::vector<TVF::N_field_constraint> c;
  for(int i = 0; i < count; ++i)
  {
    const int f = face(rng);
    const double t = angle(rng);
    c.push_back(TVF::N_field_constraint::vector_in_face(f, m.from_frame(f, std::cos(t), std::sin(t))));
  }
  return c;
}

double relative_error(const Eigen::VectorXd& a, const Eigen::VectorXd& b, const Eigen::VectorXd& mass)
{
  const Eigen::VectorXd d = a - b;
  return std::sqrt(d.dot(mass.cwiseProduct(d)) / b.dot(mass.cwiseProduct(b)));
}

// Angle (degrees) between the two n-fields' directions per face: arg of the powers over n.
std::vector<double> angles(const Eigen::VectorXd& a, const Eigen::VectorXd& b, int n)
{
  std::vector<double> out(a.size() / 2);
  for(std::size_t f = 0; f < out.size(); ++f)
  {
    const double d = std::atan2(a[2 * f + 1], a[2 * f]) - std::atan2(b[2 * f + 1], b[2 * f]);
    out[f] = std::abs(std::remainder(d, 2 * M_PI)) / n * 180 / M_PI;
  }
  std::sort(out.begin(), out.end());
  return out;
}

struct Singularity_count
{
  int interior = 0, boundary = 0, sum = 0;
};

Singularity_count count(const TVF::N_field_operators& ops, const Eigen::VectorXd& z)
{
  Singularity_count c;
  for(const auto& s : TVF::n_field_singularities(ops, z))
  {
    (s.on_boundary ? c.boundary : c.interior) += 1;
    c.sum += s.index;
  }
  return c;
}

} // namespace

int main(int argc, char** argv)
{
  std::string dir = TVF_SHARED_DATA_DIR, which = "rocker,bunny,armadillo", cache, chart_file, write_dir;
  std::vector<int> ns = {2, 4}, sizes = {100, 300, 1000};
  bool smoothest_only = false;
  for(int i = 1; i < argc; ++i)
  {
    if(!std::strcmp(argv[i], "--meshes") && i + 1 < argc) which = argv[++i];
    else if(!std::strcmp(argv[i], "--n") && i + 1 < argc) ns = parse_list(argv[++i]);
    else if(!std::strcmp(argv[i], "--sizes") && i + 1 < argc) sizes = parse_list(argv[++i]);
    else if(!std::strcmp(argv[i], "--cache") && i + 1 < argc) cache = argv[++i];
    else if(!std::strcmp(argv[i], "--chart") && i + 1 < argc) chart_file = argv[++i];
    else if(!std::strcmp(argv[i], "--write-meshes") && i + 1 < argc) write_dir = argv[++i];
    else if(!std::strcmp(argv[i], "--smoothest-only")) smoothest_only = true;
    else dir = argv[i];
  }
  const int largest = *std::max_element(sizes.begin(), sizes.end());
  const std::vector<std::pair<std::string, std::pair<std::string, int>>> sources = {
      {"rocker", {"rocker-arm.obj", 0}}, {"bunny", {"stanford-bunny.obj", 0}}, {"armadillo", {"armadillo.obj", 1}}};
  MR::Line_chart chart;
  chart.title = "Reduced n-field spline: error against the full spline vs. time of a constraint add";
  chart.x_label = "constraint add + solve [s]";
  chart.y_label = "relative L2(MX) error vs full";
  std::printf("n-fields: 30 unit vector constraints (60 rows), energy E_B (m = 2), omega = 0.  Times in ms unless marked.\n\n");
  for(const auto& [key, source] : sources)
  {
    if(which.find(key) == std::string::npos) continue;
    int faces = 0;
    auto hodge = tvf_bench::load_mesh(dir, source.first, source.second, faces,
                                      write_dir.empty() ? std::string() : write_dir + "/" + key + ".off");
    if(!hodge) continue;
    if(!write_dir.empty())
    {
      std::printf("wrote %s/%s.off (%d faces)\n", write_dir.c_str(), key.c_str(), faces);
      continue;
    }
    const std::shared_ptr<const TVF::Operator_matrices> matrices(hodge, &hodge->operators());
    const TVF::Intrinsic_mesh& mesh = matrices->mesh();
    int chi = 0;
    for(const auto& c : mesh.topology().components) chi += c.euler_characteristic();
    for(int n : ns)
    {
      // Smoothest field: everything built from scratch.
      auto start = Clock::now();
      auto ops = std::make_shared<const TVF::N_field_operators>(matrices, n);
      ops->complex_S(); // what the smoothest field uses
      ops->kernel();
      const double setup = seconds_since(start);
      start = Clock::now();
      const Eigen::VectorXd smoothest = TVF::smoothest_n_field(*ops);
      const double smoothest_seconds = seconds_since(start);
      const Singularity_count sc = count(*ops, smoothest);
      std::printf("== %s, n = %d: %d faces, chi = %d; operators %.3f s, smoothest field %.3f s: %d interior + %d boundary "
                  "singularities, sum of k = %d (n chi = %d)\n",
                  key.c_str(), n, faces, chi, setup, smoothest_seconds, sc.interior, sc.boundary, sc.sum, n * chi);
      std::fflush(stdout);
      if(smoothest_only) continue;

      start = Clock::now();
      std::shared_ptr<TVF::N_field_basis> basis;
      const std::string path =
          cache.empty() ? std::string() : cache + "/" + key + "-n" + std::to_string(n) + "-" + std::to_string(largest) + ".tvfn";
      bool loaded = false;
      if(!path.empty() && std::ifstream(path).good())
      {
        try
        {
          basis = std::make_shared<TVF::N_field_basis>(TVF::N_field_basis::load(ops, path));
          loaded = basis->size() >= largest;
        }
        catch(const std::exception& e)
        {
          std::cerr << "cache not used: " << e.what() << "\n";
        }
      }
      if(!loaded)
      {
        basis = std::make_shared<TVF::N_field_basis>(ops, largest);
        if(!path.empty()) basis->save(path);
      }
      const double basis_seconds = seconds_since(start);
      std::printf("basis of %d: %.1f s (%s; computed in %.1f s), max residual %.1e, inertia %d / expected %d\n",
                  basis->size(), basis_seconds, loaded ? "loaded" : "computed", basis->report().seconds,
                  basis->report().max_residual, basis->report().inertia, basis->report().expected);

      const auto constraints = table_constraints(mesh, 30, 7);
      const auto extra = table_constraints(mesh, 1, 11).front();
      start = Clock::now();
      TVF::Full_n_field_spline_solver full(ops);
      const double factor = seconds_since(start);
      start = Clock::now();
      full.add(constraints);
      const Eigen::VectorXd exact = full.field();
      const double pull = seconds_since(start);
      start = Clock::now();
      full.add(extra);
      full.field();
      const double full_add = seconds_since(start);
      full.remove(full.constraint_ids().back());
      const double exact_energy = ops->m_harmonic_energy(exact, 2);
      std::printf("full spline: factor %.2f s, 60 pull-backs + solve %.2f s, add 1 constraint %.3f s\n", factor, pull,
                  full_add);
      std::printf("%6s | %9s %9s %9s %9s | %9s %8s %8s %9s\n", "d", "setup", "edit", "add", "reconstr", "rel L2",
                  "med deg", "95% deg", "E ratio");
      MR::Chart_series series{key + ", n = " + std::to_string(n), {}, {}};
      std::vector<std::string> singularity_rows;
      for(int d : sizes)
      {
        if(d > basis->size()) continue;
        start = Clock::now();
        TVF::Reduced_n_field_spline_solver reduced(basis, d);
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
        const double setup_ms = 1e3 * seconds_since(start);
        // Value edits: turn the first constraint's vector, 200 times.
        const int edits = 200;
        const int id = reduced.constraint_ids().front();
        start = Clock::now();
        for(int e = 0; e < edits; ++e)
        {
          auto c = constraints[0];
          const double t = 0.01 * (e + 1);
          c.vector = mesh.from_frame(c.face, std::cos(t), std::sin(t));
          reduced.change(id, c);
          reduced.coefficients();
        }
        const double edit_ms = 1e3 * seconds_since(start) / edits;
        reduced.change(id, constraints[0]);
        // Adds: one constraint added and solved, then removed, 50 times.
        const int adds = 50;
        double add_ms = 0;
        for(int a = 0; a < adds; ++a)
        {
          start = Clock::now();
          const int added = reduced.add(extra);
          reduced.coefficients();
          add_ms += 1e3 * seconds_since(start) / adds;
          reduced.remove(added);
        }
        start = Clock::now();
        const Eigen::VectorXd z = reduced.field();
        const double reconstruct_ms = 1e3 * seconds_since(start);
        const double error = relative_error(z, exact, ops->masses());
        const std::vector<double> a = angles(z, exact, n);
        std::printf("%6d | %9.2f %9.4f %9.3f %9.1f | %9.2e %8.2f %8.2f %9.3f\n", d, setup_ms, edit_ms, add_ms,
                    reconstruct_ms, error, a[a.size() / 2], a[a.size() * 95 / 100],
                    ops->m_harmonic_energy(z, 2) / exact_energy);
        // A +1 singularity by one-ring relations at an interior vertex, with the 30 vectors:
        // accepted in this basis?  Its rows' independence and the index it gets.
        {
          int vertex = 0;
          while(vertex < mesh.number_of_vertices() && (ops->vertex_fan(vertex).faces.empty() || ops->vertex_fan(vertex).on_boundary))
            ++vertex;
          std::string outcome;
          try
          {
            const int id = reduced.add(TVF::N_field_constraint::singularity_at_vertex(vertex, 1));
            const std::vector<int> k = TVF::n_field_indices(*ops, reduced.field());
            std::ostringstream o;
            o << "accepted, smallest sin^2 " << reduced.report().smallest_independence << ", index " << k[vertex] << "/" << n;
            outcome = o.str();
            reduced.remove(id);
          }
          catch(const TVF::Infeasible_constraints& e)
          {
            std::ostringstream o;
            o << "refused as dependent (sin^2 " << e.independence() << ")";
            outcome = o.str();
          }
          singularity_rows.push_back("  d = " + std::to_string(d) + ": one-ring singularity +1/" + std::to_string(n) +
                                     " at vertex " + std::to_string(vertex) + ": " + outcome);
        }
        series.x.push_back(add_ms / 1e3);
        series.y.push_back(error);
        std::fflush(stdout);
      }
      chart.series.push_back(series);
      for(const std::string& row : singularity_rows) std::printf("%s\n", row.c_str());
      std::printf("\n");
    }
  }
  if(!chart_file.empty() && !chart.series.empty()) MR::write_svg_line_chart(chart_file, chart);
  return 0;
}
