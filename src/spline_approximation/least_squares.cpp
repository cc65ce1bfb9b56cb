// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The banded Cholesky and the least-squares finish every algorithm ends with.

#include <CGAL/Spline_approximation/internal/spline_numerics.h>

#include <CGAL/Model_reduction/internal/Thread_pool.h>

#include <Eigen/LU>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <tuple>

namespace CGAL {
namespace Spline_approximation {
namespace internal {

void Banded_spd::add_gram(const Band_rows& R, double w)
{
  const Eigen::Index c = R.values.cols();
  for(Eigen::Index r = 0; r < R.rows(); ++r)
    for(Eigen::Index a = 0; a < c; ++a)
      for(Eigen::Index b = 0; b <= a; ++b) at(R.first[r] + a, R.first[r] + b) += w * R.values(r, a) * R.values(r, b);
}

Banded_spd Banded_spd::plus(const Banded_spd& B, double beta) const
{
  Banded_spd M(size(), std::max(w_, B.w_));
  M.band_.leftCols(w_ + 1) = band_;
  M.band_.leftCols(B.w_ + 1) += beta * B.band_;
  return M;
}

bool Banded_spd::factor(double relative_pivot)
{
  const Eigen::Index n = size();
  for(Eigen::Index j = 0; j < n; ++j) {
    const Eigen::Index lo = std::max<Eigen::Index>(0, j - w_);
    double d = at(j, j);
    const double original = d;
    for(Eigen::Index k = lo; k < j; ++k) d -= at(j, k) * at(j, k);
    if(!(d > relative_pivot * original)) return false; // also catches NaN
    const double l = std::sqrt(d);
    at(j, j) = l;
    for(Eigen::Index i = j + 1; i <= std::min(n - 1, j + w_); ++i) {
      double v = at(i, j);
      for(Eigen::Index k = std::max<Eigen::Index>(0, i - w_); k < j; ++k) v -= at(i, k) * at(j, k);
      at(i, j) = v / l;
    }
  }
  return true;
}

Eigen::MatrixXd Banded_spd::solve(const Eigen::MatrixXd& B) const
{
  const Eigen::Index n = size();
  Eigen::MatrixXd X = B;
  for(Eigen::Index i = 0; i < n; ++i) {
    for(Eigen::Index k = std::max<Eigen::Index>(0, i - w_); k < i; ++k) X.row(i) -= at(i, k) * X.row(k);
    X.row(i) /= at(i, i);
  }
  for(Eigen::Index i = n - 1; i >= 0; --i) {
    for(Eigen::Index k = i + 1; k <= std::min(n - 1, i + w_); ++k) X.row(i) -= at(k, i) * X.row(k);
    X.row(i) /= at(i, i);
  }
  return X;
}

struct Spd_matrix::Cyclic
{
  Eigen::SparseMatrix<double> M;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
};

Spd_matrix::Spd_matrix(Eigen::Index n, int w, bool cyclic)
    : cyclic_(cyclic), band_(cyclic ? 0 : n, w), sparse_(cyclic ? std::make_shared<Cyclic>() : nullptr)
{
  if(cyclic) sparse_->M.resize(n, n);
}

void Spd_matrix::add_gram(const Band_rows& R, double w)
{
  if(!cyclic_) return band_.add_gram(R, w);
  std::vector<Eigen::Triplet<double>> entries;
  const Eigen::Index c = R.values.cols();
  entries.reserve(std::size_t(R.rows() * c * c));
  for(Eigen::Index r = 0; r < R.rows(); ++r)
    for(Eigen::Index a = 0; a < c; ++a)
      for(Eigen::Index b = 0; b < c; ++b) // both triangles: wrapped columns may coincide
        entries.emplace_back(R.column(r, a), R.column(r, b), w * R.values(r, a) * R.values(r, b));
  Eigen::SparseMatrix<double> G(sparse_->M.rows(), sparse_->M.cols());
  G.setFromTriplets(entries.begin(), entries.end()); // duplicates add
  sparse_->M += G;
}

Spd_matrix Spd_matrix::plus(const Spd_matrix& B, double beta) const
{
  Spd_matrix S(cyclic_ ? sparse_->M.rows() : 0, 0, cyclic_);
  if(!cyclic_) S.band_ = band_.plus(B.band_, beta);
  else S.sparse_->M = sparse_->M + beta * B.sparse_->M;
  return S;
}

double Spd_matrix::max_diagonal() const
{
  return cyclic_ ? sparse_->M.diagonal().maxCoeff() : band_.max_diagonal();
}

bool Spd_matrix::factor(double relative_pivot)
{
  if(!cyclic_) return band_.factor(relative_pivot);
  sparse_->ldlt.compute(sparse_->M);
  if(sparse_->ldlt.info() != Eigen::Success) return false;
  // The same test as the banded Cholesky: each pivot against its diagonal entry (in the
  // factor's ordering); catches NaN too.
  const Eigen::VectorXd diagonal = sparse_->ldlt.permutationP() * Eigen::VectorXd(sparse_->M.diagonal());
  const Eigen::VectorXd pivots = sparse_->ldlt.vectorD();
  for(Eigen::Index i = 0; i < pivots.size(); ++i)
    if(!(pivots[i] > relative_pivot * diagonal[i])) return false;
  return true;
}

Eigen::MatrixXd Spd_matrix::solve(const Eigen::MatrixXd& B) const
{
  if(!cyclic_) return band_.solve(B);
  return sparse_->ldlt.solve(B);
}

namespace {

// Passes over more samples than this are split over the machine's cores: a sample costs a few
// dozen flops, so below it starting a thread costs more than it saves.
constexpr Eigen::Index parallel_samples = Eigen::Index(1) << 17;
// Up to 4 threads (the passes are bound by memory bandwidth beyond that), two parts each.
constexpr int max_sample_threads = 4, max_sample_parts = 2 * max_sample_threads;

// Runs `part(p, begin, end)` for the parts p = 0 .. parts - 1 of [0, n), on the cores when n is
// large; returns the number of parts (1 for a small n, at most `max_sample_parts`).  The parts depend on the core count only, so that on one machine
// the sums always add in the same order.
template <class Part>
int over_sample_parts(Eigen::Index n, const Part& part)
{
  if(n < parallel_samples) {
    part(0, Eigen::Index(0), n);
    return 1;
  }
  Model_reduction::internal::Thread_pool pool(std::min(max_sample_threads, Model_reduction::internal::thread_count(0)));
  const int parts = std::max(4, 2 * pool.size()); // the pool splits a range of at least 2 per worker + 2
  pool.run(std::size_t(parts), [&](std::size_t begin, std::size_t end) {
    for(std::size_t p = begin; p < end; ++p)
      part(int(p), n * Eigen::Index(p) / parts, n * Eigen::Index(p + 1) / parts);
  });
  return parts;
}

// The k + 1 basis functions nonzero on span s as polynomials in the span's own variable
// tau = (t - U[s]) / h in [0, 1]: C(a, p) is the coefficient of tau^p in N_{s-k+a}.  Taken from
// the values at tau = i / k through the inverse Vandermonde matrix of those points (entries at
// most 27 for k = 3: well conditioned).  Sums over a span's samples then need only the moments
// of tau, a handful of additions per sample instead of a basis evaluation.
typedef Eigen::Matrix<double, 4, 4> Span_coefficients;

Span_coefficients span_polynomials(const Eigen::VectorXd& U, int k, Eigen::Index s)
{
  // inverse_vandermonde[k]: the inverse of V(i, p) = (i / k)^p, 0 <= i, p <= k (identity beyond).
  static const std::array<Span_coefficients, 4> inverse_vandermonde = [] {
    std::array<Span_coefficients, 4> inverse;
    for(int degree = 0; degree <= 3; ++degree) {
      Eigen::MatrixXd V(degree + 1, degree + 1);
      for(int i = 0; i <= degree; ++i)
        for(int p = 0; p <= degree; ++p) V(i, p) = std::pow(degree > 0 ? double(i) / degree : 0.0, p);
      inverse[std::size_t(degree)].setIdentity();
      inverse[std::size_t(degree)].topLeftCorner(degree + 1, degree + 1) = V.inverse();
    }
    return inverse;
  }();
  const double a = U[s], h = U[s + 1] - a;
  Span_coefficients values = Span_coefficients::Zero(); // values(i, b): N_{s-k+b} at tau_i
  for(int i = 0; i <= k; ++i) {
    double N[4];
    basis_functions(U, k, s, a + h * (k > 0 ? double(i) / k : 0.0), N);
    for(int b = 0; b <= k; ++b) values(i, b) = N[b];
  }
  Span_coefficients C = Span_coefficients::Zero();
  C.topLeftCorner(k + 1, k + 1) =
      (inverse_vandermonde[std::size_t(k)].topLeftCorner(k + 1, k + 1) * values.topLeftCorner(k + 1, k + 1)).transpose();
  return C;
}

// Calls run(s, j0, j1) for each run [j0, j1) of the samples begin .. end - 1 that lie in one
// span s (the parameters increase: a run is found by a binary search).
template <class Run>
void for_each_span_run(const Basis& basis, const Eigen::VectorXd& t, Eigen::Index begin, Eigen::Index end, const Run& run)
{
  const Eigen::VectorXd& U = basis.U;
  const Eigen::Index last_span = U.size() - basis.degree - 2;
  for(Eigen::Index j = begin; j < end;) {
    const Eigen::Index s = find_span(U, basis.degree, t[j]);
    const Eigen::Index j1 =
        s == last_span ? end : Eigen::Index(std::lower_bound(t.data() + j, t.data() + end, U[s + 1]) - t.data());
    run(s, j, std::max(j1, j + 1));
    j = std::max(j1, j + 1);
  }
}

// The reciprocal of a span's length, 0 for an empty span (whose samples then all sit at tau 0).
double inverse_length(const Eigen::VectorXd& U, Eigen::Index s)
{
  const double h = U[s + 1] - U[s];
  return h > 0 ? 1.0 / h : 0.0;
}

// The moments of one span's samples [j0, j1): mu[p] = sum tau^p (p <= 2K), nu(p, c) = sum
// tau^p P(j, c) (p <= K), tau = (t - a) * inverse_h.  The degree is a template parameter so
// that the powers stay in registers; each coordinate is its own pass over a contiguous column.
template <int K>
void span_moments(const Eigen::VectorXd& t, const Eigen::MatrixXd& P, Eigen::Index j0, Eigen::Index j1, double a,
                  double inverse_h, double* mu, Eigen::MatrixXd& nu)
{
  double m[2 * K + 1] = {};
  for(Eigen::Index j = j0; j < j1; ++j) {
    const double tau = (t[j] - a) * inverse_h;
    double power = 1;
    for(int p = 0; p <= 2 * K; ++p, power *= tau) m[p] += power;
  }
  for(int p = 0; p <= 2 * K; ++p) mu[p] = m[p];
  for(Eigen::Index c = 0; c < P.cols(); ++c) {
    const double* x = &P(0, c);
    double n[K + 1] = {};
    for(Eigen::Index j = j0; j < j1; ++j) {
      const double tau = (t[j] - a) * inverse_h;
      double power = x[j];
      for(int p = 0; p <= K; ++p, power *= tau) n[p] += power;
    }
    for(int p = 0; p <= K; ++p) nu(p, c) = n[p];
  }
}

// The normal equations A^T A X = A^T P of an open curve's fit, span by span from the moments of
// tau: no n x (k + 1) design matrix (its allocation cost as much as the arithmetic on a million
// samples) and no basis evaluation per sample.
void open_normal_equations(const Basis& basis, const Eigen::VectorXd& t, const Eigen::MatrixXd& P, Spd_matrix& AtA,
                           Eigen::MatrixXd& AtP)
{
  const int k = basis.degree;
  const Eigen::Index D = P.cols();
  auto accumulate = [&](Banded_spd& band, Eigen::MatrixXd& rhs, Eigen::Index begin, Eigen::Index end) {
    Eigen::MatrixXd nu(4, D);
    for_each_span_run(basis, t, begin, end, [&](Eigen::Index s, Eigen::Index j0, Eigen::Index j1) {
      const double a = basis.U[s], inverse_h = inverse_length(basis.U, s);
      double mu[7];
      switch(k) {
      case 1: span_moments<1>(t, P, j0, j1, a, inverse_h, mu, nu); break;
      case 2: span_moments<2>(t, P, j0, j1, a, inverse_h, mu, nu); break;
      default: span_moments<3>(t, P, j0, j1, a, inverse_h, mu, nu); break;
      }
      const Span_coefficients C = span_polynomials(basis.U, k, s);
      const Eigen::Index first = s - k;
      for(int i = 0; i <= k; ++i) {
        for(int b = 0; b <= i; ++b) {
          double sum = 0;
          for(int p = 0; p <= k; ++p)
            for(int q = 0; q <= k; ++q) sum += C(i, p) * C(b, q) * mu[p + q];
          band.at(first + i, first + b) += sum;
        }
        for(Eigen::Index c = 0; c < D; ++c) {
          double sum = 0;
          for(int p = 0; p <= k; ++p) sum += C(i, p) * nu(p, c);
          rhs(first + i, c) += sum;
        }
      }
    });
  };
  Banded_spd& band = AtA.band();
  if(t.size() < parallel_samples) return accumulate(band, AtP, 0, t.size());
  std::vector<Banded_spd> bands(max_sample_parts, Banded_spd(band.size(), band.bandwidth()));
  std::vector<Eigen::MatrixXd> rhss(max_sample_parts, Eigen::MatrixXd::Zero(AtP.rows(), AtP.cols()));
  const int parts = over_sample_parts(t.size(), [&](int p, Eigen::Index begin, Eigen::Index end) {
    accumulate(bands[std::size_t(p)], rhss[std::size_t(p)], begin, end);
  });
  for(int p = 0; p < parts; ++p) {
    band.add(bands[std::size_t(p)]);
    AtP += rhss[std::size_t(p)];
  }
}

// The squared distances of the samples [j0, j1) of one span to the polynomial g (g(p, c): the
// coefficient of tau^p of coordinate c): their sum and largest, and the distances into `errors`.
template <int K>
void run_errors(const Eigen::VectorXd& t, const Eigen::MatrixXd& P, const Eigen::Matrix<double, 4, Eigen::Dynamic>& g,
                Eigen::Index j0, Eigen::Index j1, double a, double inverse_h, double& sum, double& largest,
                Eigen::VectorXd* errors)
{
  const Eigen::Index D = P.cols(), stride = P.rows();
  const double* coefficients = g.data();
  for(Eigen::Index j = j0; j < j1; ++j) {
    const double tau = (t[j] - a) * inverse_h;
    const double* x = P.data() + j;
    double squared = 0;
    for(Eigen::Index c = 0; c < D; ++c) {
      const double* gc = coefficients + 4 * c;
      double value = gc[K];
      for(int p = K - 1; p >= 0; --p) value = value * tau + gc[p];
      const double r = x[c * stride] - value;
      squared += r * r;
    }
    sum += squared;
    largest = std::max(largest, squared);
    if(errors) (*errors)[j] = std::sqrt(squared);
  }
}

// Per sample, the distance between the sample and the spline at its parameter, into `errors`
// when it is not null; returns the largest and the sum of squares.  Span by span, the spline
// as a polynomial in tau (Horner).
std::pair<double, double> open_errors(const Basis& basis, const Eigen::VectorXd& t, const Eigen::MatrixXd& P,
                                      const Eigen::MatrixXd& X, Eigen::VectorXd* errors)
{
  const int k = basis.degree;
  const Eigen::Index D = P.cols();
  double largest[max_sample_parts] = {}, sum[max_sample_parts] = {};
  const int parts = over_sample_parts(t.size(), [&](int part, Eigen::Index begin, Eigen::Index end) {
    double part_sum = 0, part_largest = 0; // locals: the parts' sums share a cache line
    Eigen::Matrix<double, 4, Eigen::Dynamic> g(4, D); // g(p, c): the coefficient of tau^p of coordinate c
    for_each_span_run(basis, t, begin, end, [&](Eigen::Index s, Eigen::Index j0, Eigen::Index j1) {
      const double a = basis.U[s], inverse_h = inverse_length(basis.U, s);
      const Span_coefficients C = span_polynomials(basis.U, k, s);
      g.setZero();
      for(int i = 0; i <= k; ++i)
        for(int p = 0; p <= k; ++p) g.row(p) += C(i, p) * X.row(s - k + i);
      double run_sum = 0, run_largest = 0;
      switch(k) {
      case 1: run_errors<1>(t, P, g, j0, j1, a, inverse_h, run_sum, run_largest, errors); break;
      case 2: run_errors<2>(t, P, g, j0, j1, a, inverse_h, run_sum, run_largest, errors); break;
      default: run_errors<3>(t, P, g, j0, j1, a, inverse_h, run_sum, run_largest, errors); break;
      }
      part_sum += run_sum;
      part_largest = std::max(part_largest, run_largest);
    });
    sum[part] = part_sum;
    largest[part] = part_largest;
  });
  double total = 0, most = 0;
  for(int p = 0; p < parts; ++p) total += sum[p], most = std::max(most, largest[p]);
  return {std::sqrt(most), total};
}

} // namespace

Spline_fit finish(const Problem& p, const std::vector<std::size_t>& kept, double lambda, Sample_errors detail)
{
  const Eigen::MatrixXd& P = *p.samples;
  const int k = p.degree;
  Eigen::VectorXd interior(kept.size());
  for(std::size_t i = 0; i < kept.size(); ++i) interior[Eigen::Index(i)] = p.candidates[Eigen::Index(kept[i])];
  const Basis basis = make_basis(interior, k, p.closed);
  const Eigen::Index n_ctrl = basis.controls;
  Spd_matrix AtA(n_ctrl, k + 1, p.closed);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n_ctrl, P.cols());
  std::optional<Band_rows> A; // closed curves: wrapped columns, through the general rows
  if(p.closed) {
    A = design_rows(basis, p.t);
    AtA.add_gram(*A, 1.0);
    A->add_transpose_times(P, 1.0, rhs);
  } else {
    open_normal_equations(basis, p.t, P, AtA, rhs);
  }
  // A pivot below 1e-12 of its diagonal means the knots leave (nearly) a direction without
  // samples (Schoenberg-Whitney fails): then add 1e-10 |J X|^2 at the kept knots, whose kernel
  // (single polynomials) the samples do determine, so the minimiser is unique and keeps its
  // residual within about 1e-10 of the best one.
  Spd_matrix M = AtA.plus(AtA, 0.0); // a copy (the cyclic one shares nothing with AtA)
  if(!M.factor(1e-12)) {
    Spd_matrix JtJ(n_ctrl, k + 1, p.closed);
    JtJ.add_gram(jump_rows(basis), 1.0);
    M = AtA.plus(JtJ, 1e-10 * AtA.max_diagonal());
    if(!M.factor(1e-15)) throw Numerical_failure("least-squares spline: the normal equations are singular");
  }
  Spline_fit fit;
  fit.spline.degree = k;
  fit.spline.closed = p.closed;
  fit.spline.knots = p.closed ? interior : basis.U; // closed: the knots on the circle
  fit.spline.control_points = M.solve(rhs);
  fit.kept = kept; // parameters and candidates are filled in once, by the entry points (n each)
  // A trial fit of the algorithms needs the largest and total error only: the n errors (a fresh
  // allocation each time, page faults included) are kept for the answers.
  const bool keep = detail == Sample_errors::kept;
  if(p.closed) {
    fit.errors = (A->times(fit.spline.control_points) - P).rowwise().norm();
    fit.squared_error = fit.errors.squaredNorm();
    fit.max_error = fit.errors.size() ? fit.errors.maxCoeff() : 0.0;
    if(!keep) fit.errors.resize(0);
  } else {
    if(keep) fit.errors.resize(p.t.size());
    std::tie(fit.max_error, fit.squared_error) =
        open_errors(basis, p.t, P, fit.spline.control_points, keep ? &fit.errors : nullptr);
  }
  fit.rms_error = std::sqrt(fit.squared_error / double(std::max<Eigen::Index>(1, p.t.size())));
  fit.objective = fit.squared_error + lambda * double(kept.size());
  return fit;
}

bool better(const Spline_fit& a, const Spline_fit& b, const Goal& goal)
{
  if(!goal.is_bound()) return a.objective < b.objective;
  const bool ma = goal.met(a), mb = goal.met(b);
  if(ma != mb) return ma;
  if(!ma) return a.squared_error < b.squared_error;
  if(a.kept.size() != b.kept.size()) return a.kept.size() < b.kept.size();
  return a.squared_error < b.squared_error;
}

} // namespace internal
} // namespace Spline_approximation
} // namespace CGAL
