// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_SPLINE_ERROR_BOUND_IMPL_H
#define CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_SPLINE_ERROR_BOUND_IMPL_H

// The a-posteriori error bound of a reduced spline (Spline_report::error_bound), included by
// Spline_solver_impl.h.
//
// The spline minimises E(x) = x^T Q x subject to C x = c.  With x* the exact minimiser and x
// the reduced one (a feasible point of the same constraints, in the span of the basis),
// optimality of x* (Q x* = C^T mu*) gives
//     |x - x*|_Q^2 = E(x) - E(x*),
// so the error is the reduced answer's excess energy.  E(x) is known; E(x*) is bounded from
// below by duality: E(x*) = max { 2 mu.c - mu^T K mu : mu^T C_h = 0 } with K = C Q^+ C^T the
// exact pull-backs' Gram matrix, and any K' >= K gives a smaller maximum.  In the MX-orthonormal
// eigenbasis u_k of the energy (Q^+ = sum u_k u_k^T / D_k over the fields with energy),
//     K = K_d + sum_{k > d} (C u_k)(C u_k)^T / D_k
//       <= K_d + (C MX^-1 C^T - sum_{k <= d} (C u_k)(C u_k)^T) / D_min,
// where K_d is the reduced solver's Gram matrix and D_min the lowest energy of a field missing
// from the basis (its eigenvalue is at least the basis' `complete_below`), because
// sum_k u_k u_k^T = MX^-1 over the whole space.  Everything on the right is known to a reduced
// solver: its rows on the basis and the rows themselves.  So E_low, the maximum with K', is
// at most E(x*), and
//     |x - x*|_Q / |x*|_Q <= sqrt((E(x) - E_low) / E_low).
// Both energies are values of the small system, mu.c (with the harmonic part, free or with the
// ridge kappa |z|^2, eliminated as the solver eliminates it).  Cost: the rows' Gram matrix on
// the basis, O(rows^2 d), once per change of the rows (value edits keep it), and two small
// solves per report; a new row adds O(rows d).

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

namespace internal {
// A constraint row's entries sorted by coordinate, repeated coordinates summed.
inline std::vector<std::pair<int, double>> sorted_entries(const Constraint_row& row)
{
  std::vector<std::pair<int, double>> entries = row.entries;
  std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::pair<int, double>> merged;
  for(const auto& e : entries)
  {
    if(!merged.empty() && merged.back().first == e.first) merged.back().second += e.second;
    else merged.push_back(e);
  }
  return merged;
}

// r_a MX^-1 r_b^T of two sorted rows.
inline double mass_inverse_product(const std::vector<std::pair<int, double>>& a,
                                   const std::vector<std::pair<int, double>>& b, const Eigen::VectorXd& masses)
{
  double sum = 0;
  std::size_t i = 0, j = 0;
  while(i < a.size() && j < b.size())
  {
    if(a[i].first < b[j].first) ++i;
    else if(b[j].first < a[i].first) ++j;
    else
    {
      sum += a[i].second * b[j].second / masses[a[i].first];
      ++i;
      ++j;
    }
  }
  return sum;
}
} // namespace internal

template <class Constraint, class Operators>
double Basic_spline_solver<Constraint, Operators>::relative_error_bound() const
{
  const int n = number_of_rows();
  if(n == 0) return 0; // no constraint: the spline is zero in every solver
  if(unconstrained_minimiser().size() > 0) return std::numeric_limits<double>::quiet_NaN(); // a linear term
  const double lowest = lowest_missing_energy();
  if(!(lowest > 0)) return std::numeric_limits<double>::quiet_NaN();
  if(lowest == std::numeric_limits<double>::infinity()) return 0; // nothing is missing: exact
  if(!bound_system_ || bound_dropped_ != rows_dropped_)
  {
    // Rows were dropped (or the energy changed): start again.
    bound_system_ =
        std::make_unique<internal::Constraint_system>(harmonic_dimension_, harmonic_scale_, harmonic_penalty_);
    bound_entries_.clear();
    bound_dropped_ = rows_dropped_;
  }
  if(bound_system_->size() < n)
  {
    // Only appended rows are new: the earlier ones and their entries are kept.
    const Eigen::VectorXd masses = field_masses();
    for(int i = bound_system_->size(); i < n; ++i)
    {
      bound_entries_.push_back(internal::sorted_entries(rows_[i].row));
      for(const auto& e : bound_entries_.back())
        if(!(masses[e.first] > 0))
        {
          bound_system_.reset(); // a face without area: unknown, and the system incomplete
          return std::numeric_limits<double>::quiet_NaN();
        }
    }
    // The part of r_i MX^-1 r_j^T outside the basis, over the lowest missing energy.
    auto outside = [&](int i, int j) {
      return (internal::mass_inverse_product(bound_entries_[i], bound_entries_[j], masses) -
              represented_product(rows_[i], rows_[j])) /
             lowest;
    };
    for(int j = bound_system_->size(); j < n; ++j)
    {
      Eigen::VectorXd k(j);
      for(int i = 0; i < j; ++i) k[i] = apply(rows_[i], rows_[j].y) + outside(i, j);
      // The diagonal part outside is a squared norm: never below 0 but for rounding.
      const double kappa = apply(rows_[j], rows_[j].y) + std::max(0., outside(j, j));
      bound_system_->append(k, kappa, rows_[j].harmonic);
    }
  }
  // Values scaled to at most 1 (a power of two), as `solve` scales them: the ratio is scale-free.
  Eigen::VectorXd c(n);
  for(int i = 0; i < n; ++i) c[i] = rows_[i].row.value;
  const double largest = c.cwiseAbs().maxCoeff();
  if(!(largest > 0)) return 0; // all values 0: the spline is zero in every solver
  c /= std::ldexp(1., std::ilogb(largest) + 1);
  Eigen::VectorXd mu, z;
  system_->solve(c, mu, z);
  const double reduced_energy = mu.dot(c);
  bound_system_->solve(c, mu, z);
  const double lower_energy = mu.dot(c);
  if(!(reduced_energy > 0)) return 0; // met by zero-energy fields alone, which every solver has
  if(!(lower_energy > 0)) return std::numeric_limits<double>::infinity();
  return std::sqrt(std::max(0., reduced_energy - lower_energy) / lower_energy);
}

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
