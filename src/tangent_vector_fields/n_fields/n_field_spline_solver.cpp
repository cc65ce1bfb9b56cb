// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/N_field_spline_solver.h>
#include <CGAL/Model_reduction/Sparse_spd_solver.h>
#include <CGAL/Tangent_vector_fields/internal/Spline_solver_impl.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace CGAL {
namespace Tangent_vector_fields {

template class Basic_spline_solver<N_field_constraint, N_field_operators>;

namespace {

int checked_size(const N_field_basis& basis, int d)
{
  if(d == 0) d = basis.size();
  if(d < 0 || d > basis.size())
    throw Invalid_input("n-field spline: basis size " + std::to_string(d) + " asked of a basis of " +
                        std::to_string(basis.size()));
  if(d % 2)
    throw Invalid_input("n-field spline: the basis size must be even (elements come in pairs z, i z), got " +
                        std::to_string(d));
  return d;
}

int checked_order(int m)
{
  if(m < 1) throw Invalid_input("n-field spline: the energy order m must be at least 1, got " + std::to_string(m));
  return m;
}

// The energies of an order-m spline scale as area^-m: the solver works in the mesh's
// units, so its size must keep them (and their inverses, the pull-backs) inside the
// double range, with room for the sums and products of the solve.
void check_size_for_order(const N_field_operators& ops, int m)
{
  const double area = ops.face_areas().sum();
  const double exponent = std::abs(std::log10(area)) * m;
  if(!(exponent <= 300))
  {
    std::ostringstream s;
    s << "n-field spline of order " << m << ": the mesh's area " << area << " makes its energies (area^-" << m
      << ") leave the range of double precision; scale the mesh towards unit size (areas A with A^" << m
      << " between 1e-300 and 1e300)";
    throw Invalid_input(s.str());
  }
}

// The alignment, checked; active() false when it does not apply.
const N_field_alignment& checked_alignment(const N_field_alignment& a, Eigen::Index size)
{
  if(!std::isfinite(a.weight) || a.weight < 0)
    throw Invalid_input("n-field spline: the alignment weight must be finite and non-negative, got " +
                        std::to_string(a.weight));
  if(a.weight > 0 && a.guide.size() != size)
    throw Invalid_input("n-field spline: the alignment guide has " + std::to_string(a.guide.size()) +
                        " coordinates, the field " + std::to_string(size));
  if(a.weight > 0 && !a.guide.allFinite()) throw Invalid_input("n-field spline: the alignment guide is not finite");
  return a;
}

// s / area^m: the alignment term scales like the m-th order energy (lambda ~ 1/area).
double effective_weight(const N_field_alignment& a, const N_field_operators& ops, int order)
{
  return a.active() ? a.weight / std::pow(ops.face_areas().sum(), order) : 0.;
}

int reduced_kernel_dimension(const N_field_basis* basis, int d, const N_field_alignment& alignment)
{
  if(!basis) return 0;
  checked_alignment(alignment, basis->operators().masses().size());
  return alignment.active() ? 0 : std::min(basis->kernel_dimension(), checked_size(*basis, d));
}

double row_dot(const Constraint_row& row, const Eigen::MatrixXd& X, Eigen::Index column)
{
  double s = 0;
  for(const auto& e : row.entries) s += e.second * X(e.first, column);
  return s;
}

} // namespace

// --- reduced ---------------------------------------------------------------------------

Reduced_n_field_spline_solver::Reduced_n_field_spline_solver(std::shared_ptr<const N_field_basis> basis,
                                                             int basis_size, const Spline_options& options, int order,
                                                             const N_field_alignment& alignment)
  : N_field_spline_solver(basis ? basis->shared_operators() : nullptr,
                          reduced_kernel_dimension(basis.get(), basis_size, alignment), options),
    basis_(std::move(basis)), d_(checked_size(*basis_, basis_size)), order_(checked_order(order))
{
  check_size_for_order(operators(), order_);
  alignment_weight_ = effective_weight(alignment, operators(), order_);
  if(alignment_weight_ > 0)
  {
    // The basis is MX-orthonormal: |Phi a - g|^2 = |a|^2 - 2 a.(Phi^T MX g) + |g|^2.
    const Eigen::VectorXd weighted = operators().masses().cwiseProduct(alignment.guide);
    guide_ = basis_->fields().leftCols(d_).transpose() * weighted;
    guide_norm2_ = alignment.guide.dot(weighted);
  }
  update_energy();
}

void Reduced_n_field_spline_solver::update_energy()
{
  energy_.resize(d_);
  inverse_energy_.resize(d_);
  for(int k = 0; k < d_; ++k)
  {
    const double lambda = basis_->eigenvalue(k);
    energy_[k] = (k < harmonic_dimension() ? 0. : std::pow(lambda, order_) + omega_ * lambda) + alignment_weight_;
    inverse_energy_[k] = energy_[k] > 0 ? 1 / energy_[k] : 0.;
  }
  if(alignment_weight_ > 0) aligned_ = alignment_weight_ * guide_.cwiseProduct(inverse_energy_);
}

double Reduced_n_field_spline_solver::lowest_missing_energy() const
{
  // Missing: the basis' own elements from d on (sorted), and what it never computed.
  double lambda = basis_->report().complete_below;
  if(d_ < basis_->size()) lambda = std::min(lambda, basis_->eigenvalue(d_));
  if(lambda == std::numeric_limits<double>::infinity()) return lambda;
  return std::pow(lambda, order_) + omega_ * lambda + alignment_weight_; // as update_energy
}

void Reduced_n_field_spline_solver::pull_back(std::vector<Row>& rows) const
{
  const Eigen::MatrixXd& fields = basis_->fields();
  for(Row& row : rows)
  {
    row.representation = Eigen::VectorXd::Zero(d_);
    for(const auto& e : row.row.entries) row.representation += e.second * fields.row(e.first).head(d_).transpose();
    row.y = row.representation.cwiseProduct(inverse_energy_);
    row.harmonic = row.representation.head(harmonic_dimension());
  }
}

double Reduced_n_field_spline_solver::apply(const Row& row, const Eigen::VectorXd& y) const
{
  return row.representation.dot(y);
}

double Reduced_n_field_spline_solver::energy(const Eigen::VectorXd& a) const
{
  const int h = harmonic_dimension();
  double e = a.cwiseAbs2().dot(energy_) + harmonic_penalty_ * a.head(h).squaredNorm();
  if(alignment_weight_ > 0) e += alignment_weight_ * (guide_norm2_ - 2 * a.dot(guide_));
  return e;
}

void Reduced_n_field_spline_solver::add_harmonic(const Eigen::VectorXd& z, Eigen::VectorXd& a) const
{
  a.head(z.size()) += z;
}

Eigen::VectorXd Reduced_n_field_spline_solver::field() const { return basis_->field(coefficients()); }

Eigen::MatrixXd Reduced_n_field_spline_solver::fields_of(const Eigen::MatrixXd& a) const
{
  return basis_->fields().leftCols(a.rows()) * a;
}

std::string Reduced_n_field_spline_solver::dependency_hint() const
{
  if(number_of_rows() + 1 > d_ - harmonic_dimension())
    return "the basis has only " + std::to_string(d_) + " elements: use a larger basis";
  return "a larger basis may tell them apart";
}

// --- full ------------------------------------------------------------------------------

struct Full_n_field_spline_solver::Factors
{
  Model_reduction::Sparse_spd_solver S;                  // S_n, one face per kernel component held at 0
  std::optional<Model_reduction::Sparse_spd_solver> screened; // S_n + omega MX (m = 2, omega > 0)
  std::optional<Model_reduction::Sparse_spd_solver> aligned;  // the whole energy, with the alignment
  std::vector<int> pinned;              // unknowns held at 0
};

namespace {

int full_kernel_dimension(const N_field_operators* ops, const N_field_alignment& alignment)
{
  if(!ops) return 0;
  checked_alignment(alignment, ops->masses().size());
  return alignment.active() ? 0 : static_cast<int>(ops->kernel().cols());
}

} // namespace

Full_n_field_spline_solver::Full_n_field_spline_solver(std::shared_ptr<const N_field_operators> operators,
                                                       const Spline_options& options, int order,
                                                       const N_field_alignment& alignment)
  : N_field_spline_solver(operators, full_kernel_dimension(operators.get(), alignment), options),
    order_(checked_order(order)), alignment_(alignment), factors_(std::make_unique<Factors>())
{
  const N_field_operators& ops = this->operators();
  check_size_for_order(ops, order_);
  alignment_weight_ = effective_weight(alignment_, ops, order_);
  if(alignment_weight_ > 0)
  {
    energy_changed(); // no kernel to hold: the energy is positive definite
    return;
  }
  const Eigen::MatrixXd& K = ops.kernel();
  // Hold the first face of each kernel pair's component: parallel fields never vanish.
  for(Eigen::Index j = 0; j < K.cols(); j += 2)
    for(Eigen::Index i = 0; i < K.rows(); i += 2)
      if(K(i, j) != 0 || K(i + 1, j) != 0)
      {
        factors_->pinned.push_back(static_cast<int>(i));
        factors_->pinned.push_back(static_cast<int>(i + 1));
        break;
      }
  Eigen::SparseMatrix<double> S = ops.S();
  if(!factors_->pinned.empty())
  {
    std::vector<char> held(S.rows(), 0);
    for(int p : factors_->pinned) held[p] = 1;
    S.prune([&](Eigen::Index i, Eigen::Index j, double) { return !held[i] && !held[j]; });
    for(int p : factors_->pinned) S.coeffRef(p, p) = 1;
  }
  factors_->S.factor(S, "the n-field energy S_n");
  energy_changed();
}

Full_n_field_spline_solver::~Full_n_field_spline_solver() = default;

int Full_n_field_spline_solver::space_dimension() const { return static_cast<int>(operators().masses().size()); }

void Full_n_field_spline_solver::energy_changed()
{
  if(alignment_weight_ > 0)
  {
    // S_n (MX^-1 S_n)^(m-1) + omega S_n + s MX: sparse (two-ring for m = 2), positive definite.
    const N_field_operators& ops = operators();
    const Eigen::SparseMatrix<double>& S = ops.S();
    const Eigen::VectorXd inverse_mass = ops.masses().cwiseInverse();
    Eigen::SparseMatrix<double> A = S;
    for(int k = 1; k < order_; ++k) A = (S * (inverse_mass.asDiagonal() * A)).pruned();
    A += omega_ * S;
    A.diagonal() += alignment_weight_ * ops.masses();
    factors_->aligned.emplace();
    factors_->aligned->factor(A, "the aligned n-field energy");
    aligned_ = factors_->aligned->solve(Eigen::VectorXd(alignment_weight_ * ops.masses().cwiseProduct(alignment_.guide)));
    return;
  }
  if(order_ >= 3 && omega_ > 0)
    throw Invalid_input("full n-field spline: a tension omega > 0 is supported with m = 1 or 2 only (m = " +
                        std::to_string(order_) + ")");
  factors_->screened.reset();
  if(order_ == 2 && omega_ > 0)
  {
    Eigen::SparseMatrix<double> A = operators().S();
    A.diagonal() += omega_ * operators().masses();
    factors_->screened.emplace();
    factors_->screened->factor(A, "the screened n-field energy S_n + omega MX");
  }
}

void Full_n_field_spline_solver::pull_back(std::vector<Row>& rows) const
{
  if(rows.empty()) return;
  const N_field_operators& ops = operators();
  const Eigen::VectorXd& mass = ops.masses();
  const Eigen::MatrixXd& K = ops.kernel();
  const Eigen::Index n = mass.size(), c = static_cast<Eigen::Index>(rows.size());
  // Right-hand sides r~ = r - MX K K^T r: orthogonal to the kernel.
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, c);
  for(Eigen::Index j = 0; j < c; ++j)
    for(const auto& e : rows[j].row.entries) B(e.first, j) += e.second;
  if(factors_->aligned)
  {
    const Eigen::MatrixXd Y = factors_->aligned->solve(B);
    for(Eigen::Index j = 0; j < c; ++j)
    {
      rows[j].y = Y.col(j);
      rows[j].harmonic.resize(0);
    }
    return;
  }
  auto remove_kernel = [&](Eigen::MatrixXd& X, bool weighted_rhs) {
    if(K.cols() == 0) return;
    // weighted_rhs: X -= MX K (K^T X) (a right-hand side); else X -= K (K^T MX X) (a solution).
    if(weighted_rhs)
      X -= mass.asDiagonal() * (K * (K.transpose() * X));
    else
      X -= K * (K.transpose() * (mass.asDiagonal() * X));
  };
  auto solve_S = [&](Eigen::MatrixXd X) {
    for(int p : factors_->pinned) X.row(p).setZero();
    Eigen::MatrixXd U = factors_->S.solve(X);
    remove_kernel(U, false);
    return U;
  };
  remove_kernel(B, true);
  Eigen::MatrixXd Y = solve_S(B);
  if(order_ == 1)
    Y /= 1 + omega_;
  else if(order_ == 2 && factors_->screened)
    Y = factors_->screened->solve(Eigen::MatrixXd(mass.asDiagonal() * Y));
  else
    for(int k = 1; k < order_; ++k) Y = solve_S(mass.asDiagonal() * Y);
  for(Eigen::Index j = 0; j < c; ++j)
  {
    rows[j].y = Y.col(j);
    rows[j].harmonic.resize(K.cols());
    for(Eigen::Index h = 0; h < K.cols(); ++h) rows[j].harmonic[h] = row_dot(rows[j].row, K, h);
  }
}

double Full_n_field_spline_solver::apply(const Row& row, const Eigen::VectorXd& y) const { return row.row.dot(y); }

double Full_n_field_spline_solver::energy(const Eigen::VectorXd& z) const
{
  const N_field_operators& ops = operators();
  const Eigen::MatrixXd& K = ops.kernel();
  double e = ops.m_harmonic_energy(z, order_) + omega_ * ops.dirichlet_energy(z);
  if(alignment_weight_ > 0)
  {
    const Eigen::VectorXd off = z - alignment_.guide;
    return e + alignment_weight_ * off.dot(ops.masses().cwiseProduct(off));
  }
  if(K.cols() > 0) e += harmonic_penalty_ * (K.transpose() * ops.masses().cwiseProduct(z)).squaredNorm();
  return e;
}

void Full_n_field_spline_solver::add_harmonic(const Eigen::VectorXd& z, Eigen::VectorXd& x) const
{
  x += operators().kernel() * z;
}

} // namespace Tangent_vector_fields
} // namespace CGAL
