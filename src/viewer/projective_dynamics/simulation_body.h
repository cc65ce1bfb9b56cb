// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the `simulation` session simulates: the served surface as a shell or a solid
// (`body_of_surface`, shared with `tvf simulate`), a floor under it, and one simulator, full
// or hyper-reduced, behind one interface so the session does not care which.

#ifndef TVF_VIEWER_SIMULATION_BODY_H
#define TVF_VIEWER_SIMULATION_BODY_H

#include <CGAL/Projective_dynamics/internal/scene_setup.h>

#include <memory>
#include <string>
#include <vector>

namespace tvf_viewer {

namespace PD = CGAL::Projective_dynamics;

/// The served surface (the vertices the page draws, in their order).
struct Simulation_surface
{
  std::string name;
  std::vector<PD::Point> points;
  std::vector<PD::Triangle> triangles;
  bool closed = false; ///< no border edge: a solid may be made of it
};

/// How a hello asks for the body.
struct Body_request
{
  bool solid = false;
  bool reduced = true;
};

/// The operations of `Simulator` and `Reduced_simulator` the session uses.
class Stepper
{
public:
  virtual ~Stepper() = default;
  virtual void step() = 0;
  virtual PD::Positions positions() const = 0;
  virtual PD::Positions velocities() const = 0;
  virtual void set_state(const PD::Positions& q, const PD::Positions& v) = 0;
  virtual void grab(int vertex, const Eigen::RowVector3d& target) = 0;
  virtual void move_grabbed(const Eigen::RowVector3d& target) = 0;
  virtual void release_grabbed() = 0;
  virtual void set_stiffness(int group, double k) = 0;
  virtual void set_time_step(double h) = 0;
  virtual double last_step_seconds() const = 0;
};

/// A body of the surface, its simulator and its floor.
class Simulation_body
{
public:
  /// \throws Message_error for a solid of an open surface; Invalid_input and Numerical_failure
  /// of the model makers, Mesh_3 and the precomputation.
  Simulation_body(const Simulation_surface& surface, const Body_request& request);

  Stepper& stepper() { return *stepper_; }
  const PD::internal::Simulated_body& body() const { return *body_; }
  /// The surface's vertices for the simulator's positions.
  PD::Positions drawn(const PD::Positions& q) const { return body_->drawn(q); }
  /// The simulator's vertex that carries surface vertex `v` (itself for a shell; the nearest
  /// tetrahedron vertex for a solid).
  int simulated_vertex(int v, const PD::Positions& q) const;

  double floor_height() const { return floor_; }
  double diagonal() const { return diagonal_; }
  double default_stiffness() const { return default_stiffness_; }
  double default_time_step() const { return 1.0 / 60; }
  /// Strain stiffness now; a shell's bending follows it in a fixed ratio.
  void set_stiffness(double k);
  double stiffness() const { return stiffness_; }
  const PD::Positions& rest() const { return rest_; }
  /// Sizes for the info message (JSON members).
  std::string description_json() const;
  double setup_seconds() const { return setup_seconds_; }

private:
  std::unique_ptr<PD::internal::Simulated_body> body_;
  PD::Positions rest_;
  std::unique_ptr<Stepper> stepper_;
  Body_request request_;
  PD::Reduction_options reduction_;
  std::string fallback_; ///< why the reduced simulator was not built
  double floor_ = 0, diagonal_ = 1, default_stiffness_ = 1, stiffness_ = 1, bending_ratio_ = 0, setup_seconds_ = 0;
};

} // namespace tvf_viewer

#endif
