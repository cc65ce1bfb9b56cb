// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The elements of an elastic body: their rows of S, weights and projections.

#include <CGAL/Projective_dynamics/Elastic_model.h>
#include <CGAL/Projective_dynamics/errors.h>
#include <CGAL/Projective_dynamics/projections.h>

#include "element_indices.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace CGAL {
namespace Projective_dynamics {

namespace {
void check_stiffness(double k)
{
  if(!(k >= 0) || !std::isfinite(k))
    throw Invalid_input("negative or non-finite stiffness " + std::to_string(k) + ": a stiffness must be >= 0");
}
void check_limits(double rmin, double rmax, bool positive)
{
  if(!(rmin >= 0) || !(rmin <= rmax) || !std::isfinite(rmax) || (positive && !(rmin > 0)))
    throw Invalid_input("strain limits [" + std::to_string(rmin) + ", " + std::to_string(rmax) + "] must satisfy " +
                        (positive ? "0 < rmin <= rmax" : "0 <= rmin <= rmax"));
}
} // namespace

Elastic_model::Elastic_model(const Positions& rest, const Eigen::VectorXd& masses) : rest_(rest), masses_(masses)
{
  if(rest.rows() == 0) throw Invalid_mesh(Mesh_defect::empty, "the elastic model has no vertex");
  for(Eigen::Index v = 0; v < rest.rows(); ++v)
    if(!rest.row(v).allFinite())
      throw Invalid_mesh(Mesh_defect::non_finite_coordinate, "vertex " + std::to_string(v) + " has a non-finite coordinate");
  if(masses.size() != rest.rows())
    throw Invalid_input(std::to_string(masses.size()) + " masses for " + std::to_string(rest.rows()) + " vertices");
  for(Eigen::Index v = 0; v < masses.size(); ++v)
    if(!(masses[v] >= 0) || !std::isfinite(masses[v]))
      throw Invalid_input("vertex " + std::to_string(v) + " has a negative or non-finite mass " + std::to_string(masses[v]));
  S_.resize(0, rest.rows()); // no element yet: free particles
}

int Elastic_model::new_group(Element_type type, double stiffness)
{
  check_stiffness(stiffness);
  group_stiffness_.push_back(stiffness);
  group_type_.push_back(type);
  return int(group_stiffness_.size()) - 1;
}

void Elastic_model::check_indices(const int* v, int count, const char* kind, std::size_t index) const
{
  internal::check_element_indices(v, count, number_of_vertices(), kind, index);
}

int Elastic_model::add_springs(const std::vector<Edge>& edges, double stiffness, double rmin, double rmax)
{
  check_limits(rmin, rmax, false);
  for(std::size_t e = 0; e < edges.size(); ++e)
  {
    check_indices(edges[e].data(), 2, "edge", e);
    if(!((rest_.row(edges[e][1]) - rest_.row(edges[e][0])).norm() > 0))
      throw Invalid_mesh(Mesh_defect::degenerate_face, "edge " + std::to_string(e) + " has zero rest length");
  }
  const int group = new_group(Element_type::spring, stiffness);
  for(const Edge& edge : edges)
  {
    const Eigen::Vector3d d = (rest_.row(edge[1]) - rest_.row(edge[0])).transpose();
    const double L = d.norm();
    elements_.push_back({Element_type::spring, group, rows_, 1, 1 / L, L * rmin, L * rmax, d});
    triplets_.emplace_back(rows_, edge[0], -1.0);
    triplets_.emplace_back(rows_, edge[1], 1.0);
    ++rows_;
  }
  build_selection_matrix();
  return group;
}

namespace {
// 1e-12: far above the rounding of a cross product (~1e-16 longest^2), far below any triangle
// made on purpose.
bool degenerate_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  return !((b - a).cross(c - a).norm() / 2 > 1e-12 * longest);
}
} // namespace

int Elastic_model::add_triangle_strain(const std::vector<Triangle>& triangles, double stiffness, double rmin, double rmax)
{
  check_limits(rmin, rmax, false);
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Triangle& f = triangles[t];
    check_indices(f.data(), 3, "triangle", t);
    if(degenerate_triangle(rest_.row(f[0]), rest_.row(f[1]), rest_.row(f[2])))
      throw Invalid_mesh(Mesh_defect::degenerate_face, "triangle " + std::to_string(t) + " has (nearly) zero area");
  }
  const int group = new_group(Element_type::triangle_strain, stiffness);
  for(const Triangle& f : triangles)
  {
    const Eigen::Vector3d e1 = rest_.row(f[1]) - rest_.row(f[0]), e2 = rest_.row(f[2]) - rest_.row(f[0]);
    const Eigen::Vector3d n = e1.cross(e2);
    const Eigen::Vector3d u = e1.normalized(), w = n.normalized().cross(u);
    Eigen::Matrix2d Dm; // the rest edges in the isometric frame (u, w)
    Dm << e1.norm(), e2.dot(u), 0, e2.dot(w);
    Eigen::Matrix<double, 2, 3> G;
    G << -1, 1, 0, -1, 0, 1;
    const Eigen::Matrix<double, 2, 3> C = Dm.inverse().transpose() * G; // F^T = C (x_f0; x_f1; x_f2)
    elements_.push_back({Element_type::triangle_strain, group, rows_, 2, n.norm() / 2, rmin, rmax, Eigen::Vector3d::Zero()});
    for(int r = 0; r < 2; ++r, ++rows_)
      for(int k = 0; k < 3; ++k) triplets_.emplace_back(rows_, f[k], C(r, k));
  }
  build_selection_matrix();
  return group;
}

int Elastic_model::add_tet_strain(const std::vector<Tetrahedron>& tets, double stiffness, double rmin, double rmax)
{
  check_limits(rmin, rmax, true);
  for(std::size_t t = 0; t < tets.size(); ++t)
  {
    const Tetrahedron& c = tets[t];
    check_indices(c.data(), 4, "tetrahedron", t);
    Eigen::Matrix3d Dm;
    double longest = 0;
    for(int k = 0; k < 3; ++k) Dm.col(k) = (rest_.row(c[k + 1]) - rest_.row(c[0])).transpose();
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j) longest = std::max(longest, (rest_.row(c[i]) - rest_.row(c[j])).norm());
    // As check_tet_mesh: 1e-12 longest^3 is far above the rounding of the determinant.
    if(!(std::abs(Dm.determinant()) / 6 > 1e-12 * longest * longest * longest))
      throw Invalid_mesh(Mesh_defect::degenerate_face, "tetrahedron " + std::to_string(t) + " has (nearly) zero volume");
  }
  const int group = new_group(Element_type::tet_strain, stiffness);
  Eigen::Matrix<double, 3, 4> G;
  G << -1, 1, 0, 0, -1, 0, 1, 0, -1, 0, 0, 1;
  for(const Tetrahedron& c : tets)
  {
    Eigen::Matrix3d Dm;
    for(int k = 0; k < 3; ++k) Dm.col(k) = (rest_.row(c[k + 1]) - rest_.row(c[0])).transpose();
    const Eigen::Matrix<double, 3, 4> C = Dm.inverse().transpose() * G; // F^T = C (x_c0; ...; x_c3)
    elements_.push_back({Element_type::tet_strain, group, rows_, 3, std::abs(Dm.determinant()) / 6, rmin, rmax,
                         Eigen::Vector3d::Zero()});
    for(int r = 0; r < 3; ++r, ++rows_)
      for(int k = 0; k < 4; ++k) triplets_.emplace_back(rows_, c[k], C(r, k));
  }
  build_selection_matrix();
  return group;
}

int Elastic_model::add_bending(const std::vector<Triangle>& triangles, double stiffness)
{
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Triangle& f = triangles[t];
    check_indices(f.data(), 3, "triangle", t);
    if(degenerate_triangle(rest_.row(f[0]), rest_.row(f[1]), rest_.row(f[2])))
      throw Invalid_mesh(Mesh_defect::degenerate_face, "triangle " + std::to_string(t) + " has (nearly) zero area");
  }
  const int group = new_group(Element_type::bending, stiffness);
  const int n = number_of_vertices();
  // Cotangent weights c_ij = (cot alpha + cot beta) / 2, mixed Voronoi areas (Meyer et al. 2003),
  // and how many triangles share each edge (boundary vertices do not bend).
  std::map<std::pair<int, int>, double> weight;
  std::map<std::pair<int, int>, int> edge_faces;
  std::vector<double> area(n, 0.0);
  for(const Triangle& f : triangles)
  {
    Eigen::Vector3d p[3];
    for(int k = 0; k < 3; ++k) p[k] = rest_.row(f[k]).transpose();
    const double A = (p[1] - p[0]).cross(p[2] - p[0]).norm() / 2;
    double cot[3];
    for(int k = 0; k < 3; ++k)
    {
      const Eigen::Vector3d a = p[(k + 1) % 3] - p[k], b = p[(k + 2) % 3] - p[k];
      cot[k] = a.dot(b) / a.cross(b).norm(); // at corner k, opposite edge (k+1, k+2)
    }
    for(int k = 0; k < 3; ++k)
    {
      const int i = f[(k + 1) % 3], j = f[(k + 2) % 3];
      weight[{std::min(i, j), std::max(i, j)}] += cot[k] / 2;
      ++edge_faces[{std::min(i, j), std::max(i, j)}];
    }
    const bool obtuse = cot[0] < 0 || cot[1] < 0 || cot[2] < 0;
    for(int k = 0; k < 3; ++k)
    {
      if(obtuse)
        area[f[k]] += cot[k] < 0 ? A / 2 : A / 4;
      else
      {
        const int a = (k + 1) % 3, b = (k + 2) % 3; // edges k-a (opposite b) and k-b (opposite a)
        area[f[k]] += ((p[a] - p[k]).squaredNorm() * cot[b] + (p[b] - p[k]).squaredNorm() * cot[a]) / 8;
      }
    }
  }
  std::vector<bool> boundary(n, false), used(n, false);
  for(const auto& e : edge_faces)
  {
    used[e.first.first] = used[e.first.second] = true;
    if(e.second < 2) boundary[e.first.first] = boundary[e.first.second] = true;
  }
  std::vector<std::vector<std::pair<int, double>>> ring(n);
  for(const auto& e : weight)
  {
    ring[e.first.first].emplace_back(e.first.second, e.second);
    ring[e.first.second].emplace_back(e.first.first, e.second);
  }
  for(int i = 0; i < n; ++i)
  {
    if(!used[i] || boundary[i]) continue;
    double sum = 0;
    Eigen::Vector3d h = Eigen::Vector3d::Zero();
    for(const auto& [j, c] : ring[i])
    {
      triplets_.emplace_back(rows_, j, c / area[i]);
      sum += c;
      h += c / area[i] * (rest_.row(j) - rest_.row(i)).transpose();
    }
    triplets_.emplace_back(rows_, i, -sum / area[i]);
    elements_.push_back({Element_type::bending, group, rows_, 1, area[i], h.norm(), h.norm(), h});
    ++rows_;
  }
  build_selection_matrix();
  return group;
}

void Elastic_model::set_stiffness(int group, double stiffness)
{
  if(group < 0 || group >= number_of_groups())
    throw Invalid_input("unknown element group " + std::to_string(group) + " (the model has " +
                        std::to_string(number_of_groups()) + ")");
  check_stiffness(stiffness);
  group_stiffness_[group] = stiffness;
}

double Elastic_model::stiffness(int group) const { return group_stiffness_.at(group); }
Element_type Elastic_model::group_type(int group) const { return group_type_.at(group); }

void Elastic_model::build_selection_matrix()
{
  S_.resize(rows_, number_of_vertices());
  S_.setFromTriplets(triplets_.begin(), triplets_.end());
  S_.makeCompressed();
}

Eigen::VectorXd Elastic_model::row_weights() const
{
  Eigen::VectorXd w(rows_);
  for(const Element& e : elements_) w.segment(e.first_row, e.rows).setConstant(group_stiffness_[e.group] * e.measure);
  return w;
}

void Elastic_model::project(int index, const double* value, double* out) const
{
  const Element& e = elements_[index];
  switch(e.type)
  {
  case Element_type::spring: {
    const Eigen::Vector3d p = project_spring(Eigen::Vector3d(value[0], value[1], value[2]), e.min_value, e.max_value, e.fallback);
    out[0] = p[0], out[1] = p[1], out[2] = p[2];
    break;
  }
  case Element_type::bending: {
    const Eigen::Vector3d p = project_bending(Eigen::Vector3d(value[0], value[1], value[2]), e.min_value, e.fallback);
    out[0] = p[0], out[1] = p[1], out[2] = p[2];
    break;
  }
  case Element_type::triangle_strain: {
    // value holds F^T row-major (2 x 3), i.e. F column-major.
    const Eigen::Map<const Eigen::Matrix<double, 3, 2>> F(value);
    Eigen::Map<Eigen::Matrix<double, 3, 2>> P(out);
    P = project_triangle_strain(F, e.min_value, e.max_value);
    break;
  }
  case Element_type::tet_strain: {
    const Eigen::Map<const Eigen::Matrix3d> F(value);
    Eigen::Map<Eigen::Matrix3d> P(out);
    P = project_tet_strain(F, e.min_value, e.max_value);
    break;
  }
  }
}

double Elastic_model::elastic_energy(const Positions& q) const
{
  if(q.rows() != number_of_vertices()) throw Invalid_input("positions of the wrong size");
  const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> v = selection_matrix() * q;
  double energy = 0;
  double p[9];
  for(int i = 0; i < number_of_elements(); ++i)
  {
    const Element& e = elements_[i];
    project(i, v.row(e.first_row).data(), p);
    double d2 = 0;
    for(int k = 0; k < 3 * e.rows; ++k) d2 += (v.data()[3 * e.first_row + k] - p[k]) * (v.data()[3 * e.first_row + k] - p[k]);
    energy += group_stiffness_[e.group] * e.measure / 2 * d2;
  }
  return energy;
}

} // namespace Projective_dynamics
} // namespace CGAL
