// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Full-space Projective Dynamics: the constant global matrix factored once, local steps on a
// thread pool, obstacles by position correction.

#include <CGAL/Projective_dynamics/Simulator.h>

#include <CGAL/Model_reduction/Sparse_spd_solver.h>
#include <CGAL/Model_reduction/internal/Thread_pool.h>

#include "scene_handles.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <thread>

namespace CGAL {
namespace Projective_dynamics {

namespace {
typedef Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> Rows;
typedef std::chrono::steady_clock Clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

using internal::check_options;
using internal::Floor;
using internal::Sphere;
} // namespace

struct Simulator::Impl : internal::Scene_handles
{
  Impl(Elastic_model m, const Simulator_options& options)
    : Scene_handles(m.number_of_vertices()), model(std::move(m)), o(options), pool(Model_reduction::internal::thread_count(options.threads))
  {
    const int n = model.number_of_vertices();
    q = model.rest_positions();
    v = Positions::Zero(n, 3);
    f_ext = Positions::Zero(n, 3);
  }

  Elastic_model model;
  Simulator_options o;
  Model_reduction::internal::Thread_pool pool;
  Positions q, v, f_ext;

  bool dirty = true;
  std::vector<int> free_index;  // per vertex: its row among the unknowns, or -1 if held
  std::vector<int> free_vertices;
  Eigen::SparseMatrix<double, Eigen::RowMajor> A;   // M/h^2 + S^T W S over all vertices
  Eigen::SparseMatrix<double, Eigen::RowMajor> STW; // S^T W (n x rows)
  Model_reduction::Sparse_spd_solver solver;
  Step_timings timings;
  int factorizations = 0;

  void check_vertex(int vertex, const char* what) const { internal::check_vertex(vertex, vertices, what); }
  void check_rows(const Positions& x, const char* what) const { internal::check_rows(x, vertices, what); }

  void factor()
  {
    const auto start = Clock::now();
    const int n = model.number_of_vertices();
    const double h = o.time_step;
    free_index.assign(n, 0);
    for(int i : pinned) free_index[i] = -1;
    for(int i : grabbed) free_index[i] = -1;
    free_vertices.clear();
    for(int i = 0; i < n; ++i)
      if(free_index[i] == 0)
      {
        if(!(model.masses()[i] > 0))
          throw Invalid_input("vertex " + std::to_string(i) + " has zero mass: only pinned or grabbed vertices may");
        free_index[i] = int(free_vertices.size());
        free_vertices.push_back(i);
      }
    const Eigen::SparseMatrix<double, Eigen::RowMajor>& S = model.selection_matrix();
    const Eigen::VectorXd w = model.row_weights();
    STW = Eigen::SparseMatrix<double, Eigen::RowMajor>(S.transpose()) * w.asDiagonal();
    Eigen::SparseMatrix<double, Eigen::RowMajor> L = STW * S;
    A = L;
    Eigen::SparseMatrix<double, Eigen::RowMajor> Mh(n, n);
    std::vector<Eigen::Triplet<double>> diagonal;
    for(int i = 0; i < n; ++i) diagonal.emplace_back(i, i, model.masses()[i] / (h * h));
    Mh.setFromTriplets(diagonal.begin(), diagonal.end());
    A += Mh;
    A.makeCompressed();
    // The unknowns' block (lower triangle is what the solver reads; both are kept).
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(A.nonZeros());
    for(int r = 0; r < n; ++r)
    {
      if(free_index[r] < 0) continue;
      for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(A, r); it; ++it)
        if(free_index[it.col()] >= 0) t.emplace_back(free_index[r], free_index[it.col()], it.value());
    }
    Eigen::SparseMatrix<double> Aff(Eigen::Index(free_vertices.size()), Eigen::Index(free_vertices.size()));
    Aff.setFromTriplets(t.begin(), t.end());
    solver.factor(Aff, "the global matrix M/h^2 + S^T W S");
    ++factorizations;
    dirty = false;
    timings.factorization = seconds_since(start);
  }

  // Pushes the points of x out of the obstacles; marks the moved ones and their normals.
  void resolve_obstacles(Rows& x, std::vector<char>* contact, Rows* normals) const
  {
    if(floors.empty() && spheres.empty()) return;
    for(int i : free_vertices)
    {
      Eigen::Vector3d p = x.row(i).transpose();
      for(const Floor& f : floors)
      {
        const double d = (p - f.point).dot(f.normal);
        if(d < 0)
        {
          p -= d * f.normal;
          if(contact) (*contact)[i] = 1, normals->row(i) = f.normal.transpose();
        }
      }
      for(const Sphere& s : spheres)
      {
        const Eigen::Vector3d r = p - s.center;
        const double d = r.norm();
        if(d < s.radius)
        {
          // The centre itself has no direction out: push along gravity's opposite (or +z).
          const Eigen::Vector3d out = d > 0 ? Eigen::Vector3d(r / d)
                                            : (o.gravity.norm() > 0 ? Eigen::Vector3d(-o.gravity.normalized())
                                                                    : Eigen::Vector3d::UnitZ());
          p = s.center + s.radius * out;
          if(contact) (*contact)[i] = 1, normals->row(i) = out.transpose();
        }
      }
      x.row(i) = p.transpose();
    }
  }

  void step(const std::function<void(int, const Positions&)>& after_iteration)
  {
    if(dirty) factor();
    const auto start = Clock::now();
    const int n = model.number_of_vertices();
    const double h = o.time_step;
    const Eigen::VectorXd& m = model.masses();
    const Eigen::SparseMatrix<double, Eigen::RowMajor>& S = model.selection_matrix();
    const std::vector<Element>& elements = model.elements();

    // Prediction s = q + h v + h^2 M^-1 f_ext, pushed out of the obstacles.
    Rows s(n, 3);
    for(int i = 0; i < n; ++i)
    {
      Eigen::RowVector3d a = o.gravity.transpose();
      if(m[i] > 0) a += f_ext.row(i) / m[i];
      s.row(i) = q.row(i) + h * v.row(i) + h * h * a;
    }
    resolve_obstacles(s, nullptr, nullptr);
    Rows x = s;
    Rows held = Rows::Zero(n, 3);
    // Grabs first, so that a vertex both grabbed and pinned stays pinned.
    for(std::size_t k = 0; k < grabbed.size(); ++k) held.row(grabbed[k]) = grab_targets.row(Eigen::Index(k));
    for(std::size_t k = 0; k < pinned.size(); ++k) held.row(pinned[k]) = pin_targets.row(Eigen::Index(k));
    for(int i = 0; i < n; ++i)
      if(free_index[i] < 0) x.row(i) = held.row(i);
    // What the held vertices add to the unknowns' right-hand side: -A_{free, held} x_held.
    const Rows held_part = A * held;
    const int nf = int(free_vertices.size());
    Rows inertia(n, 3);
    for(int i = 0; i < n; ++i) inertia.row(i) = m[i] / (h * h) * s.row(i);

    Rows p(model.number_of_rows(), 3);
    Eigen::MatrixXd rhs(nf, 3);
    double local_time = 0, global_time = 0;
    for(int iteration = 0; iteration < o.iterations; ++iteration)
    {
      auto t0 = Clock::now();
      pool.run(elements.size(), [&](std::size_t begin, std::size_t end) {
        double value[9];
        for(std::size_t e = begin; e < end; ++e)
        {
          const Element& el = elements[e];
          for(int r = 0; r < el.rows; ++r)
          {
            double* out = value + 3 * r;
            out[0] = out[1] = out[2] = 0;
            for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(S, el.first_row + r); it; ++it)
            {
              const double* xk = x.data() + 3 * it.col();
              out[0] += it.value() * xk[0], out[1] += it.value() * xk[1], out[2] += it.value() * xk[2];
            }
          }
          model.project(int(e), value, p.data() + 3 * el.first_row);
        }
      });
      auto t1 = Clock::now();
      local_time += std::chrono::duration<double>(t1 - t0).count();
      pool.run(std::size_t(nf), [&](std::size_t begin, std::size_t end) {
        for(std::size_t k = begin; k < end; ++k)
        {
          const int i = free_vertices[k];
          Eigen::RowVector3d b = inertia.row(i) - held_part.row(i);
          for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(STW, i); it; ++it)
            b += it.value() * p.row(it.col());
          rhs.row(Eigen::Index(k)) = b;
        }
      });
      const Eigen::MatrixXd solution = solver.solve(rhs);
      for(int k = 0; k < nf; ++k) x.row(free_vertices[k]) = solution.row(k);
      global_time += seconds_since(t1);
      if(after_iteration) after_iteration(iteration, Positions(x));
    }

    std::vector<char> contact(n, 0);
    Rows normals(n, 3);
    resolve_obstacles(x, &contact, &normals);
    if(!x.allFinite())
      throw Numerical_failure("the positions stopped being finite (an absurd force or mass?); the state before the step is kept");
    Positions v_new = (Positions(x) - q) / h;
    for(int i = 0; i < n; ++i)
      if(contact[i])
      {
        const Eigen::RowVector3d nrm = normals.row(i);
        const double vn = v_new.row(i).dot(nrm);
        const Eigen::RowVector3d tangential = v_new.row(i) - vn * nrm;
        v_new.row(i) = (1 - o.friction) * tangential + std::max(vn, 0.0) * nrm;
      }
    q = x;
    v = v_new;
    timings.local = local_time;
    timings.global = global_time;
    timings.total = seconds_since(start);
  }
};

Simulator::Simulator(Elastic_model model, const Simulator_options& options)
{
  check_options(options);
  impl_ = std::make_unique<Impl>(std::move(model), options);
}
Simulator::~Simulator() = default;
Simulator::Simulator(Simulator&&) noexcept = default;
Simulator& Simulator::operator=(Simulator&&) noexcept = default;

void Simulator::step(const std::function<void(int, const Positions&)>& after_iteration) { impl_->step(after_iteration); }

const Positions& Simulator::positions() const { return impl_->q; }
const Positions& Simulator::velocities() const { return impl_->v; }
void Simulator::set_positions(const Positions& q)
{
  impl_->check_rows(q, "positions");
  impl_->q = q;
}
void Simulator::set_velocities(const Positions& v)
{
  impl_->check_rows(v, "velocities");
  impl_->v = v;
}
void Simulator::set_external_forces(const Positions& f)
{
  impl_->check_rows(f, "external forces");
  impl_->f_ext = f;
}

void Simulator::set_pinned_vertices(const std::vector<int>& vertices)
{
  Positions targets(Eigen::Index(vertices.size()), 3);
  for(std::size_t k = 0; k < vertices.size(); ++k)
  {
    impl_->check_vertex(vertices[k], "pinned");
    targets.row(Eigen::Index(k)) = impl_->q.row(vertices[k]);
  }
  impl_->pin(vertices, targets);
  impl_->dirty = true;
}

void Simulator::grab(const std::vector<int>& vertices, const Positions& targets)
{
  impl_->Scene_handles::grab(vertices, targets);
  impl_->dirty = true;
}

void Simulator::move_grabbed(const Positions& targets) { impl_->Scene_handles::move_grabbed(targets); }

void Simulator::release_grabbed()
{
  impl_->Scene_handles::release_grabbed();
  impl_->dirty = true;
}

void Simulator::add_floor(const Eigen::Vector3d& point, const Eigen::Vector3d& normal)
{
  impl_->Scene_handles::add_floor(point, normal);
}

void Simulator::add_sphere(const Eigen::Vector3d& center, double radius)
{
  impl_->Scene_handles::add_sphere(center, radius);
}

void Simulator::clear_obstacles() { impl_->Scene_handles::clear_obstacles(); }

void Simulator::set_time_step(double h)
{
  Simulator_options o = impl_->o;
  o.time_step = h;
  check_options(o);
  impl_->o = o;
  impl_->dirty = true;
}

void Simulator::set_stiffness(int group, double stiffness)
{
  impl_->model.set_stiffness(group, stiffness);
  impl_->dirty = true;
}

void Simulator::set_iterations(int iterations)
{
  Simulator_options o = impl_->o;
  o.iterations = iterations;
  check_options(o);
  impl_->o = o;
}

void Simulator::set_friction(double friction)
{
  Simulator_options o = impl_->o;
  o.friction = friction;
  check_options(o);
  impl_->o = o;
}

const Simulator_options& Simulator::options() const { return impl_->o; }
const Elastic_model& Simulator::model() const { return impl_->model; }
const Step_timings& Simulator::last_step_timings() const { return impl_->timings; }
int Simulator::number_of_factorizations() const { return impl_->factorizations; }

} // namespace Projective_dynamics
} // namespace CGAL
