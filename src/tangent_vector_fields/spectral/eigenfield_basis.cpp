// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Model_reduction/Generalized_eigensolver.h>
#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/internal/basis_file.h>
#include <CGAL/Tangent_vector_fields/internal/scalar_eigenproblem.h>

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

typedef internal::Scalar_eigenproblem Scalar_problem;

struct Solved
{
  Eigen::VectorXd values;    // of the mesh as given
  Eigenfunction_matrix functions; // mass-orthonormal, full size
  double max_residual = 0;
  double complete_below = std::numeric_limits<double>::infinity(); // of the mesh as given
  Model_reduction::Completeness_check check;
  double thread_seconds = 0;
};

// The `count` lowest pairs of each problem, solved together: the windows of both
// problems share the eigensolver's threads.
// With `precision` float32 the eigensolver rounds the vectors it has finished with while it
// works on the others, so the set-up's peak memory holds them at half size too.
std::vector<Solved> solve(const std::vector<std::pair<const Scalar_problem*, int>>& problems, const Basis_options& options,
                          Eigenfunction_precision precision, double progress_start, double progress_span)
{
  Model_reduction::Eigensolver_options eigen_options = internal::eigensolver_options(options);
  eigen_options.float32_vectors = precision == Eigenfunction_precision::float32;
  if(options.progress)
    eigen_options.progress = [&](const Model_reduction::Eigensolver_progress& e) {
      const double f = e.wanted > 0 ? std::min(1., double(e.converged) / e.wanted) : 1.;
      options.progress({"eigenfunctions", progress_start + progress_span * f});
    };
  std::vector<Model_reduction::Eigenproblem_request> requests;
  for(const auto& problem : problems)
    requests.push_back({problem.first->A, problem.first->d, problem.second, problem.first->kernel});
  std::vector<Model_reduction::Eigenpairs> pairs = Model_reduction::lowest_eigenpairs_of_each(requests, eigen_options);
  std::vector<Solved> solved(problems.size());
  for(std::size_t i = 0; i < problems.size(); ++i)
  {
    const Scalar_problem& p = *problems[i].first;
    Solved& s = solved[i];
    s.values = pairs[i].values / p.area;
    const double scale = 1 / std::sqrt(p.area);
    s.functions = eigen_options.float32_vectors
                      ? Eigenfunction_matrix(p.expand(std::move(pairs[i].vectors_float32), scale))
                      : Eigenfunction_matrix(p.expand(std::move(pairs[i].vectors), scale));
    s.max_residual = pairs[i].residuals.size() ? pairs[i].residuals.maxCoeff() : 0.;
    s.complete_below = pairs[i].complete_below / p.area;
    s.check = pairs[i].completeness;
    s.thread_seconds = pairs[i].thread_seconds;
  }
  return solved;
}

// Eigenvalues of A x = lambda D x (outside the kernel) below tau.
int count_below(const Scalar_problem& p, double tau)
{
  if(p.available() == 0) return 0;
  return Model_reduction::count_eigenvalues_below(p.A, p.d, tau * p.area) - static_cast<int>(p.kernel.cols());
}

} // namespace

Eigenfield_basis::Eigenfield_basis(std::shared_ptr<const Hodge_solver> solver) : solver_(std::move(solver))
{
  if(!solver_) throw Invalid_input("spectral basis: no Hodge solver given");
}

Eigenfield_basis::Eigenfield_basis(std::shared_ptr<const Hodge_solver> solver, const Basis_request& request,
                                   const Basis_options& options)
  : Eigenfield_basis(std::move(solver))
{
  const Operator_matrices& ops = operators();
  const Intrinsic_mesh& mesh = ops.mesh();
  const double area = ops.face_areas().sum();
  const int harmonic_available = solver_->harmonic_dimension();
  auto progress = [&](const std::string& stage, double fraction) {
    if(options.progress) options.progress({stage, fraction});
  };

  const Scalar_problem exact = internal::scalar_eigenproblem(ops, Eigenfield_type::exact, area);
  const Scalar_problem coexact = internal::scalar_eigenproblem(ops, Eigenfield_type::coexact, area);
  const int exact_available = exact.available(), coexact_available = coexact.available();
  const int space = harmonic_available + exact_available + coexact_available; // = 2 nf

  // How many eigenpairs of each type to compute, and how many elements to keep.
  int exact_count = 0, coexact_count = 0, harmonic_count = harmonic_available, keep = 0;
  switch(request.mode)
  {
  case Basis_request::Mode::lowest:
  {
    if(request.count < 0 || request.count > space)
      throw Invalid_input("asked for " + std::to_string(request.count) + " eigenfields but the space of fields has dimension " +
                          std::to_string(space) + " (2 per face)");
    keep = request.count;
    harmonic_count = std::min(harmonic_available, keep);
    const int rest = keep - harmonic_count;
    // Weyl's law: below a frequency the two types are about equally many; a margin
    // absorbs the difference (more exact ones along boundaries).
    const int margin = rest > 0 ? std::max(8, rest / 16) : 0;
    exact_count = std::min(exact_available, (rest + 1) / 2 + margin);
    coexact_count = std::min(coexact_available, (rest + 1) / 2 + margin);
    if(exact_count + coexact_count < rest)
    {
      exact_count = std::min(exact_available, rest - coexact_count);
      coexact_count = std::min(coexact_available, rest - exact_count);
    }
    break;
  }
  case Basis_request::Mode::per_type:
    if(request.exact_count < 0 || request.exact_count > exact_available || request.coexact_count < 0 ||
       request.coexact_count > coexact_available)
      throw Invalid_input("asked for " + std::to_string(request.exact_count) + " exact and " +
                          std::to_string(request.coexact_count) + " coexact eigenfields; the mesh has " +
                          std::to_string(exact_available) + " and " + std::to_string(coexact_available));
    exact_count = request.exact_count;
    coexact_count = request.coexact_count;
    keep = harmonic_count + exact_count + coexact_count;
    break;
  case Basis_request::Mode::below_eigenvalue:
  {
    if(!(request.max_eigenvalue >= 0) || !std::isfinite(request.max_eigenvalue))
      throw Invalid_input("the largest eigenvalue of the basis must be finite and non-negative");
    // Sylvester's inertia gives the exact counts (a hair above the bound, so that an
    // eigenvalue equal to it counts).
    progress("counting eigenvalues", 0);
    const double tau = request.max_eigenvalue * (1 + 1e-12);
    exact_count = request.max_eigenvalue > 0 ? count_below(exact, tau) : 0;
    coexact_count = request.max_eigenvalue > 0 ? count_below(coexact, tau) : 0;
    keep = harmonic_count + exact_count + coexact_count;
    break;
  }
  }

  // Solve both problems; in `lowest` mode enlarge one whose margin turned out too small.
  Solved exact_solved, coexact_solved;
  int exact_done = -1, coexact_done = -1;
  for(int round = 0;; ++round)
  {
    // Both problems (or the one whose count changed) at once; the wall time is shared
    // out in proportion to the thread time each took.
    std::vector<std::pair<const Scalar_problem*, int>> problems;
    if(exact_count != exact_done) problems.push_back({&exact, exact_count});
    if(coexact_count != coexact_done) problems.push_back({&coexact, coexact_count});
    const auto start = std::chrono::steady_clock::now();
    std::vector<Solved> solved = solve(problems, options, request.precision, round == 0 ? 0. : 0.9, round == 0 ? 0.9 : 0.05);
    const double seconds = seconds_since(start);
    double thread_seconds = 0;
    for(const Solved& s : solved) thread_seconds += s.thread_seconds;
    for(std::size_t i = 0; i < problems.size(); ++i)
    {
      const double share = thread_seconds > 0 ? solved[i].thread_seconds / thread_seconds : 1. / problems.size();
      if(problems[i].first == &exact)
      {
        exact_solved = std::move(solved[i]);
        exact_done = exact_count;
        report_.exact_seconds += share * seconds;
      }
      else
      {
        coexact_solved = std::move(solved[i]);
        coexact_done = coexact_count;
        report_.coexact_seconds += share * seconds;
      }
    }
    if(request.mode != Basis_request::Mode::lowest) break;
    // The `rest` lowest of the union are right if no uncomputed eigenvalue of either
    // type lies below the largest one kept.
    const int rest = keep - harmonic_count;
    std::vector<double> merged(exact_solved.values.data(), exact_solved.values.data() + exact_count);
    merged.insert(merged.end(), coexact_solved.values.data(), coexact_solved.values.data() + coexact_count);
    std::sort(merged.begin(), merged.end());
    const double largest_kept = rest > 0 ? merged[rest - 1] : 0;
    const bool exact_enough = exact_count == exact_available || largest_kept <= exact_solved.complete_below;
    const bool coexact_enough = coexact_count == coexact_available || largest_kept <= coexact_solved.complete_below;
    if(exact_enough && coexact_enough) break;
    if(round == 3) throw Numerical_failure("spectral basis: could not merge the exact and coexact spectra");
    const int more = std::max(16, rest / 8);
    if(!exact_enough) exact_count = std::min(exact_available, exact_count + more);
    if(!coexact_enough) coexact_count = std::min(coexact_available, coexact_count + more);
  }

  if(request.mode == Basis_request::Mode::below_eigenvalue)
  {
    const double bound = request.max_eigenvalue * (1 + 1e-9);
    if((exact_count > 0 && exact_solved.values.maxCoeff() > bound) ||
       (coexact_count > 0 && coexact_solved.values.maxCoeff() > bound))
      throw Numerical_failure("spectral basis: the eigensolver returned an eigenvalue above the requested bound "
                              "although the inertia count says there are enough below it");
  }

  exact_values_ = exact_solved.values;
  exact_functions_ = std::move(exact_solved.functions);
  coexact_values_ = coexact_solved.values;
  coexact_functions_ = std::move(coexact_solved.functions);
  report_.max_residual = std::max(exact_solved.max_residual, coexact_solved.max_residual);
  report_.exact_complete_below = exact_solved.complete_below;
  report_.coexact_complete_below = coexact_solved.complete_below;
  report_.exact_inertia = exact_solved.check.inertia;
  report_.exact_expected = exact_solved.check.expected;
  report_.coexact_inertia = coexact_solved.check.inertia;
  report_.coexact_expected = coexact_solved.check.expected;

  if(harmonic_count > 0)
  {
    progress("harmonic fields", 0.95);
    const auto start = std::chrono::steady_clock::now();
    harmonic_ = solver_->harmonic_basis(options.seed).leftCols(harmonic_count);
    report_.harmonic_seconds = seconds_since(start);
  }
  else
    harmonic_.resize(2 * static_cast<Eigen::Index>(mesh.number_of_faces()), 0);
  merge(keep);
  // Drop the eigenpairs computed only as a margin.
  int exact_used = 0, coexact_used = 0;
  for(const Element& e : order_)
  {
    if(e.type == Eigenfield_type::exact) exact_used = std::max(exact_used, e.index + 1);
    if(e.type == Eigenfield_type::coexact) coexact_used = std::max(coexact_used, e.index + 1);
  }
  if(exact_used < number_of_exact())
  {
    report_.exact_complete_below = exact_values_[exact_used];
    exact_values_.conservativeResize(exact_used);
    exact_functions_.keep_columns(exact_used);
  }
  if(coexact_used < number_of_coexact())
  {
    report_.coexact_complete_below = coexact_values_[coexact_used];
    coexact_values_.conservativeResize(coexact_used);
    coexact_functions_.keep_columns(coexact_used);
  }
  set_precision(request.precision);
  progress("done", 1);
}

void Eigenfield_basis::set_precision(Eigenfunction_precision precision)
{
  exact_functions_.set_precision(precision);
  coexact_functions_.set_precision(precision);
}

std::size_t Eigenfield_basis::memory_bytes() const
{
  return exact_functions_.bytes() + coexact_functions_.bytes() + sizeof(double) * static_cast<std::size_t>(harmonic_.size());
}

void Eigenfield_basis::merge(int count)
{
  order_.clear();
  for(int i = 0; i < number_of_harmonic() && static_cast<int>(order_.size()) < count; ++i)
    order_.push_back({Eigenfield_type::harmonic, i});
  int i = 0, j = 0;
  while(static_cast<int>(order_.size()) < count && (i < number_of_exact() || j < number_of_coexact()))
  {
    const bool take_exact = j >= number_of_coexact() || (i < number_of_exact() && exact_values_[i] <= coexact_values_[j]);
    if(take_exact) order_.push_back({Eigenfield_type::exact, i++});
    else order_.push_back({Eigenfield_type::coexact, j++});
  }
  update_values();
}

void Eigenfield_basis::update_values()
{
  values_.resize(size());
  for(int k = 0; k < size(); ++k)
  {
    const Element& e = order_[k];
    values_[k] = e.type == Eigenfield_type::exact     ? exact_values_[e.index]
                 : e.type == Eigenfield_type::coexact ? coexact_values_[e.index]
                                                      : 0.;
  }
}

Eigenfield_basis::Vector Eigenfield_basis::eigenfield(int k) const
{
  if(k < 0 || k >= size())
    throw Invalid_input("eigenfield index " + std::to_string(k) + " outside [0, " + std::to_string(size()) + ")");
  Vector a = Vector::Zero(k + 1);
  a[k] = 1;
  return field(a);
}

Eigenfield_basis::Matrix Eigenfield_basis::coefficients(const Matrix& fields) const
{
  const Operator_matrices& ops = operators();
  if(fields.rows() != ops.field_masses().size())
    throw Invalid_input("a field has " + std::to_string(fields.rows()) + " frame coordinates, expected " +
                        std::to_string(ops.field_masses().size()));
  if(!fields.allFinite()) throw Invalid_input("the field has non-finite entries");
  const Matrix weighted = ops.field_masses().asDiagonal() * fields; // MX v
  Matrix a(size(), fields.cols());
  if(number_of_exact() > 0)
  {
    const Matrix Ae = exact_functions_.transpose_times(ops.G().transpose() * weighted);
    for(int k = 0; k < size(); ++k)
      if(order_[k].type == Eigenfield_type::exact)
        a.row(k) = Ae.row(order_[k].index) / std::sqrt(exact_values_[order_[k].index]);
  }
  if(number_of_coexact() > 0)
  {
    // <v, J G* psi>_MX = psi^T G*^T J^T MX v = -psi^T G*^T (J MX v)
    Matrix rotated(weighted.rows(), weighted.cols());
    for(Eigen::Index c = 0; c < weighted.cols(); ++c) rotated.col(c) = ops.rotate(weighted.col(c));
    const Matrix Ac = -coexact_functions_.transpose_times(ops.G_star_interior().transpose() * rotated);
    for(int k = 0; k < size(); ++k)
      if(order_[k].type == Eigenfield_type::coexact)
        a.row(k) = Ac.row(order_[k].index) / std::sqrt(coexact_values_[order_[k].index]);
  }
  if(number_of_harmonic() > 0)
  {
    const Matrix Ah = harmonic_.transpose() * weighted;
    for(int k = 0; k < size(); ++k)
      if(order_[k].type == Eigenfield_type::harmonic) a.row(k) = Ah.row(order_[k].index);
  }
  return a;
}

Eigenfield_basis::Vector Eigenfield_basis::coefficients(const Vector& field) const
{
  return coefficients(Matrix(field)).col(0);
}

Eigenfield_basis::Vector Eigenfield_basis::field(const Vector& a) const
{
  return decompress({a, 0, 0, {}}).col(0);
}

Eigenfield_basis::Matrix Eigenfield_basis::decompress(const Compressed_fields& compressed) const
{
  const Matrix& a = compressed.coefficients;
  if(a.rows() > size())
    throw Invalid_input(std::to_string(a.rows()) + " coefficients for a basis of " + std::to_string(size()) + " elements");
  if(!a.allFinite()) throw Invalid_input("the coefficients have non-finite entries");
  const Operator_matrices& ops = operators();
  // Gather the coefficients per type, scaled to eigenfunction coefficients.
  Matrix ce = Matrix::Zero(number_of_exact(), a.cols()), cc = Matrix::Zero(number_of_coexact(), a.cols()),
         ch = Matrix::Zero(number_of_harmonic(), a.cols());
  // Only the eigenfunctions the coefficients reach are read (a prefix of each type).
  Eigen::Index exact_used = 0, coexact_used = 0;
  bool any_harmonic = false;
  for(Eigen::Index k = 0; k < a.rows(); ++k)
  {
    const Element& e = order_[k];
    switch(e.type)
    {
    case Eigenfield_type::exact:
      ce.row(e.index) = a.row(k) / std::sqrt(exact_values_[e.index]);
      exact_used = std::max<Eigen::Index>(exact_used, e.index + 1);
      break;
    case Eigenfield_type::coexact:
      cc.row(e.index) = a.row(k) / std::sqrt(coexact_values_[e.index]);
      coexact_used = std::max<Eigen::Index>(coexact_used, e.index + 1);
      break;
    case Eigenfield_type::harmonic:
      ch.row(e.index) = a.row(k);
      any_harmonic = true;
      break;
    }
  }
  Matrix v = Matrix::Zero(ops.field_masses().size(), a.cols());
  if(exact_used > 0) v += ops.G() * exact_functions_.times(ce.topRows(exact_used));
  if(coexact_used > 0)
  {
    const Matrix g = ops.G_star_interior() * coexact_functions_.times(cc.topRows(coexact_used));
    for(Eigen::Index c = 0; c < g.cols(); ++c) v.col(c) += ops.rotate(g.col(c));
  }
  if(any_harmonic) v += harmonic_ * ch;
  return v;
}

Eigenfield_basis::Vector Eigenfield_basis::rest(const Vector& v) const { return v - field(coefficients(v)); }

Eigenfield_basis::Vector Eigenfield_basis::filter(const Vector& v, const Spectral_filter& f) const
{
  // The harmonic and rest factors are not seen by the check of the transfer below when the
  // mesh has no harmonic fields or the basis represents every field: test them here.
  if(!std::isfinite(f.harmonic_factor) || !std::isfinite(f.rest_factor))
    throw Invalid_input("the filter's harmonic and rest factors must be finite");
  const Vector a = coefficients(v);
  Vector b = a;
  for(int k = 0; k < size(); ++k)
  {
    const double omega = std::sqrt(values_[k]);
    switch(order_[k].type)
    {
    case Eigenfield_type::exact: b[k] *= f.exact(omega); break;
    case Eigenfield_type::coexact: b[k] *= f.coexact(omega); break;
    case Eigenfield_type::harmonic: b[k] *= f.harmonic_factor; break;
    }
  }
  if(!b.allFinite()) throw Invalid_input("the filter's transfer function returned a non-finite value");
  Vector result = field(b);
  if(f.rest_factor != 0) result += f.rest_factor * (v - field(a));
  // Finite factors can still overflow (a transfer of 1e300 on a large coefficient).
  if(!result.allFinite()) throw Invalid_input("the filter's result is not finite: its transfer is too large");
  return result;
}

Compressed_fields Eigenfield_basis::compress(const Matrix& fields, int k) const
{
  if(k < 0 || k > size())
    throw Invalid_input("cannot keep " + std::to_string(k) + " coefficients of a basis of " + std::to_string(size()));
  Compressed_fields c;
  c.coefficients = coefficients(fields).topRows(k);
  const Eigen::Index nf = operators().mesh().number_of_faces();
  c.ratio = k > 0 ? 2. * nf / k : std::numeric_limits<double>::infinity();
  c.bits_per_face = 64. * k / nf;
  const Matrix error = fields - decompress(c);
  const Vector& mass = operators().field_masses();
  c.relative_errors.resize(fields.cols());
  for(Eigen::Index j = 0; j < fields.cols(); ++j)
  {
    const double norm = std::sqrt(fields.col(j).cwiseAbs2().dot(mass));
    c.relative_errors[j] = norm > 0 ? std::sqrt(error.col(j).cwiseAbs2().dot(mass)) / norm : 0.;
  }
  return c;
}

} // namespace Tangent_vector_fields
} // namespace CGAL
