// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the design suites share: a mesh's operators and basis, tangent vectors, a mixed
// constraint set, and the residual of constraints measured through the operators.

#ifndef TVF_TEST_DESIGN_TEST_SUPPORT_H
#define TVF_TEST_DESIGN_TEST_SUPPORT_H

#include "test_meshes.h"

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>
#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Field_constraint.h>
#include <CGAL/Tangent_vector_fields/Hodge_solver.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

namespace design_test {

namespace TVF = CGAL::Tangent_vector_fields;
using tvf_test::Mesh;

struct Design_setup
{
  std::shared_ptr<const TVF::Operator_matrices> ops;
  std::shared_ptr<TVF::Hodge_solver> hodge;
  std::shared_ptr<TVF::Eigenfield_basis> basis;
  int nf = 0;
};

// Operators, Hodge solver and a basis of `basis_size` eigenfields (0: all 2nf).
inline Design_setup setup(const Mesh& mesh, int basis_size)
{
  Design_setup s;
  TVF::Discrete_operators<Mesh> operators(mesh);
  s.ops = operators.shared_matrices();
  s.nf = s.ops->mesh().number_of_faces();
  s.hodge = std::make_shared<TVF::Hodge_solver>(s.ops);
  const int d = basis_size == 0 ? 2 * s.nf : basis_size;
  s.basis = std::make_shared<TVF::Eigenfield_basis>(s.hodge, TVF::Basis_request::lowest(d));
  return s;
}

// A tangent vector of face f: a fixed combination of its frame.
inline std::array<double, 3> tangent(const TVF::Intrinsic_mesh& m, int f, double a, double b)
{
  const auto& e1 = m.frame_e1(f);
  const auto& e2 = m.frame_e2(f);
  return {{a * e1[0] + b * e2[0], a * e1[1] + b * e2[1], a * e1[2] + b * e2[2]}};
}

// A mixed constraint set: vectors in spread-out faces, a direction, a divergence at
// a vertex and at a point, a curl at an edge and at a point.
inline std::vector<TVF::Field_constraint> mixed_constraints(const TVF::Intrinsic_mesh& m, int vectors, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<TVF::Field_constraint> c;
  const int nf = m.number_of_faces();
  for(int i = 0; i < vectors; ++i)
    c.push_back(TVF::Field_constraint::vector_in_face((i * 7919 + 13) % nf, tangent(m, (i * 7919 + 13) % nf, u(rng), u(rng))));
  c.push_back(TVF::Field_constraint::direction_in_face((nf / 2 + 3) % nf, tangent(m, (nf / 2 + 3) % nf, 1, 2)));
  c.push_back(TVF::Field_constraint::divergence_at_vertex(m.face_vertices(nf / 3)[0], 0.7));
  c.push_back(TVF::Field_constraint::divergence_at_point(nf / 5, {{0.2, 0.3, 0.5}}, -0.4));
  int interior = m.interior_edges()[m.number_of_interior_edges() / 2];
  c.push_back(TVF::Field_constraint::curl_at_edge(interior, 0.9));
  c.push_back(TVF::Field_constraint::curl_at_point((2 * nf) / 3, {{0.6, 0.1, 0.3}}, -0.5));
  return c;
}

// How far x is from each constraint, measured through the operators (not the solvers'
// constraint rows): the face's vector, its cross product with a direction, the divergence
// at vertices and the curl at edges (interpolated at points: barycentric weights for the
// divergence, Crouzeix-Raviart weights 1 - 2 b_k for the curl at the edge opposite corner k).
// Relative to the largest value asked for (1 for directions).
inline double constraint_residual(const TVF::Operator_matrices& ops, const std::vector<TVF::Field_constraint>& constraints,
                           const Eigen::VectorXd& x)
{
  const TVF::Intrinsic_mesh& m = ops.mesh();
  const Eigen::VectorXd divergence = ops.divergence(x), curl = ops.nonconforming_curl(x);
  double worst = 0, largest = 1e-300;
  for(const auto& c : constraints)
  {
    switch(c.kind)
    {
    case TVF::Constraint_kind::vector:
    {
      const auto a = m.to_frame(c.face, c.vector);
      worst = std::max({worst, std::abs(x[2 * c.face] - a[0]), std::abs(x[2 * c.face + 1] - a[1])});
      largest = std::max({largest, std::abs(a[0]), std::abs(a[1])});
      break;
    }
    case TVF::Constraint_kind::direction:
    {
      const auto a = m.to_frame(c.face, c.vector);
      const double cross = (x[2 * c.face] * a[1] - x[2 * c.face + 1] * a[0]) / std::hypot(a[0], a[1]);
      worst = std::max(worst, std::abs(cross));
      largest = std::max(largest, 1.);
      break;
    }
    case TVF::Constraint_kind::divergence:
    case TVF::Constraint_kind::curl:
    {
      const bool div = c.kind == TVF::Constraint_kind::divergence;
      double measured = 0;
      if(c.vertex >= 0) measured = divergence[c.vertex];
      else if(c.edge >= 0) measured = curl[c.edge];
      else
        for(int k = 0; k < 3; ++k)
          measured += div ? c.barycentric[k] * divergence[m.face_vertices(c.face)[k]]
                          : (1 - 2 * c.barycentric[k]) * curl[m.face_edges(c.face)[k]];
      worst = std::max(worst, std::abs(measured - c.value));
      largest = std::max(largest, std::abs(c.value));
      break;
    }
    }
  }
  return worst / largest;
}

inline double relative_mx_error(const TVF::Operator_matrices& ops, const Eigen::VectorXd& x, const Eigen::VectorXd& reference)
{
  const Eigen::VectorXd& m = ops.field_masses();
  const Eigen::VectorXd d = x - reference;
  return std::sqrt(d.dot(m.cwiseProduct(d)) / reference.dot(m.cwiseProduct(reference)));
}


} // namespace design_test

#endif
