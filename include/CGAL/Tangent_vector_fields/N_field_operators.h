// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_N_FIELD_OPERATORS_H
#define CGAL_TANGENT_VECTOR_FIELDS_N_FIELD_OPERATORS_H

/// \file N_field_operators.h
/// n-direction fields (SPEC 10) in the power representation: the discrete connection,
/// the first-order energy `S_n`, the Laplacian `L_n = MX^-1 S_n`, the higher-order
/// energies, the parallel fields (kernel) and the conversion from and to vectors.

#include <CGAL/Tangent_vector_fields/Operator_matrices.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <complex>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

/// What `S_n` does at boundary edges.
enum class N_field_boundary {
  free, ///< natural: boundary edges carry no energy (the default; the field is free along the boundary)
  zero  ///< Dirichlet: each boundary edge adds `w_e |z_f|^2`, as if the field were 0 beyond it
};

struct N_field_options
{
  N_field_boundary boundary = N_field_boundary::free;
  /// A component whose connection, raised to the power n, transports a field around
  /// every loop back onto itself to within this angle (radians) has parallel n-fields:
  /// they span the kernel of `S_n`.  Rounding leaves ~1e-13 on 1M faces; a real
  /// holonomy is at least the smallest `n K_v` mod `2 pi` of a vertex.
  double holonomy_tolerance = 1e-8;
  /// Prescribed singularities `(vertex, k)`: index `k / n` at an interior vertex.  They
  /// change the connection (below), so that the smooth fields of `S_n` have them.
  std::vector<std::pair<int, int>> singularities;
};

/// \brief Operators on n-direction fields of a triangle mesh.
///
/// An n-field is stored per face as one complex number `z_f = r e^{i n theta}` in the
/// face's frame (the frame of `Intrinsic_mesh`): n vectors of length `r` at angles
/// `theta + 2 pi j / n`.  A field of all faces is a real `2nf` vector, face `f` at rows
/// `2f` (real part) and `2f+1` (imaginary part), the layout of vector fields; for
/// `n = 1`, `z` is the vector itself.  Multiplying `z` by `i` (`Operator_matrices::J`)
/// turns each of the n vectors by `pi / (2n)`.
///
/// Interior edge `e` with faces `f = edge_faces(e)[0]`, `g = edge_faces(e)[1]`: if
/// `a_f`, `a_g` are the angles of the edge in the two frames, a vector at angle `t` in
/// `g` is at angle `t + a_f - a_g` in `f` (`rho_fg = e^{i (a_f - a_g)}`), and an n-field
/// `z_g` is `rho_fg^n z_g` there.
///
/// Prescribed singularities (a modified connection, in the manner of trivial connections):
/// each interior edge's transport turns by an extra `delta_e` so that the connection's
/// holonomy around a prescribed vertex becomes `2 pi k / n` -- a field that is smooth for
/// this connection turns by `2 pi k` (its power) around the vertex, index k/n -- while every
/// other vertex keeps its angle defect, less an equal share per unit area of what the
/// prescribed indices take from the total `2 pi chi` on a closed component (on a component
/// with boundary the boundary takes it).  `delta` is the smallest change in the norm
/// `sum_e w_e delta_e^2`: one Poisson solve on the vertices.  The energy is then
/// measured against the modified connection; the index (`n_field_indices`) always against
/// the surface's own.  The first-order energy is
/// `E_D(z) = sum_e w_e |z_f - rho_fg^n z_g|^2`, `w_e = 3 |e|^2 / (A_f + A_g)`, the
/// matrix `S_n` (free boundary by default, see `N_field_boundary`).  Matrices are built
/// on first request and cached, once, also when several threads ask at the same time.
class N_field_operators
{
public:
  typedef Eigen::SparseMatrix<double> Sparse_matrix;
  typedef Eigen::VectorXd Vector;
  typedef Eigen::MatrixXd Matrix;

  /// The largest n accepted (indices `k` are `int`s summing to `n chi`).
  static constexpr int max_n = 1 << 20;

  /// \throws Invalid_input if `n < 1` or `n > max_n`, or a prescribed singularity is not at an
  ///         interior vertex, or a vertex is prescribed twice, or every vertex of a closed
  ///         component is prescribed and their indices do not sum to `n chi`.
  N_field_operators(std::shared_ptr<const Operator_matrices> operators, int n,
                    const N_field_options& options = N_field_options());
  ~N_field_operators();
  N_field_operators(const N_field_operators&) = delete;
  N_field_operators& operator=(const N_field_operators&) = delete;

  int n() const { return n_; }
  const N_field_options& options() const { return options_; }
  const Operator_matrices& operators() const { return *operators_; }
  std::shared_ptr<const Operator_matrices> shared_operators() const { return operators_; }
  const Intrinsic_mesh& mesh() const { return operators_->mesh(); }

  /// `a_f - a_g` per interior edge (in the order of `Intrinsic_mesh::interior_edges`):
  /// the angle by which a vector turns when carried from `g` into `f` (not times n).
  const Vector& transport_angles() const;
  /// The transport angles of the connection `S_n` uses: `transport_angles()` plus the
  /// `delta_e` of the prescribed singularities (equal to it without them).
  const Vector& connection_angles() const;
  /// `w_e` per interior edge.
  const Vector& edge_weights() const;
  /// Per vertex: 1 if it lies on a boundary edge.
  const std::vector<char>& boundary_vertices() const;
  /// Per vertex: the angle defect `2 pi - sum of corner angles` at interior vertices, the
  /// turning of the boundary `pi - sum of corner angles` at boundary vertices, 0 at
  /// vertices in no face.  Their sum is `2 pi chi` (Gauss-Bonnet).
  const Vector& vertex_curvatures() const;

  /// Faces around a vertex, counter-clockwise; `edges[i]` joins `faces[i]` and `faces[i+1]`
  /// (and, around an interior vertex, the last joins `faces.back()` and `faces[0]`).  Around a
  /// boundary vertex the fan runs from the face on the outgoing boundary edge to the face on
  /// the incoming one.  Empty for a vertex in no face.
  struct Vertex_fan
  {
    std::vector<int> faces;
    std::vector<int> edges;
    bool on_boundary = false;
  };
  Vertex_fan vertex_fan(int v) const;
  /// The angle by which a vector turns when carried from face `from` across interior edge `e`
  /// into the other face (`transport_angles()` of `e`, with the sign of the direction).
  double transport_angle(int e, int from) const;

  /// Face areas (`nf`).
  const Vector& face_areas() const { return operators_->face_areas(); }
  /// `S_n`, `2nf x 2nf`, symmetric positive semi-definite.
  const Sparse_matrix& S() const;
  /// `S_n` in complex form, `nf x nf` Hermitian: entry `(f, g) = -w_e rho_fg^n` (the real
  /// form's 2x2 blocks `[a -b; b a]` as `a + i b`).  Half the cost of the real form to factor.
  const Eigen::SparseMatrix<std::complex<double>>& complex_S() const;
  /// The mass `MX` (each face area twice), `2nf`.
  const Vector& masses() const { return operators_->field_masses(); }
  /// `L_n z = MX^-1 S_n z`.
  Vector laplacian(const Vector& z) const;
  /// `E_D(z) = z^T S_n z`.
  double dirichlet_energy(const Vector& z) const;
  /// Per face, the first-order energy density: half of the `E_D` term of each of its edges
  /// (and its boundary terms under the zero condition), divided by its area.
  /// `sum_f A_f density_f = E_D(z)`; for a unit field, how fast it turns there.
  Vector energy_density(const Vector& z) const;
  /// m-harmonic energy `z^T S_n (MX^-1 S_n)^(m-1) z` (m = 1: `E_D`, m = 2: `E_B = |L_n z|^2_MX`).
  double m_harmonic_energy(const Vector& z, int m) const;

  /// Parallel n-fields (zero energy): an `MX`-orthonormal basis of the kernel of `S_n`,
  /// columns in pairs `(p, J p)`, one pair per component whose holonomy is trivial for
  /// this n (a developable patch, n = 4 on a cube); empty with the zero boundary.
  const Matrix& kernel() const;

  /// The n-field of vectors (frame coordinates, `2nf`): `z_f = |u_f| (u_f / |u_f|)^n`.
  /// \throws Invalid_input for another size or non-finite entries.
  Vector from_vectors(const Vector& vectors) const;
  /// The first of the n vectors of each face (angle `arg(z_f) / n` in `(-pi/n, pi/n]`, length `|z_f|`).
  Vector to_vectors(const Vector& z) const;
  /// Vector `j` (`0 <= j < n`) of each face: the first turned counter-clockwise by `2 pi j / n`.
  Vector to_vectors(const Vector& z, int j) const;
  /// Each face's field scaled to length 1 (faces with `z_f = 0` stay 0).
  Vector normalized(const Vector& z) const;

private:
  void add_boundary_diagonal(Vector& diagonal) const; // w_e of the zero boundary condition
  struct Cache;
  std::shared_ptr<const Operator_matrices> operators_;
  int n_;
  N_field_options options_;
  std::unique_ptr<Cache> cache_;
};

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
