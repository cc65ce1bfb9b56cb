// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_REFINING_SPLINE_SOLVER_H
#define CGAL_TANGENT_VECTOR_FIELDS_REFINING_SPLINE_SOLVER_H

/// \file Refining_spline_solver.h
/// A spline answered at once in a spectral basis and refined to the exact one at full
/// resolution: the reduced solver's answer is instant but not the spline asked for; the full
/// solver's costs one pull-back per new constraint.  This class keeps both, computes the full
/// pull-backs on request or on a worker thread, and answers exactly once every constraint has
/// its pull-back; from then on value edits are exact too (the full solver's small system and
/// one product with its pull-backs, no sparse solve).

#include <CGAL/Tangent_vector_fields/Full_spline_solver.h>
#include <CGAL/Tangent_vector_fields/N_field_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Reduced_spline_solver.h>

#include <Eigen/Core>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

/// Progress of a refinement: constraints pulled back so far and how many were pending.
/// Called from the thread that does the work (the worker thread in the background).
typedef std::function<void(int done, int total)> Refinement_progress;

/// Which spline a `Basic_refining_spline_solver` answers with.
struct Spline_answer
{
  bool exact = false; ///< the full-resolution spline (the full solver exists, every constraint pulled back)
  int basis_size = 0; ///< else the reduced spline in this many basis elements
  int pending = 0;    ///< constraints still without their full-resolution pull-back
};

/// \brief A spline design answered at once in a basis (`Reduced`) and refined to the exact
/// spline (`Full`, sharing its factorisations: nothing is refactored).
///
/// Edits go to both solvers.  The reduced solver takes them at once; the full solver gets a
/// new or moved constraint only with its pull-back, computed by `refine` (in the calling
/// thread) or by a worker thread (`refine_in_background`).  Value edits of a constraint that
/// is already pulled back cost nothing extra; a move (new rows) makes its pull-back pending
/// again; a removal drops it (and any pull-back under way for it).  `field` answers with the
/// full spline when nothing is pending, else with the reduced one; `answer` tells which.
///
/// Threads: the object is used from one thread; the worker only runs the full solver's
/// `prepare` (the pull-backs), which reads the energy's factorisations and never the
/// constraint set, and hands finished pull-backs back through a queue that the calling
/// thread drains at its next call (each member function, and `wait_until_exact`).  A
/// pull-back under way is not interrupted: cancellation (`stop_background`, a move or
/// removal of the constraint being pulled back, `set_omega`, destruction) takes effect when
/// the current constraint's pull-back ends, and its result is dropped.  The answer is always
/// consistent: the reduced spline of every constraint, or the full spline of every one.
/// The worker makes each constraint's rows again (`prepare`); the operators' caches those
/// rows need are built once whichever thread asks first, and the full solver's own matrices
/// are built by the worker alone.
template <class Reduced, class Full>
class Basic_refining_spline_solver
{
public:
  typedef typename Reduced::Constraint_type Constraint;
  /// Makes the full solver for a tension omega (for the mesh scaled to unit area).
  typedef std::function<std::unique_ptr<Full>(double omega)> Full_factory;

  /// Both solvers must be empty and made with the same options (omega).
  /// \throws Invalid_input if a solver is missing or holds constraints.
  Basic_refining_spline_solver(std::unique_ptr<Reduced> reduced, std::unique_ptr<Full> full);
  /// The full solver is made when first needed (`refine`, or on the worker thread by
  /// `refine_in_background`, so that its factorisation does not hold up the caller); until
  /// then, and after `stop_refining`, nothing of it is held.
  Basic_refining_spline_solver(std::unique_ptr<Reduced> reduced, Full_factory make_full);
  ~Basic_refining_spline_solver();
  Basic_refining_spline_solver(const Basic_refining_spline_solver&) = delete;
  Basic_refining_spline_solver& operator=(const Basic_refining_spline_solver&) = delete;

  /// \throws as `Basic_spline_solver::add` (of the reduced solver); nothing changes then.
  Constraint_id add(const Constraint& constraint);
  std::vector<Constraint_id> add(const std::vector<Constraint>& constraints);
  /// Same rows: only values change (both solvers at once).  Other rows: the reduced solver
  /// at once, the full pull-back becomes pending.
  void change(Constraint_id id, const Constraint& constraint);
  void remove(Constraint_id id);
  void clear();
  /// A new tension: the worker is stopped, the reduced solver updated, and every pull-back
  /// becomes pending (they depend on the energy); a background refinement starts again.
  void set_omega(double omega);

  const Constraint& constraint(Constraint_id id) const;
  std::vector<Constraint_id> constraint_ids() const;
  int number_of_constraints() const { return static_cast<int>(entries_.size()); }

  /// Pulls back every pending constraint in this thread, then answers exactly.
  /// `cancelled` (optional) is asked between constraints; what is done stays done.
  /// \throws Infeasible_constraints if the full solver refuses a constraint the reduced one
  ///         took (the rows are nearly dependent): the answer stays reduced.
  void refine(const Refinement_progress& progress = Refinement_progress(),
              const std::function<bool()>& cancelled = std::function<bool()>());
  /// Starts (or keeps) a worker thread that pulls back every pending constraint, and every
  /// one added or moved later, until `stop_background`.
  void refine_in_background(Refinement_progress progress = Refinement_progress());
  /// Stops the worker after the pull-back under way (dropped); pending constraints stay
  /// pending, finished ones are kept.
  void stop_background();
  /// Stops the worker and drops the full solver with its pull-backs (one field per row: the
  /// memory an exact answer costs); answers are reduced until the next refinement.
  void stop_refining();
  /// A new reduced solver (another basis size): every constraint is added to it, all or
  /// nothing; the full solver and its pull-backs stay.
  /// \throws as `Basic_spline_solver::add`; nothing changes then.
  void replace_reduced(std::unique_ptr<Reduced> reduced);
  bool refining_in_background() const { return worker_.joinable(); }
  /// Waits until nothing is pending (or the timeout passes, or the worker failed), taking in
  /// the finished pull-backs.  True if the answer is exact.
  bool wait_until_exact(std::chrono::milliseconds timeout);
  /// The reason the full solver refused a constraint (empty if none): the answer stays reduced.
  const std::string& refinement_error() const { return error_; }

  /// Which spline `field` answers with (after taking in finished pull-backs).
  Spline_answer answer();
  bool is_exact() { return answer().exact; }

  /// The exact spline if nothing is pending, else the reduced one (frame or power
  /// coordinates, `2nf`).  `which` (optional) receives the answer this field is: with a
  /// worker running, a later `answer()` may already say otherwise.
  Eigen::VectorXd field(Spline_answer* which = nullptr);
  /// `field`, but with a worker running it first waits for the exact answer when the worker
  /// should have it sooner than the reduced field takes to make, judged by the last pull-back
  /// and the last reduced field measured (on the bunny, 69k faces, d = 1000: a pull-back
  /// takes 35 ms, the reduced field 70 ms).  The wait is at most 1.5 times the expected
  /// time; then the reduced field is made after all.  For a first answer to an edit.
  ///
  /// `worth_waiting_seconds`: a caller that has shown the edit otherwise in the meantime (the
  /// editor's preview strokes) waits for the exact field whenever the worker is expected to
  /// have it within this time, and for up to this time, instead of making the reduced field
  /// (on the 346k-face armadillo at d = 1000 the reduced field is 115 ms of memory traffic that
  /// slows the worker's solves beside it).
  Eigen::VectorXd soonest_field(Spline_answer* which = nullptr, double worth_waiting_seconds = 0);
  /// `field` while only the values of constraint `id` change (a drag): from the answering
  /// solver's cached response to them (`Basic_spline_solver::field_after_value_edit`).
  Eigen::VectorXd field_after_value_edit(Constraint_id id, Spline_answer* which = nullptr);
  /// The reduced spline while only the values of constraint `id` change, whichever answer
  /// `field` gives (to compare the two answers of one constraint set cheaply).
  Eigen::VectorXd reduced_field_after_value_edit(Constraint_id id) const;
  /// The report of the answering solver.
  const Spline_report& report();

  const Reduced& reduced() const { return *reduced_; }
  /// Null until the full solver is made (see the constructors).
  const Full* full() const { return full_.get(); }

private:
  struct Entry
  {
    Constraint constraint;
    Constraint_id reduced = -1;
    Constraint_id full = -1; // -1: pending
  };
  struct Finished
  {
    Constraint_id id;
    long generation;
    typename Full::Prepared prepared;
    double seconds = 0; // the pull-back took
  };

  void integrate();         // takes in finished pull-backs (calling thread)
  void enqueue(Constraint_id id);
  void make_pending(Entry& entry, Constraint_id id);
  void worker_loop(Full* full, double omega, Refinement_progress progress);
  int pending_count() const;

  std::unique_ptr<Reduced> reduced_;
  std::unique_ptr<Full> full_; // the calling thread's; null until made
  Full_factory make_full_;
  std::map<Constraint_id, Entry> entries_;
  Constraint_id next_id_ = 0;
  std::string error_;
  double pull_back_seconds_ = 0;     // the last finished pull-back (0: none yet)
  double reduced_field_seconds_ = 0; // the last reduced field made (0: none yet)

  // Shared with the worker (under mutex_): jobs (ids and the constraint to pull back),
  // finished pull-backs, and generations that tell stale work from current.
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::pair<Constraint_id, Constraint>> jobs_;
  std::vector<Finished> finished_;
  std::map<Constraint_id, long> generation_; // bumped by every move or removal
  std::unique_ptr<Full> made_full_;          // made by the worker, not yet taken in
  std::string worker_error_;                 // the worker could not make the full solver
  Constraint_id working_on_ = -1;
  bool stop_ = false;
  Refinement_progress progress_; // the worker's, kept for restarts (set_omega)
  std::thread worker_;
};

typedef Basic_refining_spline_solver<Reduced_spline_solver, Full_spline_solver> Refining_spline_solver;
typedef Basic_refining_spline_solver<Reduced_n_field_spline_solver, Full_n_field_spline_solver>
    Refining_n_field_spline_solver;
extern template class Basic_refining_spline_solver<Reduced_spline_solver, Full_spline_solver>;
extern template class Basic_refining_spline_solver<Reduced_n_field_spline_solver, Full_n_field_spline_solver>;

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
