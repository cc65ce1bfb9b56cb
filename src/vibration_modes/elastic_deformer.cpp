// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Vibration_modes/Elastic_deformer.h>
#include <CGAL/Vibration_modes/errors.h>

#include "free_unknowns.h"

#include <Eigen/Dense>

#include <cmath>
#include <string>

namespace CGAL {
namespace Vibration_modes {

namespace {

Eigen::VectorXd target_vector(const Handle_constraints& c, const Eigen::MatrixXd& targets)
{
  if(targets.rows() != c.group_size || targets.cols() != c.number_of_handles())
    throw Invalid_input("elastic deformer: targets of size " + std::to_string(targets.rows()) + " x " +
                        std::to_string(targets.cols()) + " for " + std::to_string(c.number_of_handles()) +
                        " handles (" + std::to_string(c.group_size) + " x handles expected)");
  if(!targets.allFinite()) throw Invalid_input("elastic deformer: a target is not finite (NaN or infinity)");
  return Eigen::Map<const Eigen::VectorXd>(targets.data(), targets.size());
}

// Refuses handles that leave a zero-energy motion (a column of `kernel`, over the free
// unknowns) in place: C K must have full column rank.
void check_kernel_held(const Eigen::MatrixXd& CK, const char* who)
{
  if(CK.cols() == 0) return;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(CK);
  const Eigen::VectorXd s = svd.singularValues();
  // The motions are scaled alike (unit size, see rigid_motions), so a held motion has a
  // singular value of order one; a free one is at rounding level.
  int free = 0;
  for(Eigen::Index i = 0; i < CK.cols(); ++i) free += !(i < s.size() && s[i] > 1e-9 * std::max(1.0, s[0]));
  if(free > 0)
    throw Invalid_input(std::string(who) + ": the handles leave " + std::to_string(free) +
                        " zero-energy motion(s) free (a free body needs three handles not on one line, or pinned vertices)");
}

// A scale for rho: H's largest diagonal entry over C's largest squared row norm.
double penalty_scale(double h_scale, const Eigen::SparseMatrix<double>& C)
{
  Eigen::VectorXd rows = Eigen::VectorXd::Zero(C.rows());
  for(int k = 0; k < C.outerSize(); ++k)
    for(Eigen::SparseMatrix<double>::InnerIterator it(C, k); it; ++it) rows[it.row()] += it.value() * it.value();
  return (h_scale > 0 ? h_scale : 1.0) / rows.maxCoeff();
}

// What expand() needs of a problem (the deformers do not keep a reference to the caller's).
Mode_problem layout_of(const Mode_problem& p)
{
  Mode_problem l;
  l.free_unknowns = p.free_unknowns;
  l.full_size = p.full_size;
  l.group_size = p.group_size;
  return l;
}

} // namespace

Handle_constraints handle_constraints(const Mode_problem& p, const std::vector<std::vector<int>>& handles)
{
  p.check();
  const int g = p.group_size;
  const Eigen::Index full = internal::full_size_of(p), vertices = full / g;
  const std::vector<Eigen::Index> index = internal::free_index_of_unknowns(p);
  if(handles.empty()) throw Invalid_input("elastic deformer: no handles");
  std::vector<Eigen::Triplet<double>> entries;
  for(std::size_t j = 0; j < handles.size(); ++j)
  {
    if(handles[j].empty()) throw Invalid_input("elastic deformer: handle " + std::to_string(j) + " has no vertices");
    double total = 0;
    for(int v : handles[j])
    {
      if(v < 0 || v >= vertices)
        throw Invalid_input("elastic deformer: vertex " + std::to_string(v) + " of handle " + std::to_string(j) +
                            " is outside the mesh (" + std::to_string(vertices) + " vertices)");
      if(index[std::size_t(g) * std::size_t(v)] < 0)
        throw Invalid_input("elastic deformer: vertex " + std::to_string(v) + " of handle " + std::to_string(j) +
                            " is pinned or in no triangle: it cannot move");
      total += p.mass[index[std::size_t(g) * std::size_t(v)]];
    }
    for(int v : handles[j])
      for(int c = 0; c < g; ++c)
      {
        const Eigen::Index i = index[std::size_t(g) * std::size_t(v) + std::size_t(c)];
        entries.emplace_back(Eigen::Index(g * j + c), i, p.mass[i] / total);
      }
  }
  Handle_constraints hc;
  hc.group_size = g;
  hc.C.resize(Eigen::Index(g * handles.size()), p.H.rows());
  hc.C.setFromTriplets(entries.begin(), entries.end()); // a vertex listed twice counts twice
  return hc;
}

Reduced_elastic_deformer::Reduced_elastic_deformer(const Mode_problem& p, const Eigen::MatrixXd& modes,
                                                   const std::vector<std::vector<int>>& handles, bool with_kernel)
  : layout_(layout_of(p)), constraints_(handle_constraints(p, handles))
{
  const Eigen::MatrixXd U = internal::free_rows(p, modes, "elastic deformer: the modes");
  const Eigen::Index kernel = with_kernel ? p.kernel.cols() : 0;
  B_.resize(p.H.rows(), kernel + U.cols());
  if(kernel > 0) B_.leftCols(kernel) = p.kernel;
  B_.rightCols(U.cols()) = U;
  const Eigen::Index rows = constraints_.C.rows();
  if(B_.cols() < rows)
    throw Invalid_input("elastic deformer: " + std::to_string(constraints_.number_of_handles()) + " handles need " +
                        std::to_string(rows) + " independent directions, the basis has only " +
                        std::to_string(B_.cols()) + ": use more modes or fewer handles");
  Hr_ = B_.transpose() * (p.H * B_);
  const Eigen::MatrixXd CB = constraints_.C * B_;
  if(kernel > 0) check_kernel_held(CB.leftCols(kernel), "elastic deformer");
  const double rho = penalty_scale(Hr_.diagonal().maxCoeff(), constraints_.C);
  const Eigen::MatrixXd A = Hr_ + rho * CB.transpose() * CB;
  const Eigen::LDLT<Eigen::MatrixXd> A_factor(A);
  if(A_factor.info() != Eigen::Success || !(A_factor.vectorD().minCoeff() > 0))
    throw Invalid_input("elastic deformer: the handles leave a zero-energy motion of the basis free");
  const Eigen::MatrixXd Z = A_factor.solve(CB.transpose()); // k x rows
  const Eigen::MatrixXd S = CB * Z;
  const Eigen::FullPivLU<Eigen::MatrixXd> S_factor(S);
  // The handles' equations are independent in the basis iff S = C B A^-1 B^T C^T is
  // invertible; its condition is checked with a margin for rounding (1e-12).
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(S);
  const Eigen::VectorXd s = svd.singularValues();
  if(!(s[s.size() - 1] > 1e-12 * s[0]))
    throw Invalid_input("elastic deformer: the basis cannot move the " + std::to_string(constraints_.number_of_handles()) +
                        " handles independently (dependent handle equations in the span of the modes): use more modes");
  G_ = Z * S_factor.inverse();
  q_ = Eigen::VectorXd::Zero(B_.cols());
}

const Eigen::VectorXd& Reduced_elastic_deformer::drag(const Eigen::MatrixXd& targets)
{
  q_.noalias() = G_ * target_vector(constraints_, targets);
  return q_;
}

Eigen::VectorXd Reduced_elastic_deformer::displacement() const { return layout_.expand(B_ * q_); }

Full_elastic_deformer::Full_elastic_deformer(const Mode_problem& p, const std::vector<std::vector<int>>& handles)
  : layout_(layout_of(p)), constraints_(handle_constraints(p, handles))
{
  const Eigen::SparseMatrix<double>& C = constraints_.C;
  if(p.kernel.cols() > 0) check_kernel_held(Eigen::MatrixXd(C * p.kernel), "elastic deformer");
  double h_scale = 0;
  for(Eigen::Index i = 0; i < p.H.rows(); ++i) h_scale = std::max(h_scale, p.H.coeff(i, i));
  const double rho = penalty_scale(h_scale, C);
  const Eigen::SparseMatrix<double> A = p.H + rho * Eigen::SparseMatrix<double>(C.transpose() * C);
  Model_reduction::Sparse_spd_solver solver;
  solver.factor(A, "the full elastic deformer's H + rho C^T C");
  const Eigen::MatrixXd Z = solver.solve(Eigen::MatrixXd(C.transpose()));
  const Eigen::MatrixXd S = C * Z;
  G_ = Z * S.fullPivLu().inverse();
}

Eigen::VectorXd Full_elastic_deformer::deform(const Eigen::MatrixXd& targets) const
{
  return layout_.expand(G_ * target_vector(constraints_, targets));
}

} // namespace Vibration_modes
} // namespace CGAL
