// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Vibration_modes/linear_simulation.h>
#include <CGAL/Vibration_modes/errors.h>

#include <CGAL/Model_reduction/Sparse_spd_solver.h>
#include <CGAL/Model_reduction/internal/One_blas_thread.h>

#include "free_unknowns.h"

#include <Eigen/Dense>

#include <cmath>
#include <string>

namespace CGAL {
namespace Vibration_modes {

namespace {

void check_options(const Linear_simulation_options& o)
{
  if(!(o.time_step > 0) || !std::isfinite(o.time_step))
    throw Invalid_input("linear simulation: the time step must be finite and positive (got " +
                        std::to_string(o.time_step) + ")");
  if(o.steps < 0) throw Invalid_input("linear simulation: the number of steps must be >= 0 (got " + std::to_string(o.steps) + ")");
  if(o.output_every < 1)
    throw Invalid_input("linear simulation: output_every must be >= 1 (got " + std::to_string(o.output_every) + ")");
  if(!(o.rayleigh_mass >= 0) || !(o.rayleigh_stiffness >= 0) || !std::isfinite(o.rayleigh_mass) ||
     !std::isfinite(o.rayleigh_stiffness))
    throw Invalid_input("linear simulation: the Rayleigh damping coefficients must be finite and >= 0");
}

// The free part of an optional vector (empty: zero).
Eigen::VectorXd free_vector(const Mode_problem& p, const Eigen::VectorXd& v, const char* what)
{
  if(v.size() == 0) return Eigen::VectorXd::Zero(p.H.rows());
  return internal::free_rows(p, v, std::string("linear simulation: the ") + what);
}

// Newmark's average-acceleration rule on a system given by its operations:
//   M a + (alpha M + beta H) v + H u = f(t).
// `mass`, `stiffness`: products; `solve_mass`, `solve_step`: M^-1 and
// (M + h/2 C + h^2/4 H)^-1; `force(t, f)`: the force in the system's coordinates;
// `record(t, u, v)` at every kept frame.
template <class Vector, class Mass, class Stiffness, class Solve_mass, class Solve_step, class Force, class Record>
void newmark(const Linear_simulation_options& o, Vector u, Vector v, const Mass& mass, const Stiffness& stiffness,
             const Solve_mass& solve_mass, const Solve_step& solve_step, const Force& force, const Record& record)
{
  // Every step is a few single-vector products and solves: OpenBLAS's threads would spend
  // the time waking up (as in compressed_modes.cpp).
  Model_reduction::internal::One_blas_thread one_blas_thread;
  const double h = o.time_step, alpha = o.rayleigh_mass, beta = o.rayleigh_stiffness;
  auto damping = [&](const Vector& x) -> Vector {
    Vector c = Vector::Zero(x.size());
    if(alpha != 0) c += alpha * mass(x);
    if(beta != 0) c += beta * stiffness(x);
    return c;
  };
  Vector a = solve_mass(Vector(force(0.0) - damping(v) - stiffness(u)));
  record(0.0, u, v);
  for(int n = 1; n <= o.steps; ++n)
  {
    const double t = n * h;
    const Vector u_predicted = u + h * v + (0.25 * h * h) * a;
    const Vector v_predicted = v + (0.5 * h) * a;
    a = solve_step(Vector(force(t) - damping(v_predicted) - stiffness(u_predicted)));
    u = u_predicted + (0.25 * h * h) * a;
    v = v_predicted + (0.5 * h) * a;
    if(n % o.output_every == 0) record(t, u, v);
  }
}

struct Recorder
{
  Linear_trajectory trajectory;
  Eigen::Index frame = 0;
  Recorder(const Linear_simulation_options& o, Eigen::Index rows)
  {
    const Eigen::Index frames = o.steps / o.output_every + 1;
    trajectory.times.resize(frames);
    trajectory.energies.resize(frames);
    trajectory.displacements.resize(rows, frames);
  }
};

} // namespace

Linear_trajectory full_linear_simulation(const Mode_problem& p, const Linear_simulation_options& o)
{
  check_options(o);
  p.check();
  const Eigen::VectorXd u0 = free_vector(p, o.initial_displacement, "initial displacement");
  const Eigen::VectorXd v0 = free_vector(p, o.initial_velocity, "initial velocity");
  const Eigen::VectorXd f0 = free_vector(p, o.force, "force");
  const double h = o.time_step;
  const Eigen::Index n = p.H.rows(), full = internal::full_size_of(p);

  Eigen::SparseMatrix<double> S = (0.5 * h * o.rayleigh_stiffness + 0.25 * h * h) * p.H;
  const Eigen::VectorXd step_mass = (1 + 0.5 * h * o.rayleigh_mass) * p.mass;
  for(Eigen::Index i = 0; i < n; ++i) S.coeffRef(i, i) += step_mass[i];
  Model_reduction::Sparse_spd_solver solver;
  solver.factor(S, "the linear simulation's step matrix M + h/2 C + h^2/4 H");

  Eigen::VectorXd f_full(full);
  auto force = [&](double t) -> Eigen::VectorXd {
    if(!o.force_at_time) return f0;
    f_full.setZero();
    o.force_at_time(t, f_full);
    return f0 + internal::free_rows(p, f_full, "linear simulation: the force at time " + std::to_string(t));
  };
  Recorder r(o, full);
  newmark(
      o, u0, v0, [&](const Eigen::VectorXd& x) -> Eigen::VectorXd { return p.mass.cwiseProduct(x); },
      [&](const Eigen::VectorXd& x) -> Eigen::VectorXd { return p.H * x; },
      [&](const Eigen::VectorXd& b) -> Eigen::VectorXd { return b.cwiseQuotient(p.mass); },
      [&](const Eigen::VectorXd& b) -> Eigen::VectorXd { return solver.solve(b); }, force,
      [&](double t, const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
        r.trajectory.times[r.frame] = t;
        r.trajectory.energies[r.frame] = 0.5 * v.dot(p.mass.cwiseProduct(v)) + 0.5 * u.dot(p.H * u);
        r.trajectory.displacements.col(r.frame++) = p.expand(u);
      });
  return r.trajectory;
}

Linear_trajectory reduced_linear_simulation(const Mode_problem& p, const Eigen::MatrixXd& modes,
                                            const Linear_simulation_options& o, bool with_kernel)
{
  check_options(o);
  p.check();
  const Eigen::MatrixXd U = internal::free_rows(p, modes, "reduced linear simulation: the modes");
  const Eigen::Index kernel = with_kernel ? p.kernel.cols() : 0;
  Eigen::MatrixXd B(p.H.rows(), kernel + U.cols());
  if(kernel > 0) B.leftCols(kernel) = p.kernel;
  B.rightCols(U.cols()) = U;
  if(B.cols() == 0) throw Invalid_input("reduced linear simulation: no modes and no kernel: the basis is empty");
  const Eigen::MatrixXd MB = p.mass.asDiagonal() * B;
  const Eigen::MatrixXd Mr = B.transpose() * MB;
  const Eigen::MatrixXd Hr = B.transpose() * (p.H * B);
  const Eigen::LLT<Eigen::MatrixXd> mass_factor(Mr);
  // A basis column that depends on the others makes B^T M B singular (its smallest pivot
  // falls to rounding level, 1e-16 of the largest); 1e-12 leaves room for rounding.
  const Eigen::VectorXd pivots = Eigen::MatrixXd(mass_factor.matrixL()).diagonal();
  if(mass_factor.info() != Eigen::Success || pivots.minCoeff() * pivots.minCoeff() <= 1e-12 * pivots.maxCoeff() * pivots.maxCoeff())
    throw Invalid_input("reduced linear simulation: the modes" + std::string(with_kernel ? " and the kernel" : "") +
                        " are linearly dependent (B^T M B is singular)");
  const double h = o.time_step;
  const Eigen::MatrixXd S =
      (1 + 0.5 * h * o.rayleigh_mass) * Mr + (0.5 * h * o.rayleigh_stiffness + 0.25 * h * h) * Hr;
  const Eigen::LLT<Eigen::MatrixXd> step_factor(S);
  if(step_factor.info() != Eigen::Success)
    throw Numerical_failure("reduced linear simulation: the reduced step matrix is not positive definite");

  // M-orthogonal projections of the initial state; the reduced force B^T f.
  const Eigen::VectorXd q0 = mass_factor.solve(MB.transpose() * free_vector(p, o.initial_displacement, "initial displacement"));
  const Eigen::VectorXd w0 = mass_factor.solve(MB.transpose() * free_vector(p, o.initial_velocity, "initial velocity"));
  const Eigen::VectorXd f0 = B.transpose() * free_vector(p, o.force, "force");
  Eigen::VectorXd f_full(internal::full_size_of(p));
  auto force = [&](double t) -> Eigen::VectorXd {
    if(!o.force_at_time) return f0;
    f_full.setZero();
    o.force_at_time(t, f_full);
    return f0 + B.transpose() * internal::free_rows(p, f_full, "linear simulation: the force at time " + std::to_string(t));
  };
  Recorder r(o, internal::full_size_of(p));
  newmark(
      o, Eigen::VectorXd(q0), Eigen::VectorXd(w0), [&](const Eigen::VectorXd& x) -> Eigen::VectorXd { return Mr * x; },
      [&](const Eigen::VectorXd& x) -> Eigen::VectorXd { return Hr * x; },
      [&](const Eigen::VectorXd& b) -> Eigen::VectorXd { return mass_factor.solve(b); },
      [&](const Eigen::VectorXd& b) -> Eigen::VectorXd { return step_factor.solve(b); }, force,
      [&](double t, const Eigen::VectorXd& q, const Eigen::VectorXd& w) {
        r.trajectory.times[r.frame] = t;
        r.trajectory.energies[r.frame] = 0.5 * w.dot(Mr * w) + 0.5 * q.dot(Hr * q);
        r.trajectory.displacements.col(r.frame++) = p.expand(B * q);
      });
  return r.trajectory;
}

Linear_trajectory reduced_linear_simulation(const Mode_problem& p, const Modes& modes, int k,
                                            const Linear_simulation_options& o, bool with_kernel)
{
  if(k < 1 || k > modes.vectors.cols())
    throw Invalid_input("reduced linear simulation: " + std::to_string(k) + " modes asked for, " +
                        std::to_string(modes.vectors.cols()) + " computed");
  return reduced_linear_simulation(p, modes.vectors.leftCols(k), o, with_kernel);
}

double relative_trajectory_error(const Mode_problem& p, const Linear_trajectory& a, const Linear_trajectory& r)
{
  if(a.displacements.rows() != r.displacements.rows() || a.displacements.cols() != r.displacements.cols())
    throw Invalid_input("trajectory error: the trajectories have different sizes (" +
                        std::to_string(a.displacements.rows()) + " x " + std::to_string(a.displacements.cols()) + " and " +
                        std::to_string(r.displacements.rows()) + " x " + std::to_string(r.displacements.cols()) + ")");
  const Eigen::MatrixXd A = internal::free_rows(p, a.displacements, "trajectory error: the approximation");
  const Eigen::MatrixXd R = internal::free_rows(p, r.displacements, "trajectory error: the reference");
  const Eigen::MatrixXd D = A - R;
  const double error = (D.array().square().colwise() * p.mass.array()).sum();
  const double norm = (R.array().square().colwise() * p.mass.array()).sum();
  if(!(norm > 0)) throw Invalid_input("trajectory error: the reference trajectory is zero");
  return std::sqrt(error / norm);
}

} // namespace Vibration_modes
} // namespace CGAL
