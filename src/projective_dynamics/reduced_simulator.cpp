// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Reduced and hyper-reduced Projective Dynamics (SPEC 12): the k x k global matrix factored
// once, the local step over all elements (reduced) or over sampled elements with a fit in the
// projection subspace (hyper-reduced), soft pins, the floor at the collision vertices.

#include "reduced_simulator_impl.h"

namespace CGAL {
namespace Projective_dynamics {

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

Positions Reduced_simulator::positions() const
{
  Positions q;
  Impl::rows_times(impl_->U, impl_->a, q);
  return q;
}
Positions Reduced_simulator::velocities() const { return impl_->U * impl_->a_dot; }
Positions Reduced_simulator::positions_of(const std::vector<int>& vertices) const
{
  for(int v : vertices) impl_->check_vertex(v, "queried");
  // a by rows: each entry of a row of U reads three neighbouring numbers (a drawn surface of
  // 45,871 vertices on a 1.7-million-tet armadillo: 3.6 ms with a sparse row times a per vertex).
  const internal::Rows ar = impl_->a;
  Positions out(Eigen::Index(vertices.size()), 3);
  for(std::size_t q = 0; q < vertices.size(); ++q)
  {
    const std::array<double, 3> y = internal::row_times(impl_->U, vertices[q], ar);
    out(Eigen::Index(q), 0) = y[0], out(Eigen::Index(q), 1) = y[1], out(Eigen::Index(q), 2) = y[2];
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
  impl_->floor_multipliers.clear(); // indexed by collision vertex
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
