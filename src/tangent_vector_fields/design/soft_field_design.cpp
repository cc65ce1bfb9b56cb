// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/Soft_field_design.h>
#include <CGAL/Tangent_vector_fields/Spline_solver.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace CGAL {
namespace Tangent_vector_fields {

namespace internal {

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
    hodge_(hodge), length_unit_(internal::spline_length_unit(hodge->operators())),
    // omega_ is for the mesh as given; the pull-backs measure it in the length unit.
    pull_back_(hodge, internal::Design_energy::dirichlet, omega_ / (length_unit_ * length_unit_), length_unit_)
{}

Full_soft_design::~Full_soft_design() = default;

void Full_soft_design::rows_added(std::vector<Weighted_row>& rows)
{
  solved_ = false;
  if(rows.empty()) return;
  factor_seconds_ += pull_back_.factor();
  const auto start = std::chrono::steady_clock::now();
  const Eigen::Index n = operators_->field_masses().size(), m = static_cast<Eigen::Index>(rows.size());
  // Each row divided by a power of two near its largest entry (divergence rows of a tiny
  // mesh are huge), the pull-back multiplied back: exact.
  std::vector<Eigen::Triplet<double>> entries;
  for(Eigen::Index j = 0; j < m; ++j)
    for(const auto& e : rows[j].row.entries) entries.emplace_back(e.first, j, e.second);
  Eigen::SparseMatrix<double> R(n, m);
  R.setFromTriplets(entries.begin(), entries.end()); // repeated entries add up
  Eigen::VectorXd scales(m);
  for(Eigen::Index j = 0; j < m; ++j)
  {
    Eigen::Map<Eigen::VectorXd> values(R.valuePtr() + R.outerIndexPtr()[j],
                                       R.outerIndexPtr()[j + 1] - R.outerIndexPtr()[j]);
    scales[j] = internal::value_scale(values);
    values /= scales[j];
  }
  Eigen::MatrixXd H;
  const Eigen::MatrixXd Y = pull_back_.apply(R, H, residual_);
  for(Eigen::Index j = 0; j < m; ++j)
  {
    rows[j].y = Y.col(j) * scales[j];
    rows[j].harmonic = H.col(j) * scales[j];
  }
  pull_back_seconds_ += seconds_since(start);
}

void Full_soft_design::solve() const
{
  const auto start = std::chrono::steady_clock::now();
  std::vector<const Weighted_row*> rows;
  for(const auto& e : entries_)
    for(const Weighted_row& r : e.second.rows) rows.push_back(&r);
  const Eigen::Index m = static_cast<Eigen::Index>(rows.size());
  x_ = Eigen::VectorXd::Zero(operators_->field_masses().size());
  undetermined_ = hodge_->harmonic_dimension();
  if(m == 0)
  {
    solved_ = true;
    return;
  }
  // A = K + W^-1 (K_ij = r_i y_j through the few entries of r_i), values c.
  Eigen::MatrixXd A(m, m);
  Eigen::VectorXd c(m);
  for(Eigen::Index i = 0; i < m; ++i)
  {
    for(Eigen::Index j = 0; j < m; ++j)
    {
      double s = 0;
      for(const auto& e : rows[i]->row.entries) s += e.second * rows[j]->y[e.first];
      A(i, j) = s;
    }
    c[i] = rows[i]->row.value;
  }
  A = (0.5 * (A + A.transpose())).eval();
  for(Eigen::Index i = 0; i < m; ++i) A(i, i) += 1 / rows[i]->weight;
  // Harmonic directions some constraint sees: the complement P of the undetermined ones.
  const int nh = hodge_->harmonic_dimension();
  Eigen::MatrixXd P(nh, 0);
  if(nh > 0)
  {
    std::vector<std::pair<Eigen::VectorXd, double>> harmonic_rows;
    for(const Weighted_row* r : rows) harmonic_rows.emplace_back(r->harmonic / length_unit_, r->weight);
    const Eigen::MatrixXd N = undetermined_directions(harmonic_rows, nh);
    Eigen::MatrixXd full_basis = Eigen::MatrixXd::Identity(nh, nh);
    if(N.cols() > 0) full_basis = Eigen::HouseholderQR<Eigen::MatrixXd>(N).householderQ();
    P = full_basis.rightCols(nh - N.cols());
  }
  Eigen::MatrixXd C(m, P.cols());
  for(Eigen::Index i = 0; i < m; ++i) C.row(i) = rows[i]->harmonic.transpose() * P;
  const Eigen::LDLT<Eigen::MatrixXd> A_factor(A);
  if(A_factor.info() != Eigen::Success || !(A_factor.vectorD().minCoeff() > 0))
    throw Numerical_failure("soft design: the constraint system K + W^-1 is not positive definite "
                            "(weights too large for the constraints' dependence)");
  // Linear in the values: solved for c scaled to near 1, the result scaled back.
  const double scale = internal::value_scale(c);
  const Eigen::VectorXd b = c / scale;
  Eigen::VectorXd z = Eigen::VectorXd::Zero(P.cols());
  if(P.cols() > 0)
  {
    const Eigen::MatrixXd AiC = A_factor.solve(C);
    const Eigen::MatrixXd schur = C.transpose() * AiC;
    z = schur.ldlt().solve(AiC.transpose() * b);
  }
  const Eigen::VectorXd t = A_factor.solve(b - C * z);
  for(Eigen::Index j = 0; j < m; ++j) x_ += t[j] * rows[j]->y;
  if(P.cols() > 0) x_ += pull_back_.harmonic_field(P * z);
  x_ *= scale;
  if(!x_.allFinite()) throw Numerical_failure("soft design: the field is not finite");
  solved_ = true;
  solve_seconds_ = seconds_since(start);
}

Eigen::VectorXd Full_soft_design::field() const
{
  if(!solved_) solve();
  return x_;
}

double Full_soft_design::energy() const
{
  const double scale = internal::value_scale(field());
  const Eigen::VectorXd x = field() / scale;
  return x.dot(pull_back_.apply_energy(x).col(0)) * scale * scale;
}

} // namespace Tangent_vector_fields
} // namespace CGAL
