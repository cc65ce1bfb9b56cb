// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// What the two n-field streamline suites share: vector helpers, the torus of revolution
// and its parameter lines, a checker of n-field streamlines, and refusal checks.

#ifndef TVF_N_FIELD_STREAMLINE_SUPPORT_H
#define TVF_N_FIELD_STREAMLINE_SUPPORT_H

#include "test_meshes.h"

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>
#include <CGAL/Tangent_vector_fields/N_field_operators.h>
#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>

namespace nstream_test {

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;

typedef std::array<double, 3> P3;
typedef Mesh::Property_map<Face_index, Vector_3> Field;

inline P3 sub(const P3& a, const P3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline P3 cross(const P3& a, const P3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const P3& a) { return std::sqrt(dot(a, a)); }
inline P3 unit(const P3& a) { return {a[0] / norm(a), a[1] / norm(a), a[2] / norm(a)}; }
inline double degrees(double radians) { return radians * 180 / M_PI; }

inline std::shared_ptr<const TVF::N_field_operators> n_field_operators(const Mesh& mesh, int n)
{
  return std::make_shared<const TVF::N_field_operators>(TVF::Discrete_operators<Mesh>(mesh).shared_matrices(), n);
}

// Frame coordinates turned by `angle`.
inline std::array<double, 2> turned(double a, double b, double angle)
{
  return {std::cos(angle) * a - std::sin(angle) * b, std::sin(angle) * a + std::cos(angle) * b};
}

// The torus of make_torus (axis z, radii R = 1, r = 0.4): the unit directions of the
// parallel (around the axis) and of the meridian (around the tube) through p.
const double torus_R = 1.0, torus_r = 0.4;
inline P3 parallel_direction(const P3& p) { return unit({-p[1], p[0], 0}); }
inline P3 meridian_direction(const P3& p)
{
  const double a = std::atan2(p[1], p[0]), b = std::atan2(p[2], std::hypot(p[0], p[1]) - torus_R);
  return {-std::sin(b) * std::cos(a), -std::sin(b) * std::sin(a), std::cos(b)};
}

// The parallel direction at each face's centroid, in frame coordinates (projected on the face).
inline Eigen::VectorXd torus_parallels(const TVF::Intrinsic_mesh& M)
{
  Eigen::VectorXd x(2 * M.number_of_faces());
  for(int f = 0; f < M.number_of_faces(); ++f)
  {
    P3 c = {0, 0, 0};
    for(int v : M.face_vertices(f))
      for(int i = 0; i < 3; ++i) c[i] += M.position(v)[i] / 3;
    const auto ab = M.to_frame(f, parallel_direction(c));
    x[2 * f] = ab[0];
    x[2 * f + 1] = ab[1];
  }
  return x;
}

// Every point in its face; every segment along one of the n vectors of its face (but the
// last one into a singular vertex); consecutive faces sharing an edge or a vertex that
// holds the point between them.
inline void expect_valid_n_streamline(const TVF::Intrinsic_mesh& M, const Eigen::VectorXd& vectors, int n,
                               const TVF::Streamline& s)
{
  ASSERT_EQ(s.points.size(), s.faces.size());
  ASSERT_LT(s.seed_index, s.points.size());
  const double h = M.mean_edge_length();
  for(std::size_t i = 0; i < s.points.size(); ++i)
  {
    const int f = s.faces[i];
    ASSERT_GE(f, 0);
    ASSERT_LT(f, M.number_of_faces());
    const auto& t = M.face_vertices(f);
    const P3 d = sub(s.points[i], M.position(t[0]));
    EXPECT_LE(std::abs(dot(d, M.normal(f))), 1e-9 * h) << "point " << i << " off the plane of face " << f;
    const P3 p1 = sub(M.position(t[1]), M.position(t[0])), p2 = sub(M.position(t[2]), M.position(t[0]));
    const double area2 = dot(cross(p1, p2), M.normal(f));
    const double b1 = dot(cross(d, p2), M.normal(f)) / area2, b2 = dot(cross(p1, d), M.normal(f)) / area2;
    EXPECT_TRUE(b1 >= -1e-9 && b2 >= -1e-9 && 1 - b1 - b2 >= -1e-9) << "point " << i << " outside face " << f;
  }
  for(std::size_t i = 0; i + 1 < s.points.size(); ++i)
  {
    const int f = s.faces[i];
    const P3 segment = sub(s.points[i + 1], s.points[i]);
    const bool chord = (i == 0 && s.backward_stop == TVF::Streamline_stop::singular_vertex) ||
                       (i + 2 == s.points.size() && s.forward_stop == TVF::Streamline_stop::singular_vertex);
    if(norm(segment) > 1e-9 * h && !chord)
    {
      double best = -2;
      for(int j = 0; j < n; ++j)
      {
        const auto ab = turned(vectors[2 * f], vectors[2 * f + 1], 2 * M_PI * j / n);
        best = std::max(best, dot(unit(segment), unit(M.from_frame(f, ab[0], ab[1]))));
      }
      EXPECT_GT(best, 1 - 1e-12) << "segment " << i << " follows none of the vectors of face " << f;
    }
    if(i + 1 < s.number_of_segments() && s.faces[i + 1] != f)
    {
      int shared = 0;
      for(int a : M.face_vertices(f))
        for(int b : M.face_vertices(s.faces[i + 1])) shared += a == b;
      EXPECT_GE(shared, 1) << "faces " << f << " and " << s.faces[i + 1] << " do not touch";
    }
  }
}

inline void expect_invalid(const std::function<void()>& f, const std::string& reason)
{
  try
  {
    f();
    ADD_FAILURE() << "accepted; expected a refusal with \"" << reason << "\"";
  }
  catch(const TVF::Invalid_input& e)
  {
    EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
  }
}

} // namespace nstream_test

#endif
