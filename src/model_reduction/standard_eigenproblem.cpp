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

namespace CGAL {
namespace Model_reduction {
namespace internal {

// LAPACK's divide and conquer: several times faster than Eigen's QR iteration at m ~ 1000.
void symmetric_eigen(Eigen::MatrixXd& A, Eigen::VectorXd& values)
{
  const int n = static_cast<int>(A.rows());
  values.resize(n);
  if(n == 0) return;
  int info = 0, lwork = -1, liwork = -1, iwork_query = 0;
  double work_query = 0;
  dsyevd_("V", "L", &n, A.data(), &n, values.data(), &work_query, &lwork, &iwork_query, &liwork, &info);
  lwork = static_cast<int>(work_query);
  liwork = iwork_query;
  std::vector<double> work(lwork);
  std::vector<int> iwork(liwork);
  dsyevd_("V", "L", &n, A.data(), &n, values.data(), work.data(), &lwork, iwork.data(), &liwork, &info);
  if(info != 0) throw Numerical_failure("dense symmetric eigensolver (LAPACK dsyevd) failed, info " + std::to_string(info));
}

Eigen::MatrixXd orthonormal_columns(const Eigen::MatrixXd& X)
{
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(X);
  return qr.householderQ() * Eigen::MatrixXd::Identity(X.rows(), X.cols());
}

// Cholesky QR twice (two small Gram matrices through the BLAS; Householder's rank-one
// updates were 11% of the run), Householder when the block is (nearly) rank deficient.
void block_qr(const Eigen::MatrixXd& Z, Eigen::MatrixXd& next, Eigen::MatrixXd& R)
{
  const Eigen::Index b = Z.cols();
  Eigen::MatrixXd Y = Z;
  R = Eigen::MatrixXd::Identity(b, b);
  for(int pass = 0; pass < 2; ++pass)
  {
    const Eigen::MatrixXd gram = Y.transpose() * Y;
    Eigen::LLT<Eigen::MatrixXd> llt(gram);
    const Eigen::MatrixXd U = llt.matrixU();
    const double ratio = U.diagonal().minCoeff() / std::max(U.diagonal().maxCoeff(), 1e-300);
    if(llt.info() != Eigen::Success || !(ratio > 1e-6))
    {
      Eigen::HouseholderQR<Eigen::MatrixXd> qr(Z);
      R = qr.matrixQR().topRows(b).triangularView<Eigen::Upper>();
      next = qr.householderQ() * Eigen::MatrixXd::Identity(Z.rows(), b);
      return;
    }
    Y = U.triangularView<Eigen::Upper>().solve<Eigen::OnTheRight>(Y);
    R = (U * R).eval();
  }
  next = std::move(Y);
}

Standard_eigenproblem::Standard_eigenproblem(const Eigen::SparseMatrix<double>& A_, const Eigen::VectorXd& d_,
                                             const Eigen::MatrixXd& kernel_original)
    : A(A_), d(d_)
{
  Eigen::VectorXd row_sums = Eigen::VectorXd::Zero(A.rows());
  for(Eigen::Index j = 0; j < A.outerSize(); ++j)
    for(Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it)
      row_sums[it.row()] += std::abs(it.value()) / std::sqrt(d[it.row()] * d[j]);
  largest_eigenvalue_bound = row_sums.size() ? row_sums.maxCoeff() : 0.;
  sqrt_d = d.cwiseSqrt();
  inv_sqrt_d = sqrt_d.cwiseInverse();
  if(kernel_original.cols() > 0) kernel = orthonormal_columns(sqrt_d.asDiagonal() * kernel_original);
  else kernel.resize(d.size(), 0);
}

double Standard_eigenproblem::tolerance_for(double lambda, double tolerance) const
{
  return std::max(tolerance, 64 * std::numeric_limits<double>::epsilon() * largest_eigenvalue_bound / std::abs(lambda));
}

void Standard_eigenproblem::residuals_of_standard(const Eigen::VectorXd& values, const Eigen::Ref<const Eigen::MatrixXd>& Y,
                                                  double tolerance, Eigen::VectorXd& residuals,
                                                  Eigen::VectorXd* tolerances) const
{
  const Eigen::Index n = d.size();
  Eigen::VectorXd x(n), ax(n), abs_x(n), abs_ax(n);
  residuals.resize(values.size());
  if(tolerances) tolerances->resize(values.size());
  for(Eigen::Index i = 0; i < values.size(); ++i)
  {
    x = inv_sqrt_d.cwiseProduct(Y.col(i));
    ax.noalias() = A * x;
    const double scale = std::abs(values[i]) * Y.col(i).norm();
    residuals[i] = inv_sqrt_d.cwiseProduct(ax - values[i] * d.cwiseProduct(x)).norm() / scale;
    if(!tolerances) continue;
    abs_x = x.cwiseAbs();
    abs_ax.noalias() = A.cwiseAbs() * abs_x; // |A| is not kept: as large as A
    (*tolerances)[i] =
        std::max(tolerance, 64 * std::numeric_limits<double>::epsilon() * inv_sqrt_d.cwiseProduct(abs_ax).norm() / scale);
  }
}

Eigen::SparseMatrix<double> Standard_eigenproblem::shifted(double sigma) const
{
  Eigen::SparseMatrix<double> K = A;
  K.diagonal() -= sigma * d;
  return K;
}

Eigen::MatrixXd Standard_eigenproblem::shifted_times(double sigma, const Eigen::MatrixXd& X) const
{
  Eigen::MatrixXd Y = A * X;
  Y -= sigma * (d.asDiagonal() * X);
  return Y;
}

Eigen::VectorXd Standard_eigenproblem::residuals(const Eigen::VectorXd& values, const Eigen::MatrixXd& X) const
{
  Eigen::VectorXd r;
  residuals_of_standard(values, sqrt_d.asDiagonal() * X, 0, r);
  return r;
}

Eigen::VectorXd Standard_eigenproblem::tolerances_for(const Eigen::VectorXd& values, const Eigen::MatrixXd& X,
                                                      double tolerance) const
{
  Eigen::VectorXd r, t;
  residuals_of_standard(values, sqrt_d.asDiagonal() * X, tolerance, r, &t);
  return t;
}

} // namespace internal
} // namespace Model_reduction
} // namespace CGAL
