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
// accepts indefinite matrices.  The analysis (AMD) is shared by all shifts.
struct Sparse_ldlt_solver::Impl
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

Sparse_ldlt_solver::Sparse_ldlt_solver() : impl_(new Impl) {}
Sparse_ldlt_solver::~Sparse_ldlt_solver() = default;

void Sparse_ldlt_solver::analyze(const Eigen::SparseMatrix<double>& A, bool many_factorizations)
{
  if(impl_->factor) cholmod_free_factor(&impl_->factor, &impl_->common);
  cholmod_sparse view = Eigen::viewAsCholmod(A.selfadjointView<Eigen::Lower>());
  impl_->common.method[0].ordering = many_factorizations && A.rows() >= 20000 ? CHOLMOD_METIS : CHOLMOD_AMD;
  impl_->factor = cholmod_analyze(&view, &impl_->common);
  if(!impl_->factor && impl_->common.method[0].ordering == CHOLMOD_METIS) // a CHOLMOD built without METIS
  {
    impl_->common.method[0].ordering = CHOLMOD_AMD;
    impl_->factor = cholmod_analyze(&view, &impl_->common);
  }
  if(!impl_->factor || impl_->common.status < CHOLMOD_OK) throw Numerical_failure("LDL^T analysis failed (CHOLMOD)");
}

void Sparse_ldlt_solver::copy_analysis(const Sparse_ldlt_solver& other)
{
  if(impl_->factor) cholmod_free_factor(&impl_->factor, &impl_->common);
  impl_->factor = cholmod_copy_factor(other.impl_->factor, &impl_->common);
  if(!impl_->factor) throw Numerical_failure("LDL^T analysis could not be copied (CHOLMOD)");
}

void Sparse_ldlt_solver::factor(const Eigen::SparseMatrix<double>& A, const std::string& what)
{
  if(!impl_->factor) analyze(A);
  cholmod_sparse view = Eigen::viewAsCholmod(A.selfadjointView<Eigen::Lower>());
  cholmod_factorize(&view, impl_->factor, &impl_->common);
  cholmod_factor* L = impl_->factor;
  if(impl_->common.status < CHOLMOD_OK || L->minor < L->n || L->is_ll || L->is_super)
    throw Numerical_failure("LDL^T factorisation of " + what + " failed (CHOLMOD status " +
                            std::to_string(impl_->common.status) + ")");
  const int* p = static_cast<const int*>(L->p);
  const double* x = static_cast<const double*>(L->x);
  impl_->pivots.resize(static_cast<Eigen::Index>(L->n));
  for(std::size_t j = 0; j < L->n; ++j) impl_->pivots[static_cast<Eigen::Index>(j)] = x[p[j]];
  if(!impl_->pivots.allFinite() || (impl_->pivots.array() == 0).any())
    throw Numerical_failure("LDL^T factorisation of " + what + ": zero or non-finite pivot");
}

Eigen::MatrixXd Sparse_ldlt_solver::solve(const Eigen::MatrixXd& B) const
{
  cholmod_dense b = Eigen::viewAsCholmod(const_cast<Eigen::MatrixXd&>(B)); // read only
  if(!cholmod_solve2(CHOLMOD_A, impl_->factor, &b, nullptr, &impl_->x, nullptr, &impl_->y, &impl_->e, &impl_->common))
    throw Numerical_failure("LDL^T solve failed (CHOLMOD)");
  return Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(impl_->x->x), B.rows(), B.cols());
}

#else

struct Sparse_ldlt_solver::Impl
{
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt;
  bool analyzed = false;
  Eigen::VectorXd pivots;
};

Sparse_ldlt_solver::Sparse_ldlt_solver() : impl_(new Impl) {}
Sparse_ldlt_solver::~Sparse_ldlt_solver() = default;

void Sparse_ldlt_solver::analyze(const Eigen::SparseMatrix<double>& A, bool)
{
  impl_->ldlt.analyzePattern(A);
  impl_->analyzed = true;
}

void Sparse_ldlt_solver::copy_analysis(const Sparse_ldlt_solver& other)
{
  impl_->ldlt = other.impl_->ldlt;
  impl_->analyzed = other.impl_->analyzed;
}

void Sparse_ldlt_solver::factor(const Eigen::SparseMatrix<double>& A, const std::string& what)
{
  if(!impl_->analyzed) analyze(A);
  impl_->ldlt.factorize(A);
  impl_->pivots = impl_->ldlt.vectorD();
  if(impl_->ldlt.info() != Eigen::Success || !impl_->pivots.allFinite() || (impl_->pivots.array() == 0).any())
    throw Numerical_failure("LDL^T factorisation of " + what + " failed: zero or non-finite pivot");
}

Eigen::MatrixXd Sparse_ldlt_solver::solve(const Eigen::MatrixXd& B) const { return impl_->ldlt.solve(B); }

#endif

int Sparse_ldlt_solver::negative_pivots() const { return static_cast<int>((impl_->pivots.array() < 0).count()); }

double Sparse_ldlt_solver::smallest_relative_pivot() const
{
  const Eigen::ArrayXd a = impl_->pivots.array().abs();
  return a.size() ? a.minCoeff() / a.maxCoeff() : 1.;
}

} // namespace Model_reduction
} // namespace CGAL
