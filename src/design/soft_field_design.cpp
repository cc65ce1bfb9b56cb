// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/Soft_field_design.h>
#include <CGAL/Tangent_vector_fields/internal/projected_block_cg.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <Eigen/Eigenvalues>

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

// A power of two near the largest |x_i| (1 for zero or non-finite x): dividing by it is exact.
static double value_scale(const Eigen::VectorXd& x)
{
  const double largest = x.size() > 0 ? x.cwiseAbs().maxCoeff() : 0.;
  return largest > 0 && std::isfinite(largest) ? std::ldexp(1., std::ilogb(largest)) : 1.;
}

} // namespace internal

namespace {

double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}
} // namespace

// ---------------------------------------------------------------- common part

Soft_field_design::Soft_field_design(std::shared_ptr<const Operator_matrices> operators,
                                     const Soft_design_options& options)
  : operators_(std::move(operators)), options_(options)
{
  if(!std::isfinite(options.omega) || options.omega < 0)
    throw Invalid_input("the biharmonic weight omega must be finite and non-negative");
  // E_D is scale-free in 2D, E_B scales as 1/area: omega scales as area.
  const double area = operators_->face_areas().sum();
  omega_ = options.omega * area;
  const double lambda = 1 / area;
  energy_scale_ = lambda + omega_ * lambda * lambda;
}

Soft_field_design::~Soft_field_design() = default;

int Soft_field_design::add(const Field_constraint& constraint, double weight)
{
  if(!std::isfinite(weight) || !(weight > 0))
    throw Invalid_input("a soft constraint needs a positive finite weight: " + constraint.describe());
  Entry entry;
  entry.constraint = constraint;
  entry.weight = weight;
  for(Constraint_row& r : constraint_rows(*operators_, constraint))
  {
    Weighted_row row;
    row.weight = weight * r.unit_area_scale * r.unit_area_scale;
    row.row = std::move(r);
    entry.rows.push_back(std::move(row));
  }
  rows_added(entry.rows);
  const int id = next_id_++;
  entries_[id] = std::move(entry);
  return id;
}

void Soft_field_design::remove(int id)
{
  auto it = entries_.find(id);
  if(it == entries_.end()) throw Invalid_input("no constraint with id " + std::to_string(id));
  const std::vector<Weighted_row> rows = std::move(it->second.rows);
  entries_.erase(it);
  rows_removed(rows);
}

void Soft_field_design::change(int id, const Field_constraint& constraint, double weight)
{
  auto it = entries_.find(id);
  if(it == entries_.end()) throw Invalid_input("no constraint with id " + std::to_string(id));
  Entry& entry = it->second;
  if(entry.constraint.same_rows_as(constraint) && weight == entry.weight)
  {
    const std::vector<double> values = constraint_values(operators_->mesh(), constraint);
    for(std::size_t k = 0; k < values.size(); ++k) entry.rows[k].row.value = values[k];
    entry.constraint = constraint;
    values_changed();
    return;
  }
  // Replace, keeping the id.
  const int next = next_id_;
  const int new_id = add(constraint, weight);
  Entry replacement = std::move(entries_[new_id]);
  entries_.erase(new_id);
  next_id_ = next;
  remove(id);
  entries_[id] = std::move(replacement);
}

Eigen::MatrixXd Soft_field_design::undetermined_directions(
    const std::vector<std::pair<Eigen::VectorXd, double>>& harmonic_rows, int nh) const
{
  if(nh == 0) return Eigen::MatrixXd(0, 0);
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(nh, nh);
  for(const auto& h : harmonic_rows) gram += h.second * h.first * h.first.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gram);
  std::vector<int> free;
  for(int j = 0; j < nh; ++j)
    if(!(eigen.eigenvalues()[j] > internal::undetermined_harmonic_threshold * energy_scale_)) free.push_back(j);
  Eigen::MatrixXd N(nh, free.size());
  for(std::size_t j = 0; j < free.size(); ++j) N.col(j) = eigen.eigenvectors().col(free[j]);
  undetermined_ = static_cast<int>(free.size());
  return N;
}

// ---------------------------------------------------------------- reduced


Reduced_soft_design::Reduced_soft_design(std::shared_ptr<const Eigenfield_basis> basis, int basis_size,
                                         const Soft_design_options& options)
  : Soft_field_design(std::shared_ptr<const Operator_matrices>(basis, &basis->operators()), options),
    basis_(std::move(basis)), d_(internal::checked_basis_size(*basis_, basis_size)), rows_in_basis_(*basis_, d_)
{
  diagonal_.resize(d_);
  for(int k = 0; k < d_; ++k)
  {
    const double lambda = basis_->eigenvalue(k);
    diagonal_[k] = basis_->type(k) == Eigenfield_type::harmonic ? 0 : lambda + omega_ * lambda * lambda;
  }
  update_harmonic({}, nullptr);
  refactor();
}

bool Reduced_soft_design::update_harmonic(const std::vector<Weighted_row>& extra,
                                          const std::vector<Weighted_row>* removed)
{
  const std::vector<int>& positions = rows_in_basis_.harmonic_positions();
  const int nh = static_cast<int>(positions.size());
  std::vector<std::pair<Eigen::VectorXd, double>> harmonic_rows;
  auto take = [&](const Weighted_row& r) {
    Eigen::VectorXd h(nh);
    for(int j = 0; j < nh; ++j) h[j] = r.in_basis[positions[j]];
    harmonic_rows.emplace_back(h, r.weight);
  };
  for(const auto& e : entries_)
    for(const Weighted_row& r : e.second.rows) take(r);
  for(const Weighted_row& r : extra) take(r);
  (void)removed; // removed rows are no longer in entries_
  const Eigen::MatrixXd N = undetermined_directions(harmonic_rows, nh);
  const bool changed = N.cols() != undetermined_directions_.cols();
  undetermined_directions_ = N;
  return changed;
}

void Reduced_soft_design::refactor() { refactor_with({}); }

void Reduced_soft_design::refactor_with(const std::vector<Weighted_row>& extra)
{
  Eigen::MatrixXd A = diagonal_.asDiagonal();
  // Harmonic directions no constraint sees: pinned to zero by their own unit energy
  // (they are decoupled from everything else, so this changes nothing else).
  const std::vector<int>& positions = rows_in_basis_.harmonic_positions();
  for(int a = 0; a < static_cast<int>(positions.size()); ++a)
    for(int b = 0; b < static_cast<int>(positions.size()); ++b)
      A(positions[a], positions[b]) +=
          energy_scale_ * undetermined_directions_.row(a).dot(undetermined_directions_.row(b));
  for(const auto& e : entries_)
    for(const Weighted_row& r : e.second.rows) A.selfadjointView<Eigen::Lower>().rankUpdate(r.in_basis, r.weight);
  for(const Weighted_row& r : extra) A.selfadjointView<Eigen::Lower>().rankUpdate(r.in_basis, r.weight);
  factor_.compute(A);
  if(factor_.info() != Eigen::Success)
    throw Numerical_failure("the reduced soft-design matrix is not positive definite");
  solved_ = false;
}

void Reduced_soft_design::rows_added(std::vector<Weighted_row>& rows)
{
  for(Weighted_row& r : rows) r.in_basis = rows_in_basis_(r.row);
  if(update_harmonic(rows, nullptr))
    refactor_with(rows); // the new rows are not in entries_ yet
  else
    for(const Weighted_row& r : rows) factor_.rankUpdate(r.in_basis, r.weight);
  solved_ = false;
}

void Reduced_soft_design::rows_removed(const std::vector<Weighted_row>& rows)
{
  if(update_harmonic({}, &rows))
  {
    refactor();
    return;
  }
  for(const Weighted_row& r : rows) factor_.rankUpdate(r.in_basis, -r.weight);
  if(factor_.info() != Eigen::Success) refactor(); // a downdate lost definiteness to roundoff
  solved_ = false;
}

const Eigen::VectorXd& Reduced_soft_design::coefficients() const
{
  if(!solved_)
  {
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(d_);
    for(const auto& e : entries_)
      for(const Weighted_row& r : e.second.rows) rhs += (r.weight * r.row.value) * r.in_basis;
    const double scale = internal::value_scale(rhs);
    coefficients_ = factor_.solve(rhs / scale) * scale;
    solved_ = true;
  }
  return coefficients_;
}

Eigen::VectorXd Reduced_soft_design::field() const { return basis_->field(coefficients()); }

double Reduced_soft_design::energy() const
{
  const double scale = internal::value_scale(coefficients());
  const Eigen::VectorXd a = coefficients() / scale;
  return a.cwiseProduct(a).dot(diagonal_) * scale * scale;
}

// ---------------------------------------------------------------- full

Full_soft_design::Full_soft_design(std::shared_ptr<const Hodge_solver> hodge, const Soft_design_options& options)
  : Soft_field_design(std::shared_ptr<const Operator_matrices>(hodge, &hodge->operators()), options),
    hodge_(std::move(hodge))
{}

Full_soft_design::~Full_soft_design() = default;

void Full_soft_design::factor() const
{
  const auto start = std::chrono::steady_clock::now();
  const Operator_matrices& ops = *operators_;
  if(energy_matrix_.rows() == 0)
  {
    energy_matrix_ = ops.S();
    if(omega_ > 0) energy_matrix_ += omega_ * ops.B(); // B only when it is asked for
  }
  std::vector<Eigen::Triplet<double>> triplets;
  std::vector<std::pair<Eigen::VectorXd, double>> harmonic_rows;
  const int nh = hodge_->harmonic_dimension();
  const Eigen::MatrixXd* Uh = nh > 0 ? &hodge_->harmonic_basis() : nullptr;
  for(const auto& e : entries_)
    for(const Weighted_row& r : e.second.rows)
    {
      for(const auto& a : r.row.entries)
        for(const auto& b : r.row.entries) triplets.emplace_back(a.first, b.first, r.weight * a.second * b.second);
      if(Uh)
      {
        Eigen::VectorXd h = Eigen::VectorXd::Zero(nh);
        for(const auto& a : r.row.entries) h += a.second * Uh->row(a.first).transpose();
        harmonic_rows.emplace_back(h, r.weight);
      }
    }
  Eigen::SparseMatrix<double> constraints(energy_matrix_.rows(), energy_matrix_.cols());
  constraints.setFromTriplets(triplets.begin(), triplets.end());
  system_ = energy_matrix_ + constraints;
  const Eigen::MatrixXd N = undetermined_directions(harmonic_rows, nh);
  undetermined_fields_ = Uh ? Eigen::MatrixXd(*Uh * N) : Eigen::MatrixXd(system_.rows(), 0);
  // A tiny shift keeps the factorisation definite on undetermined harmonic fields;
  // CG against the unshifted matrix removes its effect (as in Full_spline_solver).
  const Eigen::VectorXd& masses = ops.field_masses();
  double bound = 0;
  for(int k = 0; k < system_.outerSize(); ++k)
  {
    double s = 0;
    for(Eigen::SparseMatrix<double>::InnerIterator it(system_, k); it; ++it) s += std::abs(it.value());
    bound = std::max(bound, s / masses[k]);
  }
  Eigen::SparseMatrix<double> shifted = system_;
  shifted += (1e-10 * bound) * ops.MX();
  solver_ = std::make_unique<Sparse_spd_solver>();
  solver_->factor(shifted, "S + omega B + C^T W C (full soft design)");
  factored_ = true;
  solved_ = false;
  factor_seconds_ = seconds_since(start);
}

void Full_soft_design::solve() const
{
  if(!factored_) factor();
  const auto start = std::chrono::steady_clock::now();
  const int n = static_cast<int>(system_.rows());
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 1);
  for(const auto& e : entries_)
    for(const Weighted_row& r : e.second.rows)
      for(const auto& a : r.row.entries) rhs(a.first, 0) += r.weight * r.row.value * a.second;
  const Eigen::VectorXd& masses = operators_->field_masses();
  const Eigen::MatrixXd& Z = undetermined_fields_;
  auto project_primal = [&](Eigen::MatrixXd& X) {
    if(Z.cols() > 0) X -= Z * (Z.transpose() * masses.asDiagonal() * X);
  };
  auto project_dual = [&](Eigen::MatrixXd& X) {
    if(Z.cols() > 0) X -= masses.asDiagonal() * (Z * (Z.transpose() * X));
  };
  auto apply = [&](const Eigen::MatrixXd& X) -> Eigen::MatrixXd { return system_ * X; };
  auto precondition = [&](const Eigen::MatrixXd& R) -> Eigen::MatrixXd { return solver_->solve(R); };
  int iterations = 0;
  // Linear in the values: CG on the right-hand side scaled to near 1 (its squared
  // norms would overflow for values near the largest double), the result scaled back.
  const double scale = internal::value_scale(rhs.col(0));
  x_ = internal::projected_block_cg(apply, precondition, project_primal, project_dual, rhs / scale, 1e-12, 200,
                                    iterations, residual_)
           .col(0) *
       scale;
  solved_ = true;
  solve_seconds_ = seconds_since(start);
}

Eigen::VectorXd Full_soft_design::field() const
{
  if(!solved_ || !factored_) solve();
  return x_;
}

double Full_soft_design::energy() const
{
  const double scale = internal::value_scale(field());
  const Eigen::VectorXd x = field() / scale;
  return x.dot(energy_matrix_ * x) * scale * scale;
}

} // namespace Tangent_vector_fields
} // namespace CGAL
