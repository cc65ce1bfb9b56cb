// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// What the two n-field suites share: operators on a test mesh, a subdivided cube, random
// fields and constraints, and field comparisons.

#ifndef TVF_N_FIELD_TEST_SUPPORT_H
#define TVF_N_FIELD_TEST_SUPPORT_H

#include "test_meshes.h"

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>
#include <CGAL/Tangent_vector_fields/N_field_constraint.h>
#include <CGAL/Tangent_vector_fields/N_field_operators.h>

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <vector>

namespace nfield_test {

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;

inline std::shared_ptr<const TVF::N_field_operators> n_field_operators(const Mesh& mesh, int n,
                                                                TVF::N_field_boundary boundary = TVF::N_field_boundary::free)
{
  TVF::Discrete_operators<Mesh> ops(mesh);
  TVF::N_field_options options;
  options.boundary = boundary;
  return std::make_shared<const TVF::N_field_operators>(ops.shared_matrices(), n, options);
}

// A cube [-1, 1]^3 with a k x k grid of squares per side, each split into two triangles.
inline Mesh make_cube(int k)
{
  std::vector<Point_3> points;
  std::map<std::array<int, 3>, int> index; // lattice point (in units of 2/k) -> vertex
  auto vertex = [&](std::array<int, 3> q) {
    auto it = index.find(q);
    if(it != index.end()) return it->second;
    points.emplace_back(-1 + 2. * q[0] / k, -1 + 2. * q[1] / k, -1 + 2. * q[2] / k);
    index[q] = static_cast<int>(points.size()) - 1;
    return static_cast<int>(points.size()) - 1;
  };
  std::vector<std::array<int, 3>> triangles;
  for(int axis = 0; axis < 3; ++axis)
    for(int side = 0; side < 2; ++side)
    {
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      for(int i = 0; i < k; ++i)
        for(int j = 0; j < k; ++j)
        {
          auto at = [&](int a, int b) {
            std::array<int, 3> q{};
            q[axis] = side * k;
            q[u] = a;
            q[w] = b;
            return vertex(q);
          };
          const int p00 = at(i, j), p10 = at(i + 1, j), p01 = at(i, j + 1), p11 = at(i + 1, j + 1);
          // (u, w, axis) is right-handed: counter-clockwise seen from outside on side 1.
          if(side == 1)
          {
            triangles.push_back({p00, p10, p11});
            triangles.push_back({p00, p11, p01});
          }
          else
          {
            triangles.push_back({p00, p11, p10});
            triangles.push_back({p00, p01, p11});
          }
        }
    }
  return make_mesh(points, triangles);
}

inline int euler_characteristic(const TVF::Intrinsic_mesh& mesh)
{
  int chi = 0;
  for(const auto& c : mesh.topology().components) chi += c.euler_characteristic();
  return chi;
}

// Random tangent vectors in every face (frame coordinates) of lengths in [0.5, 1.5].
inline Eigen::VectorXd random_vectors(int nf, unsigned seed)
{
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), length(0.5, 1.5);
  Eigen::VectorXd x(2 * nf);
  for(int f = 0; f < nf; ++f)
  {
    const double a = angle(gen), r = length(gen);
    x[2 * f] = r * std::cos(a);
    x[2 * f + 1] = r * std::sin(a);
  }
  return x;
}

inline Eigen::Vector3d to_eigen(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

// Mass-weighted relative difference |a - b| / |b|.
inline double relative_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b, const Eigen::VectorXd& mass)
{
  const Eigen::VectorXd d = a - b;
  return std::sqrt(d.dot(mass.cwiseProduct(d)) / b.dot(mass.cwiseProduct(b)));
}

// Of the n vectors the field has in `face`, the distance of the closest to `v` (in frame coordinates).
inline double closest_vector_distance(const TVF::N_field_operators& ops, const Eigen::VectorXd& z, int face,
                               const std::array<double, 3>& v)
{
  const auto target = ops.mesh().to_frame(face, v);
  double best = std::numeric_limits<double>::infinity();
  for(int j = 0; j < ops.n(); ++j)
  {
    const Eigen::VectorXd u = ops.to_vectors(z, j);
    best = std::min(best, std::hypot(u[2 * face] - target[0], u[2 * face + 1] - target[1]));
  }
  return best;
}

inline std::vector<TVF::N_field_constraint> random_vector_constraints(const TVF::Intrinsic_mesh& mesh, int count, unsigned seed)
{
  std::mt19937 gen(seed);
  std::uniform_int_distribution<int> face(0, mesh.number_of_faces() - 1);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  std::vector<TVF::N_field_constraint> constraints;
  std::set<int> used; // distinct faces: two vectors in one face contradict each other
  for(int i = 0; i < count; ++i)
  {
    int f = face(gen);
    while(!used.insert(f).second) f = face(gen);
    const double a = angle(gen);
    const auto v = mesh.from_frame(f, std::cos(a), std::sin(a));
    constraints.push_back(TVF::N_field_constraint::vector_in_face(f, v));
  }
  return constraints;
}


} // namespace nfield_test

#endif
