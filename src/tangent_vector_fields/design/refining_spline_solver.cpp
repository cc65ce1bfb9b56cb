// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The refining spline: reduced answers at once, full pull-backs on request or on a worker
// thread, exact answers once nothing is pending.  Instantiated for vector fields and n-fields.

#include <CGAL/Tangent_vector_fields/Refining_spline_solver.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#if defined(__linux__)
#include <sys/resource.h>
#endif

namespace CGAL {
namespace Tangent_vector_fields {

namespace {

// The worker yields the cores to the caller's threads: what the user waits for first (the
// editor's preview strokes, a reduced field) is made beside the pull-backs on the same cores
// (346k faces: the preview's strokes took 85 ms beside the worker against 30 ms alone).  Linux
// keeps the nice value per thread, and threads the worker starts inherit it.
void lower_this_threads_priority()
{
#if defined(__linux__)
  errno = 0;
  const int nice = getpriority(PRIO_PROCESS, 0);
  if(errno == 0) setpriority(PRIO_PROCESS, 0, std::min(nice + 10, 19)); // no harm if refused
#endif
}

} // namespace

template <class Reduced, class Full>
Basic_refining_spline_solver<Reduced, Full>::Basic_refining_spline_solver(std::unique_ptr<Reduced> reduced,
                                                                         std::unique_ptr<Full> full)
  : reduced_(std::move(reduced)), full_(std::move(full))
{
  if(!reduced_ || !full_) throw Invalid_input("refining spline: both a reduced and a full solver are needed");
  if(reduced_->number_of_constraints() > 0 || full_->number_of_constraints() > 0)
    throw Invalid_input("refining spline: the solvers must start without constraints");
  if(reduced_->options().omega != full_->options().omega)
    throw Invalid_input("refining spline: the solvers have different tensions");
}

template <class Reduced, class Full>
Basic_refining_spline_solver<Reduced, Full>::Basic_refining_spline_solver(std::unique_ptr<Reduced> reduced,
                                                                         Full_factory make_full)
  : reduced_(std::move(reduced)), make_full_(std::move(make_full))
{
  if(!reduced_ || !make_full_) throw Invalid_input("refining spline: a reduced solver and a way to make the full one are needed");
  if(reduced_->number_of_constraints() > 0) throw Invalid_input("refining spline: the solver must start without constraints");
}

template <class Reduced, class Full>
Basic_refining_spline_solver<Reduced, Full>::~Basic_refining_spline_solver()
{
  stop_background();
}

template <class Reduced, class Full>
int Basic_refining_spline_solver<Reduced, Full>::pending_count() const
{
  int pending = 0;
  for(const auto& e : entries_) pending += e.second.full < 0;
  return pending;
}

template <class Reduced, class Full>
void Basic_refining_spline_solver<Reduced, Full>::enqueue(Constraint_id id)
{
  if(!worker_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    // One job per constraint: a later move replaces the constraint of a job still waiting.
    auto it = std::find_if(jobs_.begin(), jobs_.end(), [id](const auto& job) { return job.first == id; });
    if(it != jobs_.end()) it->second = entries_.at(id).constraint;
    else jobs_.emplace_back(id, entries_.at(id).constraint);
  }
  changed_.notify_all();
}

template <class Reduced, class Full>
void Basic_refining_spline_solver<Reduced, Full>::make_pending(Entry& entry, Constraint_id id)
{
  if(entry.full >= 0) full_->remove(entry.full);
  entry.full = -1;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ++generation_[id]; // a pull-back under way for the old rows is stale
  }
  enqueue(id);
}

template <class Reduced, class Full>
Constraint_id Basic_refining_spline_solver<Reduced, Full>::add(const Constraint& constraint)
{
  return add(std::vector<Constraint>{constraint}).front();
}

template <class Reduced, class Full>
std::vector<Constraint_id> Basic_refining_spline_solver<Reduced, Full>::add(const std::vector<Constraint>& constraints)
{
  integrate();
  const std::vector<Constraint_id> reduced_ids = reduced_->add(constraints); // all or nothing
  std::vector<Constraint_id> ids;
  for(std::size_t i = 0; i < constraints.size(); ++i)
  {
    const Constraint_id id = next_id_++;
    entries_[id] = Entry{constraints[i], reduced_ids[i], -1};
    ids.push_back(id);
    enqueue(id);
  }
  return ids;
}

template <class Reduced, class Full>
void Basic_refining_spline_solver<Reduced, Full>::change(Constraint_id id, const Constraint& constraint)
{
  integrate();
  auto it = entries_.find(id);
  if(it == entries_.end()) throw Invalid_input("no constraint with id " + std::to_string(id));
  Entry& entry = it->second;
  const bool same_rows = entry.constraint.same_rows_as(constraint);
  reduced_->change(entry.reduced, constraint); // unchanged if it throws
  entry.constraint = constraint;
  if(!same_rows) make_pending(entry, id);
  else if(entry.full >= 0) full_->change(entry.full, constraint);
  // Pending with the same rows: the pull-back does not depend on values; it is taken in with
  // the values of then.
}

template <class Reduced, class Full>
void Basic_refining_spline_solver<Reduced, Full>::remove(Constraint_id id)
{
  integrate();
  auto it = entries_.find(id);
  if(it == entries_.end()) throw Invalid_input("no constraint with id " + std::to_string(id));
  reduced_->remove(it->second.reduced);
  if(it->second.full >= 0) full_->remove(it->second.full);
  entries_.erase(it);
  std::lock_guard<std::mutex> lock(mutex_);
  ++generation_[id];
  jobs_.erase(std::remove_if(jobs_.begin(), jobs_.end(), [id](const auto& job) { return job.first == id; }), jobs_.end());
}

template <class Reduced, class Full>
void Basic_refining_spline_solver<Reduced, Full>::clear()
{
  integrate();
  reduced_->clear();
  if(full_) full_->clear();
  std::lock_guard<std::mutex> lock(mutex_);
  for(const auto& e : entries_) ++generation_[e.first];
  jobs_.clear();
  entries_.clear();
  error_.clear();
}

template <class Reduced, class Full>
void Basic_refining_spline_solver<Reduced, Full>::set_omega(double omega)
{
  // The worker reads the factorisations that a new energy replaces: stop it first.
  const bool background = worker_.joinable();
  stop_background();
  const double previous = reduced_->options().omega;
  reduced_->set_omega(omega); // unchanged if it throws
  try
  {
    if(full_)
    {
      full_->clear(); // every pull-back depends on the energy
      full_->set_omega(omega);
    }
  }
  catch(...)
  {
    reduced_->set_omega(previous);
    for(auto& e : entries_) e.second.full = -1;
    if(background) refine_in_background(progress_);
    throw;
  }
  for(auto& e : entries_) e.second.full = -1;
  error_.clear();
  if(background) refine_in_background(progress_);
}

template <class Reduced, class Full>
const typename Basic_refining_spline_solver<Reduced, Full>::Constraint&
Basic_refining_spline_solver<Reduced, Full>::constraint(Constraint_id id) const
{
  auto it = entries_.find(id);
  if(it == entries_.end()) throw Invalid_input("no constraint with id " + std::to_string(id));
  return it->second.constraint;
}

template <class Reduced, class Full>
std::vector<Constraint_id> Basic_refining_spline_solver<Reduced, Full>::constraint_ids() const
{
  std::vector<Constraint_id> ids;
  for(const auto& e : entries_) ids.push_back(e.first);
  return ids;
}

template <class Reduced, class Full>
void Basic_refining_spline_solver<Reduced, Full>::integrate()
{
  std::vector<Finished> finished;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    finished.swap(finished_);
    if(made_full_) full_ = std::move(made_full_);
    if(!worker_error_.empty()) error_ = worker_error_;
  }
  for(Finished& f : finished)
  {
    auto it = entries_.find(f.id);
    if(it == entries_.end() || it->second.full >= 0) continue; // removed meanwhile, or done
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if(generation_[f.id] != f.generation) continue; // moved meanwhile: stale
    }
    pull_back_seconds_ = f.seconds;
    try
    {
      // With the values of now: value edits made while it was pulled back.
      it->second.full = full_->add_prepared(std::move(f.prepared), {it->second.constraint}).front();
    }
    catch(const Infeasible_constraints& e)
    {
      error_ = e.what();
      it->second.full = -2; // refused at full resolution: the answer stays reduced
    }
  }
}

template <class Reduced, class Full>
void Basic_refining_spline_solver<Reduced, Full>::refine(const Refinement_progress& progress,
                                                         const std::function<bool()>& cancelled)
{
  // One thread pulls back at a time (the full solver's factorisations are made on first use).
  const bool background = worker_.joinable();
  stop_background();
  if(!full_) full_ = make_full_(reduced_->options().omega);
  std::vector<Constraint_id> pending;
  for(const auto& e : entries_)
    if(e.second.full == -1) pending.push_back(e.first);
  int done = 0;
  for(Constraint_id id : pending)
  {
    if(cancelled && cancelled()) break;
    Entry& entry = entries_.at(id);
    try
    {
      entry.full = full_->add(entry.constraint);
    }
    catch(const Infeasible_constraints& e)
    {
      error_ = e.what();
      entry.full = -2;
      if(background) refine_in_background(progress_);
      throw;
    }
    if(progress) progress(++done, static_cast<int>(pending.size()));
  }
  if(background) refine_in_background(progress_);
}

template <class Reduced, class Full>
void Basic_refining_spline_solver<Reduced, Full>::refine_in_background(Refinement_progress progress)
{
  integrate();
  if(!worker_.joinable())
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = false;
    }
    progress_ = progress;
    worker_error_.clear();
    Full* full = full_.get(); // null: the worker makes it
    const double omega = reduced_->options().omega;
    worker_ = std::thread([this, full, omega, progress] { worker_loop(full, omega, progress); });
  }
  for(const auto& e : entries_)
    if(e.second.full == -1) enqueue(e.first);
}

template <class Reduced, class Full>
void Basic_refining_spline_solver<Reduced, Full>::worker_loop(Full* full, double omega, Refinement_progress progress)
{
  lower_this_threads_priority();
  if(!full)
  {
    // Made here: its factorisation is the first part of the wait for an exact answer.
    try
    {
      std::unique_ptr<Full> made = make_full_(omega);
      full = made.get();
      std::lock_guard<std::mutex> lock(mutex_);
      made_full_ = std::move(made);
    }
    catch(const std::exception& e)
    {
      std::lock_guard<std::mutex> lock(mutex_);
      worker_error_ = std::string("the full solver could not be made: ") + e.what();
      jobs_.clear();
      changed_.notify_all();
      return;
    }
  }
  int done = 0;
  std::unique_lock<std::mutex> lock(mutex_);
  for(;;)
  {
    changed_.wait(lock, [this] { return stop_ || !jobs_.empty(); });
    if(stop_) break;
    const auto [id, constraint] = jobs_.front();
    jobs_.pop_front();
    const long generation = generation_[id];
    working_on_ = id;
    lock.unlock();
    Finished finished{id, generation, typename Full::Prepared()};
    bool ok = true;
    try
    {
      const auto start = std::chrono::steady_clock::now();
      finished.prepared = full->prepare({constraint});
      finished.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    catch(...)
    {
      ok = false; // malformed at full resolution cannot happen (the reduced solver took it); drop
    }
    lock.lock();
    working_on_ = -1;
    if(ok && !stop_)
    {
      finished_.push_back(std::move(finished));
      ++done;
      const int total = done + static_cast<int>(jobs_.size());
      if(progress)
      {
        lock.unlock();
        progress(done, total);
        lock.lock();
      }
    }
    changed_.notify_all();
  }
}

template <class Reduced, class Full>
void Basic_refining_spline_solver<Reduced, Full>::stop_background()
{
  if(!worker_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
    jobs_.clear();
  }
  changed_.notify_all();
  worker_.join();
  worker_ = std::thread();
  integrate(); // what finished before the stop is kept
}

template <class Reduced, class Full>
void Basic_refining_spline_solver<Reduced, Full>::stop_refining()
{
  stop_background();
  full_.reset();
  for(auto& e : entries_) e.second.full = -1;
  error_.clear();
}

template <class Reduced, class Full>
void Basic_refining_spline_solver<Reduced, Full>::replace_reduced(std::unique_ptr<Reduced> reduced)
{
  if(!reduced || reduced->number_of_constraints() > 0)
    throw Invalid_input("refining spline: the new reduced solver must exist and start without constraints");
  std::vector<Constraint> constraints;
  for(const auto& e : entries_) constraints.push_back(e.second.constraint);
  const std::vector<Constraint_id> ids = reduced->add(constraints); // all or nothing
  std::size_t i = 0;
  for(auto& e : entries_) e.second.reduced = ids[i++];
  reduced_ = std::move(reduced);
}

template <class Reduced, class Full>
bool Basic_refining_spline_solver<Reduced, Full>::wait_until_exact(std::chrono::milliseconds timeout)
{
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for(;;)
  {
    integrate();
    if(full_ && pending_count() == 0) return true;
    std::unique_lock<std::mutex> lock(mutex_);
    // Nothing will arrive without a worker with work (or a finished result waiting).
    if(!worker_error_.empty()) return false;
    if(!worker_.joinable() || (jobs_.empty() && working_on_ < 0 && finished_.empty() && !made_full_)) return false;
    if(!finished_.empty() || made_full_) continue;
    if(changed_.wait_until(lock, deadline) == std::cv_status::timeout && finished_.empty()) return false;
  }
}

template <class Reduced, class Full>
Spline_answer Basic_refining_spline_solver<Reduced, Full>::answer()
{
  integrate();
  Spline_answer a;
  a.pending = pending_count();
  a.exact = full_ && a.pending == 0;
  a.basis_size = reduced_->basis_size();
  return a;
}

template <class Reduced, class Full>
Eigen::VectorXd Basic_refining_spline_solver<Reduced, Full>::field(Spline_answer* which)
{
  const Spline_answer a = answer();
  if(which) *which = a;
  if(a.exact && full_) return full_->field();
  const auto start = std::chrono::steady_clock::now();
  Eigen::VectorXd x = reduced_->field();
  reduced_field_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return x;
}

template <class Reduced, class Full>
Eigen::VectorXd Basic_refining_spline_solver<Reduced, Full>::soonest_field(Spline_answer* which,
                                                                           double worth_waiting_seconds)
{
  if(!(worth_waiting_seconds >= 0) || !std::isfinite(worth_waiting_seconds))
    throw Invalid_input("soonest_field: the time worth waiting must be finite and non-negative");
  const Spline_answer a = answer();
  if(!a.exact && a.pending > 0 && worker_.joinable() && pull_back_seconds_ > 0)
  {
    const double expected = a.pending * pull_back_seconds_;
    if(expected < worth_waiting_seconds)
      wait_until_exact(std::chrono::milliseconds(static_cast<long>(std::ceil(1e3 * worth_waiting_seconds))));
    else if(reduced_field_seconds_ > 0 && expected < reduced_field_seconds_)
      wait_until_exact(std::chrono::milliseconds(2 + static_cast<long>(1.5e3 * expected)));
  }
  return field(which);
}

template <class Reduced, class Full>
Eigen::VectorXd Basic_refining_spline_solver<Reduced, Full>::field_after_value_edit(Constraint_id id,
                                                                                    Spline_answer* which)
{
  const Spline_answer a = answer();
  if(which) *which = a;
  const bool exact = a.exact;
  auto it = entries_.find(id);
  if(it == entries_.end()) throw Invalid_input("no constraint with id " + std::to_string(id));
  return exact && full_ ? full_->field_after_value_edit(it->second.full)
                        : reduced_->field_after_value_edit(it->second.reduced);
}

template <class Reduced, class Full>
Eigen::VectorXd Basic_refining_spline_solver<Reduced, Full>::reduced_field_after_value_edit(Constraint_id id) const
{
  auto it = entries_.find(id);
  if(it == entries_.end()) throw Invalid_input("no constraint with id " + std::to_string(id));
  return reduced_->field_after_value_edit(it->second.reduced);
}

template <class Reduced, class Full>
const Spline_report& Basic_refining_spline_solver<Reduced, Full>::report()
{
  return answer().exact && full_ ? full_->report() : reduced_->report();
}

template class Basic_refining_spline_solver<Reduced_spline_solver, Full_spline_solver>;
template class Basic_refining_spline_solver<Reduced_n_field_spline_solver, Full_n_field_spline_solver>;

} // namespace Tangent_vector_fields
} // namespace CGAL
