// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Model_reduction/internal/Standard_eigenproblem.h>
#include <CGAL/Model_reduction/errors.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

extern "C" void dsyevd_(const char* jobz, const char* uplo, const int* n, double* a, const int* lda, double* w,
                        double* work, const int* lwork, int* iwork, const int* liwork, int* info);
extern "C" void zheevd_(const char* jobz, const char* uplo, const int* n, std::complex<double>* a, const int* lda,
                        double* w, std::complex<double>* work, const int* lwork, double* rwork, const int* lrwork,
                        int* iwork, const int* liwork, int* info);

namespace CGAL {
namespace Model_reduction {
namespace internal {

namespace {

// One call of LAPACK's divide and conquer, dsyevd or zheevd (which has a real workspace
// `rwork` besides); -1 sizes ask for the workspace sizes.
int lapack_eigen(int n, double* a, double* w, double* work, int lwork, double*, int, int* iwork, int liwork)
{
  int info = 0;
  dsyevd_("V", "L", &n, a, &n, w, work, &lwork, iwork, &liwork, &info);
  return info;
}
int lapack_eigen(int n, std::complex<double>* a, double* w, std::complex<double>* work, int lwork, double* rwork,
                 int lrwork, int* iwork, int liwork)
{
  int info = 0;
  zheevd_("V", "L", &n, a, &n, w, work, &lwork, rwork, &lrwork, iwork, &liwork, &info);
  return info;
}

// LAPACK's divide and conquer: several times faster than Eigen's QR iteration at m ~ 1000.
template <class Scalar>
void lapack_symmetric_eigen(Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& A, Eigen::VectorXd& values)
{
  const int n = static_cast<int>(A.rows());
  values.resize(n);
  if(n == 0) return;
  Scalar work_query = 0;
  double rwork_query = 0;
  int iwork_query = 0;
  lapack_eigen(n, A.data(), values.data(), &work_query, -1, &rwork_query, -1, &iwork_query, -1);
  const int lwork = static_cast<int>(std::real(work_query)), lrwork = std::max(1, static_cast<int>(rwork_query));
  std::vector<Scalar> work(lwork);
  std::vector<double> rwork(lrwork);
  std::vector<int> iwork(iwork_query);
  const int info =
      lapack_eigen(n, A.data(), values.data(), work.data(), lwork, rwork.data(), lrwork, iwork.data(), iwork_query);
  if(info != 0) throw Numerical_failure("dense symmetric eigensolver (LAPACK) failed, info " + std::to_string(info));
}

// |a|.  For complex a without std::abs's hypot, whose care against overflow cost a twentieth of
// the rocker arm's complex n-field solve (every entry of A for every residual).
struct Magnitude
{
  double operator()(double a) const { return std::abs(a); }
  double operator()(const std::complex<double>& a) const { return std::sqrt(std::norm(a)); }
};

} // namespace

void symmetric_eigen(Eigen::MatrixXd& A, Eigen::VectorXd& values) { lapack_symmetric_eigen(A, values); }
void symmetric_eigen(Eigen::MatrixXcd& A, Eigen::VectorXd& values) { lapack_symmetric_eigen(A, values); }

template <class Scalar>
Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>
orthonormal_columns(const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& X)
{
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> Matrix;
  Eigen::HouseholderQR<Matrix> qr(X);
  return qr.householderQ() * Matrix::Identity(X.rows(), X.cols());
}

// Cholesky QR twice (two small Gram matrices through the BLAS; Householder's rank-one
// updates were 11% of the run), Householder when the block is (nearly) rank deficient.
template <class Scalar>
void block_qr(const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& Z,
              Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& next,
              Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& R)
{
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> Matrix;
  const Eigen::Index b = Z.cols();
  Matrix Y = Z;
  R = Matrix::Identity(b, b);
  for(int pass = 0; pass < 2; ++pass)
  {
    const Matrix gram = Y.adjoint() * Y;
    Eigen::LLT<Matrix> llt(gram);
    const Matrix U = llt.matrixU();
    const Eigen::VectorXd diagonal = U.diagonal().real();
    const double ratio = diagonal.minCoeff() / std::max(diagonal.maxCoeff(), 1e-300);
    if(llt.info() != Eigen::Success || !(ratio > 1e-6))
    {
      Eigen::HouseholderQR<Matrix> qr(Z);
      R = qr.matrixQR().topRows(b).template triangularView<Eigen::Upper>();
      next = qr.householderQ() * Matrix::Identity(Z.rows(), b);
      return;
    }
    Y = U.template triangularView<Eigen::Upper>().template solve<Eigen::OnTheRight>(Y);
    R = (U * R).eval();
  }
  next = std::move(Y);
}

template <class Scalar>
Basic_standard_eigenproblem<Scalar>::Basic_standard_eigenproblem(const Sparse_matrix& A_, const Eigen::VectorXd& d_,
                                                                 const Matrix& kernel_original)
    : A(A_), d(d_)
{
  Eigen::VectorXd row_sums = Eigen::VectorXd::Zero(A.rows());
  for(Eigen::Index j = 0; j < A.outerSize(); ++j)
    for(typename Sparse_matrix::InnerIterator it(A, j); it; ++it)
      row_sums[it.row()] += std::abs(it.value()) / std::sqrt(d[it.row()] * d[j]);
  largest_eigenvalue_bound = row_sums.size() ? row_sums.maxCoeff() : 0.;
  sqrt_d = d.cwiseSqrt();
  inv_sqrt_d = sqrt_d.cwiseInverse();
  if(kernel_original.cols() > 0) kernel = orthonormal_columns<Scalar>(sqrt_d.asDiagonal() * kernel_original);
  else kernel.resize(d.size(), 0);
}

template <class Scalar>
double Basic_standard_eigenproblem<Scalar>::tolerance_for(double lambda, double tolerance) const
{
  return std::max(tolerance, 64 * std::numeric_limits<double>::epsilon() * largest_eigenvalue_bound / std::abs(lambda));
}

template <class Scalar>
void Basic_standard_eigenproblem<Scalar>::residuals_of_standard(const Eigen::VectorXd& values,
                                                                const Eigen::Ref<const Matrix>& Y, double tolerance,
                                                                Eigen::VectorXd& residuals,
                                                                Eigen::VectorXd* tolerances) const
{
  const Eigen::Index n = d.size();
  Vector x(n), ax(n);
  Eigen::VectorXd abs_x(n), abs_ax(n);
  residuals.resize(values.size());
  if(tolerances) tolerances->resize(values.size());
  for(Eigen::Index i = 0; i < values.size(); ++i)
  {
    x = inv_sqrt_d.cwiseProduct(Y.col(i));
    ax.noalias() = A * x;
    const double scale = std::abs(values[i]) * Y.col(i).norm();
    residuals[i] = inv_sqrt_d.cwiseProduct(ax - values[i] * d.cwiseProduct(x)).norm() / scale;
    if(!tolerances) continue;
    abs_x = x.unaryExpr(Magnitude());
    abs_ax.noalias() = A.unaryExpr(Magnitude()) * abs_x; // |A| is not kept: as large as A
    (*tolerances)[i] =
        std::max(tolerance, 64 * std::numeric_limits<double>::epsilon() * inv_sqrt_d.cwiseProduct(abs_ax).norm() / scale);
  }
}

template <class Scalar>
typename Basic_standard_eigenproblem<Scalar>::Sparse_matrix Basic_standard_eigenproblem<Scalar>::shifted(double sigma) const
{
  Sparse_matrix K = A;
  K.diagonal() -= sigma * d;
  return K;
}

template <class Scalar>
typename Basic_standard_eigenproblem<Scalar>::Matrix Basic_standard_eigenproblem<Scalar>::shifted_times(double sigma,
                                                                                                       const Matrix& X) const
{
  Matrix Y = A * X;
  Y -= sigma * (d.asDiagonal() * X);
  return Y;
}

template <class Scalar>
Eigen::VectorXd Basic_standard_eigenproblem<Scalar>::residuals(const Eigen::VectorXd& values, const Matrix& X) const
{
  Eigen::VectorXd r;
  residuals_of_standard(values, sqrt_d.asDiagonal() * X, 0, r);
  return r;
}

template <class Scalar>
Eigen::VectorXd Basic_standard_eigenproblem<Scalar>::tolerances_for(const Eigen::VectorXd& values, const Matrix& X,
                                                                    double tolerance) const
{
  Eigen::VectorXd r, t;
  residuals_of_standard(values, sqrt_d.asDiagonal() * X, tolerance, r, &t);
  return t;
}

template struct Basic_standard_eigenproblem<double>;
template struct Basic_standard_eigenproblem<std::complex<double>>;
template Eigen::MatrixXd orthonormal_columns<double>(const Eigen::MatrixXd&);
template Eigen::MatrixXcd orthonormal_columns<std::complex<double>>(const Eigen::MatrixXcd&);
template void block_qr<double>(const Eigen::MatrixXd&, Eigen::MatrixXd&, Eigen::MatrixXd&);
template void block_qr<std::complex<double>>(const Eigen::MatrixXcd&, Eigen::MatrixXcd&, Eigen::MatrixXcd&);

} // namespace internal
} // namespace Model_reduction
} // namespace CGAL
