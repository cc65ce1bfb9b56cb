// Copyright (c) 2026 The Discrete_shells authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Discrete_shells/Shell_energy.h>
#include <CGAL/Discrete_shells/errors.h>

#include "second_order.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>

namespace CGAL {
namespace Discrete_shells {

namespace {

using internal::Derivatives;

// A 3-vector over any scalar (double, or values with derivatives).
template <class T>
struct V3
{
  T x, y, z;
};
template <class T> V3<T> operator-(const V3<T>& a, const V3<T>& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <class T> T dot(const V3<T>& a, const V3<T>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <class T> V3<T> cross(const V3<T>& a, const V3<T>& b)
{
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// The three geometric quantities of the energy, for any scalar type.
template <class T> T edge_length(const V3<T>* p)
{
  using internal::sqrt;
  const V3<T> d = p[1] - p[0];
  return sqrt(dot(d, d));
}
template <class T> T triangle_area(const V3<T>* p)
{
  using internal::sqrt;
  const V3<T> n = cross(p[1] - p[0], p[2] - p[0]);
  return 0.5 * sqrt(dot(n, n));
}
// Signed angle between the normals of (a, b, c) and (a, b, d) oriented so that a flat
// hinge (c and d on opposite sides of ab) has angle 0, whatever the faces' orientations.
template <class T> T dihedral_angle(const V3<T>* p)
{
  using internal::atan2;
  using internal::sqrt;
  const V3<T> e = p[1] - p[0];
  const V3<T> n1 = cross(e, p[2] - p[0]);
  const V3<T> n2 = cross(p[3] - p[0], e);
  // |n1||n2| sin = (n1 x n2) . e / |e| and |n1||n2| cos = n1 . n2: scale both by |e|.
  return atan2(dot(cross(n1, n2), e), dot(n1, n2) * sqrt(dot(e, e)));
}

V3<double> point(const Eigen::VectorXd& x, int v) { return {x[3 * v], x[3 * v + 1], x[3 * v + 2]}; }

// f and its derivatives with respect to the K vertices' coordinates.
template <int K, bool with_hessian, class F>
Derivatives<3 * K, with_hessian> differentiate(const Eigen::VectorXd& y, const int* v, const F& f)
{
  typedef Derivatives<3 * K, with_hessian> D;
  V3<D> p[K];
  for(int i = 0; i < K; ++i)
    p[i] = {D::variable(3 * i, y[3 * v[i]]), D::variable(3 * i + 1, y[3 * v[i] + 1]),
            D::variable(3 * i + 2, y[3 * v[i] + 2])};
  return f(p);
}

std::string face_name(std::size_t f) { return "face " + std::to_string(f); }

} // namespace

Shell_energy::Shell_energy(const Eigen::VectorXd& rest, const std::vector<Triangle>& triangles,
                           const Shell_stiffness& stiffness)
  : rest_(rest), triangles_(triangles), stiffness_(stiffness)
{
  for(double k : {stiffness.stretching, stiffness.area, stiffness.bending})
    if(!(k >= 0) || !std::isfinite(k))
      throw Invalid_input("shell stiffness: every stiffness must be finite and >= 0 (got " + std::to_string(k) + ")");
  if(stiffness.stretching == 0 && stiffness.area == 0 && stiffness.bending == 0)
    throw Invalid_input("shell stiffness: all three stiffnesses are 0, the energy would vanish");
  if(rest.size() % 3 != 0)
    throw Invalid_input("shell rest positions: " + std::to_string(rest.size()) + " values, not 3 per vertex");
  if(triangles.empty()) throw Invalid_mesh(Mesh_defect::empty, "the shell has no triangles");
  const int n = int(rest.size() / 3);
  for(int i = 0; i < rest.size(); ++i)
    if(!std::isfinite(rest[i]))
      throw Invalid_mesh(Mesh_defect::non_finite_coordinate,
                         "vertex " + std::to_string(i / 3) + " has a non-finite coordinate");

  // Faces: valid indices and a normal area.  A triangle whose doubled area is below
  // 64 eps of its longest edge squared is zero up to the rounding of its cross product.
  face_areas_.resize(triangles.size());
  std::vector<std::tuple<int, int, int, double>> edge_faces; // (a < b), opposite vertex, face area
  edge_faces.reserve(3 * triangles.size());
  for(std::size_t f = 0; f < triangles.size(); ++f)
  {
    const Triangle& t = triangles[f];
    for(int i = 0; i < 3; ++i)
      if(t[i] < 0 || t[i] >= n)
        throw Invalid_mesh(Mesh_defect::invalid_index, face_name(f) + " has vertex index " + std::to_string(t[i]) +
                                                           " outside [0, " + std::to_string(n) + ")");
    if(t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      throw Invalid_mesh(Mesh_defect::invalid_index, face_name(f) + " repeats a vertex");
    const V3<double> p[3] = {point(rest, t[0]), point(rest, t[1]), point(rest, t[2])};
    const double area = triangle_area(p);
    double longest = 0;
    for(int i = 0; i < 3; ++i)
    {
      const V3<double> e[2] = {p[i], p[(i + 1) % 3]};
      longest = std::max(longest, edge_length(e));
    }
    if(!(2 * area > 64 * std::numeric_limits<double>::epsilon() * longest * longest))
      throw Invalid_mesh(Mesh_defect::degenerate_face,
                         face_name(f) + " is degenerate (area " + std::to_string(area) + ", longest edge " +
                             std::to_string(longest) + ")");
    face_areas_[f] = area;
    for(int i = 0; i < 3; ++i)
    {
      const int a = t[i], b = t[(i + 1) % 3];
      edge_faces.emplace_back(std::min(a, b), std::max(a, b), t[(i + 2) % 3], area);
    }
  }

  // Edges (the area share: a third of their faces' areas), then hinges at every pair of
  // faces of an edge.
  std::sort(edge_faces.begin(), edge_faces.end());
  const auto& with_area = edge_faces;
  for(std::size_t i = 0; i < with_area.size();)
  {
    std::size_t j = i;
    double share = 0;
    while(j < with_area.size() && std::get<0>(with_area[j]) == std::get<0>(with_area[i]) &&
          std::get<1>(with_area[j]) == std::get<1>(with_area[i]))
      share += std::get<3>(with_area[j++]) / 3;
    const int a = std::get<0>(with_area[i]), b = std::get<1>(with_area[i]);
    const V3<double> e[2] = {point(rest, a), point(rest, b)};
    edges_.push_back({a, b, edge_length(e), share});
    for(std::size_t p = i; p < j; ++p)
      for(std::size_t q = p + 1; q < j; ++q)
      {
        const std::array<int, 4> h = {a, b, std::get<2>(with_area[p]), std::get<2>(with_area[q])};
        const V3<double> x[4] = {point(rest, h[0]), point(rest, h[1]), point(rest, h[2]), point(rest, h[3])};
        const double hinge_share = (std::get<3>(with_area[p]) + std::get<3>(with_area[q])) / 3;
        hinges_.push_back(h);
        hinge_rest_.push_back({dihedral_angle(x), edges_.back().rest_length * edges_.back().rest_length / hinge_share});
      }
    i = j;
  }

  // The sparsity of every Hessian: 3x3 blocks for the vertex pairs of each face and hinge.
  std::vector<Eigen::Triplet<double>> entries;
  auto couple = [&](const int* v, int k) {
    for(int i = 0; i < k; ++i)
      for(int j = 0; j < k; ++j)
        for(int r = 0; r < 3; ++r)
          for(int c = 0; c < 3; ++c) entries.emplace_back(3 * v[i] + r, 3 * v[j] + c, 0.0);
  };
  for(const Triangle& t : triangles_) couple(t.data(), 3);
  if(stiffness_.bending > 0)
    for(const auto& h : hinges_) couple(h.data(), 4);
  pattern_.resize(rest_.size(), rest_.size());
  pattern_.setFromTriplets(entries.begin(), entries.end());
  pattern_.makeCompressed();
}

void Shell_energy::check_size(const Eigen::VectorXd& y) const
{
  if(y.size() != rest_.size())
    throw Invalid_input("shell deformed positions: " + std::to_string(y.size()) + " values for " +
                        std::to_string(rest_.size()) + " unknowns");
  if(!y.allFinite()) throw Invalid_input("shell deformed positions: a non-finite coordinate");
}

// Calls add(vertices, K, w, f - f_rest, grad f, hess f) for every term w (f - f_rest)^2;
// hess f is only computed with_hessian.
template <bool H, class Add_term>
void Shell_energy::for_each_term(const Eigen::VectorXd& y, const Add_term& add) const
{
    if(stiffness_.stretching > 0)
      for(const Edge& e : edges_)
      {
        const int v[2] = {e.a, e.b};
        const auto f = differentiate<2, H>(y, v, [](const auto* p) { return edge_length(p); });
        add(v, 2, stiffness_.stretching * e.area_share / (e.rest_length * e.rest_length), f.v - e.rest_length, f);
      }
    if(stiffness_.area > 0)
      for(std::size_t t = 0; t < triangles_.size(); ++t)
      {
        const auto f = differentiate<3, H>(y, triangles_[t].data(), [](const auto* p) { return triangle_area(p); });
        add(triangles_[t].data(), 3, stiffness_.area / face_areas_[t], f.v - face_areas_[t], f);
      }
    if(stiffness_.bending > 0)
      for(std::size_t h = 0; h < hinges_.size(); ++h)
      {
        const auto f = differentiate<4, H>(y, hinges_[h].data(), [](const auto* p) { return dihedral_angle(p); });
        // The angle difference taken in (-pi, pi]: a hinge folded through the flat side
        // is a small change, not a full turn.
        double d = f.v - hinge_rest_[h].angle;
        d -= 2 * M_PI * std::round(d / (2 * M_PI));
        add(hinges_[h].data(), 4, stiffness_.bending * hinge_rest_[h].weight, d, f);
      }
}

double Shell_energy::energy(const Eigen::VectorXd& y) const
{
  check_size(y);
  double total = 0;
  for_each_term<false>(y, [&](const int*, int, double w, double d, const auto&) { total += w * d * d; });
  return total;
}

Eigen::VectorXd Shell_energy::gradient(const Eigen::VectorXd& y) const
{
  check_size(y);
  Eigen::VectorXd g = Eigen::VectorXd::Zero(y.size());
  for_each_term<false>(y, [&](const int* v, int k, double w, double d, const auto& f) {
    for(int i = 0; i < k; ++i) g.segment<3>(3 * v[i]) += 2 * w * d * f.g.template segment<3>(3 * i);
  });
  return g;
}

namespace {

// Adds a local 3k x 3k block into a matrix with the pattern already in place.
template <class Local>
void scatter(Eigen::SparseMatrix<double>& H, const int* v, int k, const Local& local)
{
  for(int j = 0; j < k; ++j)
    for(int c = 0; c < 3; ++c)
    {
      const int col = 3 * v[j] + c;
      for(int i = 0; i < k; ++i)
        for(int r = 0; r < 3; ++r) H.coeffRef(3 * v[i] + r, col) += local(3 * i + r, 3 * j + c);
    }
}

} // namespace

Eigen::SparseMatrix<double> Shell_energy::hessian(const Eigen::VectorXd& y) const
{
  check_size(y);
  Eigen::SparseMatrix<double> H = pattern_;
  for_each_term<true>(y, [&](const int* v, int k, double w, double d, const auto& f) {
    scatter(H, v, k, 2 * w * (f.g * f.g.transpose() + d * f.h));
  });
  return H;
}

Eigen::SparseMatrix<double> Shell_energy::rest_hessian() const
{
  Eigen::SparseMatrix<double> H = pattern_;
  for_each_term<false>(rest_, [&](const int* v, int k, double w, double, const auto& f) {
    scatter(H, v, k, 2 * w * f.g * f.g.transpose());
  });
  return H;
}

Eigen::VectorXd Shell_energy::lumped_mass() const
{
  Eigen::VectorXd m = Eigen::VectorXd::Zero(rest_.size());
  for(std::size_t t = 0; t < triangles_.size(); ++t)
    for(int v : triangles_[t]) m.segment<3>(3 * v).array() += face_areas_[t] / 3;
  return m;
}

} // namespace Discrete_shells
} // namespace CGAL
