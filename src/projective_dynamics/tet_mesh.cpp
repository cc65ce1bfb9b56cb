// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Checks of tetrahedral meshes, their boundary and edges, and the meshes made in code.

#include <CGAL/Projective_dynamics/Tet_mesh.h>
#include <CGAL/Projective_dynamics/errors.h>
#include <CGAL/Projective_dynamics/mesh_generators.h>

#include "element_indices.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

namespace CGAL {
namespace Projective_dynamics {

namespace {
std::array<double, 3> minus(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
std::array<double, 3> cross(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const std::array<double, 3>& a, const std::array<double, 3>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double squared_length(const std::array<double, 3>& a) { return dot(a, a); }
} // namespace

double signed_volume(const std::vector<Point>& p, const Tetrahedron& t)
{
  return dot(cross(minus(p[t[1]], p[t[0]]), minus(p[t[2]], p[t[0]])), minus(p[t[3]], p[t[0]])) / 6;
}

void check_tet_mesh(const Tet_mesh& mesh)
{
  if(mesh.points.empty() || mesh.tetrahedra.empty())
    throw Invalid_mesh(Mesh_defect::empty, "the tetrahedral mesh is empty (" + std::to_string(mesh.points.size()) +
                                               " vertices, " + std::to_string(mesh.tetrahedra.size()) + " tetrahedra)");
  const int n = int(mesh.points.size());
  for(int v = 0; v < n; ++v)
    for(double c : mesh.points[v])
      if(!std::isfinite(c))
        throw Invalid_mesh(Mesh_defect::non_finite_coordinate, "vertex " + std::to_string(v) + " has a non-finite coordinate");
  auto check_indices = [n](const int* v, int count, const char* kind, std::size_t index) {
    internal::check_element_indices(v, count, n, kind, index);
  };
  for(std::size_t t = 0; t < mesh.tetrahedra.size(); ++t)
  {
    const Tetrahedron& tet = mesh.tetrahedra[t];
    check_indices(tet.data(), 4, "tetrahedron", t);
    double longest = 0;
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
        longest = std::max(longest, squared_length(minus(mesh.points[tet[i]], mesh.points[tet[j]])));
    longest = std::sqrt(longest);
    // 1e-12: far above the rounding of the triple product (~1e-16 longest^3), far below any
    // tetrahedron a mesher makes on purpose (a sliver of volume 1e-6 longest^3 is still accepted).
    if(!(std::abs(signed_volume(mesh.points, tet)) > 1e-12 * longest * longest * longest))
      throw Invalid_mesh(Mesh_defect::degenerate_face,
                         "tetrahedron " + std::to_string(t) + " has (nearly) zero volume");
  }
  for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
    check_indices(mesh.triangles[f].data(), 3, "triangle", f);
}

std::vector<Triangle> boundary_triangles(const std::vector<Point>& points, const std::vector<Tetrahedron>& tets)
{
  // Every face as (sorted vertices, tetrahedron, opposite corner); faces listed once are boundary.
  std::vector<std::tuple<std::array<int, 3>, int, int>> faces;
  faces.reserve(4 * tets.size());
  for(std::size_t t = 0; t < tets.size(); ++t)
    for(int o = 0; o < 4; ++o)
    {
      std::array<int, 3> f;
      for(int i = 0, k = 0; i < 4; ++i)
        if(i != o) f[k++] = tets[t][i];
      std::sort(f.begin(), f.end());
      faces.emplace_back(f, int(t), o);
    }
  std::sort(faces.begin(), faces.end());
  std::vector<Triangle> boundary;
  for(std::size_t i = 0; i < faces.size();)
  {
    std::size_t j = i + 1;
    while(j < faces.size() && std::get<0>(faces[j]) == std::get<0>(faces[i])) ++j;
    if(j == i + 1)
    {
      Triangle f = std::get<0>(faces[i]);
      const Point& opposite = points[tets[std::get<1>(faces[i])][std::get<2>(faces[i])]];
      // Outward: the opposite corner lies behind the face's normal.
      if(dot(cross(minus(points[f[1]], points[f[0]]), minus(points[f[2]], points[f[0]])), minus(opposite, points[f[0]])) > 0)
        std::swap(f[1], f[2]);
      boundary.push_back(f);
    }
    i = j;
  }
  return boundary;
}

namespace {
template <std::size_t N>
std::vector<Edge> edges_of(const std::vector<std::array<int, N>>& cells)
{
  std::vector<Edge> edges;
  edges.reserve(cells.size() * N * (N - 1) / 2);
  for(const auto& c : cells)
    for(std::size_t i = 0; i < N; ++i)
      for(std::size_t j = i + 1; j < N; ++j)
        edges.push_back({std::min(c[i], c[j]), std::max(c[i], c[j])});
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}
} // namespace

std::vector<Edge> unique_edges(const std::vector<Tetrahedron>& tets) { return edges_of(tets); }
std::vector<Edge> unique_edges(const std::vector<Triangle>& triangles) { return edges_of(triangles); }

Tet_mesh make_tet_box(int nx, int ny, int nz, const Point& min, const Point& max)
{
  if(nx < 1 || ny < 1 || nz < 1)
    throw Invalid_input("a tetrahedral box needs at least one cell in each direction, not " + std::to_string(nx) + " x " +
                        std::to_string(ny) + " x " + std::to_string(nz));
  for(int c = 0; c < 3; ++c)
    if(!(min[c] < max[c]))
      throw Invalid_input("a tetrahedral box needs min < max in every coordinate (coordinate " + std::to_string(c) + ")");
  Tet_mesh mesh;
  const int n[3] = {nx, ny, nz};
  auto index = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  mesh.points.resize(std::size_t(nx + 1) * (ny + 1) * (nz + 1));
  for(int k = 0; k <= nz; ++k)
    for(int j = 0; j <= ny; ++j)
      for(int i = 0; i <= nx; ++i)
      {
        const int ijk[3] = {i, j, k};
        Point& p = mesh.points[index(i, j, k)];
        for(int c = 0; c < 3; ++c) p[c] = min[c] + (max[c] - min[c]) * ijk[c] / n[c];
      }
  // Freudenthal (Kuhn) subdivision: one tetrahedron per order of the axes, each a monotone path
  // from corner (0,0,0) to (1,1,1) of the cube; every cube is cut the same way, so faces match.
  static const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  mesh.tetrahedra.reserve(std::size_t(6) * nx * ny * nz);
  for(int k = 0; k < nz; ++k)
    for(int j = 0; j < ny; ++j)
      for(int i = 0; i < nx; ++i)
        for(const auto& order : orders)
        {
          int c[3] = {i, j, k};
          Tetrahedron t;
          t[0] = index(c[0], c[1], c[2]);
          for(int s = 0; s < 3; ++s)
          {
            ++c[order[s]];
            t[s + 1] = index(c[0], c[1], c[2]);
          }
          if(signed_volume(mesh.points, t) < 0) std::swap(t[2], t[3]);
          mesh.tetrahedra.push_back(t);
        }
  mesh.triangles = boundary_triangles(mesh.points, mesh.tetrahedra);
  return mesh;
}

Tet_mesh make_tet_rod(int cells, int cells_across, double length, double width)
{
  return make_tet_box(cells, cells_across, cells_across, {0, 0, 0}, {length, width, width});
}

Spring_chain make_spring_chain(int springs, double spacing, const Point& top, const Point& axis)
{
  if(springs < 1 || !(spacing > 0))
    throw Invalid_input("a spring chain needs at least one spring and a positive spacing");
  const double a = std::sqrt(squared_length(axis));
  if(!(a > 0)) throw Invalid_input("a spring chain needs a non-zero axis");
  Spring_chain chain;
  for(int i = 0; i <= springs; ++i)
    chain.points.push_back({top[0] - i * spacing * axis[0] / a, top[1] - i * spacing * axis[1] / a,
                            top[2] - i * spacing * axis[2] / a});
  for(int i = 0; i < springs; ++i) chain.edges.push_back({i, i + 1});
  return chain;
}

} // namespace Projective_dynamics
} // namespace CGAL
