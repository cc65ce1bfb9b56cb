// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Benchmark of Spline_approximation (issue 37): error against run time and against knot
// count per algorithm, on generated noisy planar curves.
//   1. cubic within an RMS bound: penalty decomposition, greedy removal, and least squares on
//      uniform knots (the fewest uniform knots reaching the same RMS error);
//   2. degree 1 within a max error: knots + 2 vertices against Douglas-Peucker at the same
//      max error (DP's error is the distance to the polyline, ours the distance at the sample's
//      parameter, which is never smaller: the comparison favours Douglas-Peucker);
//   3. the gap to the exact optimum where it is known: degree 1 by dynamic programming on a
//      grid of candidates, every degree by brute force on 14 candidates;
//   4. error against knot count along a sweep of lambda;
//   5. motion capture (bench_motion.cpp): a generated 21-joint walk and any BVH files given,
//      compressed within 0.1 to 2 degrees: stored-value ratio, knots, errors, seconds;
//   6. a jittery walk regularised (distance to the clean walk before and after);
//   7. degree 1 side by side with Douglas-Peucker and CGAL's Polyline_simplification_2 on glyph
//      contours, SVG paths and the noisy rose, every result measured with one independent error
//      (polyline_comparison.cpp).
//   8. degree 1: the fewest vertices within an RMS bound against the exact optimum (dynamic
//      programming on a grid of candidates), with and without knot relocation (optimum_gap.cpp).
//
// Usage: bench_spline_approximation [--sizes 1000,10000,...] [--rms 0.002] [--max-error 0.005]
//                                   [--noise 0.0005] [--sweep-size 2000] [--tables 1234]
//                                   [--algorithms penalty,greedy] [--coarse-start-above 4096]
//                                   [--motion-frames 4000]
//                                   [--motion-noise 0.02] [--motion-bounds 0.1,0.5,1,2]
//                                   [--bvh a.bvh,b.bvh] [--motion-algorithms greedy,penalty]
//                                   [--svg FILE] [--targets 0.001,0.005]
//                                   [--methods greedy,penalty,exact,dp,cgal,cgal-hybrid] [--help]

#include "bench_motion.h"

#include <CGAL/Spline_approximation/Spline_fit.h>

#include "optimum_gap.h"
#include "polyline_comparison.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace SA = CGAL::Spline_approximation;

namespace {

// A noisy rose-like planar curve (the fit_curve example's), n samples.
Eigen::MatrixXd curve(Eigen::Index n, double noise, unsigned seed = 1)
{
  std::mt19937 gen(seed);
  std::normal_distribution<double> g(0.0, noise);
  Eigen::MatrixXd P(n, 2);
  for(Eigen::Index j = 0; j < n; ++j) {
    const double s = 3.0 * double(j) / double(n - 1), r = std::cos(2 * s) + 0.2 * s;
    P(j, 0) = r * std::cos(s) + g(gen);
    P(j, 1) = r * std::sin(s) + g(gen);
  }
  return P;
}

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::size_t coarse_start_above = SA::Fit_options().coarse_start_above;
std::size_t relocate_knots_up_to = SA::Fit_options().relocate_knots_up_to;

SA::Fit_options options(int k, SA::Fit_algorithm a)
{
  SA::Fit_options o;
  o.coarse_start_above = coarse_start_above;
  o.relocate_knots_up_to = relocate_knots_up_to;
  o.degree = k;
  o.algorithm = a;
  return o;
}

// The fewest uniform knots whose least-squares cubic reaches the RMS bound (doubling, then
// bisection; the error is nearly monotone in the knot count).
std::pair<std::size_t, double> uniform_knots_for(const Eigen::MatrixXd& P, const Eigen::VectorXd& t, double rms)
{
  auto rms_of = [&](std::size_t g) {
    return SA::least_squares_spline(P, t, 3, Eigen::VectorXd::LinSpaced(Eigen::Index(g + 2), 0, 1).segment(1, Eigen::Index(g)))
        .rms_error;
  };
  std::size_t hi = 1;
  while(rms_of(hi) > rms && hi < std::size_t(P.rows()) / 2) hi *= 2;
  std::size_t lo = hi / 2;
  while(hi - lo > 1) {
    const std::size_t mid = (lo + hi) / 2;
    (rms_of(mid) <= rms ? hi : lo) = mid;
  }
  return {hi, rms_of(hi)};
}

std::vector<std::string> parse_list(const std::string& s)
{
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while(std::getline(in, item, ',')) out.push_back(item);
  return out;
}

std::vector<Eigen::Index> parse_sizes(const std::string& s)
{
  std::vector<Eigen::Index> out;
  std::stringstream in(s);
  std::string item;
  while(std::getline(in, item, ',')) out.push_back(Eigen::Index(std::atoll(item.c_str())));
  return out;
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<Eigen::Index> sizes = {1000, 10000, 100000, 1000000};
  double rms = 0.002, max_error = 0.005, noise = 0.0005;
  Eigen::Index sweep_size = 2000;
  std::string tables = "1234", algorithm_names = "penalty,greedy", svg_file;
  Motion_bench_options motion;
  std::string methods = "greedy,penalty,exact,dp,cgal,cgal-hybrid";
  std::vector<double> targets = {0.001, 0.005};
  Eigen::Index comparison_size = 2000;
  int samples_per_segment = 16;
  std::size_t gap_grid = 60;
  unsigned gap_seeds = 4;
  std::string gap_curves = "open";
  std::setvbuf(stdout, nullptr, _IOLBF, 0); // rows appear as they are measured, also into a file
  for(int i = 1; i < argc; ++i)
    if(std::string(argv[i]) == "--help") {
      std::printf("bench_spline_approximation [--sizes 1000,10000,100000,1000000] [--rms 0.002] [--max-error 0.005]\n"
                  "  [--noise 0.0005] [--sweep-size 2000] [--tables 1234] [--algorithms penalty,greedy]\n"
                  "  [--coarse-start-above 4096] (the heuristics' coarse-to-fine start past this many candidates)\n"
                  "tables: 1 cubic within an RMS bound against uniform knots, 2 degree 1 within a max error against\n"
                  "Douglas-Peucker, 3 gap to the exact optimum, 4 lambda sweep; algorithms: the heuristics run in 1, 2, 4\n"
                  "  5 motion compression, 6 a jittery motion regularised: [--motion-frames 4000] [--motion-noise 0.02]\n"
                  "  [--motion-bounds 0.1,0.5,1,2] [--bvh a.bvh,b.bvh] [--motion-algorithms greedy,penalty]\n"
                  "  7 degree 1 against Douglas-Peucker and CGAL's Polyline_simplification_2: [--svg FILE] [--targets 0.001,0.005 (fractions of the extent)] [--comparison-size 2000]\n"
                  "  [--samples-per-segment 16] [--methods greedy,penalty,exact,dp,cgal,cgal-hybrid]\n"
                  "  8 degree 1 vertex count against the exact optimum: [--gap-grid 60] [--gap-seeds 4] [--gap-curves open,closed]\n"
                  "[--relocate-knots-up-to 1048576] (degree 1: the knot relocation up to this many samples; 0 never)\n");
      return 0;
    }
  for(int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i], v = argv[i + 1];
    if(a == "--sizes") sizes = parse_sizes(v);
    else if(a == "--rms") rms = std::atof(v.c_str());
    else if(a == "--max-error") max_error = std::atof(v.c_str());
    else if(a == "--noise") noise = std::atof(v.c_str());
    else if(a == "--sweep-size") sweep_size = Eigen::Index(std::atoll(v.c_str()));
    else if(a == "--tables") tables = v;
    else if(a == "--algorithms") algorithm_names = v;
    else if(a == "--coarse-start-above") coarse_start_above = std::size_t(std::atoll(v.c_str()));
    else if(a == "--gap-grid") gap_grid = std::size_t(std::atoll(v.c_str()));
    else if(a == "--gap-seeds") gap_seeds = unsigned(std::atoi(v.c_str()));
    else if(a == "--gap-curves") gap_curves = v;
    else if(a == "--relocate-knots-up-to") relocate_knots_up_to = std::size_t(std::atoll(v.c_str()));
    else if(a == "--motion-frames") motion.frames = std::atol(v.c_str());
    else if(a == "--motion-noise") motion.noise_degrees = std::atof(v.c_str());
    else if(a == "--bvh") motion.bvh_files = parse_list(v);
    else if(a == "--motion-algorithms") motion.penalty = v.find("penalty") != std::string::npos;
    else if(a == "--motion-bounds") {
      motion.bounds.clear();
      for(const std::string& b : parse_list(v)) motion.bounds.push_back(std::atof(b.c_str()));
    }
    else if(a == "--svg") svg_file = v;
    else if(a == "--methods") methods = v;
    else if(a == "--comparison-size") comparison_size = Eigen::Index(std::atoll(v.c_str()));
    else if(a == "--samples-per-segment") samples_per_segment = std::atoi(v.c_str());
    else if(a == "--targets") {
      targets.clear();
      std::stringstream in(v);
      for(std::string item; std::getline(in, item, ',');) targets.push_back(std::atof(item.c_str()));
    }
    else { std::fprintf(stderr, "unknown option %s\n", a.c_str()); return 2; }
  }
  if(tables.find_first_of("1234") != std::string::npos)
    std::printf("curves: noisy rose, noise sigma %g per coordinate; candidates: every sample\n\n", noise);
  std::vector<SA::Fit_algorithm> heuristics;
  for(SA::Fit_algorithm a : {SA::Fit_algorithm::penalty_decomposition, SA::Fit_algorithm::greedy_removal})
    if(algorithm_names.find(SA::algorithm_name(a)) != std::string::npos) heuristics.push_back(a);
  auto table = [&](char c) { return tables.find(c) != std::string::npos; };

  if(table('1')) {
    std::printf("1. cubic within RMS %g: knots and time per algorithm, and least squares on uniform knots\n", rms);
    std::printf("%9s | %-8s %7s %10s %10s %9s | %8s %10s %9s | %s\n", "samples", "algo", "knots", "rms", "max", "seconds",
                "uniform", "rms", "seconds", "uniform/knots");
    for(Eigen::Index n : sizes) {
      const Eigen::MatrixXd P = curve(n, noise);
      const Eigen::VectorXd t = SA::chord_length_parameters(P);
      const auto t0 = std::chrono::steady_clock::now();
      const auto [g, g_rms] = uniform_knots_for(P, t, rms);
      const double g_seconds = seconds_since(t0);
      for(SA::Fit_algorithm a : heuristics) {
        SA::Fit_options o = options(3, a);
        o.rms_error = rms;
        const SA::Spline_fit f = SA::fit_spline(P, t, o);
        std::printf("%9lld | %-8s %7zu %10.3e %10.3e %9.3f | %8zu %10.3e %9.3f | %.2fx\n", (long long)n,
                    SA::algorithm_name(a), f.number_of_knots(), f.rms_error, f.max_error, f.seconds, g, g_rms, g_seconds,
                    double(g) / double(std::max<std::size_t>(1, f.number_of_knots())));
      }
    }
  }

  if(table('2')) {
    std::printf("\n2. degree 1 within max error %g: vertices (knots + 2) against Douglas-Peucker\n", max_error);
    std::printf("%9s | %-8s %9s %10s %9s | %9s %9s | %s\n", "samples", "algo", "vertices", "max", "seconds", "DP verts",
                "seconds", "saving");
    for(Eigen::Index n : sizes) {
      const Eigen::MatrixXd P = curve(n, noise);
      const auto t0 = std::chrono::steady_clock::now();
      const std::size_t dp_vertices = bench_spline::douglas_peucker(P, max_error).size();
      const double dp_seconds = seconds_since(t0);
      for(SA::Fit_algorithm a : heuristics) {
        SA::Fit_options o = options(1, a);
        o.max_error = max_error;
        const SA::Spline_fit f = SA::fit_spline(P, o);
        const std::size_t v = f.number_of_knots() + 2;
        std::printf("%9lld | %-8s %9zu %10.3e %9.3f | %9zu %9.3f | %+.1f %%\n", (long long)n, SA::algorithm_name(a), v,
                    f.max_error, f.seconds, dp_vertices, dp_seconds, 100.0 * (1.0 - double(v) / double(dp_vertices)));
      }
    }
  }

  if(table('3')) {
    std::printf("\n3. gap to the exact optimum (penalty mode, objective |AX-P|^2 + lambda #knots)\n");
    std::printf("%-28s %8s | %-8s %7s %12s %9s %8s\n", "problem", "lambda", "algo", "knots", "objective", "seconds", "gap");
    struct Exact_case { int degree; Eigen::Index samples; std::size_t grid; SA::Fit_algorithm exact; };
    const Exact_case cases[] = {{1, 1000, 20, SA::Fit_algorithm::dynamic_programming},
                                {1, 1000, 14, SA::Fit_algorithm::brute_force},
                                {3, 1000, 14, SA::Fit_algorithm::brute_force}};
    for(const Exact_case& c : cases) {
      const Eigen::MatrixXd P = curve(c.samples, noise);
      for(double lambda : {1e-3, 1e-2, 1e-1}) {
        SA::Fit_options o = options(c.degree, c.exact);
        o.penalty = lambda;
        o.candidate_grid_size = c.grid;
        SA::Spline_fit best;
        try {
          best = SA::fit_spline(P, o);
        } catch(const SA::Invalid_input& e) {
          std::printf("degree %d, %lld samples, %zu cand. %8g | not computable: %s\n", c.degree, (long long)c.samples,
                      c.grid, lambda, e.what());
          continue;
        }
        char problem[64];
        std::snprintf(problem, sizeof problem, "degree %d, %lld samples, %zu cand.", c.degree, (long long)c.samples, c.grid);
        for(SA::Fit_algorithm a : {c.exact, SA::Fit_algorithm::penalty_decomposition, SA::Fit_algorithm::greedy_removal}) {
          o.algorithm = a;
          const SA::Spline_fit f = a == c.exact ? best : SA::fit_spline(P, o);
          std::printf("%-28s %8g | %-8s %7zu %12.6e %9.4f %+7.2f%%\n", problem, lambda, SA::algorithm_name(a),
                      f.number_of_knots(), f.objective, f.seconds, 100.0 * (f.objective / best.objective - 1.0));
        }
      }
    }
  }

  if(table('4')) {
    std::printf("\n4. error against knot count, cubic, %lld samples, lambda sweep\n", (long long)sweep_size);
    std::printf("%10s | %-8s %7s %10s %10s %9s\n", "lambda", "algo", "knots", "rms", "max", "seconds");
    const Eigen::MatrixXd S = curve(sweep_size, noise);
    for(double lambda : {1e-1, 1e-2, 1e-3, 1e-4, 1e-5})
      for(SA::Fit_algorithm a : heuristics) {
        SA::Fit_options o = options(3, a);
        o.penalty = lambda;
        const SA::Spline_fit f = SA::fit_spline(S, o);
        std::printf("%10g | %-8s %7zu %10.3e %10.3e %9.3f\n", lambda, SA::algorithm_name(a), f.number_of_knots(),
                    f.rms_error, f.max_error, f.seconds);
      }
  }
  if(table('5')) motion_compression_table(motion);
  if(table('6')) motion_jitter_table(motion);
  if(table('7')) {
    std::printf("\n7. degree 1 against Douglas-Peucker and CGAL Polyline_simplification_2 at equal measured error\n"
                "   (measured: max distance of the input vertices to the output polyline; each method's tolerance bisected\n"
                "   to meet the target, the fewest vertices kept; glyphs and SVG paths sampled %d points per segment)\n",
                samples_per_segment);
    std::vector<bench_spline::Comparison_curve> curves = bench_spline::comparison_curves(svg_file, samples_per_segment);
    bench_spline::Comparison_curve rose;
    rose.name = "noisy rose " + std::to_string(comparison_size);
    rose.polylines.push_back(curve(comparison_size, noise));
    rose.closed.push_back(false);
    curves.push_back(std::move(rose));
    bench_spline::polyline_comparison(curves, targets, methods);
  }
  if(table('8'))
    bench_spline::optimum_gap_table(gap_grid, gap_seeds, gap_curves.find("open") != std::string::npos,
                                    gap_curves.find("closed") != std::string::npos);
  return 0;
}
