// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_ANSWERING_SPLINE_H
#define CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_ANSWERING_SPLINE_H

/// \file Answering_spline.h
/// What `Vector_field_spline` and `N_field_spline` share: one constraint set answered either
/// exactly from the start (a full-resolution solver) or at once in a basis and refined to the
/// exact spline on request or in the background (a `Basic_refining_spline_solver`).

#include <CGAL/Tangent_vector_fields/Refining_spline_solver.h>

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

template <class Reduced, class Full>
class Answering_spline
{
public:
  typedef Basic_refining_spline_solver<Reduced, Full> Refining;
  typedef typename Reduced::Constraint_type Constraint;

  /// Exact from the start.
  explicit Answering_spline(std::unique_ptr<Full> full) : full_(std::move(full)) {}
  /// Reduced at once; the full solver is made by `make_full` when a refinement first needs it.
  Answering_spline(std::unique_ptr<Reduced> reduced, typename Refining::Full_factory make_full)
    : refining_(std::make_unique<Refining>(std::move(reduced), std::move(make_full)))
  {
  }

  Constraint_id add(const Constraint& c) { return full_ ? full_->add(c) : refining_->add(c); }
  std::vector<Constraint_id> add(const std::vector<Constraint>& c) { return full_ ? full_->add(c) : refining_->add(c); }
  void change(Constraint_id id, const Constraint& c) { full_ ? full_->change(id, c) : refining_->change(id, c); }
  void remove(Constraint_id id) { full_ ? full_->remove(id) : refining_->remove(id); }
  void clear() { full_ ? full_->clear() : refining_->clear(); }
  void set_omega(double omega) { full_ ? full_->set_omega(omega) : refining_->set_omega(omega); }
  const Constraint& constraint(Constraint_id id) const { return full_ ? full_->constraint(id) : refining_->constraint(id); }
  std::vector<Constraint_id> constraint_ids() const { return full_ ? full_->constraint_ids() : refining_->constraint_ids(); }

  /// The exact spline when it is known, else the reduced one; `which` tells which.
  Eigen::VectorXd field(Spline_answer* which = nullptr)
  {
    if(!full_) return refining_->field(which);
    if(which) *which = exact_answer();
    return full_->field();
  }
  const Spline_report& report() { return full_ ? full_->report() : refining_->report(); }
  Spline_answer answer() { return full_ ? exact_answer() : refining_->answer(); }

  void refine(const Refinement_progress& progress, const std::function<bool()>& cancelled)
  {
    if(refining_) refining_->refine(progress, cancelled);
  }
  void refine_in_background(Refinement_progress progress)
  {
    if(refining_) refining_->refine_in_background(std::move(progress));
  }
  bool wait_until_exact(std::chrono::milliseconds timeout) { return full_ || refining_->wait_until_exact(timeout); }
  void stop_refining()
  {
    if(refining_) refining_->stop_refining();
  }
  const std::string& refinement_error() const { return full_ ? no_error_ : refining_->refinement_error(); }

  /// The reduced solver (null for an exact-from-the-start spline).
  const Reduced* reduced() const { return refining_ ? &refining_->reduced() : nullptr; }
  /// The full solver: from the start, or once a refinement made it (else null).
  const Full* full() const { return full_ ? full_.get() : refining_->full(); }

private:
  static Spline_answer exact_answer()
  {
    Spline_answer a;
    a.exact = true;
    return a;
  }

  std::unique_ptr<Full> full_;
  std::unique_ptr<Refining> refining_;
  const std::string no_error_;
};

/// The members of `Vector_field_spline` and `N_field_spline` that say which spline answers
/// and ask for the exact one.  `Solver` is the solvers' common base (`Spline_solver`,
/// `N_field_spline_solver`).
template <class Reduced, class Full, class Solver>
class Spline_answers
{
public:
  /// The report of the answering spline; for a reduced one `error_bound` bounds its distance
  /// to the exact spline.
  const Spline_report& report() const { return spline_->report(); }
  /// Which spline `field` answers with.
  Spline_answer answer() const { return spline_->answer(); }
  bool is_exact() const { return answer().exact; }

  /// On a basis: computes the exact spline in this thread, one pull-back at full resolution per
  /// constraint (the energy is factored once, or taken from the basis where it has it);
  /// `cancelled` is asked between constraints.  Nothing to do at full resolution.
  /// \throws Infeasible_constraints as `Basic_refining_spline_solver::refine`.
  void refine(const Refinement_progress& progress = Refinement_progress(),
              const std::function<bool()>& cancelled = std::function<bool()>())
  {
    spline_->refine(progress, cancelled);
  }
  /// On a basis: refines on a worker thread, also every constraint added or moved later, while
  /// the reduced answers keep coming at once; `field` turns exact when the worker is done.
  void refine_in_background(Refinement_progress progress = Refinement_progress())
  {
    spline_->refine_in_background(std::move(progress));
  }
  /// Waits for the exact spline (at most `timeout`); true if `field` now answers exactly.
  bool wait_until_exact(std::chrono::milliseconds timeout) { return spline_->wait_until_exact(timeout); }
  /// Stops refining and drops the full-resolution pull-backs (one field per row).
  void stop_refining() { spline_->stop_refining(); }
  /// Why a refinement failed (empty if none): the answer stays reduced.
  const std::string& refinement_error() const { return spline_->refinement_error(); }

  /// The solver `field` answers with (the reduced one until a refinement is complete).
  const Solver& solver() const
  {
    const Solver* full = spline_->full();
    return full && is_exact() ? *full : static_cast<const Solver&>(*spline_->reduced());
  }

protected:
  std::unique_ptr<Answering_spline<Reduced, Full>> spline_;
};

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
