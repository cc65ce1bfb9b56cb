// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Seeing fields: exact streamlines (on the surface, along the field, continuous
// across edges, stopping where they should), evenly spaced seeding and fur.  The export
// formats, charts and pictures are in test_exports_and_pictures.cpp.

#include "expect_reason.h"
#include "test_meshes.h"
#include "visual_test_support.h"

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>
#include <CGAL/Tangent_vector_fields/Streamlines.h>
#include <CGAL/Tangent_vector_fields/field_export.h>
#include <CGAL/Model_reduction/svg_chart.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <fstream>
#include <sstream>
#include <cmath>
#include <random>
#include <set>

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;

namespace {

P3 sub(const P3& a, const P3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
P3 cross(const P3& a, const P3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const P3& a) { return std::sqrt(dot(a, a)); }

// Counts of what the geometric checks saw.
struct Seen
{
  int segments = 0, edge_crossings = 0, vertex_passes = 0, tiny_segments = 0;
};

// Every point on its face (in its plane and inside the triangle), every segment
// along its face vector, consecutive faces meeting on an edge (point on it) or at a
// vertex (point on it).
void expect_valid_streamline(const TVF::Intrinsic_mesh& M, const Eigen::VectorXd& x, const TVF::Streamline& s,
                             Seen& seen)
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
    const double size = std::max({M.face_edge_length(f, 0), M.face_edge_length(f, 1), M.face_edge_length(f, 2)});
    EXPECT_LE(std::abs(dot(d, M.normal(f))), 1e-9 * size) << "point " << i << " off the plane of face " << f;
    // Barycentric coordinates from signed areas in the plane.
    const P3 p1 = sub(M.position(t[1]), M.position(t[0])), p2 = sub(M.position(t[2]), M.position(t[0]));
    const double area2 = dot(cross(p1, p2), M.normal(f));
    const double b1 = dot(cross(d, p2), M.normal(f)) / area2, b2 = dot(cross(p1, d), M.normal(f)) / area2;
    EXPECT_GE(b1, -1e-9);
    EXPECT_GE(b2, -1e-9);
    EXPECT_GE(1 - b1 - b2, -1e-9) << "point " << i << " outside face " << f;
  }
  for(std::size_t i = 0; i + 1 < s.points.size(); ++i)
  {
    ++seen.segments;
    const int f = s.faces[i];
    const P3 seg = sub(s.points[i + 1], s.points[i]);
    const P3 v = M.from_frame(f, x[2 * f], x[2 * f + 1]);
    const double ls = norm(seg), lv = norm(v);
    if(ls < 1e-9 * h)
      ++seen.tiny_segments;
    else
    {
      EXPECT_LE(norm(cross(seg, v)), 1e-9 * ls * lv) << "segment " << i << " not parallel to the field of face " << f;
      EXPECT_GT(dot(seg, v), 0) << "segment " << i << " runs against the field";
    }
    if(i + 1 < s.number_of_segments() && s.faces[i + 1] != f)
    {
      const int g = s.faces[i + 1];
      std::vector<int> shared;
      for(int a : M.face_vertices(f))
        for(int b : M.face_vertices(g))
          if(a == b) shared.push_back(a);
      const P3& q = s.points[i + 1];
      if(shared.size() == 2)
      {
        ++seen.edge_crossings;
        const P3 a = M.position(shared[0]), e = sub(M.position(shared[1]), a);
        const double u = dot(sub(q, a), e) / dot(e, e);
        EXPECT_GE(u, -1e-12);
        EXPECT_LE(u, 1 + 1e-12);
        EXPECT_LE(norm(cross(sub(q, a), e)) / norm(e), 1e-12 * h) << "crossing point off the shared edge";
      }
      else
      {
        ASSERT_EQ(shared.size(), 1u) << "faces " << f << " and " << g << " are not neighbours";
        ++seen.vertex_passes;
        EXPECT_EQ(q, M.position(shared[0])) << "passage from face " << f << " to " << g << " not on their vertex";
      }
    }
  }
}

std::vector<std::pair<Face_index, Point_3>> random_seeds(const Mesh& mesh, int count, unsigned seed)
{
  std::mt19937 gen(seed);
  std::uniform_int_distribution<int> pick(0, static_cast<int>(mesh.number_of_faces()) - 1);
  std::uniform_real_distribution<double> u(0.05, 0.9);
  std::vector<std::pair<Face_index, Point_3>> seeds;
  for(int i = 0; i < count; ++i)
  {
    const Face_index f(pick(gen));
    std::vector<Point_3> p;
    for(Vertex_index v : vertices_around_face(mesh.halfedge(f), mesh)) p.push_back(mesh.point(v));
    const double a = u(gen), b = u(gen) * (1 - a);
    seeds.emplace_back(f, p[0] + a * (p[1] - p[0]) + b * (p[2] - p[0]));
  }
  return seeds;
}

} // namespace

TEST(Streamlines, StayOnTheSurfaceFollowTheFieldAndCrossOnSharedEdges)
{
  std::vector<std::pair<std::string, Mesh>> meshes;
  Mesh sphere = make_icosphere(3);
  jitter_vertices(sphere, 0.2, 3);
  meshes.emplace_back("jittered icosphere", sphere);
  meshes.emplace_back("irregular torus", make_torus(30, 14));
  meshes.emplace_back("curved annulus", make_curved_disk(8, 0.3));
  for(auto& named : meshes)
  {
    SCOPED_TRACE(named.first);
    Mesh& mesh = named.second;
    Field field = ambient_field_map(mesh, "wind", 5);
    TVF::Mesh_streamline_tracer<Mesh> tracer(mesh, field);
    const TVF::Intrinsic_mesh& M = tracer.tracer().mesh();
    const Eigen::VectorXd x = tracer.adapter().read_field(field);
    Seen seen;
    for(const auto& seed : random_seeds(mesh, 40, 11))
    {
      const TVF::Streamline s = tracer.trace(seed.first, seed.second);
      ASSERT_GE(s.points.size(), 2u);
      // The seed is kept (projected onto its face).
      EXPECT_LT(norm(sub(s.points[s.seed_index], {seed.second.x(), seed.second.y(), seed.second.z()})), 1e-12);
      EXPECT_EQ(s.faces[s.seed_index], static_cast<int>(std::size_t(seed.first)));
      expect_valid_streamline(M, x, s, seen);
    }
    TVF::Evenly_spaced_options even;
    even.separation = 0.05;
    for(const TVF::Streamline& s : tracer.evenly_spaced(even)) expect_valid_streamline(M, x, s, seen);
    EXPECT_GT(seen.edge_crossings, 1000);
    EXPECT_LT(seen.tiny_segments, seen.segments / 1000 + 1);
  }
}

TEST(Streamlines, PassThroughVerticesHitExactly)
{
  // A regular grid in the plane, cut along the diagonals (i, j)-(i+1, j+1); the field
  // (2, 1) carries the streamline from (0.5, 0.25) exactly through the vertices (2k, k).
  std::vector<Point_3> p;
  std::vector<std::array<int, 3>> t;
  const int n = 12;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i) p.emplace_back(i, j, 0);
  auto id = [&](int i, int j) { return j * (n + 1) + i; };
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
    {
      t.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  Mesh mesh = make_mesh(p, t);
  Field field = field_map(mesh, "diagonal");
  for(Face_index f : mesh.faces()) field[f] = Vector_3(2, 1, 0);
  TVF::Mesh_streamline_tracer<Mesh> tracer(mesh, field);
  const Face_index start(0); // triangle (0,0), (1,0), (1,1)
  const TVF::Streamline s = tracer.trace(start, Point_3(0.5, 0.25, 0));
  Seen seen;
  expect_valid_streamline(tracer.tracer().mesh(), tracer.adapter().read_field(field), s, seen);
  EXPECT_EQ(s.forward_stop, TVF::Streamline_stop::boundary);
  EXPECT_EQ(s.backward_stop, TVF::Streamline_stop::boundary);
  for(const P3& q : s.points) EXPECT_NEAR(q[1], q[0] / 2, 1e-12);
  EXPECT_EQ(s.points.front(), (P3{0, 0, 0})); // backward it ends on the corner vertex
  EXPECT_NEAR(s.points.back()[0], 12, 1e-12);
  EXPECT_NEAR(s.points.back()[1], 6, 1e-12);
  EXPECT_EQ(seen.vertex_passes, 5); // (2,1), (4,2), (6,3), (8,4), (10,5)
}

TEST(Streamlines, StopAtTheBoundaryOfADisk)
{
  Mesh disk = make_disk(10);
  Field outward = field_map(disk, "outward");
  Field constant = field_map(disk, "constant");
  for(Face_index f : disk.faces())
  {
    const Point_3 c = CGAL::centroid(disk.point(disk.source(disk.halfedge(f))), disk.point(disk.target(disk.halfedge(f))),
                                     disk.point(disk.target(disk.next(disk.halfedge(f)))));
    outward[f] = c - CGAL::ORIGIN;
    constant[f] = Vector_3(1, 0.2, 0);
  }
  for(int which = 0; which < 2; ++which)
  {
    SCOPED_TRACE(which == 0 ? "outward field" : "constant field");
    const Field field = which == 0 ? outward : constant;
    TVF::Mesh_streamline_tracer<Mesh> tracer(disk, field);
    const TVF::Intrinsic_mesh& M = tracer.tracer().mesh();
    Seen seen;
    for(const auto& seed : random_seeds(disk, 30, 4))
    {
      const TVF::Streamline s = tracer.trace(seed.first, seed.second);
      expect_valid_streamline(M, tracer.adapter().read_field(field), s, seen);
      EXPECT_EQ(s.forward_stop, TVF::Streamline_stop::boundary);
      const P3& end = s.points.back();
      const double r = std::hypot(end[0], end[1]);
      EXPECT_GE(r, 0.99); // the boundary polygon's vertices are on the unit circle
      EXPECT_LE(r, 1 + 1e-12);
      // The last face has a boundary edge, and the end point lies on it.
      bool on_boundary_edge = false;
      for(int e : M.face_edges(s.faces.back()))
        if(M.is_boundary_edge(e))
        {
          const P3 a = M.position(M.edge_vertices(e)[0]), b = M.position(M.edge_vertices(e)[1]);
          if(norm(cross(sub(end, a), sub(b, a))) <= 1e-12 * norm(sub(b, a))) on_boundary_edge = true;
        }
      EXPECT_TRUE(on_boundary_edge);
      if(which == 1) EXPECT_EQ(s.backward_stop, TVF::Streamline_stop::boundary);
    }
  }
}

TEST(Streamlines, StopAtSinksInsteadOfZigZagging)
{
  // -grad of the (piecewise-linear) distance to q flows downhill towards q: each
  // streamline ends where the flow converges, on a sink edge (the face beyond points
  // back across it) or a sink vertex, after a handful of segments.
  struct Case
  {
    std::string name;
    Mesh mesh;
    Point_3 q;
  };
  std::vector<Case> cases;
  cases.push_back({"disk, q at the centre vertex", make_disk(10), Point_3(0, 0, 0)});
  cases.push_back({"disk, q inside a face", make_disk(10), Point_3(0.313, -0.271, 0)});
  cases.push_back({"sphere, q at the north pole", make_icosphere(3), Point_3(0, 0, 1)});
  for(Case& c : cases)
  {
    SCOPED_TRACE(c.name);
    auto distance = c.mesh.add_property_map<Vertex_index, double>("v:distance", 0.).first;
    for(Vertex_index v : c.mesh.vertices()) distance[v] = -std::sqrt(CGAL::squared_distance(c.mesh.point(v), c.q));
    Field field = field_map(c.mesh, "downhill");
    TVF::Discrete_operators<Mesh>(c.mesh).gradient(distance, field); // grad of -distance
    TVF::Mesh_streamline_tracer<Mesh> tracer(c.mesh, field);
    const TVF::Intrinsic_mesh& M = tracer.tracer().mesh();
    const Eigen::VectorXd x = tracer.adapter().read_field(field);
    const double h = M.mean_edge_length();
    const P3 q = {c.q.x(), c.q.y(), c.q.z()};
    Seen seen;
    TVF::Streamline_options forward_only;
    forward_only.backward = false;
    int near_q = 0, count = 0;
    for(const auto& seed : random_seeds(c.mesh, 40, 9))
    {
      const TVF::Streamline s = tracer.trace(seed.first, seed.second, forward_only);
      expect_valid_streamline(M, x, s, seen);
      ++count;
      const P3& end = s.points.back();
      const double start_distance = norm(sub(s.points.front(), q));
      EXPECT_LT(static_cast<double>(s.number_of_segments()), 4 * start_distance / h + 10);
      near_q += norm(sub(end, q)) < 2 * h;
      if(s.forward_stop == TVF::Streamline_stop::sink_vertex)
      {
        bool on_vertex = false;
        for(int v : M.face_vertices(s.faces.back())) on_vertex = on_vertex || end == M.position(v);
        EXPECT_TRUE(on_vertex);
        continue;
      }
      ASSERT_EQ(s.forward_stop, TVF::Streamline_stop::sink_edge) << TVF::to_string(s.forward_stop);
      // The end lies on an edge of the last face, and the field of the face beyond
      // that edge points back across it.
      const int f = s.faces.back();
      int edge = -1;
      for(int e : M.face_edges(f))
      {
        const P3 a = M.position(M.edge_vertices(e)[0]), b = M.position(M.edge_vertices(e)[1]);
        if(norm(cross(sub(end, a), sub(b, a))) <= 1e-12 * norm(sub(b, a))) edge = e;
      }
      ASSERT_GE(edge, 0);
      const int g = M.edge_faces(edge)[0] == f ? M.edge_faces(edge)[1] : M.edge_faces(edge)[0];
      ASSERT_GE(g, 0);
      const P3 a = M.position(M.edge_vertices(edge)[0]), b = M.position(M.edge_vertices(edge)[1]);
      P3 inward = cross(M.normal(g), sub(b, a));
      int apex = 0;
      for(int v : M.face_vertices(g))
        if(v != M.edge_vertices(edge)[0] && v != M.edge_vertices(edge)[1]) apex = v;
      if(dot(inward, sub(M.position(apex), a)) < 0) inward = {-inward[0], -inward[1], -inward[2]};
      EXPECT_LE(dot(M.from_frame(g, x[2 * g], x[2 * g + 1]), inward), 0);
    }
    // Most flows end next to q (the rest in valleys of the interpolated distance).
    EXPECT_GT(near_q, count / 2);
  }
}

TEST(Streamlines, ClosedLoopsOfARotationalFieldAreDetected)
{
  // J grad z on a sphere and a torus: the streamlines are the level polygons of z.
  struct Case
  {
    std::string name;
    Mesh mesh;
    double z, perimeter; // level and the length of the smooth level circle
  };
  std::vector<Case> cases;
  Mesh sphere = make_icosphere(4);
  jitter_vertices(sphere, 0.1, 5);
  cases.push_back({"sphere", sphere, 0.5, 2 * M_PI * std::sqrt(0.75)});
  cases.push_back({"torus", make_torus(60, 30, 1.0, 0.4, 0.2), 0.2, 2 * M_PI * (1 + 0.4 * std::sqrt(0.75))});
  for(Case& c : cases)
  {
    SCOPED_TRACE(c.name);
    Field field = field_map(c.mesh, "rotation");
    rotated_height_gradient(c.mesh, field);
    TVF::Mesh_streamline_tracer<Mesh> tracer(c.mesh, field);
    const TVF::Intrinsic_mesh& M = tracer.tracer().mesh();
    // Seeds: the faces the level z crosses, on the outside of the torus.
    int tested = 0;
    Seen seen;
    for(Face_index f : c.mesh.faces())
    {
      std::vector<Point_3> p;
      for(Vertex_index v : vertices_around_face(c.mesh.halfedge(f), c.mesh)) p.push_back(c.mesh.point(v));
      const Point_3 m = CGAL::centroid(p[0], p[1], p[2]);
      const double lo = std::min({p[0].z(), p[1].z(), p[2].z()}), hi = std::max({p[0].z(), p[1].z(), p[2].z()});
      if(!(lo < c.z && c.z < hi) || std::hypot(m.x(), m.y()) < 0.75 || (tested++ % 7) != 0) continue;
      // The point of the face at height c.z on the segment between the centroid and a corner.
      const Point_3& a = p[0].z() < c.z == m.z() < c.z ? (p[1].z() < c.z == m.z() < c.z ? p[2] : p[1]) : p[0];
      const double u = (c.z - m.z()) / (a.z() - m.z());
      const Point_3 seed = m + u * (a - m);
      const TVF::Streamline s = tracer.trace(f, seed);
      expect_valid_streamline(M, tracer.adapter().read_field(field), s, seen);
      EXPECT_TRUE(s.closed) << TVF::to_string(s.forward_stop);
      EXPECT_EQ(s.forward_stop, TVF::Streamline_stop::closed_loop);
      EXPECT_EQ(s.backward_stop, TVF::Streamline_stop::none);
      EXPECT_LT(norm(sub(s.points.back(), s.points.front())), 1e-9);
      EXPECT_NEAR(s.length(), c.perimeter, 0.02 * c.perimeter);
      for(const P3& q : s.points) EXPECT_NEAR(q[2], c.z, 1e-12);
    }
    EXPECT_GT(tested, 7);
  }
}

TEST(Streamlines, EvenlySpacedLinesKeepTheirDistanceAndCoverTheSurface)
{
  Mesh sphere = make_icosphere(4);
  jitter_vertices(sphere, 0.2, 8);
  Field field = ambient_field_map(sphere, "wind", 12);
  TVF::Mesh_streamline_tracer<Mesh> tracer(sphere, field);
  TVF::Evenly_spaced_options options;
  options.separation = 0.08; // of the bounding-box diagonal (2 sqrt 3)
  const double separation = 0.08 * tracer.tracer().bounding_box_diagonal();
  const std::vector<TVF::Streamline> lines = tracer.evenly_spaced(options);
  ASSERT_GT(lines.size(), 10u);
  // Samples of every line, 0.1 separation apart.
  struct Sample
  {
    P3 p;
    std::size_t line;
  };
  std::vector<Sample> samples;
  for(std::size_t l = 0; l < lines.size(); ++l)
  {
    EXPECT_GE(lines[l].length(), separation * options.minimum_length_ratio);
    const auto& q = lines[l].points;
    for(std::size_t i = 0; i + 1 < q.size(); ++i)
    {
      const int k = 1 + static_cast<int>(norm(sub(q[i + 1], q[i])) / (0.1 * separation));
      for(int j = 0; j < k; ++j)
      {
        const double u = double(j) / k;
        samples.push_back({{q[i][0] + u * (q[i + 1][0] - q[i][0]), q[i][1] + u * (q[i + 1][1] - q[i][1]),
                            q[i][2] + u * (q[i + 1][2] - q[i][2])},
                           l});
      }
    }
  }
  // Separation: different lines never come much closer than the test distance.
  double closest = 1e300;
  for(std::size_t i = 0; i < samples.size(); ++i)
    for(std::size_t j = i + 1; j < samples.size(); ++j)
      if(samples[i].line != samples[j].line) closest = std::min(closest, norm(sub(samples[i].p, samples[j].p)));
  EXPECT_GT(closest, 0.4 * separation);
  // Coverage: random points of the sphere are near some line.
  std::mt19937 gen(3);
  std::normal_distribution<double> N;
  int far = 0;
  const int trials = 2000;
  for(int t = 0; t < trials; ++t)
  {
    P3 p = {N(gen), N(gen), N(gen)};
    const double r = norm(p);
    p = {p[0] / r, p[1] / r, p[2] / r};
    double d = 1e300;
    for(const Sample& s : samples) d = std::min(d, norm(sub(s.p, p)));
    if(d > 1.0 * separation) ++far;
  }
  EXPECT_LT(far, trials / 50);
  // Deterministic for a given random seed.
  const std::vector<TVF::Streamline> again = tracer.evenly_spaced(options);
  ASSERT_EQ(again.size(), lines.size());
  for(std::size_t l = 0; l < lines.size(); ++l) EXPECT_EQ(again[l].points, lines[l].points);
}

TEST(Streamlines, FurStrokesHaveTheRequestedCountLengthAndDirection)
{
  Mesh sphere = make_icosphere(3);
  Field field = field_map(sphere, "rotation");
  rotated_height_gradient(sphere, field);
  TVF::Mesh_streamline_tracer<Mesh> tracer(sphere, field);
  const TVF::Intrinsic_mesh& M = tracer.tracer().mesh();
  double area = 0;
  for(int f = 0; f < M.number_of_faces(); ++f) area += M.face_area(f);
  TVF::Fur_options fur;
  fur.length = 0.1;
  fur.length_unit = TVF::Length_unit::absolute;
  fur.density = 40;
  const std::vector<TVF::Streamline> strokes = tracer.fur(fur);
  EXPECT_NEAR(static_cast<double>(strokes.size()), 40 * area, 1.0);
  int full_length = 0;
  Seen seen;
  for(const TVF::Streamline& s : strokes)
  {
    expect_valid_streamline(M, tracer.adapter().read_field(field), s, seen);
    EXPECT_EQ(s.seed_index, 0u);
    EXPECT_EQ(s.backward_stop, TVF::Streamline_stop::none);
    EXPECT_LE(s.length(), 0.1 * (1 + 1e-9));
    if(s.forward_stop == TVF::Streamline_stop::maximum_length)
    {
      ++full_length;
      EXPECT_NEAR(s.length(), 0.1, 1e-9);
    }
  }
  EXPECT_GT(full_length, static_cast<int>(strokes.size()) * 95 / 100);
  // Scaled by magnitude: the rotational field is weakest near the poles.
  fur.scale_length_by_magnitude = true;
  fur.number_of_strokes = 300;
  const double largest = tracer.tracer().maximum_magnitude();
  const Eigen::VectorXd x = tracer.adapter().read_field(field);
  for(const TVF::Streamline& s : tracer.fur(fur))
  {
    const int f = s.faces.front();
    const double expected = 0.1 * std::hypot(x[2 * f], x[2 * f + 1]) / largest;
    EXPECT_LE(s.length(), expected * (1 + 1e-9));
  }
  // Roots are spread by area: about as many in each hemisphere.
  int north = 0;
  for(const TVF::Streamline& s : strokes) north += s.points.front()[2] > 0;
  EXPECT_NEAR(north, static_cast<double>(strokes.size()) / 2, 4 * std::sqrt(static_cast<double>(strokes.size())));
}

TEST(Streamlines, BadArgumentsAreRefused)
{
  Mesh sphere = make_icosphere(1);
  Field field = ambient_field_map(sphere, "wind", 1);
  TVF::Mesh_streamline_tracer<Mesh> tracer(sphere, field);
  EXPECT_THROW_REASON(tracer.tracer().trace(-1, {1, 0, 0}), TVF::Invalid_input, "streamline: face -1 does not exist");
  EXPECT_THROW_REASON(tracer.tracer().trace(0, {NAN, 0, 0}),
                      TVF::Invalid_input, "streamline: non-finite barycentric coordinates");
  TVF::Evenly_spaced_options bad;
  bad.separation = 0;
  EXPECT_THROW_REASON(tracer.evenly_spaced(bad),
                      TVF::Invalid_input, "evenly spaced streamlines: the separation must be positive");
  TVF::Fur_options no_count;
  EXPECT_THROW_REASON(tracer.fur(no_count),
                      TVF::Invalid_input, "fur: give number_of_strokes or a positive finite density");
  EXPECT_THROW_REASON(TVF::Streamline_tracer(tracer.adapter().intrinsic_mesh(), Eigen::VectorXd::Zero(3)),
                      TVF::Invalid_input, "streamlines: the field has 3 frame coordinates");
  // A zero field gives a streamline of one point.
  Field zero = field_map(sphere, "zero");
  const TVF::Streamline s = TVF::trace_streamline(sphere, zero, *sphere.faces().begin(), sphere.point(Vertex_index(0)));
  EXPECT_EQ(s.points.size(), 1u);
  EXPECT_EQ(s.forward_stop, TVF::Streamline_stop::zero_field);
}
