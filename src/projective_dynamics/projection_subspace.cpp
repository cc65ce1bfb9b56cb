// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Mass-weighted PCA and the constraint-projection subspace of one element group (SPEC 12).

#include <CGAL/Projective_dynamics/Position_subspace.h>
#include <CGAL/Projective_dynamics/Projection_subspace.h>
#include <CGAL/Projective_dynamics/errors.h>
#include <CGAL/Projective_dynamics/internal/projection_subspace_factors.h>

#include "element_graph.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include <cmath>
#include <string>

namespace CGAL {
namespace Projective_dynamics {

namespace {
// The coefficients E diag(lambda)^{-1/2} of the l leading eigenvectors of the Gram matrix G of
// the candidates (c x c, symmetric positive semi-definite).
Eigen::MatrixXd leading_coefficients(const Eigen::MatrixXd& G, int l)
{
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(G);
  // Eigen sorts the eigenvalues increasingly: the leading ones are the LAST columns (the
  // reference's code takes the first ones, the least important).
  const Eigen::Index c = G.cols();
  const double largest = eig.eigenvalues()[c - 1];
  const double lth = eig.eigenvalues()[c - l];
  if(!(largest > 0) || !(lth > 1e-12 * largest))
    throw Invalid_input("l = " + std::to_string(l) + " exceeds the numerical rank of the candidate columns (eigenvalue " + std::to_string(l) +
                        " is " + std::to_string(lth) + ", the largest " + std::to_string(largest) + ")");
  Eigen::MatrixXd E(c, l);
  for(int k = 0; k < l; ++k) E.col(k) = eig.eigenvectors().col(c - 1 - k) / std::sqrt(eig.eigenvalues()[c - 1 - k]);
  return E;
}
} // namespace

Eigen::MatrixXd mass_weighted_pca(const Eigen::MatrixXd& C, const Eigen::VectorXd& weights, int l)
{
  if(weights.size() != C.rows())
    throw Invalid_input("mass_weighted_pca: " + std::to_string(weights.size()) + " weights for " + std::to_string(C.rows()) + " rows");
  if((weights.array() < 0).any() || !weights.allFinite()) throw Invalid_input("mass_weighted_pca: the weights must be finite and >= 0");
  if(l < 0 || l > C.cols())
    throw Invalid_input("mass_weighted_pca: l = " + std::to_string(l) + " columns asked of " + std::to_string(C.cols()) + " candidates");
  if(l == 0) return Eigen::MatrixXd(C.rows(), 0);
  const Eigen::MatrixXd E = leading_coefficients(C.transpose() * weights.asDiagonal() * C, l);
  return C * E;
}

namespace internal {

internal::Projection_subspace_factors projection_subspace_factors(const Elastic_model& model, int group, int constraint_samples,
                                                                  double radius_multiplier, int l)
{
  if(group < 0 || group >= model.number_of_groups()) throw Invalid_input("unknown element group " + std::to_string(group));
  if(!(radius_multiplier > 1) || !std::isfinite(radius_multiplier))
    throw Invalid_input("the constraint radius multiplier must be finite and above 1, not " + std::to_string(radius_multiplier));
  const std::vector<Element>& elements = model.elements();
  int first_row = -1, rows = 0;
  std::vector<int> members;
  for(int e = 0; e < model.number_of_elements(); ++e)
    if(elements[std::size_t(e)].group == group)
    {
      if(first_row < 0) first_row = elements[std::size_t(e)].first_row;
      rows += elements[std::size_t(e)].rows;
      members.push_back(e);
    }
  if(members.empty()) throw Invalid_input("element group " + std::to_string(group) + " is empty");

  const internal::Element_graph graph = internal::element_graph(model);
  std::vector<double> distance;
  const std::vector<int> samples = internal::farthest_point_samples(graph, constraint_samples, &distance);
  double covering = 0;
  for(double d : distance) covering = std::max(covering, d);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> W = sample_weights(model, samples, radius_multiplier * covering);
  const int m = int(samples.size());

  // Rest projections and element weights (mean of the vertex weights, renormalised).
  const Positions& x = model.rest_positions();
  const auto& S = model.selection_matrix();
  Eigen::MatrixXd P(rows, 3);
  Eigen::VectorXd measure(rows);
  // The scaled candidates B = D^{1/2} C (C is sparse: an element sees a few samples), in two
  // passes over the elements: the entries per row are counted, then written straight into B's
  // compressed arrays.  At 1.7 million tets B holds ~100 million entries; triplets and their
  // sorted copies, or vectors grown while filling, took several GB more than B itself.
  Projection_subspace_factors f;
  f.B.resize(rows, 4 * m);
  Eigen::VectorXd omega(m);
  double out[9];
  auto candidates_of = [&](int e) { // fills out (the rest projection) and omega (the weights)
    const Element& el = elements[std::size_t(e)];
    double value[9];
    for(int r = 0; r < el.rows; ++r)
    {
      const Eigen::RowVector3d v = S.row(el.first_row + r) * x;
      for(int c = 0; c < 3; ++c) value[3 * r + c] = v[c];
    }
    model.project(e, value, out);
    omega.setZero();
    for(int v : internal::element_vertices(model, e))
      for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(W, v); it; ++it) omega[it.col()] += it.value();
    omega /= omega.sum();
  };
  int* start = f.B.outerIndexPtr();
  start[0] = 0;
  for(int e : members)
  {
    const Element& el = elements[std::size_t(e)];
    const int r0 = el.first_row - first_row;
    candidates_of(e);
    for(int r = 0; r < el.rows; ++r)
    {
      measure[r0 + r] = el.measure;
      for(int c = 0; c < 3; ++c) P(r0 + r, c) = out[3 * r + c];
      int count = 0;
      for(int j = 0; j < m; ++j)
        if(omega[j] != 0)
          for(int c = 0; c < 4; ++c) count += c == 3 || out[3 * r + c] != 0;
      start[r0 + r + 1] = count; // per row for now
    }
  }
  for(int r = 0; r < rows; ++r) start[r + 1] += start[r];
  f.B.resizeNonZeros(start[rows]);
  int* column = f.B.innerIndexPtr();
  double* entry = f.B.valuePtr();
  for(int e : members)
  {
    const Element& el = elements[std::size_t(e)];
    const int r0 = el.first_row - first_row;
    candidates_of(e);
    const double root = std::sqrt(el.measure);
    for(int r = 0; r < el.rows; ++r)
    {
      int k = start[r0 + r];
      for(int j = 0; j < m; ++j) // columns in increasing order, as compressed rows need
        if(omega[j] != 0)
          for(int c = 0; c < 4; ++c)
            if(c == 3 || out[3 * r + c] != 0) column[k] = 4 * j + c, entry[k++] = root * omega[j] * (c == 3 ? 1.0 : out[3 * r + c]);
    }
  }

  // The rest projections' span, orthonormal for the measure-weighted inner product (rank
  // revealed by column-pivoted QR: directions below 1e-10 of the largest are rounding).
  const Eigen::VectorXd root = measure.cwiseSqrt();
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(root.asDiagonal() * P);
  qr.setThreshold(1e-10);
  const int z = int(qr.rank());
  if(l < z) throw Invalid_input("l = " + std::to_string(l) + " is below the rank " + std::to_string(z) + " of the rest projections");
  // The thin Q (rows x z) without forming the rows x rows one.
  const Eigen::MatrixXd Q = qr.householderQ() * Eigen::MatrixXd::Identity(rows, z); // orthonormal in the scaled space
  // The scaled candidates B = D^{1/2} C without the span of Q: B' = B - Q Q^T B, never formed
  // densely (rows x 4m): its Gram matrix is B^T B - (Q^T B)^T (Q^T B), and its leading columns
  // are B E - Q (Q^T B E).
  // Q^T B and B^T B accumulated row by row (4m x 4m is small; a sparse product of B^T and B took
  // 2.3 s of a 6 s precomputation on a 68,666-tet armadillo, and B^T is a copy of B).
  Eigen::MatrixXd QtB = Eigen::MatrixXd::Zero(z, 4 * m), G = Eigen::MatrixXd::Zero(4 * m, 4 * m);
  for(Eigen::Index r = 0; r < f.B.rows(); ++r)
    for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator a(f.B, r); a; ++a)
    {
      QtB.col(a.col()) += a.value() * Q.row(r).transpose();
      for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator b(f.B, r); b; ++b) G(a.col(), b.col()) += a.value() * b.value();
    }
  G -= QtB.transpose() * QtB;
  if(l - z > 4 * m)
    throw Invalid_input("l = " + std::to_string(l) + " exceeds the " + std::to_string(4 * m) + " candidate columns");
  f.inverse_root = root.cwiseInverse();
  f.Q = Q;
  f.A = Eigen::MatrixXd::Zero(z, l);
  f.A.leftCols(z).setIdentity();
  f.E = Eigen::MatrixXd::Zero(4 * m, l);
  if(l > z)
  {
    f.E.rightCols(l - z) = leading_coefficients(G, l - z);
    f.A.rightCols(l - z) = -QtB * f.E.rightCols(l - z);
  }
  return f;
}

Eigen::MatrixXd Projection_subspace_factors::rows_of_V(const std::vector<int>& rows) const
{
  Eigen::MatrixXd out(Eigen::Index(rows.size()), A.cols());
  for(std::size_t q = 0; q < rows.size(); ++q)
  {
    const int r = rows[q];
    Eigen::RowVectorXd v = Q.row(r) * A;
    for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(B, r); it; ++it) v += it.value() * E.row(it.col());
    out.row(Eigen::Index(q)) = inverse_root[r] * v;
  }
  return out;
}

Eigen::MatrixXd Projection_subspace_factors::V() const
{
  return inverse_root.asDiagonal() * (Q * A + B * E);
}

Eigen::MatrixXd Projection_subspace_factors::projected(const Eigen::SparseMatrix<double, Eigen::RowMajor>& Sg,
                                                       const Eigen::SparseMatrix<double, Eigen::RowMajor>& Ut) const
{
  // U^T S^T D V = U^T S^T D^{1/2} (Q A + B E) = P_Q A + P_B E with [P_Q P_B] = U^T Y and
  // Y = S^T D^{1/2} [Q B] (vertices x (z + 4m), dense: a few tens of MB), made row by row of S.
  const Eigen::Index z = Q.cols(), c = B.cols();
  Eigen::MatrixXd Y = Eigen::MatrixXd::Zero(Sg.cols(), z + c);
  for(Eigen::Index r = 0; r < Sg.rows(); ++r)
  {
    const double root = 1 / inverse_root[r];
    for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator s(Sg, r); s; ++s)
    {
      const double w = s.value() * root;
      Y.row(s.col()).head(z) += w * Q.row(r);
      for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator b(B, r); b; ++b) Y(s.col(), z + b.col()) += w * b.value();
    }
  }
  const Eigen::MatrixXd P = Ut * Y;
  return P.leftCols(z) * A + P.rightCols(c) * E;
}

} // namespace internal

Eigen::MatrixXd projection_subspace(const Elastic_model& model, int group, int constraint_samples, double radius_multiplier,
                                    int l)
{
  return internal::projection_subspace_factors(model, group, constraint_samples, radius_multiplier, l).V();
}

} // namespace Projective_dynamics
} // namespace CGAL
