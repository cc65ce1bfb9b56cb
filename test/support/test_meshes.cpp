// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "test_meshes.h"

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <fstream>

namespace tvf_test {

Mesh make_mesh(const std::vector<Point_3>& points, const std::vector<std::array<int, 3>>& triangles)
{
  Mesh mesh;
  std::vector<Vertex_index> v;
  for(const Point_3& p : points) v.push_back(mesh.add_vertex(p));
  for(const auto& t : triangles)
    if(mesh.add_face(v[t[0]], v[t[1]], v[t[2]]) == Mesh::null_face()) throw std::runtime_error("make_mesh: bad face");
  return mesh;
}

Mesh make_icosphere(int levels)
{
  const double t = (1 + std::sqrt(5.0)) / 2;
  std::vector<Point_3> p = {{-1, t, 0}, {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                            {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<int, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  auto normalized = [](const Point_3& q) {
    const double n = std::sqrt(q.x() * q.x() + q.y() * q.y() + q.z() * q.z());
    return Point_3(q.x() / n, q.y() / n, q.z() / n);
  };
  for(Point_3& q : p) q = normalized(q);
  for(int l = 0; l < levels; ++l)
  {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = midpoint.find(key);
      if(it != midpoint.end()) return it->second;
      p.push_back(normalized(CGAL::midpoint(p[a], p[b])));
      return midpoint[key] = static_cast<int>(p.size()) - 1;
    };
    std::vector<std::array<int, 3>> g;
    for(const auto& t3 : f)
    {
      const int a = mid(t3[0], t3[1]), b = mid(t3[1], t3[2]), c = mid(t3[2], t3[0]);
      g.push_back({t3[0], a, c});
      g.push_back({t3[1], b, a});
      g.push_back({t3[2], c, b});
      g.push_back({a, b, c});
    }
    f = std::move(g);
  }
  return make_mesh(p, f);
}

Mesh make_torus(int n, int m, double R, double r, double jitter, unsigned seed)
{
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  std::vector<Point_3> p;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j)
    {
      const double a = 2 * M_PI * (i + u(gen)) / n, b = 2 * M_PI * (j + u(gen)) / m;
      p.emplace_back((R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a), r * std::sin(b));
    }
  std::vector<std::array<int, 3>> f;
  auto id = [&](int i, int j) { return ((i + n) % n) * m + (j + m) % m; };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j)
    {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if((i + j) % 3 == 0)
      {
        f.push_back({a, b, d});
        f.push_back({b, c, d});
      }
      else
      {
        f.push_back({a, b, c});
        f.push_back({a, c, d});
      }
    }
  return make_mesh(p, f);
}

Mesh make_disk(int rings, double hole_radius, double jitter, unsigned seed)
{
  // Rings of vertices at radius hole + (1 - hole) k / rings; ring k has 6k
  // vertices (or a fixed count for an annulus), joined by triangle strips.
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  std::vector<Point_3> p;
  std::vector<std::vector<int>> ring;
  const bool annulus = hole_radius > 0;
  const int first = annulus ? 0 : 1;
  if(!annulus)
  {
    p.emplace_back(0, 0, 0);
    ring.push_back({0});
  }
  for(int k = first; k <= rings; ++k)
  {
    const int count = annulus ? 6 * (rings + 2) + 3 * k : 6 * k;
    const double rad = hole_radius + (1 - hole_radius) * k / rings;
    const bool on_boundary = k == rings || (annulus && k == 0);
    std::vector<int> ids;
    for(int i = 0; i < count; ++i)
    {
      const double dr = on_boundary ? 0 : u(gen) * (1 - hole_radius) / rings;
      const double a = 2 * M_PI * (i + u(gen)) / count;
      p.emplace_back((rad + dr) * std::cos(a), (rad + dr) * std::sin(a), 0);
      ids.push_back(static_cast<int>(p.size()) - 1);
    }
    ring.push_back(ids);
  }
  std::vector<std::array<int, 3>> f;
  for(std::size_t k = 0; k + 1 < ring.size(); ++k)
  {
    const auto& in = ring[k];
    const auto& out = ring[k + 1];
    if(in.size() == 1)
    {
      for(std::size_t i = 0; i < out.size(); ++i) f.push_back({in[0], out[i], out[(i + 1) % out.size()]});
      continue;
    }
    // Merge the two rings by angle: advance on whichever ring is behind.
    std::size_t i = 0, j = 0;
    const std::size_t ni = in.size(), no = out.size();
    while(i < ni || j < no)
    {
      const double ai = 2 * M_PI * (i + 0.5) / ni, aj = 2 * M_PI * (j + 0.5) / no;
      if(j < no && (i >= ni || aj < ai))
      {
        f.push_back({in[i % ni], out[j % no], out[(j + 1) % no]});
        ++j;
      }
      else
      {
        f.push_back({in[i % ni], out[j % no], in[(i + 1) % ni]});
        ++i;
      }
    }
  }
  return make_mesh(p, f);
}

Mesh make_curved_disk(int rings, double hole_radius)
{
  Mesh mesh = make_disk(rings, hole_radius);
  for(Vertex_index v : mesh.vertices())
  {
    const Point_3& q = mesh.point(v);
    mesh.point(v) = Point_3(q.x(), q.y(), 0.3 * std::sin(2 * q.x()) * std::cos(3 * q.y()));
  }
  return mesh;
}

void transform(Mesh& mesh, double s, const std::array<double, 9>& R, const Vector_3& t)
{
  for(Vertex_index v : mesh.vertices())
  {
    const Point_3& q = mesh.point(v);
    mesh.point(v) = Point_3(s * (R[0] * q.x() + R[1] * q.y() + R[2] * q.z()) + t.x(),
                            s * (R[3] * q.x() + R[4] * q.y() + R[5] * q.z()) + t.y(),
                            s * (R[6] * q.x() + R[7] * q.y() + R[8] * q.z()) + t.z());
  }
}

std::array<double, 9> rotation_matrix(Vector_3 axis, double angle)
{
  axis = axis / std::sqrt(axis.squared_length());
  const double c = std::cos(angle), s = std::sin(angle), x = axis.x(), y = axis.y(), z = axis.z();
  return {c + x * x * (1 - c),     x * y * (1 - c) - z * s, x * z * (1 - c) + y * s,
          y * x * (1 - c) + z * s, c + y * y * (1 - c),     y * z * (1 - c) - x * s,
          z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c)};
}

void jitter_vertices(Mesh& mesh, double amount, unsigned seed)
{
  double total = 0;
  for(Edge_index e : mesh.edges())
    total += std::sqrt(CGAL::squared_distance(mesh.point(mesh.vertex(e, 0)), mesh.point(mesh.vertex(e, 1))));
  const double h = amount * total / mesh.number_of_edges();
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  for(Vertex_index v : mesh.vertices()) mesh.point(v) = mesh.point(v) + Vector_3(u(gen), u(gen), u(gen)) * (h / 2);
}

std::string cgal_data_dir()
{
#ifdef TVF_CGAL_DATA_DIR
  std::ifstream probe(std::string(TVF_CGAL_DATA_DIR) + "/meshes/elephant.off");
  if(probe) return TVF_CGAL_DATA_DIR;
#endif
  return "";
}

std::string cgal_data_missing()
{
#ifdef TVF_CGAL_DATA_DIR
  const std::string where = TVF_CGAL_DATA_DIR;
#else
  const std::string where = "(no TVF_CGAL_DATA_DIR)";
#endif
  return "SKIPPED: CGAL's data tree is not at " + where +
         " (unpacked at configure time from /usr/share/doc/libcgal-dev/data.tar.gz; Debian: libcgal-dev, "
         "or libcgal-demo in older releases). This test needs real meshes; CI refuses to configure without them.";
}

std::string shared_data_dir()
{
#ifdef TVF_SHARED_DATA_DIR
  std::ifstream probe(std::string(TVF_SHARED_DATA_DIR) + "/README.md");
  if(probe) return TVF_SHARED_DATA_DIR;
#endif
  return "";
}

bool read_mesh(const std::string& path, Mesh& mesh)
{
  mesh.clear();
  return CGAL::IO::read_polygon_mesh(path, mesh, CGAL::parameters::verbose(false)) && !is_empty(mesh);
}

std::vector<Vector_3> ambient_linear_field(const Mesh& mesh, unsigned seed)
{
  std::mt19937 gen(seed);
  std::normal_distribution<double> n;
  double B[3][3], a[3];
  for(int i = 0; i < 3; ++i)
  {
    a[i] = n(gen);
    for(int j = 0; j < 3; ++j) B[i][j] = n(gen);
  }
  std::vector<Vector_3> out;
  for(Face_index f : mesh.faces())
  {
    double c[3] = {0, 0, 0};
    for(Vertex_index v : vertices_around_face(mesh.halfedge(f), mesh))
    {
      c[0] += mesh.point(v).x() / 3;
      c[1] += mesh.point(v).y() / 3;
      c[2] += mesh.point(v).z() / 3;
    }
    double w[3];
    for(int i = 0; i < 3; ++i) w[i] = a[i] + B[i][0] * c[0] + B[i][1] * c[1] + B[i][2] * c[2];
    out.emplace_back(w[0], w[1], w[2]);
  }
  return out;
}

Mesh::Property_map<Face_index, Vector_3> ambient_field_map(Mesh& mesh, const std::string& name, unsigned seed)
{
  auto map = mesh.add_property_map<Face_index, Vector_3>("f:" + name, Vector_3(0, 0, 0)).first;
  const std::vector<Vector_3> values = ambient_linear_field(mesh, seed);
  for(Face_index f : mesh.faces()) map[f] = values[std::size_t(f)];
  return map;
}

double largest_relative_difference(const std::vector<Vector_3>& a, const std::vector<Vector_3>& b)
{
  double d = 0, n = 0;
  for(std::size_t f = 0; f < a.size() && f < b.size(); ++f)
  {
    d = std::max(d, std::sqrt((a[f] - b[f]).squared_length()));
    n = std::max(n, std::sqrt(b[f].squared_length()));
  }
  return a.size() == b.size() ? d / n : HUGE_VAL;
}

Eigen::VectorXd random_field(int number_of_faces, unsigned seed)
{
  std::mt19937 gen(seed);
  std::normal_distribution<double> N;
  Eigen::VectorXd v(2 * number_of_faces);
  for(Eigen::Index i = 0; i < v.size(); ++i) v[i] = N(gen);
  return v;
}

Polygon_soup mesh_to_soup(const Mesh& mesh)
{
  Polygon_soup soup;
  for(Vertex_index v : mesh.vertices()) soup.points.push_back(mesh.point(v));
  for(Face_index f : mesh.faces())
  {
    soup.polygons.emplace_back();
    for(Vertex_index v : vertices_around_face(mesh.halfedge(f), mesh)) soup.polygons.back().push_back(std::size_t(v));
  }
  return soup;
}

Polygon_soup make_quad_torus(int n, int m, double R, double r)
{
  Polygon_soup soup;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j)
    {
      const double u = 2 * M_PI * i / n, w = 2 * M_PI * j / m;
      soup.points.emplace_back((R + r * std::cos(w)) * std::cos(u), (R + r * std::cos(w)) * std::sin(u), r * std::sin(w));
    }
  auto id = [&](int i, int j) { return std::size_t(((i + n) % n) * m + (j + m) % m); };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j) soup.polygons.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return soup;
}

Polygon_soup shuffled_orientation_soup(const Mesh& mesh, unsigned seed, std::vector<bool>& reversed)
{
  Polygon_soup soup = mesh_to_soup(mesh);
  std::mt19937 gen(seed);
  std::bernoulli_distribution coin(0.5);
  reversed.assign(soup.polygons.size(), false);
  for(std::size_t i = 1; i < soup.polygons.size(); ++i)
    if(coin(gen))
    {
      std::reverse(soup.polygons[i].begin(), soup.polygons[i].end());
      reversed[i] = true;
    }
  return soup;
}

Polygon_soup make_double_cone(int n)
{
  Polygon_soup soup;
  soup.points.emplace_back(0, 0, 0);
  for(int side = 0; side < 2; ++side)
  {
    const std::size_t first = soup.points.size();
    for(int k = 0; k < n; ++k)
    {
      const double a = 2 * M_PI * k / n;
      soup.points.emplace_back(std::cos(a), std::sin(a), side == 0 ? 1 : -1);
    }
    for(int k = 0; k < n; ++k)
    {
      const std::size_t b = first + std::size_t(k), c = first + std::size_t((k + 1) % n);
      soup.polygons.push_back(side == 0 ? std::vector<std::size_t>{0, b, c} : std::vector<std::size_t>{0, c, b});
    }
  }
  return soup;
}

Polygon_soup make_moebius_strip(int n)
{
  // Points (i, s) for s = -1, +1 across the strip; after a full turn the sides swap.
  Polygon_soup soup;
  for(int i = 0; i < n; ++i)
    for(int s : {-1, 1})
    {
      const double u = 2 * M_PI * i / n, w = 0.3 * s;
      soup.points.emplace_back((1 + w * std::cos(u / 2)) * std::cos(u), (1 + w * std::cos(u / 2)) * std::sin(u),
                               w * std::sin(u / 2));
    }
  for(int i = 0; i < n; ++i)
  {
    const std::size_t a = std::size_t(2 * i), b = a + 1;
    const bool wrap = i + 1 == n;
    const std::size_t c = wrap ? 1 : a + 2, d = wrap ? 0 : a + 3; // the twist: side -1 meets side +1
    soup.polygons.push_back({a, c, d});
    soup.polygons.push_back({a, d, b});
  }
  return soup;
}

} // namespace tvf_test

namespace tvf_test {

namespace {

// The cotangent of the angle at corner `c` of triangle (a, b, c).
double cotangent_at(const Point_3& a, const Point_3& b, const Point_3& c)
{
  const Vector_3 u = a - c, v = b - c;
  return (u * v) / std::sqrt(CGAL::cross_product(u, v).squared_length());
}

typedef std::vector<Eigen::Triplet<double>> Triplets;

// Assembles a stiffness and a lumped mass over the faces: corner k of a face stands for the
// unknown `unknown(corners, k)` (-1: none, the row and column are dropped), whose basis
// function's gradient is `scale` times that of corner k's hat function.  So the stiffness
// between two corners is `scale^2` times the P1 one, -cot/2 of the third corner; each unknown
// gets a third of the area of its faces as mass.
template <class Unknown>
Sparse_eigenproblem assemble(const Mesh& mesh, int n, double scale, const Unknown& unknown)
{
  Sparse_eigenproblem p;
  p.d = Eigen::VectorXd::Zero(n);
  Triplets t;
  for(Face_index f : mesh.faces())
  {
    std::array<Vertex_index, 3> v;
    int k = 0;
    for(Vertex_index x : vertices_around_face(mesh.halfedge(f), mesh)) v[k++] = x;
    std::array<Point_3, 3> q;
    std::array<int, 3> idx;
    for(k = 0; k < 3; ++k) q[k] = mesh.point(v[k]), idx[k] = unknown(v, k);
    const double area = 0.5 * std::sqrt(CGAL::cross_product(q[1] - q[0], q[2] - q[0]).squared_length());
    for(k = 0; k < 3; ++k)
    {
      if(idx[k] >= 0) p.d[idx[k]] += area / 3;
      // The pair (i, j) facing corner k; a dropped unknown takes its entries with it, but its
      // partner keeps its diagonal (a function that vanishes there, not a missing face).
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      const double w = 0.5 * scale * scale * cotangent_at(q[i], q[j], q[k]);
      if(idx[i] >= 0) t.emplace_back(idx[i], idx[i], w);
      if(idx[j] >= 0) t.emplace_back(idx[j], idx[j], w);
      if(idx[i] >= 0 && idx[j] >= 0)
      {
        t.emplace_back(idx[i], idx[j], -w);
        t.emplace_back(idx[j], idx[i], -w);
      }
    }
  }
  p.A.resize(n, n);
  p.A.setFromTriplets(t.begin(), t.end());
  return p;
}

} // namespace

Sparse_eigenproblem cotan_vertex_problem(const Mesh& mesh)
{
  const int n = int(mesh.number_of_vertices());
  Sparse_eigenproblem p = assemble(mesh, n, 1.0, [](const std::array<Vertex_index, 3>& v, int k) { return int(v[k]); });
  p.kernel = Eigen::MatrixXd::Ones(n, 1);
  return p;
}

Sparse_eigenproblem crouzeix_raviart_edge_problem(const Mesh& mesh)
{
  // Interior edges numbered in edge order; boundary edges get -1 and are dropped.
  std::vector<int> interior(mesh.number_of_edges(), -1);
  int n = 0;
  for(Edge_index e : mesh.edges())
    if(!mesh.is_border(e)) interior[std::size_t(e)] = n++;
  // The edge opposite corner k joins the other two corners; its function 1 - 2 lambda_k has
  // -2 times the gradient of corner k's hat function.
  Sparse_eigenproblem p = assemble(mesh, n, 2.0, [&](const std::array<Vertex_index, 3>& v, int k) {
    return interior[std::size_t(mesh.edge(mesh.halfedge(v[(k + 1) % 3], v[(k + 2) % 3])))];
  });
  const bool closed = n == int(mesh.number_of_edges());
  p.kernel = closed ? Eigen::MatrixXd::Ones(n, 1) : Eigen::MatrixXd(n, 0);
  return p;
}

Mesh_counts count_topology(const Mesh& mesh)
{
  Mesh_counts c;
  Mesh scratch = mesh; // for the component map, so that the caller's mesh is not touched
  auto component = scratch.add_property_map<Face_index, std::size_t>("f:component", 0).first;
  c.components = int(CGAL::Polygon_mesh_processing::connected_components(scratch, component));
  std::vector<Mesh::Halfedge_index> cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(scratch, std::back_inserter(cycles));
  c.boundary_loops = int(cycles.size());
  const int chi = int(mesh.number_of_vertices()) - int(mesh.number_of_edges()) + int(mesh.number_of_faces());
  c.genus = (2 * c.components - c.boundary_loops - chi) / 2;
  return c;
}

} // namespace tvf_test
