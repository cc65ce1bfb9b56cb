// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The state of a Reduced_simulator, shared by its simulation (reduced_simulator.cpp) and its
// precomputation file (reduced_simulator_file.cpp).

#ifndef CGAL_PROJECTIVE_DYNAMICS_SRC_REDUCED_SIMULATOR_IMPL_H
#define CGAL_PROJECTIVE_DYNAMICS_SRC_REDUCED_SIMULATOR_IMPL_H

#include <CGAL/Projective_dynamics/Position_subspace.h>
#include <CGAL/Projective_dynamics/Projection_subspace.h>
#include <CGAL/Projective_dynamics/Reduced_simulator.h>
#include <CGAL/Projective_dynamics/internal/floor_push.h>

#include "element_graph.h"
#include "hyper_reduction.h"
#include "scene_handles.h"

#include <CGAL/Model_reduction/internal/One_blas_thread.h>
#include <CGAL/Model_reduction/internal/Thread_pool.h>
#include <CGAL/Model_reduction/internal/binary_file.h>
#include <CGAL/Model_reduction/internal/mesh_identity.h>

#include <Eigen/Cholesky>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <thread>

namespace CGAL {
namespace Projective_dynamics {

namespace internal {

typedef Eigen::SparseMatrix<double, Eigen::RowMajor> Sparse;
typedef Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> Rows;
typedef std::chrono::steady_clock Clock;
inline double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Row v of B x for x given by rows (k x 3, row-major): each entry of B's row reads three
// neighbouring numbers (Eigen's sparse row times a column-major x walks x once per column).
inline std::array<double, 3> row_times(const Sparse& B, Eigen::Index v, const Rows& x)
{
  std::array<double, 3> y{0, 0, 0};
  for(Sparse::InnerIterator it(B, v); it; ++it)
  {
    const double* r = x.data() + 3 * it.col();
    y[0] += it.value() * r[0], y[1] += it.value() * r[1], y[2] += it.value() * r[2];
  }
  return y;
}


inline void check_reduction(const Reduction_options& r, int n)
{
  if(r.samples < 1 || r.samples > n)
    throw Invalid_input("the number of position samples must be in [1, " + std::to_string(n) + "] (the number of vertices), not " +
                        std::to_string(r.samples));
  if(!(r.pin_stiffness > 0) || !std::isfinite(r.pin_stiffness))
    throw Invalid_input("the pin stiffness must be positive and finite, not " + std::to_string(r.pin_stiffness));
  if(!r.hyper_reduction) return;
  if(r.projection_columns < 1) throw Invalid_input("the number of projection columns l must be at least 1");
  if(r.sampled_elements < r.projection_columns + 20)
    throw Invalid_input("s = " + std::to_string(r.sampled_elements) + " sampled elements is fewer than l + 20 = " +
                        std::to_string(r.projection_columns + 20) +
                        " (the fit of l columns needs clearly more sampled elements than unknowns)");
  if(r.constraint_samples < 1 || r.constraint_samples > n)
    throw Invalid_input("the number of constraint samples must be in [1, " + std::to_string(n) + "], not " +
                        std::to_string(r.constraint_samples));
  if(4 * r.constraint_samples < r.projection_columns)
    throw Invalid_input("l = " + std::to_string(r.projection_columns) + " exceeds the 4 candidate columns per constraint sample (" +
                        std::to_string(4 * r.constraint_samples) + ")");
}

} // namespace internal

using internal::check_options;
using internal::check_reduction;
using internal::Clock;
using internal::Floor;
using internal::Rows;
using internal::seconds_since;
using internal::Sparse;

struct Reduced_simulator::Impl : internal::Scene_handles
{
  Elastic_model model;
  Simulator_options o;
  Reduction_options r;
  Model_reduction::internal::Thread_pool pool;
  Sparse U, Ut;
  std::vector<int> samples;
  Eigen::MatrixXd Mr;
  Eigen::LLT<Eigen::MatrixXd> Mr_llt;
  // (U^T M U)^-1, for the floor's pushes with a basis handed in (its columns near the contact
  // make the push's problem).  Made at the first push (O(k^3)): a scene without a floor, or with
  // the samples' basis, never pays for it.
  Eigen::MatrixXd Mr_inverse;
  // The samples' translations' rows of U and Mr's inverse on them, for the pushes with the
  // samples' basis (made at the first push).
  internal::Push_subspace translation_push;
  // The last push's multipliers (per floor, per collision vertex), to start the next.
  std::vector<std::vector<double>> floor_multipliers;
  Eigen::VectorXd gvec; // U^T m
  std::vector<internal::Reduced_group> groups;
  // Hyper-reduction: the sampled elements' rows on the used vertices.
  std::vector<int> used, sampled_all, sampled_row;
  Sparse U_used, S_used;
  // State.
  Eigen::MatrixXd a, a_dot, ext;
  bool has_ext = false;
  std::vector<int> collision;
  bool dirty = true;
  double kappa = 0;
  Eigen::LLT<Eigen::MatrixXd> K;
  Sparse STW;
  Reduced_step_timings timings;
  int factorizations = 0;

  Impl(Elastic_model m, const Simulator_options& options, const Reduction_options& reduction)
    : Scene_handles(m.number_of_vertices()), model(std::move(m)), o(options), r(reduction),
      pool(Model_reduction::internal::thread_count(options.threads))
  {}

  int n() const { return model.number_of_vertices(); }
  int k() const { return int(U.cols()); }

  void check_vertex(int v, const char* what) const { internal::check_vertex(v, n(), what); }
  void check_rows(const Positions& x, const char* what) const { internal::check_rows(x, n(), what); }

  // Tells the progress callback; throws Cancelled if it says stop.
  void report(const char* stage, double fraction) const
  {
    if(!r.progress) return;
    Reduced_precomputation_progress p;
    p.stage = stage;
    p.fraction = fraction;
    if(!r.progress(p))
      throw Cancelled(std::string("the reduced simulator's precomputation was cancelled (at \"") + stage + "\")");
  }

  // The mass matrix U^T M U and the start state (cheap: also done by a loaded simulator).
  void prepare_masses(const Eigen::MatrixXd* rest_coordinates)
  {
    Ut = U.transpose();
    const Eigen::VectorXd& m = model.masses();
    Mr = Eigen::MatrixXd(Ut * m.asDiagonal() * U);
    Mr_llt.compute(Mr);
    if(Mr_llt.info() != Eigen::Success)
      throw Numerical_failure("U^T M U is not positive definite: the basis has dependent columns on the massive vertices "
                              "(a sample's support too small or flat: fewer samples or a larger radius multiplier)");
    Mr_inverse.resize(0, 0); // of the masses before
    translation_push = internal::Push_subspace();
    gvec = Ut * m;
    a = rest_coordinates ? *rest_coordinates : Eigen::MatrixXd(Mr_llt.solve(Ut * m.asDiagonal() * model.rest_positions()));
    if(!rest_coordinates)
    {
      const double residual = (Positions(U * a) - model.rest_positions()).norm();
      if(!(residual <= 1e-9 * std::max(1.0, model.rest_positions().norm())))
        throw Invalid_input("the basis does not reproduce the rest positions (relative residual " + std::to_string(residual) + ")");
    }
    a_dot = Eigen::MatrixXd::Zero(k(), 3);
    ext = Eigen::MatrixXd::Zero(k(), 3);
  }

  // The groups' rows and measures (cheap); returns each group's elements.
  // Groups: contiguous rows (elements are added group by group).
  std::vector<std::vector<int>> group_layout()
  {
    const auto& elements = model.elements();
    groups.clear();
    groups.resize(std::size_t(model.number_of_groups()));
    std::vector<std::vector<int>> members(groups.size());
    for(int e = 0; e < model.number_of_elements(); ++e) members[std::size_t(elements[std::size_t(e)].group)].push_back(e);
    for(std::size_t g = 0; g < groups.size(); ++g)
    {
      internal::Reduced_group& G = groups[g];
      if(members[g].empty()) continue;
      G.first_row = elements[std::size_t(members[g].front())].first_row;
      std::vector<double> measure;
      for(int e : members[g])
        for(int q = 0; q < elements[std::size_t(e)].rows; ++q) measure.push_back(elements[std::size_t(e)].measure);
      G.rows = int(measure.size());
      G.measure = Eigen::Map<Eigen::VectorXd>(measure.data(), G.rows);
    }
    return members;
  }

  void default_collision()
  {
    if(!collision.empty()) return;
    if(samples.empty())
      for(int i = 0; i < n(); ++i) collision.push_back(i);
    else
    {
      collision = samples;
      collision.insert(collision.end(), used.begin(), used.end());
      std::sort(collision.begin(), collision.end());
      collision.erase(std::unique(collision.begin(), collision.end()), collision.end());
    }
  }

  // Progress: the position subspace up to 0.25 (reported by the constructor), the projected
  // matrices up to 0.4 (all of the rest when not hyper-reduced), the sampled elements and the
  // projection subspaces up to 1.
  void precompute(const Eigen::MatrixXd* rest_coordinates)
  {
    const auto start = Clock::now();
    prepare_masses(rest_coordinates);
    const double end_of_matrices = r.hyper_reduction ? 0.4 : 1.0;
    const std::vector<std::vector<int>> members = group_layout();
    const Sparse& S = model.selection_matrix();
    for(std::size_t g = 0; g < groups.size(); ++g)
    {
      report("projected matrices", 0.25 + (end_of_matrices - 0.25) * double(g) / double(groups.size()));
      internal::Reduced_group& G = groups[g];
      if(members[g].empty()) continue;
      const Sparse Sg = S.middleRows(G.first_row, G.rows);
      const Sparse A = Sparse(Sg.transpose()) * G.measure.asDiagonal() * Sg;
      const Sparse AU = A * U;
      G.L = Eigen::MatrixXd(Ut * AU);
    }
    if(r.hyper_reduction)
    {
      // The element samples (farthest points) take about a quarter of the rest.
      internal::Hyper_sampling h = internal::sample_and_fit(model, r, U, Ut, members, groups, [&](const char* stage, double f) {
        report(stage, std::string(stage) == "sampled elements" ? 0.4 : 0.55 + 0.45 * f);
      });
      used = std::move(h.used), sampled_all = std::move(h.sampled_all), sampled_row = std::move(h.sampled_row);
      S_used = std::move(h.S_used), U_used = std::move(h.U_used);
    }
    default_collision();
    timings.precomputation = seconds_since(start);
  }

  void factor()
  {
    const auto start = Clock::now();
    const double h = o.time_step;
    Eigen::MatrixXd A = Mr / (h * h);
    for(std::size_t g = 0; g < groups.size(); ++g)
      if(groups[g].L.size()) A += model.stiffness(int(g)) * groups[g].L;
    kappa = r.pin_stiffness * model.masses().mean() / (h * h);
    auto add_held = [&](const std::vector<int>& held) {
      for(int i : held)
      {
        const Eigen::RowVectorXd u = U.row(i);
        A += kappa * u.transpose() * u;
      }
    };
    add_held(pinned);
    add_held(grabbed);
    K.compute(A);
    if(K.info() != Eigen::Success) throw Numerical_failure("the reduced global matrix K is not positive definite");
    if(!r.hyper_reduction) STW = Sparse(model.selection_matrix().transpose()) * model.row_weights().asDiagonal();
    else
      for(internal::Reduced_group& G : groups)
        if(!G.sampled.empty()) G.solved_F = K.solve(Eigen::MatrixXd(G.fit.solve(G.F.transpose()).transpose()));
    ++factorizations;
    dirty = false;
    timings.factorization = seconds_since(start);
  }

  // The rows of B x (B sparse, row-major, e.g. U; x with 3 columns), x copied to rows first.
  // Serial: a const query (positions()) may come from any thread; the pool serves the step's.
  static void rows_times(const Sparse& B, const Eigen::MatrixXd& x, Positions& out)
  {
    const Rows xr = x;
    out.resize(B.rows(), 3);
    for(Eigen::Index v = 0; v < B.rows(); ++v)
    {
      const std::array<double, 3> y = internal::row_times(B, v, xr);
      out(v, 0) = y[0], out(v, 1) = y[1], out(v, 2) = y[2];
    }
  }

  // Projections of the sampled elements and each group's fit right-hand side (J V)^T p_S (l x 3,
  // times the group's stiffness), in chunks on the thread pool (each chunk its own partial sum,
  // added in a fixed order: same bits for any thread count).
  void local_hyper(const Eigen::MatrixXd& x, std::vector<Eigen::MatrixXd>& fit_rhs)
  {
    fit_rhs.resize(groups.size());
    const Rows xr = x; // three neighbouring numbers per entry of a row of U
    const auto& elements = model.elements();
    constexpr int chunks = 8;
    for(std::size_t g = 0; g < groups.size(); ++g)
    {
      const internal::Reduced_group& G = groups[g];
      const double stiffness = model.stiffness(int(g));
      fit_rhs[g].resize(0, 3);
      if(G.sampled.empty() || stiffness == 0) continue;
      const int count = int(G.sampled.size()), l = int(G.JV.cols());
      std::array<Eigen::Matrix<double, Eigen::Dynamic, 3>, chunks> partial;
      pool.run(chunks, [&](std::size_t begin, std::size_t end) {
        double value[9];
        Rows p;
        // The element's vertices (columns of its rows of S) and their positions, computed from
        // their rows of U per element: sampled elements rarely share a vertex (the cantilever:
        // 1,000 tets on 3,790 vertices), and a pass over all used vertices first would cost a
        // second wake of the pool per iteration.
        std::vector<Eigen::Index> vertex;
        std::vector<std::array<double, 3>> position;
        auto position_of = [&](Eigen::Index u) -> const double* {
          for(std::size_t i = 0; i < vertex.size(); ++i)
            if(vertex[i] == u) return position[i].data();
          vertex.push_back(u), position.push_back(internal::row_times(U_used, u, xr));
          return position.back().data();
        };
        for(std::size_t c = begin; c < end; ++c)
        {
          const int q0 = G.first_sampled + int(c) * count / chunks, q1 = G.first_sampled + int(c + 1) * count / chunks;
          const int row0 = q0 < int(sampled_row.size()) ? sampled_row[std::size_t(q0)] : int(S_used.rows());
          const int row1 = q1 < int(sampled_row.size()) ? sampled_row[std::size_t(q1)] : int(S_used.rows());
          p.resize(row1 - row0, 3);
          for(int q = q0; q < q1; ++q)
          {
            const int e = sampled_all[std::size_t(q)];
            const int row = sampled_row[std::size_t(q)];
            vertex.clear(), position.clear();
            for(int j = 0; j < elements[std::size_t(e)].rows; ++j)
            {
              double* out = value + 3 * j;
              out[0] = out[1] = out[2] = 0;
              for(Sparse::InnerIterator it(S_used, row + j); it; ++it)
              {
                const double* xk = position_of(it.col());
                out[0] += it.value() * xk[0], out[1] += it.value() * xk[1], out[2] += it.value() * xk[2];
              }
            }
            model.project(e, value, p.data() + 3 * (row - row0));
          }
          partial[c].noalias() = G.JV.middleRows(row0 - G.first_sampled_row, row1 - row0).transpose() * p;
        }
      });
      Eigen::Matrix<double, Eigen::Dynamic, 3> sum = Eigen::Matrix<double, Eigen::Dynamic, 3>::Zero(l, 3);
      for(const auto& part : partial) sum += part;
      fit_rhs[g] = stiffness * sum;
    }
  }

  void local_full(const Eigen::MatrixXd& x, Eigen::MatrixXd& rhs)
  {
    const Rows q = U * x;
    const Sparse& S = model.selection_matrix();
    const auto& elements = model.elements();
    Rows p(model.number_of_rows(), 3);
    pool.run(elements.size(), [&](std::size_t begin, std::size_t end) {
      double value[9];
      for(std::size_t e = begin; e < end; ++e)
      {
        const Element& el = elements[e];
        for(int j = 0; j < el.rows; ++j)
        {
          double* out = value + 3 * j;
          out[0] = out[1] = out[2] = 0;
          for(Sparse::InnerIterator it(S, el.first_row + j); it; ++it)
          {
            const double* xk = q.data() + 3 * it.col();
            out[0] += it.value() * xk[0], out[1] += it.value() * xk[1], out[2] += it.value() * xk[2];
          }
        }
        model.project(int(e), value, p.data() + 3 * el.first_row);
      }
    });
    const Rows force = STW * p;
    rhs.noalias() += Ut * force;
  }

  // Lifts the collision vertices onto each floor by the smallest change of x in the norm of
  // U^T M U along the normal (smallest_floor_push), holding the pinned and grabbed vertices'
  // heights.  Vertices that the push itself moves below join the problem, which is solved
  // again; with several floors, up to ten rounds, as one floor's push may move vertices below
  // another.  Every collision vertex ends at least `floor_tolerance` above its floor.
  void resolve_floors(Eigen::MatrixXd& x)
  {
    timings.contact_vertices = timings.contact_columns = timings.contact_factorizations = 0;
    if(floors.empty() || collision.empty()) return;
    // A basis made from samples pushes by their translations (columns 4 j + 3); another basis by
    // all its columns near the contact (Mr's inverse).  Either made once.
    const bool by_translations = !samples.empty() && k() == 4 * int(samples.size());
    if(by_translations && translation_push.columns.empty())
    {
      std::vector<int> translations;
      for(int j = 0; j < int(samples.size()); ++j) translations.push_back(4 * j + 3);
      translation_push = internal::push_subspace(U, Mr, translations);
    }
    if(!by_translations && Mr_inverse.rows() != k()) Mr_inverse = Mr_llt.solve(Eigen::MatrixXd::Identity(k(), k()));
    const Sparse& push_U = by_translations ? translation_push.U : U;
    std::vector<int> held = pinned;
    held.insert(held.end(), grabbed.begin(), grabbed.end());
    std::sort(held.begin(), held.end());
    held.erase(std::unique(held.begin(), held.end()), held.end());
    const double tolerance = floor_tolerance();
    floor_multipliers.resize(floors.size());
    for(int round = 0; round < (floors.size() > 1 ? 10 : 1); ++round)
    {
      bool moved = false;
      for(std::size_t fi = 0; fi < floors.size(); ++fi)
      {
        const Floor& f = floors[fi];
        // The last push's multipliers, by vertex.
        std::vector<double>& multiplier = floor_multipliers[fi];
        multiplier.resize(collision.size(), 0.0);
        const Eigen::VectorXd normal_coordinates = x * f.normal;
        const double offset = f.point.dot(f.normal);
        Eigen::VectorXd height(Eigen::Index(collision.size()));
        for(std::size_t q = 0; q < collision.size(); ++q) height[Eigen::Index(q)] = U.row(collision[q]).dot(normal_coordinates) - offset;
        std::vector<int> rows, in_problem(collision.size(), 0);
        auto add_below = [&](const Eigen::VectorXd& h, bool held_last_step_only) {
          bool added = false;
          for(std::size_t q = 0; q < collision.size(); ++q)
            if(h[Eigen::Index(q)] < 0 && !in_problem[q] && (!held_last_step_only || multiplier[q] > 0))
            {
              // Only the vertices outside the pushed set need a test: the others already hold.
              in_problem[q] = 1, rows.push_back(int(q)), added = true;
            }
          return added;
        };
        // A resting body: the problem starts from the vertices below the floor that held it last
        // step (positive multipliers); the others below join only if the push leaves them below
        // (an optimum over some constraints that meets the others is the optimum over all).  The
        // authors' armadillo at rest: a few hundred rows instead of ~5,000.  A new contact: all.
        if(!add_below(height, true) && !add_below(height, false)) continue;
        moved = true;
        // Lifted to twice the tolerance, solved to the tolerance: every vertex ends above.
        Eigen::VectorXd delta;
        for(int growth = 0; growth < 20; ++growth)
        {
          std::vector<int> vertices;
          Eigen::VectorXd need(Eigen::Index(rows.size()));
          for(std::size_t i = 0; i < rows.size(); ++i)
            vertices.push_back(collision[std::size_t(rows[i])]), need[Eigen::Index(i)] = 2 * tolerance - height[rows[i]];
          internal::Floor_push_report report;
          Eigen::VectorXd start(Eigen::Index(rows.size()));
          for(std::size_t i = 0; i < rows.size(); ++i) start[Eigen::Index(i)] = multiplier[std::size_t(rows[i])];
          delta = internal::smallest_floor_push(push_U, by_translations ? translation_push.Mr_inverse : Mr_inverse, vertices,
                                                need, held, tolerance, &report, &start);
          std::fill(multiplier.begin(), multiplier.end(), 0.0);
          for(std::size_t i = 0; i < rows.size(); ++i) multiplier[std::size_t(rows[i])] = start[Eigen::Index(i)];
          timings.contact_vertices = report.constraints, timings.contact_columns = report.columns;
          timings.contact_factorizations += report.factorizations;
          Eigen::VectorXd lifted(Eigen::Index(collision.size()));
          for(std::size_t q = 0; q < collision.size(); ++q) lifted[Eigen::Index(q)] = height[Eigen::Index(q)] + push_U.row(collision[q]).dot(delta);
          if(!add_below(lifted, false)) break;
        }
        if(by_translations)
          for(std::size_t a = 0; a < translation_push.columns.size(); ++a) x.row(translation_push.columns[a]) += delta[Eigen::Index(a)] * f.normal.transpose();
        else x += delta * f.normal.transpose();
      }
      if(!moved) break;
    }
  }

  // How far the floor's solve may leave a constraint: a relative 1e-10 of the body's extent
  // (far below what a picture shows; well above the rounding of positions of that size).
  double floor_tolerance() const
  {
    const Positions& rest = model.rest_positions();
    const double extent = (rest.colwise().maxCoeff() - rest.colwise().minCoeff()).norm();
    return 1e-10 * std::max(extent, std::numeric_limits<double>::min());
  }

  void step(const std::function<void(int, const Eigen::MatrixXd&)>& after_iteration)
  {
    if(dirty) factor();
    const auto start = Clock::now();
    // One BLAS thread: the products and triangular solves here are small (k x k), and OpenBLAS's
    // threads only spin and yield beside the local step's own threads (cantilever, 24,000 tets,
    // k = 600: global 33.4 ms per step with OpenBLAS's default threads, 2.6 ms with one).
    Model_reduction::internal::One_blas_thread one_blas_thread;
    const double h = o.time_step;
    const Eigen::MatrixXd predicted = a + h * a_dot;
    Eigen::MatrixXd base = Mr * predicted / (h * h) + gvec * o.gravity.transpose();
    if(has_ext) base += ext;
    for(std::size_t q = 0; q < pinned.size(); ++q)
      base += kappa * Eigen::MatrixXd(U.row(pinned[q]).transpose()) * pin_targets.row(Eigen::Index(q));
    for(std::size_t q = 0; q < grabbed.size(); ++q)
      base += kappa * Eigen::MatrixXd(U.row(grabbed[q]).transpose()) * grab_targets.row(Eigen::Index(q));
    Eigen::MatrixXd x = predicted;
    double local_time = 0, global_time = 0;
    // Hyper-reduced: x = K^-1 base + sum_g K^-1 F_g fit_g^-1 (J V)^T p, the first term solved once
    // per step (the cantilever of bench_reduced_pd, k = 600, l = 120: two k x k triangular solves
    // per iteration cost more than the whole local step's fit).
    Eigen::MatrixXd solved_base;
    std::vector<Eigen::MatrixXd> fit_rhs;
    if(r.hyper_reduction)
    {
      const auto t0 = Clock::now();
      solved_base = K.solve(base);
      global_time += seconds_since(t0);
    }
    for(int iteration = 0; iteration < o.iterations; ++iteration)
    {
      const auto t0 = Clock::now();
      if(r.hyper_reduction)
      {
        local_hyper(x, fit_rhs);
        const auto t1 = Clock::now();
        local_time += std::chrono::duration<double>(t1 - t0).count();
        x = solved_base;
        for(std::size_t g = 0; g < groups.size(); ++g)
          if(fit_rhs[g].size()) x.noalias() += groups[g].solved_F * fit_rhs[g];
        global_time += seconds_since(t1);
      }
      else
      {
        Eigen::MatrixXd rhs = base;
        local_full(x, rhs);
        const auto t1 = Clock::now();
        local_time += std::chrono::duration<double>(t1 - t0).count();
        x = K.solve(rhs);
        global_time += seconds_since(t1);
      }
      if(after_iteration) after_iteration(iteration, x);
    }
    const auto t2 = Clock::now();
    resolve_floors(x);
    timings.contact = seconds_since(t2);
    if(!x.allFinite())
      throw Numerical_failure("the coordinates stopped being finite (an absurd force or mass?); the state before the step is kept");
    a_dot = (x - a) / h;
    a = x;
    timings.local = local_time;
    timings.global = global_time;
    timings.total = seconds_since(start);
  }
};

} // namespace Projective_dynamics
} // namespace CGAL

#endif
