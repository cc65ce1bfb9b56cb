// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Model_reduction/Sparse_spd_solver.h>
#include <CGAL/Model_reduction/errors.h>

#ifdef CGAL_MODEL_REDUCTION_HAS_CHOLMOD
#include <Eigen/CholmodSupport>
#else
#include <Eigen/SparseCholesky>
#endif

#include <mutex>

namespace CGAL {
namespace Model_reduction {

#ifdef CGAL_MODEL_REDUCTION_HAS_CHOLMOD
namespace {
// Eigen's CHOLMOD LL^T, with access to its CHOLMOD factor and workspace.
template <class Matrix>
struct Cholmod_llt : Eigen::CholmodDecomposition<Matrix, Eigen::Lower>
{
  cholmod_factor* factor() const { return this->m_cholmodFactor; }
  cholmod_common& common() const { return const_cast<Cholmod_llt*>(this)->cholmod(); }
};
} // namespace
#endif

template <class Scalar>
struct Basic_sparse_spd_solver<Scalar>::Impl
{
#ifdef CGAL_MODEL_REDUCTION_HAS_CHOLMOD
  Cholmod_llt<Eigen::SparseMatrix<Scalar>> factorization;
  // A simplicial copy of the factor, made on the first solve of at most two columns: the
  // supernodal solve of one or two columns spends its time in small BLAS calls (2 columns of
  // W* on 346k faces: 77 ms supernodal, 41 ms simplicial; 6 columns: 112 and 101 ms).
  mutable cholmod_factor* simplicial = nullptr;
  mutable std::mutex simplicial_mutex;
  ~Impl() { drop_simplicial(); }
  void drop_simplicial()
  {
    if(simplicial) cholmod_free_factor(&simplicial, &factorization.common());
  }
#else
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<Scalar>, Eigen::Lower> factorization;
#endif
  bool factored = false;
  bool supernodal = true;
  Eigen::Index n = 0;
};

template <class Scalar>
Basic_sparse_spd_solver<Scalar>::Basic_sparse_spd_solver(Spd_factorization kind) : impl_(new Impl)
{
  impl_->supernodal = kind == Spd_factorization::supernodal;
#ifdef CGAL_MODEL_REDUCTION_HAS_CHOLMOD
  impl_->factorization.setMode(impl_->supernodal ? Eigen::CholmodSupernodalLLt : Eigen::CholmodSimplicialLLt);
#endif
}
template <class Scalar>
Basic_sparse_spd_solver<Scalar>::~Basic_sparse_spd_solver() = default;
template <class Scalar>
Basic_sparse_spd_solver<Scalar>::Basic_sparse_spd_solver(Basic_sparse_spd_solver&&) noexcept = default;
template <class Scalar>
Basic_sparse_spd_solver<Scalar>& Basic_sparse_spd_solver<Scalar>::operator=(Basic_sparse_spd_solver&&) noexcept = default;

template <class Scalar>
const char* Basic_sparse_spd_solver<Scalar>::backend_name()
{
#ifdef CGAL_MODEL_REDUCTION_HAS_CHOLMOD
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
#ifdef CGAL_MODEL_REDUCTION_HAS_CHOLMOD
  // AMD ordering only.  CHOLMOD's default also tries METIS when AMD's fill looks
  // high; on mesh Laplacians METIS gave no better factor and its own run cost more
  // than the factorisation (Loop-subdivided bunny, 1.1M faces: W* 12.8 s -> 5.0 s).
  impl_->drop_simplicial();
  cholmod_common& common = impl_->factorization.cholmod();
  common.nmethods = 1;
  common.method[0].ordering = CHOLMOD_AMD;
#endif
  impl_->factorization.compute(A);
  bool ok = impl_->factorization.info() == Eigen::Success;
#ifndef CGAL_MODEL_REDUCTION_HAS_CHOLMOD
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
  return solve(Matrix(b)).col(0);
}

template <class Scalar>
typename Basic_sparse_spd_solver<Scalar>::Matrix Basic_sparse_spd_solver<Scalar>::solve(const Matrix& B) const
{
  if(impl_->n == 0) return Matrix(0, B.cols());
#ifdef CGAL_MODEL_REDUCTION_HAS_CHOLMOD
  if(B.cols() <= 2 && impl_->factored && impl_->supernodal)
  {
    cholmod_common& common = impl_->factorization.common();
    {
      std::lock_guard<std::mutex> lock(impl_->simplicial_mutex);
      if(!impl_->simplicial)
      {
        cholmod_factor* copy = cholmod_copy_factor(impl_->factorization.factor(), &common);
        if(copy && !cholmod_change_factor(copy->xtype, 1, 0, 1, 1, copy, &common)) cholmod_free_factor(&copy, &common);
        impl_->simplicial = copy;
      }
    }
    if(impl_->simplicial)
    {
      Matrix rhs = B;
      cholmod_dense b = Eigen::viewAsCholmod(rhs);
      cholmod_dense* x = cholmod_solve(CHOLMOD_A, impl_->simplicial, &b, &common);
      if(x)
      {
        const Matrix X = Eigen::Map<const Matrix>(static_cast<const Scalar*>(x->x), B.rows(), B.cols());
        cholmod_free_dense(&x, &common);
        return X;
      }
    }
  }
#endif
  return impl_->factorization.solve(B);
}

template class Basic_sparse_spd_solver<double>;
template class Basic_sparse_spd_solver<std::complex<double>>;

} // namespace Model_reduction
} // namespace CGAL
