// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/Full_spline_solver.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace CGAL {
namespace Tangent_vector_fields {


Full_spline_solver::Full_spline_solver(std::shared_ptr<const Hodge_solver> hodge, const Spline_options& options)
  : Spline_solver(std::shared_ptr<const Operator_matrices>(hodge, &hodge->operators()), hodge->harmonic_dimension(),
                  options),
    hodge_(std::move(hodge))
{
  energy_changed();
}

Full_spline_solver::~Full_spline_solver() = default;

// A new omega: new chains, factored by the next pull-back.
void Full_spline_solver::energy_changed()
{
  pull_back_ =
      std::make_unique<internal::Hodge_pull_back>(hodge_, internal::Design_energy::biharmonic, omega_, length_unit_);
}

void Full_spline_solver::pull_back(std::vector<Row>& rows) const
{
  if(rows.empty()) return;
  const internal::Hodge_pull_back& Q = *pull_back_;
  if(const double seconds = Q.factor()) statistics_.factor_seconds = seconds;
  const auto start = std::chrono::steady_clock::now();
  const int m = static_cast<int>(rows.size());
  std::vector<Eigen::Triplet<double>> entries;
  for(int j = 0; j < m; ++j)
    for(const auto& e : rows[j].row.entries) entries.emplace_back(e.first, j, e.second);
  Eigen::SparseMatrix<double> R(space_dimension(), m);
  R.setFromTriplets(entries.begin(), entries.end()); // repeated entries add up
  Eigen::MatrixXd H;
  const Eigen::MatrixXd Y = Q.apply(R, H, statistics_.residual);
  for(int j = 0; j < m; ++j)
  {
    rows[j].y = Y.col(j);
    rows[j].harmonic = H.col(j);
  }
  statistics_.pull_back_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double Full_spline_solver::energy(const Eigen::VectorXd& x) const
{
  if(x.squaredNorm() == 0) return 0;
  const internal::Hodge_pull_back& Q = *pull_back_;
  const double harmonic = harmonic_penalty_ > 0 ? Q.harmonic_squared_norm(x) : 0.;
  return x.dot(Q.apply_energy(x).col(0)) + harmonic_penalty_ * harmonic;
}

void Full_spline_solver::add_harmonic(const Eigen::VectorXd& z, Eigen::VectorXd& x) const
{
  x += pull_back_->harmonic_field(z);
}

} // namespace Tangent_vector_fields
} // namespace CGAL
