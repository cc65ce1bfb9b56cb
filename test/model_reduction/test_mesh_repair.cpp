// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Model_reduction::polygon_soup_to_mesh: polygon meshes triangulated, soups oriented, non-manifold
// vertices and edges cut apart, degenerate and duplicate polygons removed, each checked
// against what the soup was built to be (counts, Euler characteristic, orientation of
// every edge, the face map, the topology from CGAL's own functions); bad soups refused.

#include "test_meshes.h"

#include <CGAL/Model_reduction/polygon_soup_to_mesh.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include <dirent.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <set>

namespace MR = CGAL::Model_reduction;
using namespace tvf_test;

namespace {

typedef Mesh::Property_map<Face_index, std::size_t> Origin_map;

struct Repaired
{
  Mesh mesh;
  MR::Mesh_repair_report report;
  std::vector<std::size_t> origin; // per face, in face index order
};

Repaired repair(const Polygon_soup& soup)
{
  Repaired r;
  Origin_map origin = r.mesh.add_property_map<Face_index, std::size_t>("f:origin", 99999).first;
  r.report = MR::polygon_soup_to_mesh(soup.points, soup.polygons, r.mesh, MR::parameters::face_to_polygon_map(origin));
  for(Face_index f : r.mesh.faces()) r.origin.push_back(origin[f]);
  return r;
}

int euler_characteristic(const Mesh& m)
{
  return int(m.number_of_vertices()) - int(m.number_of_edges()) + int(m.number_of_faces());
}

// Directed edges (source, target point index) of every face, counted.
std::map<std::pair<std::size_t, std::size_t>, int> directed_edges(const Mesh& m)
{
  std::map<std::pair<std::size_t, std::size_t>, int> count;
  for(Face_index f : m.faces())
  {
    std::vector<std::size_t> v;
    for(Vertex_index x : vertices_around_face(m.halfedge(f), m)) v.push_back(std::size_t(x));
    for(std::size_t k = 0; k < v.size(); ++k) ++count[{v[k], v[(k + 1) % v.size()]}];
  }
  return count;
}

// How many triangles turn against the polygon they came from: a triangle's normal (from its
// corners in face order) against the polygon's Newell normal (from the soup's order).  To
// match the repair's count of reoriented polygons.  (Counting directed edges, as this check
// once did, could not fail: a halfedge structure holds each directed edge at most once.)
std::size_t turned_against_the_soup(const Repaired& r, const Polygon_soup& soup)
{
  std::size_t i = 0, turned = 0;
  for(Face_index f : r.mesh.faces())
  {
    const auto& polygon = soup.polygons[r.origin[i++]];
    Vector_3 newell(0, 0, 0);
    for(std::size_t k = 0; k < polygon.size(); ++k)
    {
      const Point_3 &a = soup.points[polygon[k]], &b = soup.points[polygon[(k + 1) % polygon.size()]];
      newell = newell + Vector_3((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
                                 (a.x() - b.x()) * (a.y() + b.y()));
    }
    std::vector<Point_3> p;
    for(Vertex_index x : vertices_around_face(r.mesh.halfedge(f), r.mesh)) p.push_back(r.mesh.point(x));
    EXPECT_EQ(p.size(), 3u);
    const Vector_3 normal = CGAL::cross_product(p[1] - p[0], p[2] - p[0]);
    // Planar polygons here: the normals are parallel, their cosine +1 or -1.
    const double cosine = normal * newell / std::sqrt(normal.squared_length() * newell.squared_length());
    EXPECT_NEAR(std::abs(cosine), 1, 1e-9) << "face " << f;
    turned += cosine < 0;
  }
  return turned;
}

// What every algorithm of the thesis requires of its input: a valid halfedge structure of
// triangles with no vertex shared by two fans (Surface_mesh cannot hold a non-manifold edge).
void expect_manifold_triangle_mesh(const Mesh& m)
{
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
  EXPECT_TRUE(CGAL::is_triangle_mesh(m));
  for(Vertex_index v : m.vertices())
    EXPECT_FALSE(CGAL::Polygon_mesh_processing::is_non_manifold_vertex(v, m)) << "vertex " << v;
}

} // namespace

TEST(Repair, TriangleMeshComesOutUnchanged)
{
  const Mesh torus = make_torus(12, 7);
  const Polygon_soup soup = mesh_to_soup(torus);
  const Repaired r = repair(soup);
  EXPECT_FALSE(r.report.changed()) << r.report;
  EXPECT_TRUE(r.report.faces_match_polygons);
  EXPECT_EQ(r.report.summary(), "no repairs");
  ASSERT_EQ(r.mesh.number_of_vertices(), soup.points.size());
  ASSERT_EQ(r.mesh.number_of_faces(), soup.polygons.size());
  for(Vertex_index v : r.mesh.vertices()) EXPECT_EQ(r.mesh.point(v), soup.points[std::size_t(v)]);
  for(Face_index f : r.mesh.faces())
  {
    EXPECT_EQ(r.origin[std::size_t(f)], std::size_t(f));
    std::vector<std::size_t> v;
    for(Vertex_index x : vertices_around_face(r.mesh.halfedge(f), r.mesh)) v.push_back(std::size_t(x));
    // The same cyclic sequence as the polygon.
    const auto& p = soup.polygons[std::size_t(f)];
    const std::size_t shift = std::size_t(std::find(v.begin(), v.end(), p[0]) - v.begin());
    for(std::size_t k = 0; k < 3; ++k) EXPECT_EQ(v[(shift + k) % 3], p[k]);
  }
}

TEST(Repair, QuadTorusIsTriangulated)
{
  const int n = 10, m = 6;
  const Polygon_soup soup = make_quad_torus(n, m);
  const Repaired r = repair(soup);
  EXPECT_EQ(r.report.triangulated_polygons, std::size_t(n * m));
  EXPECT_EQ(r.report.triangles_from_polygons, std::size_t(2 * n * m));
  EXPECT_EQ(r.report.reoriented_polygons, 0u);
  EXPECT_EQ(r.report.duplicated_vertices, 0u);
  EXPECT_FALSE(r.report.faces_match_polygons);
  EXPECT_EQ(r.report.summary(), "60 polygons triangulated into 120 triangles");
  // A torus: V = nm, F = 2nm, E = 3nm, chi = 0, genus 1, harmonic dimension 2.
  EXPECT_EQ(r.mesh.number_of_vertices(), std::size_t(n * m));
  EXPECT_EQ(r.mesh.number_of_faces(), std::size_t(2 * n * m));
  EXPECT_EQ(euler_characteristic(r.mesh), 0);
  EXPECT_EQ(turned_against_the_soup(r, soup), r.report.reoriented_polygons);
  // Each quad became two consecutive triangles, which together use its four vertices
  // and nothing else: a value given per quad goes to both.
  std::vector<std::set<std::size_t>> used(soup.polygons.size());
  for(Face_index f : r.mesh.faces())
  {
    const std::size_t q = r.origin[std::size_t(f)];
    EXPECT_EQ(q, std::size_t(f) / 2);
    for(Vertex_index x : vertices_around_face(r.mesh.halfedge(f), r.mesh)) used[q].insert(std::size_t(x));
  }
  for(std::size_t q = 0; q < soup.polygons.size(); ++q)
    EXPECT_EQ(used[q], std::set<std::size_t>(soup.polygons[q].begin(), soup.polygons[q].end())) << "quad " << q;
  const Mesh_counts t = count_topology(r.mesh);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.genus, 1);
  EXPECT_EQ(t.boundary_loops, 0);
}

TEST(Repair, LargerPolygonsAreTriangulated)
{
  // A hexagonal prism: two hexagons and six quads; a closed genus-0 surface.
  Polygon_soup soup;
  for(int z : {0, 1})
    for(int k = 0; k < 6; ++k) soup.points.emplace_back(std::cos(M_PI * k / 3), std::sin(M_PI * k / 3), z);
  soup.polygons.push_back({5, 4, 3, 2, 1, 0});
  soup.polygons.push_back({6, 7, 8, 9, 10, 11});
  for(std::size_t k = 0; k < 6; ++k) soup.polygons.push_back({k, (k + 1) % 6, 6 + (k + 1) % 6, 6 + k});
  const Repaired r = repair(soup);
  EXPECT_EQ(r.report.triangulated_polygons, 8u);
  EXPECT_EQ(r.report.triangles_from_polygons, 2 * 4 + 6 * 2u);
  EXPECT_EQ(r.mesh.number_of_faces(), 20u);
  EXPECT_EQ(euler_characteristic(r.mesh), 2);
  EXPECT_EQ(turned_against_the_soup(r, soup), r.report.reoriented_polygons);
  const Mesh_counts t = count_topology(r.mesh);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.genus, 0);
  EXPECT_EQ(t.boundary_loops, 0);
  // Triangles of one polygon follow each other, in polygon order.
  EXPECT_TRUE(std::is_sorted(r.origin.begin(), r.origin.end()));
  EXPECT_EQ(std::count(r.origin.begin(), r.origin.end(), 0u), 4);
}

TEST(Repair, PolygonWithTwoCornersAtOnePointIsCutAsAFan)
{
  // A pentagon whose corners 1 and 2 are distinct points of the soup at one position:
  // CGAL's constrained triangulation dereferenced a null handle on it (found by the mesh
  // fuzzer).  It is cut as a fan from its first corner: 3 triangles, every corner kept.
  Polygon_soup soup;
  soup.points = {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(1, 0, 0), Point_3(1, 1, 0), Point_3(0, 1, 0)};
  soup.polygons.push_back({0, 1, 2, 3, 4});
  const Repaired r = repair(soup);
  EXPECT_EQ(r.report.triangulated_polygons, 1u);
  EXPECT_EQ(r.report.triangles_from_polygons, 3u);
  EXPECT_EQ(r.mesh.number_of_faces(), 3u);
  EXPECT_EQ(r.mesh.number_of_vertices(), 5u);
}

TEST(Repair, PolygonWhoseProjectionCrossesItselfIsTriangulatedWithoutCrossings)
{
  // A pentagon whose projection onto its plane (along its Newell normal) has crossing sides:
  // CGAL's constrained triangulation inserted a vertex at the crossing and dereferenced its
  // missing halfedge (SEGV, found by the mesh fuzzer).  It goes to hole filling instead.
  Polygon_soup soup;
  soup.points = {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0, 1, 0), Point_3(2, 0, 2), Point_3(0.5, 0.5, 0)};
  soup.polygons.push_back({0, 1, 2, 3, 4});
  const Repaired r = repair(soup);
  EXPECT_EQ(r.report.triangles_from_polygons, 3u);
  EXPECT_EQ(r.mesh.number_of_faces(), 3u);
  EXPECT_EQ(r.mesh.number_of_vertices(), 5u);
}

TEST(Repair, NonConvexPolygonWithCollinearSidesIsTriangulatedInsideItself)
{
  // A U, whose two top sides lie on one line without meeting: still a simple polygon, so it
  // keeps the constrained triangulation.  A fan from its first corner would fold a triangle
  // over the notch (its areas would sum to more than the U's 5).
  Polygon_soup soup;
  soup.points = {Point_3(0, 0, 0), Point_3(3, 0, 0), Point_3(3, 2, 0), Point_3(2, 2, 0),
                 Point_3(2, 1, 0), Point_3(1, 1, 0), Point_3(1, 2, 0), Point_3(0, 2, 0)};
  soup.polygons.push_back({0, 1, 2, 3, 4, 5, 6, 7});
  const Repaired r = repair(soup);
  ASSERT_EQ(r.mesh.number_of_faces(), 6u);
  double area = 0;
  for(const auto f : r.mesh.faces())
  {
    const auto h = r.mesh.halfedge(f);
    const Point_3 &a = r.mesh.point(r.mesh.source(h)), &b = r.mesh.point(r.mesh.target(h)),
                  &c = r.mesh.point(r.mesh.target(r.mesh.next(h)));
    const double z = CGAL::cross_product(b - a, c - a).z() / 2;
    EXPECT_GT(z, 0) << "a triangle folded over";
    area += std::abs(z);
  }
  EXPECT_NEAR(area, 5, 1e-12);
}

TEST(Repair, ShuffledOrientationsAreMadeConsistent)
{
  const Mesh sphere = make_icosphere(2);
  std::vector<bool> reversed;
  const Polygon_soup soup = shuffled_orientation_soup(sphere, 3, reversed);
  const std::size_t flipped = std::size_t(std::count(reversed.begin(), reversed.end(), true));
  ASSERT_GT(flipped, 50u);
  const Repaired r = repair(soup);
  // Polygon 0 was not reversed, so the orientation is the sphere's: exactly the
  // reversed polygons are turned back.
  EXPECT_EQ(r.report.reoriented_polygons, flipped);
  EXPECT_TRUE(r.report.faces_match_polygons);
  EXPECT_EQ(r.report.duplicated_vertices, 0u);
  ASSERT_EQ(r.mesh.number_of_faces(), sphere.number_of_faces());
  EXPECT_EQ(turned_against_the_soup(r, soup), flipped);
  const auto original = directed_edges(sphere), repaired = directed_edges(r.mesh);
  EXPECT_EQ(original, repaired);
  EXPECT_EQ(euler_characteristic(r.mesh), 2);
}

TEST(Repair, NonManifoldVertexIsDuplicated)
{
  const int n = 7;
  const Polygon_soup soup = make_double_cone(n);
  const Repaired r = repair(soup);
  EXPECT_EQ(r.report.non_manifold_vertices, 1u);
  EXPECT_EQ(r.report.duplicated_vertices, 1u);
  EXPECT_EQ(r.report.reoriented_polygons, 0u);
  EXPECT_TRUE(r.report.faces_match_polygons);
  EXPECT_EQ(r.report.summary(), "1 non-manifold vertex duplicated (1 new vertex)");
  EXPECT_EQ(r.mesh.number_of_vertices(), soup.points.size() + 1);
  // The copy sits where the apex was; the two cones are two disks (chi = 1 each).
  EXPECT_EQ(r.mesh.point(Vertex_index(Mesh::size_type(soup.points.size()))), soup.points[0]);
  EXPECT_EQ(euler_characteristic(r.mesh), 2);
  const Mesh_counts t = count_topology(r.mesh);
  EXPECT_EQ(t.components, 2);
  EXPECT_EQ(t.boundary_loops, 2);
  EXPECT_EQ(t.genus, 0);
}

TEST(Repair, BowtieAndNonManifoldEdge)
{
  // Two triangles touching at point 2 only.
  Polygon_soup bowtie;
  bowtie.points = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0, 2, 0}, {1, 2, 0}};
  bowtie.polygons = {{0, 1, 2}, {2, 4, 3}};
  const Repaired b = repair(bowtie);
  EXPECT_EQ(b.report.non_manifold_vertices, 1u);
  EXPECT_EQ(b.report.duplicated_vertices, 1u);
  EXPECT_EQ(b.mesh.number_of_vertices(), 6u);
  expect_manifold_triangle_mesh(b.mesh);

  // Three triangles on edge 0-1: the edge is cut apart.
  Polygon_soup book;
  book.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  book.polygons = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const Repaired e = repair(book);
  EXPECT_EQ(e.report.non_manifold_edges, 1u);
  EXPECT_GE(e.report.duplicated_vertices, 2u);
  EXPECT_NE(e.report.summary().find("1 non-manifold edge cut apart"), std::string::npos) << e.report;
  EXPECT_EQ(turned_against_the_soup(e, book), e.report.reoriented_polygons);
  expect_manifold_triangle_mesh(e.mesh);
  // Three sheets around the cut edge: with boundary everywhere, components plus the first
  // Betti number, 2g + b, is 3 however the cut joined them.
  const Mesh_counts t = count_topology(e.mesh);
  EXPECT_EQ(2 * t.genus + t.boundary_loops, 3) << t.components << " components, " << t.boundary_loops << " loops";
}

TEST(Repair, MoebiusStripIsCutOpen)
{
  // Not orientable: orient_polygon_soup cuts it along an edge where the orientation
  // cannot be made consistent, duplicating the edge's ends.  What is left is a disk.
  const int n = 12;
  const Polygon_soup soup = make_moebius_strip(n);
  const Repaired r = repair(soup);
  EXPECT_GT(r.report.duplicated_vertices, 0u);
  EXPECT_TRUE(r.report.faces_match_polygons);
  EXPECT_EQ(turned_against_the_soup(r, soup), r.report.reoriented_polygons);
  EXPECT_EQ(r.mesh.number_of_faces(), std::size_t(2 * n));
  const Mesh_counts t = count_topology(r.mesh);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.genus, 0);
  EXPECT_GE(t.boundary_loops, 1);
}

TEST(Repair, DegenerateDuplicateAndPinchedPolygons)
{
  Polygon_soup soup = mesh_to_soup(make_disk(3));
  const std::size_t n = soup.polygons.size(), p = soup.points.size();
  soup.points.emplace_back(5, 5, 0);
  soup.points.emplace_back(6, 5, 0);
  soup.points.emplace_back(5, 6, 0);
  soup.points.emplace_back(6, 6, 0);
  soup.points.emplace_back(7, 5.5, 0);
  soup.polygons.push_back({p, p, p + 1});                        // n: degenerate, removed
  soup.polygons.push_back(soup.polygons[0]);                     // n+1: duplicate of 0, removed
  soup.polygons.push_back({p, p + 1, p + 1, p + 2});             // n+2: repeat dropped: a triangle
  soup.polygons.push_back({p + 1, p + 4, p + 3, p + 1, p + 3, p + 2}); // n+3: pinched at p+1, twice at p+3
  const Repaired r = repair(soup);
  EXPECT_EQ(r.report.removed_degenerate_polygons, 1u);
  EXPECT_EQ(r.report.removed_duplicate_polygons, 1u);
  EXPECT_EQ(r.report.simplified_polygons, 1u);
  EXPECT_EQ(r.report.split_polygons, 1u);
  EXPECT_FALSE(r.report.faces_match_polygons);
  // The disk's n faces, the simplified triangle p p+1 p+2, and the two halves of the
  // pinched polygon, p+1 p+4 p+3 and p+1 p+3 p+2: n + 3 faces.
  EXPECT_EQ(r.mesh.number_of_faces(), n + 3);
  const std::multiset<std::size_t> origins(r.origin.begin(), r.origin.end());
  EXPECT_EQ(origins.count(n), 0u);
  EXPECT_EQ(origins.count(n + 1), 0u);
  EXPECT_EQ(origins.count(n + 2), 1u);
  EXPECT_EQ(origins.count(n + 3), 2u);
  expect_manifold_triangle_mesh(r.mesh);
}

TEST(Repair, BadSoupsAreRefusedWithoutTouchingTheMesh)
{
  Polygon_soup soup = mesh_to_soup(make_icosphere(1));
  soup.polygons[4][1] = 1000;
  Mesh mesh;
  try
  {
    MR::polygon_soup_to_mesh(soup.points, soup.polygons, mesh);
    ADD_FAILURE() << "accepted";
  }
  catch(const MR::Invalid_mesh& e)
  {
    EXPECT_EQ(e.defect(), MR::Mesh_defect::invalid_index);
    EXPECT_NE(std::string(e.what()).find("polygon 4 refers to point 1000"), std::string::npos) << e.what();
  }
  EXPECT_EQ(mesh.number_of_vertices(), 0u);

  soup = mesh_to_soup(make_icosphere(1));
  soup.points[7] = Point_3(0, std::nan(""), 0);
  try
  {
    MR::polygon_soup_to_mesh(soup.points, soup.polygons, mesh);
    ADD_FAILURE() << "accepted";
  }
  catch(const MR::Invalid_mesh& e)
  {
    EXPECT_EQ(e.defect(), MR::Mesh_defect::non_finite_coordinate);
    EXPECT_NE(std::string(e.what()).find("point 7"), std::string::npos) << e.what();
  }
  EXPECT_EQ(mesh.number_of_vertices(), 0u);

  // Nothing but degenerate polygons: an empty mesh, which the operators refuse.
  Polygon_soup flat;
  flat.points = {{0, 0, 0}, {1, 0, 0}};
  flat.polygons = {{0, 1, 0}, {1, 1, 1}};
  const Repaired r = repair(flat);
  EXPECT_EQ(r.report.removed_degenerate_polygons, 2u);
  EXPECT_EQ(r.mesh.number_of_faces(), 0u);
}
