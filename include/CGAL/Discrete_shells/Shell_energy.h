// Copyright (c) 2026 The Discrete_shells authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISCRETE_SHELLS_SHELL_ENERGY_H
#define CGAL_DISCRETE_SHELLS_SHELL_ENERGY_H

/// \file Shell_energy.h
/// The discrete shell energy `W[x, y]` of a triangle mesh with rest positions `x` and
/// deformed positions `y` (SPEC 13.1): membrane (edge stretching and triangle area) plus
/// bending (dihedral angles of interior edges),
/// \f[
///   W = k_s \sum_e a_e \Big(\frac{l_e(y)}{l_e(x)} - 1\Big)^2
///     + k_a \sum_t A_t(x) \Big(\frac{A_t(y)}{A_t(x)} - 1\Big)^2
///     + k_b \sum_{e\ \mathrm{interior}} \frac{l_e(x)^2}{a_e} \big(\theta_e(y) - \theta_e(x)\big)^2,
/// \f]
/// `a_e` a third of the area of the faces at edge `e`.  Every term is `w (f(y) - f(x))^2`, so
/// at rest the Hessian `2 sum w grad f grad f^T` needs first derivatives only and is
/// positive semi-definite; its kernel holds the rigid motions.
///
/// Units: the membrane terms scale with area (as `s^2` when both shapes are scaled by `s`),
/// the bending term does not scale, so `k_b / k_s` is a squared length: for a material of
/// thickness `h`, about `h^2 / 12`.
///
/// Positions and displacements are stacked per vertex: `(x0, y0, z0, x1, y1, z1, ...)`.
/// This class sees arrays only; `make_shell_energy` builds it from a CGAL mesh.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <array>
#include <vector>

namespace CGAL {
namespace Discrete_shells {

/// The stiffnesses `k_s`, `k_a` and `k_b` (each at least 0, not all 0).
struct Shell_stiffness
{
  double stretching = 1;
  double area = 1;
  double bending = 1;
};

class Shell_energy
{
public:
  typedef std::array<int, 3> Triangle;

  /// The rest shape: `rest` stacks `n` vertex positions, `triangles` index them.
  /// Edges with more than two faces bend at every pair of them; edges with one face do not
  /// bend (boundaries are free).  Vertices in no triangle carry no energy and no mass.
  /// \throws Invalid_mesh naming the face if a triangle has a repeated or out-of-range
  ///         index, a non-finite coordinate, or (nearly) zero area; Invalid_input for a
  ///         negative or non-finite stiffness, or all three zero.
  Shell_energy(const Eigen::VectorXd& rest, const std::vector<Triangle>& triangles,
               const Shell_stiffness& stiffness = {});

  Eigen::Index number_of_vertices() const { return rest_.size() / 3; }
  const Eigen::VectorXd& rest_positions() const { return rest_; }
  const std::vector<Triangle>& triangles() const { return triangles_; }
  const Shell_stiffness& stiffness() const { return stiffness_; }
  /// Interior edges (hinges): the edge `(a, b)` and the opposite vertices `c`, `d` of two of
  /// its faces.
  const std::vector<std::array<int, 4>>& hinges() const { return hinges_; }

  /// `W[x, y]` at deformed positions `y` (3n values).
  double energy(const Eigen::VectorXd& y) const;
  /// `d W / d y`.
  Eigen::VectorXd gradient(const Eigen::VectorXd& y) const;
  /// `d^2 W / d y^2` (symmetric, both triangles stored).  Indefinite away from rest.
  Eigen::SparseMatrix<double> hessian(const Eigen::VectorXd& y) const;
  /// The Hessian at `y = x`: `2 sum w grad f grad f^T`, positive semi-definite.
  Eigen::SparseMatrix<double> rest_hessian() const;
  /// Lumped mass per unknown: a third of the incident faces' area, for each of the three
  /// coordinates of the vertex (density 1).
  Eigen::VectorXd lumped_mass() const;

private:
  struct Edge
  {
    int a, b;
    double rest_length, area_share;
  };
  struct Hinge_rest
  {
    double angle, weight;
  };

  template <bool with_hessian, class Add_term>
  void for_each_term(const Eigen::VectorXd& y, const Add_term& add) const;
  void check_size(const Eigen::VectorXd& y) const;

  Eigen::VectorXd rest_;
  std::vector<Triangle> triangles_;
  Shell_stiffness stiffness_;
  std::vector<Edge> edges_;
  std::vector<double> face_areas_;
  std::vector<std::array<int, 4>> hinges_;
  std::vector<Hinge_rest> hinge_rest_;
  Eigen::SparseMatrix<double> pattern_; // every coupled pair of unknowns, values 0
};

} // namespace Discrete_shells
} // namespace CGAL

#endif
