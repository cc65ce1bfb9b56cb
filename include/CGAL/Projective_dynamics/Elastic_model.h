// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PROJECTIVE_DYNAMICS_ELASTIC_MODEL_H
#define CGAL_PROJECTIVE_DYNAMICS_ELASTIC_MODEL_H

/// \file Elastic_model.h
/// An elastic body for Projective Dynamics (SPEC 12): rest positions, lumped masses and
/// groups of elements.  Element `i` has a linear map `S_i` from the positions `q` (n x 3) to a
/// small value `S_i q` (rows x 3), a constraint set `C_i`, and a weight `w_i`; its energy is
/// `w_i / 2 dist^2(S_i q, C_i)`, zero at rest.
///
/// | element | `S_i q` | `C_i` | weight `w_i` |
/// |---|---|---|---|
/// | spring `(a, b)` | `q_b - q_a` (1 row) | lengths in `[L rmin, L rmax]` | `k / L` |
/// | triangle strain | `F^T`, `F = D_s D_m^-1` (3x2, rest in an isometric 2D frame; 2 rows) | singular values in `[rmin, rmax]` | `k` area |
/// | tetrahedron strain | `F^T`, `F = D_s D_m^-1` (3 rows) | rotations times singular values in `[rmin, rmax]` | `k` volume |
/// | bending at an interior vertex | cotangent Laplacian row over the Voronoi area (1 row) | vectors of the rest length | `k` Voronoi area |
///
/// With these weights the energies approximate continuum ones: `k` is a modulus (for springs,
/// one times a cross-section: the spring's tension is `k` times its strain `(|d| - L) / L`);
/// bending's `k` is a modulus times a squared length.  Units are the user's: with metres,
/// kilograms and seconds, `k` is in pascals (N/m for springs).

#include <CGAL/Projective_dynamics/Tet_mesh.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace CGAL {
namespace Projective_dynamics {

/// Positions or forces or velocities, one row per vertex.
typedef Eigen::Matrix<double, Eigen::Dynamic, 3> Positions;

enum class Element_type { spring, triangle_strain, tet_strain, bending };

/// One element: its rows of `S q`, its constraint set, its group.
struct Element
{
  Element_type type;
  int group;
  int first_row;  ///< its rows in the stacked `S` are `first_row, ..., first_row + rows - 1`
  int rows;
  double measure; ///< the weight per unit stiffness: `1 / L`, area, volume, Voronoi area
  double min_value, max_value; ///< `[L rmin, L rmax]` (springs), `[rmin, rmax]` (strain), rest norm twice (bending)
  Eigen::Vector3d fallback;    ///< springs: rest edge; bending: rest mean-curvature vector
};

class Elastic_model
{
public:
  /// `rest`: n x 3 rest positions; `masses`: n lumped masses (`lumped_masses` in make_models.h).
  /// \throws Invalid_mesh (`empty`) for no vertex, (`non_finite_coordinate`) naming the vertex;
  ///         Invalid_input for a wrong number of masses or a negative or non-finite mass, naming
  ///         the vertex (a zero mass is allowed here: the simulator refuses it unless the vertex
  ///         is pinned).
  Elastic_model(const Positions& rest, const Eigen::VectorXd& masses);

  /// Adds springs along `edges` with rest lengths from the rest positions; returns the group.
  /// \throws Invalid_mesh for an index out of range or repeated, or a zero-length edge (named);
  ///         Invalid_input for a negative stiffness or limits outside `0 <= rmin <= rmax`.
  int add_springs(const std::vector<Edge>& edges, double stiffness, double rmin = 1, double rmax = 1);
  /// Adds triangle strain elements (shells, cloth).  \throws as `add_springs`, and for a
  /// (nearly) zero-area triangle: `area <= 1e-12 * (longest edge)^2` (rounding of the cross product).
  int add_triangle_strain(const std::vector<Triangle>& triangles, double stiffness, double rmin = 1, double rmax = 1);
  /// Adds tetrahedron strain elements (solids).  \throws as `add_springs`, and for a (nearly)
  /// zero-volume tetrahedron named by index: `|volume| <= 1e-12 * (longest edge)^3`;
  /// `rmin` must be positive (an inverted element is pushed back to positive volume).
  int add_tet_strain(const std::vector<Tetrahedron>& tets, double stiffness, double rmin = 1, double rmax = 1);
  /// Adds bending at the interior vertices of `triangles` (those whose edges all have two
  /// triangles; boundary vertices do not bend).  \throws as `add_triangle_strain`.
  int add_bending(const std::vector<Triangle>& triangles, double stiffness);

  /// Changes a group's stiffness (a simulator using this model refactors its matrix).
  /// \throws Invalid_input for an unknown group or a negative or non-finite stiffness.
  void set_stiffness(int group, double stiffness);
  double stiffness(int group) const;
  int number_of_groups() const { return int(group_stiffness_.size()); }
  Element_type group_type(int group) const;

  int number_of_vertices() const { return int(rest_.rows()); }
  int number_of_elements() const { return int(elements_.size()); }
  int number_of_rows() const { return rows_; }
  const Positions& rest_positions() const { return rest_; }
  const Eigen::VectorXd& masses() const { return masses_; }
  const std::vector<Element>& elements() const { return elements_; }

  /// The stacked `S` (rows x n).
  const Eigen::SparseMatrix<double, Eigen::RowMajor>& selection_matrix() const { return S_; }
  /// `w_i = stiffness * measure` of the element of each row.
  Eigen::VectorXd row_weights() const;

  /// Projects the value `value` (`rows` x 3, row-major) of element `e` on its constraint set,
  /// writing `rows` x 3 row-major entries to `out` (the local step).
  void project(int e, const double* value, double* out) const;

  /// `sum_i w_i / 2 |S_i q - P_i(S_i q)|^2`: the elastic energy at `q`.
  double elastic_energy(const Positions& q) const;

private:
  int new_group(Element_type type, double stiffness);
  void check_indices(const int* v, int count, const char* kind, std::size_t index) const;

  Positions rest_;
  Eigen::VectorXd masses_;
  std::vector<double> group_stiffness_;
  std::vector<Element_type> group_type_;
  std::vector<Element> elements_;
  int rows_ = 0;
  // The triplets of S (row, vertex, coefficient), made a matrix after each group is added (so
  // that every const member is safe to call from several threads).
  void build_selection_matrix();
  std::vector<Eigen::Triplet<double>> triplets_;
  Eigen::SparseMatrix<double, Eigen::RowMajor> S_;
};

} // namespace Projective_dynamics
} // namespace CGAL

#endif
