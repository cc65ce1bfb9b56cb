// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_SPLINE_SOLVER_IMPL_H
#define CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_SPLINE_SOLVER_IMPL_H

// The definitions of Basic_spline_solver, included only by the translation units that
// instantiate it (src/tangent_vector_fields/design/spline_solver.cpp, src/tangent_vector_fields/n_fields/n_field_spline_solver.cpp).

#include <CGAL/Tangent_vector_fields/Spline_solver.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <thread>

namespace CGAL {
namespace Tangent_vector_fields {

template <class Constraint, class Operators>
Basic_spline_solver<Constraint, Operators>::Basic_spline_solver(std::shared_ptr<const Operators> operators, int harmonic_dimension,
                             const Spline_options& options)
  : operators_(std::move(operators)), options_(options), harmonic_dimension_(harmonic_dimension)
{
  if(!operators_) throw Invalid_input("spline solver: no operators given");
  if(!std::isfinite(options.omega) || options.omega < 0)
    throw Invalid_input("the tension omega must be finite and non-negative");
  if(!std::isfinite(options.harmonic_eigenvalue) || options.harmonic_eigenvalue < 0)
    throw Invalid_input("the harmonic eigenvalue must be finite and non-negative");
  set_scales();
  system_ = std::make_unique<internal::Constraint_system>(harmonic_dimension_, harmonic_scale_, harmonic_penalty_);
}

template <class Constraint, class Operators>
Basic_spline_solver<Constraint, Operators>::~Basic_spline_solver() = default;

template <class Constraint, class Operators>
void Basic_spline_solver<Constraint, Operators>::set_scales()
{
  // The energy is E_B + omega E_D with omega given on the unit-area mesh: lambda
  // scales as 1/area, so omega as 1/area too.  Areas in the solver's length unit
  // (see `length_unit_`).
  length_unit_ = internal::spline_length_unit(*operators_);
  const double area = operators_->face_areas().sum() / length_unit_ / length_unit_;
  omega_ = options_.omega / area;
  const double lambda = 1 / area;
  harmonic_scale_ = lambda * lambda + omega_ * lambda;
  const double lambda_h = options_.harmonic_eigenvalue / area;
  harmonic_penalty_ = lambda_h * lambda_h + omega_ * lambda_h;
}

template <class Constraint, class Operators>
Constraint_id Basic_spline_solver<Constraint, Operators>::add(const Constraint& constraint)
{
  return add(std::vector<Constraint>{constraint}).front();
}

template <class Constraint, class Operators>
std::vector<Constraint_id> Basic_spline_solver<Constraint, Operators>::add(const std::vector<Constraint>& constraints)
{
  std::vector<Constraint_id> ids;
  for(std::size_t i = 0; i < constraints.size(); ++i) ids.push_back(next_id_ + static_cast<int>(i));
  insert(constraints, ids);
  next_id_ += static_cast<int>(constraints.size());
  return ids;
}

template <class Constraint, class Operators>
typename Basic_spline_solver<Constraint, Operators>::Prepared
Basic_spline_solver<Constraint, Operators>::prepare(const std::vector<Constraint>& constraints) const
{
  // Rows first: a malformed constraint throws before anything is computed.
  Prepared prepared;
  prepared.constraints = constraints;
  prepared.energy_version = energy_version_;
  for(std::size_t i = 0; i < constraints.size(); ++i)
    for(Constraint_row& r : constraint_rows(*operators_, constraints[i]))
    {
      // Each row divided by a power of two near its largest entry (exact): divergence
      // and curl rows carry 1/size, which on a tiny mesh would overflow in the products
      // of the small system next to vector rows of size 1.
      Row row;
      double largest = 0;
      for(const auto& e : r.entries) largest = std::max(largest, std::abs(e.second));
      row.scale = largest > 0 && std::isfinite(largest) ? std::ldexp(1., std::ilogb(largest)) : 1.;
      for(auto& e : r.entries) e.second /= row.scale;
      r.value /= row.scale;
      row.row = std::move(r);
      prepared.rows.push_back(std::move(row));
      prepared.owner.push_back(static_cast<int>(i));
    }
  pull_back(prepared.rows);
  return prepared;
}

template <class Constraint, class Operators>
std::vector<Constraint_id> Basic_spline_solver<Constraint, Operators>::add_prepared(Prepared prepared,
                                                                                   const std::vector<Constraint>& values)
{
  if(prepared.energy_version != energy_version_)
    throw Invalid_input("prepared constraints: the energy (omega) changed since they were pulled back");
  if(!values.empty())
  {
    if(values.size() != prepared.constraints.size())
      throw Invalid_input("prepared constraints: " + std::to_string(values.size()) + " replacements for " +
                          std::to_string(prepared.constraints.size()) + " constraints");
    std::vector<int> next(values.size(), 0);
    std::vector<std::vector<double>> row_values(values.size());
    for(std::size_t i = 0; i < values.size(); ++i)
    {
      // Directions never have the same rows as another direction (their row is the
      // direction), but a copy of one has: compare the rows themselves then.
      auto identical_rows = [&] {
        const std::vector<Constraint_row> a = constraint_rows(*operators_, prepared.constraints[i]),
                                          b = constraint_rows(*operators_, values[i]);
        if(a.size() != b.size()) return false;
        for(std::size_t k = 0; k < a.size(); ++k)
          if(a[k].entries != b[k].entries) return false;
        return true;
      };
      if(!prepared.constraints[i].same_rows_as(values[i]) && !identical_rows())
        throw Invalid_input("prepared constraints: \"" + values[i].describe() + "\" has other rows than \"" +
                            prepared.constraints[i].describe() + "\"");
      row_values[i] = constraint_values(*operators_, values[i]);
      prepared.constraints[i] = values[i];
    }
    for(std::size_t j = 0; j < prepared.rows.size(); ++j)
    {
      const int i = prepared.owner[j];
      prepared.rows[j].row.value = row_values[i][next[i]++] / prepared.rows[j].scale;
    }
  }
  std::vector<Constraint_id> ids;
  for(std::size_t i = 0; i < prepared.constraints.size(); ++i) ids.push_back(next_id_ + static_cast<int>(i));
  append(prepared, ids);
  next_id_ += static_cast<int>(prepared.constraints.size());
  return ids;
}

template <class Constraint, class Operators>
void Basic_spline_solver<Constraint, Operators>::insert(const std::vector<Constraint>& constraints, const std::vector<Constraint_id>& ids)
{
  Prepared prepared = prepare(constraints);
  append(prepared, ids);
}

template <class Constraint, class Operators>
void Basic_spline_solver<Constraint, Operators>::append(Prepared& prepared, const std::vector<Constraint_id>& ids)
{
  const std::vector<Constraint>& constraints = prepared.constraints;
  std::vector<Row>& rows = prepared.rows;
  const std::vector<int>& owner = prepared.owner;

  const int first = number_of_rows();
  for(std::size_t j = 0; j < rows.size(); ++j)
  {
    const int n = number_of_rows();
    Eigen::VectorXd k(n);
    for(int i = 0; i < n; ++i) k[i] = apply(rows_[i], rows[j].y);
    const double kappa = apply(rows[j], rows[j].y);
    const double independence = system_->independence(k, kappa);
    if(!(independence >= options_.dependency_tolerance))
    {
      // The value the other rows already imply for this one: K^-1 k combines them.
      // With an unconstrained minimiser x0 the rows act on x - x0.
      const Eigen::VectorXd& x0 = unconstrained_minimiser();
      auto offset = [&](const Row& r) { return x0.size() > 0 ? apply(r, x0) : 0.; };
      double implied = offset(rows[j]);
      if(n > 0)
      {
        const Eigen::VectorXd alpha = system_->solve_K(k);
        for(int i = 0; i < n; ++i) implied += alpha[i] * (rows_[i].row.value - offset(rows_[i]));
      }
      implied *= rows[j].scale; // as given
      const double asked = rows[j].row.value * rows[j].scale;
      const double residual = std::abs(asked - implied);
      const std::string hint = dependency_hint();
      // All or nothing: take back the rows of this call.
      if(n > first) system_->remove(first, n - first);
      rows_.resize(first);
      std::ostringstream s;
      s << "constraint \"" << constraints[owner[j]].describe() << "\" depends on the constraints already set (sin^2 "
        << independence << " < tolerance " << options_.dependency_tolerance << "); they imply the value " << implied
        << " where " << asked << " is asked: residual " << residual;
      if(kappa == 0) s << " (the row is zero on every field the solver can represent)";
      if(!hint.empty()) s << "; " << hint;
      throw Infeasible_constraints(s.str(), independence, residual);
    }
    system_->append(k, kappa, rows[j].harmonic);
    rows_.push_back(std::move(rows[j]));
  }
  int row = first;
  for(std::size_t i = 0; i < constraints.size(); ++i)
  {
    const int count = static_cast<int>(std::count(owner.begin(), owner.end(), static_cast<int>(i)));
    entries_[ids[i]] = Entry{constraints[i], row, count};
    row += count;
  }
  ++version_;
  solved_ = false;
}


template <class Constraint, class Operators>
void Basic_spline_solver<Constraint, Operators>::change(Constraint_id id, const Constraint& constraint)
{
  auto it = entries_.find(id);
  if(it == entries_.end()) throw Invalid_input("no constraint with id " + std::to_string(id));
  Entry& entry = it->second;
  if(entry.constraint.same_rows_as(constraint))
  {
    // Only the values change: no new rows (the fast path of interactive edits).
    const std::vector<double> values = constraint_values(*operators_, constraint);
    for(int k = 0; k < entry.row_count; ++k)
    {
      Row& row = rows_[entry.first_row + k];
      row.row.value = values[k] / row.scale;
    }
    entry.constraint = constraint;
    if(id != edit_cache_.id) ++version_; // the cached field was made with the old values
    solved_ = false;
    return;
  }
  const Constraint old = entry.constraint;
  remove(id);
  try
  {
    insert({constraint}, {id});
  }
  catch(...)
  {
    insert({old}, {id}); // it fitted before
    throw;
  }
}

template <class Constraint, class Operators>
void Basic_spline_solver<Constraint, Operators>::remove(Constraint_id id)
{
  auto it = entries_.find(id);
  if(it == entries_.end()) throw Invalid_input("no constraint with id " + std::to_string(id));
  const int first = it->second.first_row, count = it->second.row_count;
  system_->remove(first, count);
  rows_.erase(rows_.begin() + first, rows_.begin() + first + count);
  entries_.erase(it);
  for(auto& e : entries_)
    if(e.second.first_row > first) e.second.first_row -= count;
  ++version_;
  ++rows_dropped_;
  solved_ = false;
}

template <class Constraint, class Operators>
void Basic_spline_solver<Constraint, Operators>::clear()
{
  entries_.clear();
  rows_.clear();
  system_ = std::make_unique<internal::Constraint_system>(harmonic_dimension_, harmonic_scale_, harmonic_penalty_);
  ++version_;
  ++rows_dropped_;
  solved_ = false;
}

template <class Constraint, class Operators>
void Basic_spline_solver<Constraint, Operators>::set_omega(double omega)
{
  if(!std::isfinite(omega) || omega < 0) throw Invalid_input("the tension omega must be finite and non-negative");
  const double previous = options_.omega;
  options_.omega = omega;
  ++energy_version_;
  set_scales();
  try
  {
    energy_changed();
  }
  catch(...)
  {
    // A solver may refuse an energy (Full_n_field_spline_solver: omega > 0 with m >= 3): unchanged.
    options_.omega = previous;
    set_scales();
    energy_changed();
    throw;
  }
  // Every pull-back depends on the energy: rebuild the small system in the same order.
  std::vector<std::pair<Constraint_id, Entry>> entries(entries_.begin(), entries_.end());
  std::sort(entries.begin(), entries.end(),
            [](const auto& a, const auto& b) { return a.second.first_row < b.second.first_row; });
  entries_.clear();
  rows_.clear();
  ++rows_dropped_;
  system_ = std::make_unique<internal::Constraint_system>(harmonic_dimension_, harmonic_scale_, harmonic_penalty_);
  std::vector<Constraint> constraints;
  std::vector<Constraint_id> ids;
  for(const auto& e : entries)
  {
    constraints.push_back(e.second.constraint);
    ids.push_back(e.first);
  }
  insert(constraints, ids);
}

template <class Constraint, class Operators>
const Constraint& Basic_spline_solver<Constraint, Operators>::constraint(Constraint_id id) const
{
  auto it = entries_.find(id);
  if(it == entries_.end()) throw Invalid_input("no constraint with id " + std::to_string(id));
  return it->second.constraint;
}

template <class Constraint, class Operators>
std::vector<Constraint_id> Basic_spline_solver<Constraint, Operators>::constraint_ids() const
{
  std::vector<Constraint_id> ids;
  for(const auto& e : entries_) ids.push_back(e.first);
  return ids;
}

template <class Constraint, class Operators>
const Eigen::VectorXd& Basic_spline_solver<Constraint, Operators>::solution() const
{
  if(!solved_) solve();
  return solution_;
}

template <class Constraint, class Operators>
const Spline_report& Basic_spline_solver<Constraint, Operators>::report() const
{
  if(!solved_) solve();
  if(!reported_) make_report();
  return report_;
}

template <class Constraint, class Operators>
Eigen::VectorXd Basic_spline_solver<Constraint, Operators>::values(Constraint_id id) const
{
  auto it = entries_.find(id);
  if(it == entries_.end()) throw Invalid_input("no constraint with id " + std::to_string(id));
  Eigen::VectorXd c(it->second.row_count);
  for(int k = 0; k < c.size(); ++k)
  {
    const Row& row = rows_[it->second.first_row + k];
    c[k] = row.row.value * row.scale; // as given
  }
  return c;
}

template <class Constraint, class Operators>
Eigen::MatrixXd Basic_spline_solver<Constraint, Operators>::value_response(Constraint_id id) const
{
  auto it = entries_.find(id);
  if(it == entries_.end()) throw Invalid_input("no constraint with id " + std::to_string(id));
  // The solution is x0 + sum_i mu_i y_i + harmonic(z) with (mu, z) linear in the
  // right-hand side c - C x0: a unit change of row value k is the solve for e_k.
  const int n = number_of_rows();
  const int count = it->second.row_count;
  Eigen::MatrixXd mus(n, count);
  std::vector<Eigen::VectorXd> zs(count);
  for(int k = 0; k < count; ++k)
  {
    Eigen::VectorXd c = Eigen::VectorXd::Zero(n), mu;
    c[it->second.first_row + k] = 1;
    system_->solve(c, mu, zs[k]);
    mus.col(k) = mu;
  }
  Eigen::MatrixXd response = combined_pull_backs(mus);
  for(int k = 0; k < count; ++k)
  {
    if(zs[k].size() > 0)
    {
      Eigen::VectorXd x = response.col(k);
      add_harmonic(zs[k], x);
      response.col(k) = x;
    }
    response.col(k) /= rows_[it->second.first_row + k].scale; // per unit of the value as given
  }
  return response;
}

template <class Constraint, class Operators>
Eigen::VectorXd Basic_spline_solver<Constraint, Operators>::field_after_value_edit(Constraint_id id) const
{
  const Eigen::VectorXd c = values(id);
  Value_edit_cache& cache = edit_cache_;
  if(cache.id != id || cache.version != version_)
  {
    // One pass over the basis for the field and its responses.
    const Eigen::MatrixXd response = value_response(id);
    Eigen::MatrixXd solutions(space_dimension(), 1 + response.cols());
    solutions.col(0) = solution();
    solutions.rightCols(response.cols()) = response;
    const Eigen::MatrixXd x = fields_of(solutions);
    cache.id = id;
    cache.version = version_;
    cache.values = c;
    cache.field = x.col(0);
    cache.responses = x.rightCols(response.cols());
    return cache.field;
  }
  Eigen::VectorXd x = cache.field + cache.responses * (c - cache.values);
  if(!x.allFinite()) throw Numerical_failure("the spline solve produced non-finite values");
  return x;
}

template <class Constraint, class Operators>
void Basic_spline_solver<Constraint, Operators>::solve() const
{
  const int n = number_of_rows();
  const Eigen::VectorXd& x0 = unconstrained_minimiser();
  Eigen::VectorXd c(n);
  for(int i = 0; i < n; ++i) c[i] = rows_[i].row.value - (x0.size() > 0 ? apply(rows_[i], x0) : 0.);
  // The spline is linear in the values: solved for values scaled to at most 1 (by a
  // power of two, exact) and scaled back, so that values near the largest double
  // overflow only if the field itself does.
  const double largest = c.size() > 0 ? c.cwiseAbs().maxCoeff() : 0.;
  const double scale = largest > 0 && std::isfinite(largest) ? std::ldexp(1., std::ilogb(largest) + 1) : 1.;
  Eigen::VectorXd mu, z;
  system_->solve(c / scale, mu, z);
  Eigen::VectorXd x = combined_pull_backs(mu);
  if(z.size() > 0) add_harmonic(z, x);
  solution_ = x * scale;
  if(x0.size() > 0) solution_ += x0;
  if(!solution_.allFinite())
  {
    std::ostringstream s;
    s << "the spline is not finite in double precision: its constraint values reach " << largest;
    throw Numerical_failure(s.str());
  }
  solved_ = true;
  reported_ = false;
}

// Blocked so that each pull-back is read once while a block of the result stays in cache:
// at 346k faces 62 pull-backs are 340 MB, and `x += mu_i y_i` row by row also read and wrote
// the 5.5 MB result 62 times.  Large sums are split over two threads.
template <class Constraint, class Operators>
Eigen::MatrixXd Basic_spline_solver<Constraint, Operators>::combined_pull_backs(const Eigen::MatrixXd& weights) const
{
  const Eigen::Index size = space_dimension(), n = weights.rows(), k = weights.cols();
  Eigen::MatrixXd x(size, k);
  auto combine = [&](Eigen::Index begin, Eigen::Index end) {
    const Eigen::Index block = 1024;
    for(Eigen::Index b = begin; b < end; b += block)
    {
      const Eigen::Index length = std::min(block, end - b);
      x.middleRows(b, length).setZero();
      for(Eigen::Index i = 0; i < n; ++i)
        for(Eigen::Index c = 0; c < k; ++c)
          if(weights(i, c) != 0) x.col(c).segment(b, length) += weights(i, c) * rows_[i].y.segment(b, length);
    }
  };
  if(size * n * k >= (Eigen::Index(1) << 22) && std::thread::hardware_concurrency() > 1)
  {
    const Eigen::Index half = size / 2;
    std::thread second(combine, half, size);
    combine(0, half);
    second.join();
  }
  else
    combine(0, size);
  return x;
}

// The report costs as much as the solve (a pass over every row, the energy): it is
// made only when asked for, not on every edit.
template <class Constraint, class Operators>
void Basic_spline_solver<Constraint, Operators>::make_report() const
{
  const int n = number_of_rows();
  Spline_report r;
  r.constraints = number_of_constraints();
  r.rows = n;
  r.smallest_independence = system_->smallest_independence();
  r.undetermined_harmonic = n > 0 ? system_->undetermined_harmonic() : harmonic_dimension_;
  double largest = 0, residual = 0;
  for(int i = 0; i < n; ++i)
  {
    // The rows as given (unscaled).
    const double c = rows_[i].row.value * rows_[i].scale;
    largest = std::max(largest, std::abs(c));
    residual = std::max(residual, std::abs(apply(rows_[i], solution_) - rows_[i].row.value) * rows_[i].scale);
  }
  r.constraint_residual = largest > 0 ? residual / largest : residual;
  // For the mesh as given; a quadratic energy (no linear term, no offset) from the
  // solution scaled to near 1, so that its squares cannot overflow.
  {
    const double largest = solution_.size() > 0 ? solution_.cwiseAbs().maxCoeff() : 0.;
    const bool quadratic = unconstrained_minimiser().size() == 0;
    const double scale = quadratic && largest > 0 ? std::ldexp(1., std::ilogb(largest)) : 1.;
    r.energy = energy(solution_ / scale) / length_unit_ / length_unit_ * scale * scale;
  }
  if(n > 0 && r.smallest_independence < options_.warning_tolerance)
  {
    std::ostringstream s;
    s << "nearly dependent constraints (sin^2 " << r.smallest_independence
      << "): meeting all of them makes the field swing wildly between them";
    r.warnings.push_back(s.str());
  }
  if(r.undetermined_harmonic > 0)
    r.warnings.push_back(std::to_string(r.undetermined_harmonic) + " of " + std::to_string(harmonic_dimension_) + " " +
                         kernel_noun() + " directions are not determined by the constraints and set to zero");
  if(n > 0 && system_->harmonic_determination() < 1e-6)
  {
    std::ostringstream s;
    s << "the " << kernel_noun() << " part is only weakly determined by the constraints (" << system_->harmonic_determination()
      << " of the energy scale): it may be large";
    r.warnings.push_back(s.str());
  }
  r.error_bound = relative_error_bound();
  if(r.error_bound > error_bound_warning)
  {
    std::ostringstream s;
    s << "the reduced answer may be far from the exact spline: the bound on its energy-norm error is " << r.error_bound
      << " of the exact field's; use a larger basis, or refine to the exact spline";
    r.warnings.push_back(s.str());
  }
  if(!std::isfinite(r.energy))
  {
    // A finite field whose energy exceeds the largest double: report it, do not fail.
    r.energy = std::numeric_limits<double>::infinity();
    r.warnings.push_back("the field's energy exceeds the largest double (the constraint values are huge)");
  }
  report_ = r;
  reported_ = true;
}

} // namespace Tangent_vector_fields
} // namespace CGAL

#include <CGAL/Tangent_vector_fields/internal/Spline_error_bound_impl.h>

#endif
