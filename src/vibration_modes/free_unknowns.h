// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_VIBRATION_MODES_SRC_FREE_UNKNOWNS_H
#define CGAL_VIBRATION_MODES_SRC_FREE_UNKNOWNS_H

// Vectors given over all unknowns or over the free ones of a Mode_problem, checked.

#include <CGAL/Vibration_modes/Mode_problem.h>
#include <CGAL/Vibration_modes/errors.h>

#include <string>

namespace CGAL {
namespace Vibration_modes {
namespace internal {

inline Eigen::Index full_size_of(const Mode_problem& p) { return p.free_unknowns.empty() ? p.H.rows() : p.full_size; }

/// The rows of `X` at the free unknowns; `X` has `full_size` rows or as many as the free
/// unknowns; every entry must be finite.
/// \throws Invalid_input "<what> has N rows, not ..." or "<what> has a non-finite entry"
inline Eigen::MatrixXd free_rows(const Mode_problem& p, const Eigen::MatrixXd& X, const std::string& what)
{
  if(!X.allFinite()) throw Invalid_input(what + " has a non-finite entry (NaN or infinity)");
  if(X.rows() == p.H.rows()) return X;
  if(!p.free_unknowns.empty() && X.rows() == p.full_size)
  {
    Eigen::MatrixXd F(p.H.rows(), X.cols());
    for(std::size_t i = 0; i < p.free_unknowns.size(); ++i) F.row(Eigen::Index(i)) = X.row(p.free_unknowns[i]);
    return F;
  }
  throw Invalid_input(what + " has " + std::to_string(X.rows()) + " rows, not one per unknown (" +
                      std::to_string(full_size_of(p)) + ")");
}

/// The free index of every full unknown (-1 at pinned ones).
inline std::vector<Eigen::Index> free_index_of_unknowns(const Mode_problem& p)
{
  std::vector<Eigen::Index> index(std::size_t(full_size_of(p)), -1);
  if(p.free_unknowns.empty())
    for(Eigen::Index i = 0; i < p.H.rows(); ++i) index[std::size_t(i)] = i;
  else
    for(std::size_t i = 0; i < p.free_unknowns.size(); ++i) index[std::size_t(p.free_unknowns[i])] = Eigen::Index(i);
  return index;
}

} // namespace internal
} // namespace Vibration_modes
} // namespace CGAL

#endif
