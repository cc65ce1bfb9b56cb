// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/Sparse_spd_solver.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#ifdef TVF_HAS_CHOLMOD
#include <Eigen/CholmodSupport>
#else
#include <Eigen/SparseCholesky>
#endif

namespace CGAL {
namespace Tangent_vector_fields {

template <class Scalar>
struct Basic_sparse_spd_solver<Scalar>::Impl
{
#ifdef TVF_HAS_CHOLMOD
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<Scalar>, Eigen::Lower> factorization;
#else
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<Scalar>, Eigen::Lower> factorization;
#endif
  bool factored = false;
  Eigen::Index n = 0;
};

template <class Scalar>
Basic_sparse_spd_solver<Scalar>::Basic_sparse_spd_solver() : impl_(new Impl) {}
template <class Scalar>
Basic_sparse_spd_solver<Scalar>::~Basic_sparse_spd_solver() = default;
template <class Scalar>
Basic_sparse_spd_solver<Scalar>::Basic_sparse_spd_solver(Basic_sparse_spd_solver&&) noexcept = default;
template <class Scalar>
Basic_sparse_spd_solver<Scalar>& Basic_sparse_spd_solver<Scalar>::operator=(Basic_sparse_spd_solver&&) noexcept = default;

template <class Scalar>
const char* Basic_sparse_spd_solver<Scalar>::backend_name()
{
#ifdef TVF_HAS_CHOLMOD
  return "CHOLMOD supernodal";
#else
  return "Eigen SimplicialLDLT";
#endif
}

template <class Scalar>
void Basic_sparse_spd_solver<Scalar>::factor(const Eigen::SparseMatrix<Scalar>& A, const std::string& what)
{
  impl_->factored = false;
  impl_->n = A.rows();
  if(A.rows() == 0)
  {
    impl_->factored = true;
    return;
  }
#ifdef TVF_HAS_CHOLMOD
  // AMD ordering only.  CHOLMOD's default also tries METIS when AMD's fill looks
  // high; on mesh Laplacians METIS gave no better factor and its own run cost more
  // than the factorisation (Loop-subdivided bunny, 1.1M faces: W* 12.8 s -> 5.0 s).
  cholmod_common& common = impl_->factorization.cholmod();
  common.nmethods = 1;
  common.method[0].ordering = CHOLMOD_AMD;
#endif
  impl_->factorization.compute(A);
  bool ok = impl_->factorization.info() == Eigen::Success;
#ifndef TVF_HAS_CHOLMOD
  // LDL^T succeeds on indefinite matrices: require a positive pivot everywhere.
  ok = ok && (impl_->factorization.vectorD().real().array() > 0).all();
#endif
  if(!ok) throw Numerical_failure("factorisation of " + what + " failed: the matrix is not numerically positive definite");
  impl_->factored = true;
}

template <class Scalar>
bool Basic_sparse_spd_solver<Scalar>::is_factored() const { return impl_->factored; }
template <class Scalar>
Eigen::Index Basic_sparse_spd_solver<Scalar>::size() const { return impl_->n; }

template <class Scalar>
typename Basic_sparse_spd_solver<Scalar>::Vector Basic_sparse_spd_solver<Scalar>::solve(const Vector& b) const
{
  if(impl_->n == 0) return Vector(0);
  return impl_->factorization.solve(b);
}

template <class Scalar>
typename Basic_sparse_spd_solver<Scalar>::Matrix Basic_sparse_spd_solver<Scalar>::solve(const Matrix& B) const
{
  if(impl_->n == 0) return Matrix(0, B.cols());
  return impl_->factorization.solve(B);
}

template class Basic_sparse_spd_solver<double>;
template class Basic_sparse_spd_solver<std::complex<double>>;

} // namespace Tangent_vector_fields
} // namespace CGAL
