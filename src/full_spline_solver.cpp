// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/Full_spline_solver.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace CGAL {
namespace Tangent_vector_fields {

namespace internal {

Eigen::MatrixXd projected_block_cg(const std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)>& apply_A,
                                   const std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)>& precondition,
                                   const std::function<void(Eigen::MatrixXd&)>& project_primal,
                                   const std::function<void(Eigen::MatrixXd&)>& project_dual,
                                   const Eigen::MatrixXd& B, double tolerance, int max_iterations,
                                   int& iterations, double& residual)
{
  const Eigen::Index m = B.cols();
  Eigen::MatrixXd R = B;
  project_dual(R);
  const Eigen::VectorXd b_norm = R.colwise().norm().transpose();
  // Start from the preconditioner's answer: it is already accurate in most directions.
  Eigen::MatrixXd X = Eigen::MatrixXd::Zero(B.rows(), m);
  Eigen::MatrixXd Z = precondition(R);
  project_primal(Z);
  Eigen::MatrixXd P = Z;
  Eigen::VectorXd rz = (R.cwiseProduct(Z)).colwise().sum().transpose();
  std::vector<bool> active(m);
  for(Eigen::Index j = 0; j < m; ++j) active[j] = b_norm[j] > 0;
  iterations = 0;
  residual = 0;
  Eigen::VectorXd relative = Eigen::VectorXd::Zero(m);
  for(int it = 0; it < max_iterations; ++it)
  {
    if(std::none_of(active.begin(), active.end(), [](bool a) { return a; })) break;
    ++iterations;
    const Eigen::MatrixXd AP = apply_A(P);
    for(Eigen::Index j = 0; j < m; ++j)
    {
      if(!active[j]) continue;
      const double pap = P.col(j).dot(AP.col(j));
      if(!(pap > 0))
      {
        active[j] = false; // converged to roundoff: no descent direction left
        continue;
      }
      const double alpha = rz[j] / pap;
      X.col(j) += alpha * P.col(j);
      R.col(j) -= alpha * AP.col(j);
      relative[j] = R.col(j).norm() / b_norm[j];
      if(relative[j] <= tolerance) active[j] = false;
    }
    Z = precondition(R);
    project_primal(Z);
    for(Eigen::Index j = 0; j < m; ++j)
    {
      if(!active[j]) continue;
      const double rz_new = R.col(j).dot(Z.col(j));
      const double beta = rz_new / rz[j];
      rz[j] = rz_new;
      P.col(j) = Z.col(j) + beta * P.col(j);
    }
  }
  // True residuals (the recurrence drifts).
  Eigen::MatrixXd true_residual = B - apply_A(X);
  project_dual(true_residual);
  for(Eigen::Index j = 0; j < m; ++j)
    if(b_norm[j] > 0) residual = std::max(residual, true_residual.col(j).norm() / b_norm[j]);
  return X;
}

} // namespace internal

Full_spline_solver::Full_spline_solver(std::shared_ptr<const Hodge_solver> hodge, const Spline_options& options)
  : Spline_solver(std::shared_ptr<const Operator_matrices>(hodge, &hodge->operators()), hodge->harmonic_dimension(),
                  options),
    hodge_(std::move(hodge))
{}

Full_spline_solver::~Full_spline_solver() = default;

void Full_spline_solver::energy_changed()
{
  preconditioner_.reset();
  Q_.resize(0, 0);
}

void Full_spline_solver::factor() const
{
  const auto start = std::chrono::steady_clock::now();
  const Operator_matrices& ops = *operators_;
  Q_ = ops.B() + omega_ * ops.S();
  // sigma: 1e-10 of a bound on the largest eigenvalue of MX^-1 Q (Gershgorin), so
  // that the factorisation stays positive definite on the harmonic fields, where Q
  // vanishes, with ample margin over roundoff (~1e-16 of that bound).
  const Eigen::VectorXd& masses = ops.field_masses();
  double bound = 0;
  for(int k = 0; k < Q_.outerSize(); ++k)
  {
    double s = 0;
    for(Eigen::SparseMatrix<double>::InnerIterator it(Q_, k); it; ++it) s += std::abs(it.value());
    bound = std::max(bound, s / masses[k]);
  }
  const double sigma = 1e-10 * bound;
  Eigen::SparseMatrix<double> P = Q_;
  P += sigma * ops.MX();
  preconditioner_ = std::make_unique<Sparse_spd_solver>();
  preconditioner_->factor(P, "B + omega S + sigma MX (full spline)");
  statistics_.factor_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void Full_spline_solver::pull_back(std::vector<Row>& rows) const
{
  if(rows.empty()) return;
  if(!preconditioner_) factor();
  const auto start = std::chrono::steady_clock::now();
  const int n = space_dimension();
  const int m = static_cast<int>(rows.size());
  const Eigen::VectorXd& masses = operators_->field_masses();
  const Eigen::MatrixXd* Uh = harmonic_dimension() > 0 ? &hodge_->harmonic_basis() : nullptr;
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, m);
  for(int j = 0; j < m; ++j)
    for(const auto& e : rows[j].row.entries) B(e.first, j) += e.second;
  // Primal vectors are made MX-orthogonal to the harmonic fields; dual vectors
  // (residuals, right-hand sides) orthogonal to them in the Euclidean sense.
  auto project_primal = [&](Eigen::MatrixXd& X) {
    if(Uh) X -= *Uh * (Uh->transpose() * masses.asDiagonal() * X);
  };
  auto project_dual = [&](Eigen::MatrixXd& X) {
    if(Uh) X -= masses.asDiagonal() * (*Uh * (Uh->transpose() * X));
  };
  auto apply_Q = [&](const Eigen::MatrixXd& X) -> Eigen::MatrixXd { return Q_ * X; };
  auto precondition = [&](const Eigen::MatrixXd& R) -> Eigen::MatrixXd { return preconditioner_->solve(R); };
  int iterations = 0;
  double residual = 0;
  const Eigen::MatrixXd Y = internal::projected_block_cg(apply_Q, precondition, project_primal, project_dual, B,
                                                         pull_back_tolerance, 200, iterations, residual);
  for(int j = 0; j < m; ++j)
  {
    rows[j].y = Y.col(j);
    rows[j].harmonic = Uh ? Eigen::VectorXd(Uh->transpose() * B.col(j)) : Eigen::VectorXd(0);
  }
  statistics_.iterations = std::max(statistics_.iterations, iterations);
  statistics_.residual = std::max(statistics_.residual, residual);
  statistics_.pull_back_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double Full_spline_solver::energy(const Eigen::VectorXd& x) const
{
  if(x.squaredNorm() == 0) return 0;
  if(Q_.rows() == 0) factor();
  return x.dot(Q_ * x);
}

void Full_spline_solver::add_harmonic(const Eigen::VectorXd& z, Eigen::VectorXd& x) const
{
  x += hodge_->harmonic_basis() * z;
}

} // namespace Tangent_vector_fields
} // namespace CGAL
