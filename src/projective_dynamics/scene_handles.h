// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PROJECTIVE_DYNAMICS_SRC_SCENE_HANDLES_H
#define CGAL_PROJECTIVE_DYNAMICS_SRC_SCENE_HANDLES_H

// What the full and the reduced simulator hold the same way: pinned and grabbed vertices with
// their targets, floor and sphere obstacles, and the checks of what a caller hands in.

#include <CGAL/Projective_dynamics/Elastic_model.h>
#include <CGAL/Projective_dynamics/Simulator.h>
#include <CGAL/Projective_dynamics/errors.h>

#include <Eigen/Core>

#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Projective_dynamics {
namespace internal {

/// \throws Invalid_input naming `what` if `vertex` lies outside `[0, n)`.
inline void check_vertex(int vertex, int n, const char* what)
{
  if(vertex < 0 || vertex >= n)
    throw Invalid_input(std::string(what) + " vertex " + std::to_string(vertex) + " is outside [0, " +
                        std::to_string(n) + ")");
}

/// \throws Invalid_input naming `what` unless `x` has `n` rows, all finite.
inline void check_rows(const Positions& x, int n, const char* what)
{
  if(x.rows() != n)
    throw Invalid_input(std::string(what) + ": " + std::to_string(x.rows()) + " rows for " + std::to_string(n) +
                        " vertices");
  for(Eigen::Index i = 0; i < x.rows(); ++i)
    if(!x.row(i).allFinite())
      throw Invalid_input(std::string(what) + ": vertex " + std::to_string(i) + " has a non-finite entry (NaN or infinity)");
}

/// \throws Invalid_input with the reason for options no simulator can run with.
inline void check_options(const Simulator_options& o)
{
  if(!(o.time_step > 0) || !std::isfinite(o.time_step))
    throw Invalid_input("the time step h = " + std::to_string(o.time_step) + " must be positive and finite");
  if(o.iterations < 1) throw Invalid_input("the number of iterations per step must be at least 1, not " + std::to_string(o.iterations));
  if(!o.gravity.allFinite()) throw Invalid_input("gravity must be finite");
  if(o.threads < 0) throw Invalid_input("the number of threads must be >= 0 (0: all cores)");
  if(!(o.friction >= 0 && o.friction <= 1)) throw Invalid_input("the friction factor must be in [0, 1], not " + std::to_string(o.friction));
}

struct Floor
{
  Eigen::Vector3d point, normal; // unit normal
};

struct Sphere
{
  Eigen::Vector3d center;
  double radius;
};

/// Pins, grabs and obstacles of a simulator of `vertices` vertices.  Changing which vertices are
/// held (`pin`, `grab`, `release_grabbed`) returns true: the caller's factorisation depends on it.
struct Scene_handles
{
  explicit Scene_handles(int vertices) : vertices(vertices) {}

  int vertices;
  std::vector<int> pinned, grabbed;
  Positions pin_targets, grab_targets;
  std::vector<Floor> floors;
  std::vector<Sphere> spheres;

  /// Holds `held` at `targets` (one row each), replacing earlier pins.
  void pin(const std::vector<int>& held, const Positions& targets)
  {
    for(int i : held) check_vertex(i, vertices, "pinned");
    pinned = held;
    pin_targets = targets;
  }
  void grab(const std::vector<int>& held, const Positions& targets)
  {
    for(int i : held) check_vertex(i, vertices, "grabbed");
    if(targets.rows() != Eigen::Index(held.size()) || !targets.allFinite())
      throw Invalid_input("grab: " + std::to_string(targets.rows()) + " targets for " + std::to_string(held.size()) +
                          " vertices, or a non-finite target");
    grabbed = held;
    grab_targets = targets;
  }
  void move_grabbed(const Positions& targets)
  {
    if(targets.rows() != Eigen::Index(grabbed.size()) || !targets.allFinite())
      throw Invalid_input("move_grabbed: " + std::to_string(targets.rows()) + " targets for " +
                          std::to_string(grabbed.size()) + " grabbed vertices, or a non-finite target");
    grab_targets = targets;
  }
  void release_grabbed()
  {
    grabbed.clear();
    grab_targets.resize(0, 3);
  }
  void add_floor(const Eigen::Vector3d& point, const Eigen::Vector3d& normal)
  {
    if(!point.allFinite() || !normal.allFinite() || !(normal.norm() > 0))
      throw Invalid_input("a floor needs a finite point and a finite non-zero normal");
    floors.push_back({point, normal.normalized()});
  }
  void add_sphere(const Eigen::Vector3d& center, double radius)
  {
    if(!center.allFinite() || !(radius > 0) || !std::isfinite(radius))
      throw Invalid_input("a sphere obstacle needs a finite centre and a positive radius, not " + std::to_string(radius));
    spheres.push_back({center, radius});
  }
  void clear_obstacles()
  {
    floors.clear();
    spheres.clear();
  }
};

} // namespace internal
} // namespace Projective_dynamics
} // namespace CGAL

#endif
