// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_OPERATOR_MATRICES_H
#define CGAL_TANGENT_VECTOR_FIELDS_OPERATOR_MATRICES_H

/// \file Operator_matrices.h
/// The sparse matrices of the thesis' Chapter 1 (SPEC sections 2 and 3), each
/// assembled on first request from the intrinsic edge lengths and then cached.

#include <CGAL/Tangent_vector_fields/Intrinsic_mesh.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>

namespace CGAL {
namespace Tangent_vector_fields {

/// Sparse matrix representation of the discrete operators on piecewise-constant
/// tangent fields.
///
/// Unknowns: a field is a `2 nf` vector of frame coordinates (face `f` at rows
/// `2f, 2f+1`, see `Intrinsic_mesh`), an `S_h` function one value per vertex, an
/// `S*_h` (Crouzeix-Raviart) function one value per edge.  Following SPEC 3, the
/// matrices of the Hodge-Laplacian use `S*_h` functions that vanish on boundary
/// edges: `G_star_interior()`, `W_star()`, `S()`, `L()`, `B()` work on interior
/// edges only (numbered by `Intrinsic_mesh::interior_edge_index`).  Vertices in no
/// face have zero mass and zero rows.
///
/// Each accessor builds its matrix on first call and caches it.  The accessors may be
/// called from several threads at once: a matrix is built once, the others wait for it.
class Operator_matrices
{
public:
  typedef Eigen::SparseMatrix<double> Sparse_matrix;
  typedef Eigen::VectorXd Vector;

  explicit Operator_matrices(std::shared_ptr<const Intrinsic_mesh> mesh);
  ~Operator_matrices();
  Operator_matrices(const Operator_matrices&) = delete;
  Operator_matrices& operator=(const Operator_matrices&) = delete;

  const Intrinsic_mesh& mesh() const { return *mesh_; }
  std::shared_ptr<const Intrinsic_mesh> shared_mesh() const { return mesh_; }

  /// Face areas (`nf`).
  const Vector& face_areas() const;
  /// Diagonal of `M`: a third of the area of the faces at each vertex (`nv`).
  const Vector& vertex_masses() const;
  /// Diagonal of `M*`: a third of the area of the faces at each edge (`ne`, all edges).
  const Vector& edge_masses() const;
  /// Diagonal of `MX`: each face area twice (`2nf`).
  const Vector& field_masses() const;

  /// `G`, `2nf x nv`: gradient of `S_h` functions.
  const Sparse_matrix& G() const;
  /// `G*`, `2nf x ne`: gradient of `S*_h` functions, all edges.
  const Sparse_matrix& G_star() const;
  /// `G*` restricted to the columns of interior edges, `2nf x ne_int`.
  const Sparse_matrix& G_star_interior() const;
  /// `M` (`nv x nv`), `M*` (all edges), `MX` (`2nf x 2nf`) as sparse diagonal matrices.
  const Sparse_matrix& M() const;
  const Sparse_matrix& M_star() const;
  const Sparse_matrix& MX() const;
  /// `J`: rotation by +pi/2 in every face, `(a, b) -> (-b, a)`.
  const Sparse_matrix& J() const;
  /// `W = G^T MX G`, the cotan matrix (`nv x nv`), assembled directly.
  const Sparse_matrix& W() const;
  /// `W* = G*^T MX G*` on interior edges (`ne_int x ne_int`), assembled directly.
  const Sparse_matrix& W_star() const;
  /// Dirichlet energy `S = MX (G M^-1 G^T - J G* M*^-1 G*^T J) MX` (interior edges).
  const Sparse_matrix& S() const;
  /// Hodge-Laplacian `L = MX^-1 S` (self-adjoint in `MX`).
  const Sparse_matrix& L() const;
  /// Biharmonic energy `B = S MX^-1 S`.
  const Sparse_matrix& B() const;

  /// `J v` without forming `J` (needs no mesh: each face's `(a, b)` becomes `(-b, a)`).
  static Vector rotate(const Vector& field);
  /// Conforming divergence and curl (vertex values): `-M^-1 G^T MX v`, `M^-1 G^T J MX v`.
  Vector divergence(const Vector& field) const;
  Vector curl(const Vector& field) const;
  /// Nonconforming divergence and curl (edge values, all edges):
  /// `-M*^-1 G*^T MX v`, `M*^-1 G*^T J MX v`.
  Vector nonconforming_divergence(const Vector& field) const;
  Vector nonconforming_curl(const Vector& field) const;

  /// Expands interior-edge values to all edges (zero on boundary edges).
  Vector interior_to_all_edges(const Vector& interior_values) const;
  /// Restricts edge values to interior edges.
  Vector all_to_interior_edges(const Vector& edge_values) const;

private:
  struct Cache;
  std::shared_ptr<const Intrinsic_mesh> mesh_;
  std::unique_ptr<Cache> cache_;
};

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
