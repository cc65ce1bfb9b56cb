// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The simulation session's body: sizes chosen for real time, the simulators behind `Stepper`.

#include "simulation_body.h"
#include "messages.h"

#include <CGAL/Projective_dynamics/Reduced_simulator.h>
#include <CGAL/Projective_dynamics/Simulator.h>

#include <Eigen/Geometry>

#include <algorithm>

namespace tvf_viewer {

namespace {

// Real-time sizes of the hyper-reduced simulator: k = 4 m <= 160 coordinates, l = 60 and
// s = 200 per group, so that a step costs about the same on any mesh.
const int real_time_samples = 40, real_time_projection_columns = 60, real_time_sampled_elements = 200;
// Stiff enough that gravity stretches the body by about 0.1 % of its size (strain ~ rho g L / k).
const double stiffness_per_weight = 1e3, density = 1, gravity = 9.81;

template <class Simulator>
class Stepper_of : public Stepper
{
public:
  explicit Stepper_of(Simulator s) : sim_(std::move(s)) {}
  void step() override { sim_.step(); }
  PD::Positions positions() const override { return sim_.positions(); }
  PD::Positions velocities() const override { return sim_.velocities(); }
  void set_state(const PD::Positions& q, const PD::Positions& v) override
  {
    sim_.set_positions(q);
    sim_.set_velocities(v);
  }
  void grab(int vertex, const Eigen::RowVector3d& target) override { sim_.grab({vertex}, PD::Positions(target)); }
  void move_grabbed(const Eigen::RowVector3d& target) override { sim_.move_grabbed(PD::Positions(target)); }
  void release_grabbed() override { sim_.release_grabbed(); }
  void set_stiffness(int group, double k) override { sim_.set_stiffness(group, k); }
  void set_time_step(double h) override { sim_.set_time_step(h); }
  double last_step_seconds() const override { return sim_.last_step_timings().total; }
  Simulator& simulator() { return sim_; }

private:
  Simulator sim_;
};

double diagonal_of(const std::vector<PD::Point>& points)
{
  Eigen::RowVector3d lo = Eigen::RowVector3d::Constant(1e300), hi = -lo;
  for(const PD::Point& p : points)
    for(int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  return points.empty() ? 1 : (hi - lo).norm();
}

double mean_area(const std::vector<PD::Point>& points, const std::vector<PD::Triangle>& triangles)
{
  double sum = 0;
  for(const PD::Triangle& t : triangles)
  {
    const Eigen::Vector3d a(points[t[0]].data()), b(points[t[1]].data()), c(points[t[2]].data());
    sum += 0.5 * (b - a).cross(c - a).norm();
  }
  return triangles.empty() ? 0 : sum / double(triangles.size());
}

} // namespace

Simulation_body::Simulation_body(const Simulation_surface& surface, const Body_request& request)
  : request_(request)
{
  if(request.solid && !surface.closed)
    throw Message_error("the surface is open: a solid needs a closed surface (ask for mode \"shell\")");
  const auto start = Clock::now();
  diagonal_ = diagonal_of(surface.points);
  default_stiffness_ = stiffness_ = stiffness_per_weight * density * gravity * diagonal_;
  PD::internal::Body_material material;
  material.stiffness = stiffness_;
  material.density = density;
  // Bending about as stiff as stretching over one triangle: cloth that folds but does not crumple.
  bending_ratio_ = request.solid ? 0 : mean_area(surface.points, surface.triangles);
  material.bending = bending_ratio_ * stiffness_;
  PD::Tetrahedralization_options tets;
  tets.cell_size = 0.08; // a few thousand tetrahedra: real time with the reduced simulator
  body_ = std::make_unique<PD::internal::Simulated_body>(
      PD::internal::body_of_surface(surface.points, surface.triangles, request.solid, material, tets));
  rest_ = body_->model.rest_positions();
  floor_ = PD::internal::drop_floor_height(rest_);

  PD::Simulator_options options;
  options.time_step = default_time_step();
  options.iterations = 10;
  options.threads = 1; // the server serves several pages; one core each
  const int n = body_->model.number_of_vertices();
  // The floor holds at the vertices the page sees move.
  const std::vector<int> colliding = PD::internal::collision_vertices(*body_, n);
  if(request_.reduced)
  {
    reduction_ = PD::internal::capped_reduction_options(n, real_time_samples, false, real_time_projection_columns,
                                                         real_time_sampled_elements);
    try
    {
      auto s = std::make_unique<Stepper_of<PD::Reduced_simulator>>(
          PD::Reduced_simulator(body_->model, options, reduction_));
      s->simulator().add_floor(Eigen::Vector3d(0, 0, floor_), Eigen::Vector3d(0, 0, 1));
      s->simulator().set_collision_vertices(colliding);
      stepper_ = std::move(s);
    }
    catch(const PD::Numerical_failure& e)
    {
      // A flat cloth: its samples' affine maps have a dependent column (z is constant), so the
      // subspace cannot be built.  Full PD instead, and the page is told why.
      fallback_ = e.what();
      request_.reduced = false;
    }
  }
  if(!request_.reduced)
  {
    auto s = std::make_unique<Stepper_of<PD::Simulator>>(PD::Simulator(body_->model, options));
    s->simulator().add_floor(Eigen::Vector3d(0, 0, floor_), Eigen::Vector3d(0, 0, 1));
    stepper_ = std::move(s);
  }
  setup_seconds_ = milliseconds_since(start) / 1000;
}

int Simulation_body::simulated_vertex(int v, const PD::Positions& q) const
{
  if(!body_->embedded) return v;
  // The corner of the vertex's tetrahedron nearest to it.
  const PD::Positions drawn_now = body_->drawn(q);
  const PD::Tetrahedron& corners = body_->embedding.corners[std::size_t(v)];
  int best = corners[0];
  for(int c : corners)
    if((q.row(c) - drawn_now.row(v)).squaredNorm() < (q.row(best) - drawn_now.row(v)).squaredNorm()) best = c;
  return best;
}

void Simulation_body::set_stiffness(double k)
{
  stiffness_ = k;
  stepper_->set_stiffness(0, k);
  if(!request_.solid && body_->model.number_of_groups() > 1) stepper_->set_stiffness(1, bending_ratio_ * k);
}

std::string Simulation_body::description_json() const
{
  std::string s = "\"mode\":\"" + std::string(request_.solid ? "solid" : "shell") + "\",\"simulator\":\"" +
                  (request_.reduced ? "reduced" : "full") + "\",\"vertices\":" +
                  std::to_string(body_->model.number_of_vertices()) + ",\"elements\":" + std::to_string(body_->elements);
  if(request_.reduced)
    s += ",\"samples\":" + std::to_string(reduction_.samples) + ",\"dimension\":" + std::to_string(4 * reduction_.samples) +
         ",\"projection_columns\":" + std::to_string(reduction_.projection_columns) +
         ",\"sampled_elements\":" + std::to_string(reduction_.sampled_elements);
  if(!fallback_.empty()) s += ",\"fallback\":" + quote("the reduced simulator could not be built (" + fallback_ + "): full PD");
  return s + ",\"setup_ms\":" + short_number(1000 * setup_seconds_);
}

} // namespace tvf_viewer
