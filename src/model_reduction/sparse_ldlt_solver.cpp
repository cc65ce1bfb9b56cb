// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Model_reduction/Sparse_ldlt_solver.h>
#include <CGAL/Model_reduction/errors.h>

#ifdef CGAL_MODEL_REDUCTION_HAS_CHOLMOD
#include <Eigen/CholmodSupport>
#else
#include <Eigen/SparseCholesky>
#endif

#include <cmath>

namespace CGAL {
namespace Model_reduction {

#ifdef CGAL_MODEL_REDUCTION_HAS_CHOLMOD

// CHOLMOD simplicial LDL^T: on mesh Laplacians it factors as fast as the supernodal
// LL^T and solves blocks of 16 columns faster (measured to 519k unknowns), and it
// accepts indefinite matrices.  The analysis (AMD) is shared by all shifts.  Complex
// Hermitian matrices (xtype CHOLMOD_COMPLEX, as Eigen passes std::complex<double>) are
// factored as L D L^H with D real, stored as complex numbers of zero imaginary part.
template <class Scalar>
struct Basic_sparse_ldlt_solver<Scalar>::Impl
{
  cholmod_common common;
  cholmod_factor* factor = nullptr;
  Eigen::VectorXd pivots;
  // Solution and workspace kept from solve to solve: allocated afresh, each solve's
  // blocks of a few MB were new pages (a quarter of the eigensolver's page faults).
  cholmod_dense *x = nullptr, *y = nullptr, *e = nullptr;
  Impl()
  {
    cholmod_start(&common);
    common.supernodal = CHOLMOD_SIMPLICIAL;
    common.final_ll = 0;
    common.nmethods = 1;
    common.method[0].ordering = CHOLMOD_AMD;
    common.print = 0;
  }
  ~Impl()
  {
    for(cholmod_dense** d : {&x, &y, &e})
      if(*d) cholmod_free_dense(d, &common);
    if(factor) cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
};

template <class Scalar>
Basic_sparse_ldlt_solver<Scalar>::Basic_sparse_ldlt_solver() : impl_(new Impl) {}
template <class Scalar>
Basic_sparse_ldlt_solver<Scalar>::~Basic_sparse_ldlt_solver() = default;

template <class Scalar>
void Basic_sparse_ldlt_solver<Scalar>::analyze(const Sparse_matrix& A, bool many_factorizations)
{
  if(impl_->factor) cholmod_free_factor(&impl_->factor, &impl_->common);
  cholmod_sparse view = Eigen::viewAsCholmod(A.template selfadjointView<Eigen::Lower>());
  impl_->common.method[0].ordering = many_factorizations && A.rows() >= 20000 ? CHOLMOD_METIS : CHOLMOD_AMD;
  impl_->factor = cholmod_analyze(&view, &impl_->common);
  if(!impl_->factor && impl_->common.method[0].ordering == CHOLMOD_METIS) // a CHOLMOD built without METIS
  {
    impl_->common.method[0].ordering = CHOLMOD_AMD;
    impl_->factor = cholmod_analyze(&view, &impl_->common);
  }
  if(!impl_->factor || impl_->common.status < CHOLMOD_OK) throw Numerical_failure("LDL^T analysis failed (CHOLMOD)");
}

template <class Scalar>
void Basic_sparse_ldlt_solver<Scalar>::copy_analysis(const Basic_sparse_ldlt_solver& other)
{
  if(impl_->factor) cholmod_free_factor(&impl_->factor, &impl_->common);
  impl_->factor = cholmod_copy_factor(other.impl_->factor, &impl_->common);
  if(!impl_->factor) throw Numerical_failure("LDL^T analysis could not be copied (CHOLMOD)");
}

template <class Scalar>
void Basic_sparse_ldlt_solver<Scalar>::factor(const Sparse_matrix& A, const std::string& what)
{
  if(!impl_->factor) analyze(A);
  cholmod_sparse view = Eigen::viewAsCholmod(A.template selfadjointView<Eigen::Lower>());
  cholmod_factorize(&view, impl_->factor, &impl_->common);
  cholmod_factor* L = impl_->factor;
  if(impl_->common.status < CHOLMOD_OK || L->minor < L->n || L->is_ll || L->is_super)
    throw Numerical_failure("LDL^T factorisation of " + what + " failed (CHOLMOD status " +
                            std::to_string(impl_->common.status) + ")");
  const int* p = static_cast<const int*>(L->p);
  const Scalar* x = static_cast<const Scalar*>(L->x);
  impl_->pivots.resize(static_cast<Eigen::Index>(L->n));
  for(std::size_t j = 0; j < L->n; ++j) impl_->pivots[static_cast<Eigen::Index>(j)] = std::real(x[p[j]]);
  if(!impl_->pivots.allFinite() || (impl_->pivots.array() == 0).any())
    throw Numerical_failure("LDL^T factorisation of " + what + ": zero or non-finite pivot");
}

template <class Scalar>
typename Basic_sparse_ldlt_solver<Scalar>::Matrix Basic_sparse_ldlt_solver<Scalar>::solve(const Matrix& B) const
{
  cholmod_dense b = Eigen::viewAsCholmod(const_cast<Matrix&>(B)); // read only
  if(!cholmod_solve2(CHOLMOD_A, impl_->factor, &b, nullptr, &impl_->x, nullptr, &impl_->y, &impl_->e, &impl_->common))
    throw Numerical_failure("LDL^T solve failed (CHOLMOD)");
  return Eigen::Map<const Matrix>(static_cast<const Scalar*>(impl_->x->x), B.rows(), B.cols());
}

#else

template <class Scalar>
struct Basic_sparse_ldlt_solver<Scalar>::Impl
{
  Eigen::SimplicialLDLT<Sparse_matrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt; // L D L^H, D real
  bool analyzed = false;
  Eigen::VectorXd pivots;
};

template <class Scalar>
Basic_sparse_ldlt_solver<Scalar>::Basic_sparse_ldlt_solver() : impl_(new Impl) {}
template <class Scalar>
Basic_sparse_ldlt_solver<Scalar>::~Basic_sparse_ldlt_solver() = default;

template <class Scalar>
void Basic_sparse_ldlt_solver<Scalar>::analyze(const Sparse_matrix& A, bool)
{
  impl_->ldlt.analyzePattern(A);
  impl_->analyzed = true;
}

// Eigen's SimplicialLDLT cannot be copied: the first `factor` analyses the pattern again (AMD
// orders one pattern the same way each time).
template <class Scalar>
void Basic_sparse_ldlt_solver<Scalar>::copy_analysis(const Basic_sparse_ldlt_solver&)
{
  impl_->analyzed = false;
}

template <class Scalar>
void Basic_sparse_ldlt_solver<Scalar>::factor(const Sparse_matrix& A, const std::string& what)
{
  if(!impl_->analyzed) analyze(A);
  impl_->ldlt.factorize(A);
  impl_->pivots = impl_->ldlt.vectorD().real();
  if(impl_->ldlt.info() != Eigen::Success || !impl_->pivots.allFinite() || (impl_->pivots.array() == 0).any())
    throw Numerical_failure("LDL^T factorisation of " + what + " failed: zero or non-finite pivot");
}

template <class Scalar>
typename Basic_sparse_ldlt_solver<Scalar>::Matrix Basic_sparse_ldlt_solver<Scalar>::solve(const Matrix& B) const
{
  return impl_->ldlt.solve(B);
}

#endif

template <class Scalar>
int Basic_sparse_ldlt_solver<Scalar>::negative_pivots() const { return static_cast<int>((impl_->pivots.array() < 0).count()); }

template <class Scalar>
double Basic_sparse_ldlt_solver<Scalar>::smallest_relative_pivot() const
{
  const Eigen::ArrayXd a = impl_->pivots.array().abs();
  return a.size() ? a.minCoeff() / a.maxCoeff() : 1.;
}

template class Basic_sparse_ldlt_solver<double>;
template class Basic_sparse_ldlt_solver<std::complex<double>>;

} // namespace Model_reduction
} // namespace CGAL
