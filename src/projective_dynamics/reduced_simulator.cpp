// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Reduced and hyper-reduced Projective Dynamics (SPEC 12): the k x k global matrix factored
// once, the local step over all elements (reduced) or over sampled elements with a fit in the
// projection subspace (hyper-reduced), soft pins, the floor at the collision vertices.

#include <CGAL/Projective_dynamics/Position_subspace.h>
#include <CGAL/Projective_dynamics/Projection_subspace.h>
#include <CGAL/Projective_dynamics/Reduced_simulator.h>

#include "element_graph.h"
#include "hyper_reduction.h"
#include "scene_handles.h"
#include "thread_pool.h"

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
#include <string>
#include <thread>

namespace CGAL {
namespace Projective_dynamics {

namespace {
typedef Eigen::SparseMatrix<double, Eigen::RowMajor> Sparse;
typedef Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> Rows;
typedef std::chrono::steady_clock Clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

using internal::check_options;
using internal::Floor;

void check_reduction(const Reduction_options& r, int n)
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

} // namespace

struct Reduced_simulator::Impl : internal::Scene_handles
{
  Elastic_model model;
  Simulator_options o;
  Reduction_options r;
  internal::Thread_pool pool;
  Sparse U, Ut;
  std::vector<int> samples;
  Eigen::MatrixXd Mr;
  Eigen::LLT<Eigen::MatrixXd> Mr_llt;
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
      pool(internal::thread_count(options.threads))
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
    ++factorizations;
    dirty = false;
    timings.factorization = seconds_since(start);
  }

  // Projections of the sampled elements and the fit's right-hand side (J V)^T p_S, in chunks on
  // the thread pool (each chunk its own partial sum, added in a fixed order: same bits for any
  // thread count).
  void local_hyper(const Eigen::MatrixXd& x, Eigen::MatrixXd& rhs)
  {
    const Rows xu = U_used * x;
    const auto& elements = model.elements();
    constexpr int chunks = 8;
    for(std::size_t g = 0; g < groups.size(); ++g)
    {
      const internal::Reduced_group& G = groups[g];
      const double stiffness = model.stiffness(int(g));
      if(G.sampled.empty() || stiffness == 0) continue;
      const int count = int(G.sampled.size()), l = int(G.JV.cols());
      std::array<Eigen::Matrix<double, Eigen::Dynamic, 3>, chunks> partial;
      pool.run(chunks, [&](std::size_t begin, std::size_t end) {
        double value[9];
        Rows p;
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
            for(int j = 0; j < elements[std::size_t(e)].rows; ++j)
            {
              double* out = value + 3 * j;
              out[0] = out[1] = out[2] = 0;
              for(Sparse::InnerIterator it(S_used, row + j); it; ++it)
              {
                const double* xk = xu.data() + 3 * it.col();
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
      rhs.noalias() += stiffness * (G.F * G.fit.solve(sum));
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

  // Pushes the penetrating collision vertices onto each floor by the smallest change of x in
  // the norm of U^T M U along the normal, holding the pinned and grabbed vertices' heights; up to
  // ten rounds, as fixing some may push others below.
  void resolve_floors(Eigen::MatrixXd& x) const
  {
    for(int round = 0; round < 10; ++round)
    {
      bool moved = false;
      for(const Floor& f : floors)
      {
        std::vector<int> c;
        std::vector<double> depth;
        const Rows pos = [&] {
          Rows out(Eigen::Index(collision.size()), 3);
          for(std::size_t q = 0; q < collision.size(); ++q) out.row(Eigen::Index(q)) = U.row(collision[q]) * x;
          return out;
        }();
        for(std::size_t q = 0; q < collision.size(); ++q)
        {
          const double d = (pos.row(Eigen::Index(q)).transpose() - f.point).dot(f.normal);
          if(d < 0) c.push_back(collision[q]), depth.push_back(-d);
        }
        if(c.empty()) continue;
        moved = true;
        // Pinned and grabbed vertices keep their height over the floor (a push must not undo a grab).
        for(const std::vector<int>* held : {&pinned, &grabbed})
          for(int i : *held)
            if(std::find(c.begin(), c.end(), i) == c.end()) c.push_back(i), depth.push_back(0);
        Eigen::MatrixXd Uc(Eigen::Index(c.size()), k());
        for(std::size_t q = 0; q < c.size(); ++q) Uc.row(Eigen::Index(q)) = U.row(c[q]);
        const Eigen::MatrixXd Y = Mr_llt.solve(Uc.transpose());
        Eigen::MatrixXd G = Uc * Y;
        // A relative 1e-10 on the diagonal: more penetrating vertices than the subspace can
        // move independently make G singular; then the least-squares push.
        G.diagonal().array() += 1e-10 * G.diagonal().mean();
        const Eigen::VectorXd lambda = G.ldlt().solve(Eigen::Map<const Eigen::VectorXd>(depth.data(), Eigen::Index(depth.size())));
        x += (Y * lambda) * f.normal.transpose();
      }
      if(!moved) break;
    }
  }

  void step(const std::function<void(int, const Eigen::MatrixXd&)>& after_iteration)
  {
    if(dirty) factor();
    const auto start = Clock::now();
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
    for(int iteration = 0; iteration < o.iterations; ++iteration)
    {
      const auto t0 = Clock::now();
      Eigen::MatrixXd rhs = base;
      if(r.hyper_reduction) local_hyper(x, rhs);
      else local_full(x, rhs);
      const auto t1 = Clock::now();
      local_time += std::chrono::duration<double>(t1 - t0).count();
      x = K.solve(rhs);
      global_time += seconds_since(t1);
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

Reduced_simulator::Reduced_simulator(Elastic_model model, const Simulator_options& options, const Reduction_options& reduction)
{
  check_options(options);
  check_reduction(reduction, model.number_of_vertices());
  impl_ = std::make_unique<Impl>(std::move(model), options, reduction);
  const auto start = Clock::now();
  impl_->report("position subspace", 0);
  Position_subspace P = make_position_subspace(impl_->model, reduction.samples, reduction.radius_multiplier);
  impl_->U = std::move(P.basis);
  impl_->samples = P.samples;
  const Eigen::MatrixXd rest = P.rest_coordinates();
  impl_->precompute(&rest);
  impl_->timings.precomputation = seconds_since(start);
  impl_->report("done", 1);
}

Reduced_simulator::Reduced_simulator(Elastic_model model, const Eigen::SparseMatrix<double, Eigen::RowMajor>& basis,
                                     const Simulator_options& options, const Reduction_options& reduction)
{
  check_options(options);
  Reduction_options r = reduction;
  r.samples = 1; // unused with an explicit basis
  check_reduction(r, model.number_of_vertices());
  if(basis.rows() != model.number_of_vertices() || basis.cols() < 1)
    throw Invalid_input("the basis has " + std::to_string(basis.rows()) + " rows for " + std::to_string(model.number_of_vertices()) +
                        " vertices (or no column)");
  impl_ = std::make_unique<Impl>(std::move(model), options, reduction);
  impl_->U = basis;
  impl_->report("position subspace", 0);
  impl_->precompute(nullptr);
  impl_->report("done", 1);
}

// The precomputation file (.pdr), in the shared binary format (binary_file.h):
//   header (magic "PDREDUCE", version, byte order, the model's identity: connectivity = its
//     vertex count and every row's vertices of S; geometry = the element measures' sum and
//     the element graph's edge lengths)
//   4 doubles   position signature of the rest positions
//   int32       groups; per group: int32 type, int64 elements, uint64 hash of its constants
//   the shaping reduction options: uint8 explicit basis, int32 samples, double radius
//     multiplier, uint8 hyper, int32 constraint samples, double constraint radius multiplier,
//     int32 l, int32 s
//   U: int64 rows, cols; ints (int64 count, int32 each) row starts, columns; values (matrix)
//   ints        samples
//   per group   L (k x k)
//   hyper: per group ints sampled elements, J V (sampled rows x l), F (k x l)
//   magic       end marker
namespace {

namespace MRI = Model_reduction::internal;

const char file_magic[8] = {'P', 'D', 'R', 'E', 'D', 'U', 'C', 'E'};
const std::uint32_t file_version = 1;
const char* const file_what = "reduced simulator";

MRI::Mesh_identity model_identity(const Elastic_model& model)
{
  MRI::Mesh_identity id;
  MRI::Hasher h;
  const Sparse& S = model.selection_matrix();
  h.add(std::int64_t(model.number_of_vertices()));
  h.add(std::int64_t(S.rows()));
  for(Eigen::Index i = 0; i < S.rows(); ++i)
  {
    h.add(std::int64_t(-1)); // row separator
    for(Sparse::InnerIterator it(S, i); it; ++it) h.add(std::int64_t(it.col()));
  }
  id.connectivity = h.h;
  double total = 0;
  for(const Element& el : model.elements()) total += el.measure;
  const internal::Element_graph g = internal::element_graph(model);
  id.geometry = MRI::geometry_signature(total, g.lengths);
  return id;
}

Eigen::VectorXd stacked(const Positions& x)
{
  Eigen::VectorXd v(x.size());
  for(Eigen::Index i = 0; i < x.rows(); ++i) v.segment<3>(3 * i) = x.row(i).transpose();
  return v;
}

struct Group_description
{
  std::int32_t type = 0;
  std::int64_t elements = 0;
  std::uint64_t constants = 0; // the elements' constraint sets and measures
};

std::vector<Group_description> group_descriptions(const Elastic_model& model)
{
  std::vector<Group_description> d(std::size_t(model.number_of_groups()));
  std::vector<MRI::Hasher> h(d.size());
  for(int g = 0; g < model.number_of_groups(); ++g) d[std::size_t(g)].type = std::int32_t(model.group_type(g));
  for(const Element& el : model.elements())
  {
    Group_description& gd = d[std::size_t(el.group)];
    ++gd.elements;
    MRI::Hasher& hg = h[std::size_t(el.group)];
    hg.add(std::int32_t(el.rows));
    for(double x : {el.min_value, el.max_value, el.fallback[0], el.fallback[1], el.fallback[2]}) hg.add(x);
  }
  for(std::size_t g = 0; g < d.size(); ++g) d[g].constants = h[g].h;
  return d;
}

const char* type_name(std::int32_t t)
{
  switch(t)
  {
  case std::int32_t(Element_type::spring): return "springs";
  case std::int32_t(Element_type::triangle_strain): return "triangle strain";
  case std::int32_t(Element_type::tet_strain): return "tetrahedron strain";
  case std::int32_t(Element_type::bending): return "bending";
  default: return "of an unknown type";
  }
}

void write_ints(std::ostream& out, const int* v, std::size_t count)
{
  MRI::write_value<std::int64_t>(out, std::int64_t(count));
  for(std::size_t q = 0; q < count; ++q) MRI::write_value<std::int32_t>(out, v[q]);
}
void write_ints(std::ostream& out, const std::vector<int>& v) { write_ints(out, v.data(), v.size()); }

std::vector<int> read_ints(MRI::Binary_reader& r, std::uint64_t most, const char* name)
{
  const std::int64_t count = r.value<std::int64_t>();
  if(count < 0 || std::uint64_t(count) > most) r.fail(std::string("the file is corrupt (the count of ") + name + ")");
  std::vector<int> v(static_cast<std::size_t>(count));
  for(int& x : v) x = r.value<std::int32_t>();
  return v;
}

// The shortest of 15 or 17 digits that reads back as x.
std::string number(double x)
{
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.15g", x);
  if(std::strtod(buffer, nullptr) != x) std::snprintf(buffer, sizeof(buffer), "%.17g", x);
  return buffer;
}

} // namespace

void Reduced_simulator::save(const std::string& path) const
{
  const Impl& I = *impl_;
  std::ofstream out(path, std::ios::binary);
  if(!out) throw Invalid_input("cannot write the reduced simulator to '" + path + "'");
  MRI::write_header(out, file_magic, file_version, model_identity(I.model));
  for(double x : MRI::position_signature(stacked(I.model.rest_positions()))) MRI::write_value(out, x);
  const std::vector<Group_description> groups = group_descriptions(I.model);
  MRI::write_value<std::int32_t>(out, std::int32_t(groups.size()));
  for(const Group_description& g : groups)
  {
    MRI::write_value(out, g.type);
    MRI::write_value(out, g.elements);
    MRI::write_value(out, g.constants);
  }
  MRI::write_value<std::uint8_t>(out, I.samples.empty() ? 1 : 0);
  MRI::write_value<std::int32_t>(out, I.r.samples);
  MRI::write_value(out, I.r.radius_multiplier);
  MRI::write_value<std::uint8_t>(out, I.r.hyper_reduction ? 1 : 0);
  MRI::write_value<std::int32_t>(out, I.r.constraint_samples);
  MRI::write_value(out, I.r.constraint_radius_multiplier);
  MRI::write_value<std::int32_t>(out, I.r.projection_columns);
  MRI::write_value<std::int32_t>(out, I.r.sampled_elements);
  Sparse U = I.U;
  U.makeCompressed();
  MRI::write_value<std::int64_t>(out, U.rows());
  MRI::write_value<std::int64_t>(out, U.cols());
  write_ints(out, U.outerIndexPtr(), std::size_t(U.rows()) + 1);
  write_ints(out, U.innerIndexPtr(), std::size_t(U.nonZeros()));
  MRI::write_matrix(out, Eigen::Map<const Eigen::VectorXd>(U.valuePtr(), U.nonZeros()));
  write_ints(out, I.samples);
  for(const internal::Reduced_group& G : I.groups) MRI::write_matrix(out, G.L);
  if(I.r.hyper_reduction)
    for(const internal::Reduced_group& G : I.groups)
    {
      write_ints(out, G.sampled);
      MRI::write_matrix(out, G.JV);
      MRI::write_matrix(out, G.F);
    }
  MRI::write_value(out, file_magic);
  if(!out) throw Invalid_input("writing the reduced simulator to '" + path + "' failed");
}

Reduced_simulator Reduced_simulator::load(Elastic_model model, const std::string& path, const Simulator_options& options,
                                          const Reduction_options& reduction)
{
  check_options(options);
  const int n = model.number_of_vertices();
  std::uint64_t bytes = 0;
  std::ifstream in = MRI::open_binary_file(path, file_what, bytes);
  MRI::Binary_reader r(in, path, bytes, file_what);
  r.expect_header(file_magic, file_version, model_identity(model));
  const std::array<double, 4> here = MRI::position_signature(stacked(model.rest_positions()));
  for(int q = 0; q < 4; ++q)
  {
    // Equal to rounding for the same positions (see modes_file.cpp); the basis holds the rest
    // coordinates, so a moved or turned model needs its own.
    const double stored = r.value<double>();
    if(!(std::abs(stored - here[std::size_t(q)]) <= 1e-9 * here[3]))
      r.fail("its rest positions are elsewhere (the model was moved or turned: the basis holds the rest coordinates)");
  }
  const std::vector<Group_description> groups = group_descriptions(model);
  const std::int32_t group_count = r.value<std::int32_t>();
  if(group_count != std::int32_t(groups.size()))
    r.fail("made for " + std::to_string(group_count) + " element groups, the model has " + std::to_string(groups.size()));
  for(std::size_t g = 0; g < groups.size(); ++g)
  {
    Group_description d;
    d.type = r.value<std::int32_t>();
    d.elements = r.value<std::int64_t>();
    d.constants = r.value<std::uint64_t>();
    const std::string which = "element group " + std::to_string(g);
    if(d.type != groups[g].type)
      r.fail(which + " is " + type_name(d.type) + " in the file, " + type_name(groups[g].type) + " in the model");
    if(d.elements != groups[g].elements)
      r.fail(which + " has " + std::to_string(d.elements) + " elements in the file, " + std::to_string(groups[g].elements) +
             " in the model");
    if(d.constants != groups[g].constants)
      r.fail(which + " has other constraint sets (strain limits or rest constants) in the file");
  }
  const bool explicit_basis = r.value<std::uint8_t>() != 0;
  Reduction_options stored;
  stored.samples = r.value<std::int32_t>();
  stored.radius_multiplier = r.value<double>();
  stored.hyper_reduction = r.value<std::uint8_t>() != 0;
  stored.constraint_samples = r.value<std::int32_t>();
  stored.constraint_radius_multiplier = r.value<double>();
  stored.projection_columns = r.value<std::int32_t>();
  stored.sampled_elements = r.value<std::int32_t>();
  {
    auto differ = [&](const char* name, const std::string& in_file, const std::string& given) {
      r.fail(std::string("made with other reduction options: ") + name + " " + in_file + " in the file, " + given + " given");
    };
    if(stored.hyper_reduction != reduction.hyper_reduction)
      differ("hyper_reduction", stored.hyper_reduction ? "true" : "false", reduction.hyper_reduction ? "true" : "false");
    if(!explicit_basis)
    {
      if(stored.samples != reduction.samples)
        differ("number_of_samples", std::to_string(stored.samples), std::to_string(reduction.samples));
      if(stored.radius_multiplier != reduction.radius_multiplier)
        differ("radius_multiplier", number(stored.radius_multiplier), number(reduction.radius_multiplier));
    }
    if(stored.hyper_reduction)
    {
      if(stored.constraint_samples != reduction.constraint_samples)
        differ("number_of_constraint_samples", std::to_string(stored.constraint_samples), std::to_string(reduction.constraint_samples));
      if(stored.constraint_radius_multiplier != reduction.constraint_radius_multiplier)
        differ("constraint_radius_multiplier", number(stored.constraint_radius_multiplier),
               number(reduction.constraint_radius_multiplier));
      if(stored.projection_columns != reduction.projection_columns)
        differ("number_of_projection_columns", std::to_string(stored.projection_columns), std::to_string(reduction.projection_columns));
      if(stored.sampled_elements != reduction.sampled_elements)
        differ("number_of_sampled_elements", std::to_string(stored.sampled_elements), std::to_string(reduction.sampled_elements));
    }
  }
  Reduction_options checked = reduction;
  if(explicit_basis) checked.samples = 1;
  check_reduction(checked, n);

  Reduced_simulator sim;
  sim.impl_ = std::make_unique<Impl>(std::move(model), options, reduction);
  Impl& I = *sim.impl_;
  const auto start = Clock::now();
  // U, checked entry by entry (a corrupt index must not reach Eigen).
  const std::int64_t rows = r.value<std::int64_t>(), cols = r.value<std::int64_t>();
  if(rows != n) r.fail("the basis has " + std::to_string(rows) + " rows for " + std::to_string(n) + " vertices");
  if(cols < 1 || cols > std::int64_t(4) * n || (!explicit_basis && cols != 4 * std::int64_t(reduction.samples)))
    r.fail("the file is corrupt (the basis has " + std::to_string(cols) + " columns)");
  const std::vector<int> outer = read_ints(r, std::uint64_t(n) + 1, "basis rows");
  if(outer.size() != std::size_t(n) + 1 || outer.front() != 0) r.fail("the file is corrupt (the basis rows)");
  for(int i = 0; i < n; ++i)
    if(outer[std::size_t(i) + 1] < outer[std::size_t(i)]) r.fail("the file is corrupt (the basis rows)");
  const std::vector<int> inner = read_ints(r, bytes / 4, "basis entries");
  if(inner.size() != std::size_t(outer.back())) r.fail("the file is corrupt (the basis entries)");
  for(int i = 0; i < n; ++i)
    for(int q = outer[std::size_t(i)]; q < outer[std::size_t(i) + 1]; ++q)
      if(inner[std::size_t(q)] < 0 || inner[std::size_t(q)] >= cols ||
         (q > outer[std::size_t(i)] && inner[std::size_t(q)] <= inner[std::size_t(q) - 1]))
        r.fail("the file is corrupt (a basis column index)");
  const Eigen::MatrixXd values = r.matrix(Eigen::Index(inner.size()), 1, "basis values");
  if(!values.allFinite()) r.fail("the file holds non-finite numbers (the basis)");
  I.U = Eigen::Map<const Sparse>(n, Eigen::Index(cols), Eigen::Index(inner.size()), outer.data(), inner.data(), values.data());
  I.samples = read_ints(r, std::uint64_t(n), "samples");
  if(explicit_basis ? !I.samples.empty() : I.samples.size() != std::size_t(reduction.samples))
    r.fail("the file is corrupt (the number of samples)");
  for(int v : I.samples)
    if(v < 0 || v >= n) r.fail("the file is corrupt (a sample outside the mesh)");
  Eigen::MatrixXd rest;
  if(!explicit_basis) rest = Position_subspace{I.U, I.samples}.rest_coordinates();
  try
  {
    I.prepare_masses(explicit_basis ? nullptr : &rest);
  }
  catch(const Numerical_failure& e)
  {
    r.fail(std::string("the file is corrupt (") + e.what() + ")");
  }
  const std::vector<std::vector<int>> members = I.group_layout();
  const Eigen::Index k = I.U.cols();
  for(internal::Reduced_group& G : I.groups)
  {
    G.L = r.matrix(k, k, "projected matrices");
    if(!G.L.allFinite()) r.fail("the file holds non-finite numbers (a projected matrix)");
  }
  if(reduction.hyper_reduction)
  {
    const auto& elements = I.model.elements();
    for(std::size_t g = 0; g < I.groups.size(); ++g)
    {
      internal::Reduced_group& G = I.groups[g];
      G.sampled = read_ints(r, members[g].size(), "sampled elements");
      if(G.sampled.size() != std::min(members[g].size(), std::size_t(reduction.sampled_elements)))
        r.fail("the file is corrupt (the number of sampled elements of group " + std::to_string(g) + ")");
      int sampled_rows = 0;
      for(std::size_t q = 0; q < G.sampled.size(); ++q)
      {
        const int e = G.sampled[q];
        if(e < 0 || e >= I.model.number_of_elements() || elements[std::size_t(e)].group != int(g) ||
           (q > 0 && e <= G.sampled[q - 1]))
          r.fail("the file is corrupt (a sampled element of group " + std::to_string(g) + ")");
        sampled_rows += elements[std::size_t(e)].rows;
      }
      const Eigen::Index l = members[g].empty() ? -1 : reduction.projection_columns;
      G.JV = r.matrix(members[g].empty() ? 0 : sampled_rows, l, "projection subspace rows");
      G.F = r.matrix(members[g].empty() ? 0 : k, l, "projected subspace matrices F");
      if(!G.JV.allFinite() || !G.F.allFinite()) r.fail("the file holds non-finite numbers (a projection subspace)");
    }
    internal::Hyper_sampling h;
    try
    {
      h = internal::finish_sampling(I.model, I.U, I.groups);
    }
    catch(const Numerical_failure& e)
    {
      r.fail(std::string("the file is corrupt (") + e.what() + ")");
    }
    I.used = std::move(h.used), I.sampled_all = std::move(h.sampled_all), I.sampled_row = std::move(h.sampled_row);
    I.S_used = std::move(h.S_used), I.U_used = std::move(h.U_used);
  }
  r.expect_magic(file_magic, "the file is corrupt (no end marker)");
  I.default_collision();
  I.timings.precomputation = seconds_since(start);
  return sim;
}

Reduced_simulator::~Reduced_simulator() = default;
Reduced_simulator::Reduced_simulator(Reduced_simulator&&) noexcept = default;
Reduced_simulator& Reduced_simulator::operator=(Reduced_simulator&&) noexcept = default;

void Reduced_simulator::step(const std::function<void(int, const Eigen::MatrixXd&)>& after_iteration) { impl_->step(after_iteration); }

const Eigen::MatrixXd& Reduced_simulator::coordinates() const { return impl_->a; }
const Eigen::MatrixXd& Reduced_simulator::coordinate_velocities() const { return impl_->a_dot; }

namespace {
void check_coordinates(const Eigen::MatrixXd& a, int k, const char* what)
{
  if(a.rows() != k || a.cols() != 3 || !a.allFinite())
    throw Invalid_input(std::string(what) + ": expected a finite " + std::to_string(k) + " x 3 matrix");
}
} // namespace

void Reduced_simulator::set_coordinates(const Eigen::MatrixXd& a)
{
  check_coordinates(a, impl_->k(), "coordinates");
  impl_->a = a;
}
void Reduced_simulator::set_coordinate_velocities(const Eigen::MatrixXd& a_dot)
{
  check_coordinates(a_dot, impl_->k(), "coordinate velocities");
  impl_->a_dot = a_dot;
}

Positions Reduced_simulator::positions() const { return impl_->U * impl_->a; }
Positions Reduced_simulator::velocities() const { return impl_->U * impl_->a_dot; }
Positions Reduced_simulator::positions_of(const std::vector<int>& vertices) const
{
  Positions out(Eigen::Index(vertices.size()), 3);
  for(std::size_t q = 0; q < vertices.size(); ++q)
  {
    impl_->check_vertex(vertices[q], "queried");
    out.row(Eigen::Index(q)) = impl_->U.row(vertices[q]) * impl_->a;
  }
  return out;
}

void Reduced_simulator::set_positions(const Positions& q)
{
  impl_->check_rows(q, "positions");
  impl_->a = impl_->Mr_llt.solve(impl_->Ut * impl_->model.masses().asDiagonal() * q);
}
void Reduced_simulator::set_velocities(const Positions& v)
{
  impl_->check_rows(v, "velocities");
  impl_->a_dot = impl_->Mr_llt.solve(impl_->Ut * impl_->model.masses().asDiagonal() * v);
}
void Reduced_simulator::set_external_forces(const Positions& f)
{
  impl_->check_rows(f, "external forces");
  impl_->ext = impl_->Ut * f;
  impl_->has_ext = true;
}

void Reduced_simulator::set_pinned_vertices(const std::vector<int>& vertices)
{
  for(int i : vertices) impl_->check_vertex(i, "pinned");
  impl_->pin(vertices, positions_of(vertices));
  impl_->dirty = true;
}

void Reduced_simulator::grab(const std::vector<int>& vertices, const Positions& targets)
{
  impl_->Scene_handles::grab(vertices, targets);
  impl_->dirty = true;
}

void Reduced_simulator::move_grabbed(const Positions& targets) { impl_->Scene_handles::move_grabbed(targets); }

void Reduced_simulator::release_grabbed()
{
  impl_->Scene_handles::release_grabbed();
  impl_->dirty = true;
}

void Reduced_simulator::add_floor(const Eigen::Vector3d& point, const Eigen::Vector3d& normal)
{
  impl_->Scene_handles::add_floor(point, normal);
}
void Reduced_simulator::clear_obstacles() { impl_->Scene_handles::clear_obstacles(); }
void Reduced_simulator::set_collision_vertices(const std::vector<int>& vertices)
{
  for(int i : vertices) impl_->check_vertex(i, "collision");
  impl_->collision = vertices;
}

void Reduced_simulator::set_time_step(double h)
{
  Simulator_options o = impl_->o;
  o.time_step = h;
  check_options(o);
  impl_->o = o;
  impl_->dirty = true;
}
void Reduced_simulator::set_stiffness(int group, double stiffness)
{
  impl_->model.set_stiffness(group, stiffness);
  impl_->dirty = true;
}
void Reduced_simulator::set_iterations(int iterations)
{
  Simulator_options o = impl_->o;
  o.iterations = iterations;
  check_options(o);
  impl_->o = o;
}

const Eigen::SparseMatrix<double, Eigen::RowMajor>& Reduced_simulator::basis() const { return impl_->U; }
int Reduced_simulator::dimension() const { return impl_->k(); }
const std::vector<int>& Reduced_simulator::samples() const { return impl_->samples; }
std::vector<int> Reduced_simulator::sampled_elements() const { return impl_->sampled_all; }
std::vector<int> Reduced_simulator::used_vertices() const { return impl_->used; }
const Simulator_options& Reduced_simulator::options() const { return impl_->o; }
const Reduction_options& Reduced_simulator::reduction_options() const { return impl_->r; }
const Elastic_model& Reduced_simulator::model() const { return impl_->model; }
const Reduced_step_timings& Reduced_simulator::last_step_timings() const { return impl_->timings; }
int Reduced_simulator::number_of_factorizations() const { return impl_->factorizations; }

} // namespace Projective_dynamics
} // namespace CGAL
