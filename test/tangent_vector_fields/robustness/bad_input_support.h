// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Shared by the bad-input tests of every entry point: the check of an error's type and
// reason, and small meshes of awkward shape and topology whose topology the tests know
// independently of the package (they count it from the faces they build).

#ifndef TVF_BAD_INPUT_SUPPORT_H
#define TVF_BAD_INPUT_SUPPORT_H

#include "test_meshes.h"

#include <CGAL/Tangent_vector_fields/errors.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <set>
#include <string>
#include <typeinfo>
#include <utility>
#include <vector>

namespace bad_input {

using namespace tvf_test;
namespace TVF = CGAL::Tangent_vector_fields;

/// Expects `f` to throw exactly `Error` (not a subclass or another type) whose message
/// contains `phrase`; returns the message.
template <class Error>
std::string expect_error(const std::function<void()>& f, const std::string& phrase)
{
  try
  {
    f();
  }
  catch(const std::exception& e)
  {
    EXPECT_TRUE(typeid(e) == typeid(Error)) << "thrown " << typeid(e).name() << ": " << e.what();
    EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos)
        << "message '" << e.what() << "' lacks '" << phrase << "'";
    return e.what();
  }
  ADD_FAILURE() << "nothing thrown (expected '" << phrase << "')";
  return "";
}

/// Expects `Invalid_mesh` with `defect` and `phrase` in the message, and a message that says
/// more than a word; returns the message.
inline std::string expect_defect(TVF::Mesh_defect defect, const std::function<void()>& f, const std::string& phrase = "")
{
  const std::string what = expect_error<TVF::Invalid_mesh>(
      [&] {
        try
        {
          f();
        }
        catch(const TVF::Invalid_mesh& e)
        {
          EXPECT_EQ(static_cast<int>(e.defect()), static_cast<int>(defect)) << e.what();
          throw;
        }
      },
      phrase);
  EXPECT_GT(what.size(), 10u) << what;
  return what;
}

/// A face vector property map named "f:<name>", every value `value`.
inline Mesh::Property_map<Face_index, Vector_3> field_map(Mesh& mesh, const std::string& name,
                                                        const Vector_3& value = Vector_3(0, 0, 0))
{
  return mesh.add_property_map<Face_index, Vector_3>("f:" + name, value).first;
}

inline bool all_finite(const Eigen::VectorXd& x) { return x.allFinite(); }

/// One triangle, not in a coordinate plane.
inline Mesh single_triangle()
{
  return make_mesh({{0, 0, 0}, {1, 0, 0.2}, {0.3, 1, 0.1}}, {{{0, 1, 2}}});
}

/// A band of `n` x 2 triangles between two circles (radius 1 at z = 0 and z = h): an
/// annulus (genus 0, two boundary loops) in which every vertex is on the boundary.
inline Mesh boundary_only_band(int n, double h = 0.4)
{
  std::vector<Point_3> p;
  for(int i = 0; i < n; ++i)
  {
    const double a = 2 * M_PI * i / n, b = 2 * M_PI * (i + 0.5) / n;
    p.emplace_back(std::cos(a), std::sin(a), 0);
    p.emplace_back(std::cos(b), std::sin(b), h);
  }
  std::vector<std::array<int, 3>> f;
  for(int i = 0; i < n; ++i)
  {
    const int a = 2 * i, b = 2 * i + 1, c = 2 * ((i + 1) % n), d = 2 * ((i + 1) % n) + 1;
    f.push_back({a, c, b});
    f.push_back({b, c, d});
  }
  return make_mesh(p, f);
}

/// An open strip of `n` x 2 triangles (a disk in which every vertex is on the boundary).
inline Mesh boundary_only_strip(int n)
{
  std::vector<Point_3> p;
  for(int i = 0; i <= n; ++i)
  {
    p.emplace_back(i, 0, 0.1 * std::sin(i));
    p.emplace_back(i + 0.5, 1, 0.1 * std::cos(i));
  }
  std::vector<std::array<int, 3>> f;
  for(int i = 0; i < n; ++i)
  {
    f.push_back({2 * i, 2 * i + 2, 2 * i + 1});
    f.push_back({2 * i + 1, 2 * i + 2, 2 * i + 3});
  }
  return make_mesh(p, f);
}

/// The closed surface of a slab over an `n` x `n` grid of unit squares with
/// `holes` single squares cut out along the diagonal (every second one): genus = holes.
/// Flat faces meeting at right angles: a mesh whose curvature sits on its edges.
inline Mesh holed_slab(int n, int holes)
{
  std::set<std::pair<int, int>> cut;
  for(int k = 0; k < holes; ++k) cut.insert({1 + 2 * k, 1 + 2 * k});
  auto inside = [&](int i, int j) { return i >= 0 && j >= 0 && i < n && j < n && !cut.count({i, j}); };
  std::vector<Point_3> p;
  auto vid = [&](int i, int j, int top) { return 2 * (i * (n + 1) + j) + top; };
  for(int i = 0; i <= n; ++i)
    for(int j = 0; j <= n; ++j)
    {
      p.emplace_back(i, j, 0);
      p.emplace_back(i, j, 1);
    }
  std::vector<std::array<int, 3>> f;
  auto quad = [&](int a, int b, int c, int d) { // counter-clockwise seen from outside
    f.push_back({a, b, c});
    f.push_back({a, c, d});
  };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
    {
      if(!inside(i, j)) continue;
      quad(vid(i, j, 1), vid(i + 1, j, 1), vid(i + 1, j + 1, 1), vid(i, j + 1, 1));
      quad(vid(i, j, 0), vid(i, j + 1, 0), vid(i + 1, j + 1, 0), vid(i + 1, j, 0));
      // Walls where the neighbour is outside: outward normals -x, +x, -y, +y.
      if(!inside(i - 1, j)) quad(vid(i, j, 0), vid(i, j, 1), vid(i, j + 1, 1), vid(i, j + 1, 0));
      if(!inside(i + 1, j)) quad(vid(i + 1, j, 0), vid(i + 1, j + 1, 0), vid(i + 1, j + 1, 1), vid(i + 1, j, 1));
      if(!inside(i, j - 1)) quad(vid(i, j, 0), vid(i + 1, j, 0), vid(i + 1, j, 1), vid(i, j, 1));
      if(!inside(i, j + 1)) quad(vid(i, j + 1, 0), vid(i, j + 1, 1), vid(i + 1, j + 1, 1), vid(i + 1, j + 1, 0));
    }
  // Drop the grid points no face uses (inside holes' walls all are used; none unused for n >= 3).
  return make_mesh(p, f);
}

/// Euler characteristic V - E + F counted on the Surface_mesh (vertices in faces only),
/// and the number of boundary loops: the truth the package's topology is checked against.
inline std::pair<int, int> euler_and_boundary_loops(const Mesh& mesh)
{
  int v = 0, b = 0;
  for(Vertex_index x : mesh.vertices())
    if(!mesh.is_isolated(x)) ++v;
  std::set<Mesh::Halfedge_index> seen;
  for(Mesh::Halfedge_index h : mesh.halfedges())
  {
    if(!mesh.is_border(h) || seen.count(h)) continue;
    ++b;
    for(Mesh::Halfedge_index g = h; seen.insert(g).second; g = mesh.next(g)) {}
  }
  return {v - static_cast<int>(mesh.number_of_edges()) + static_cast<int>(mesh.number_of_faces()), b};
}

/// A unit sphere and a copy of it scaled by `tiny`, far apart, as one mesh.
inline Mesh sphere_with_tiny_companion(double tiny)
{
  Mesh mesh = make_icosphere(2);
  Mesh small = make_icosphere(1);
  transform(small, tiny, {1, 0, 0, 0, 1, 0, 0, 0, 1}, Vector_3(3, 0, 0));
  mesh.join(small);
  return mesh;
}

} // namespace bad_input

#endif
