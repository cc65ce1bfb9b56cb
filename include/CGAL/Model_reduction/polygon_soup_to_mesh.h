// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_POLYGON_SOUP_TO_MESH_H
#define CGAL_MODEL_REDUCTION_POLYGON_SOUP_TO_MESH_H

/// \file polygon_soup_to_mesh.h
/// Turns what `CGAL::IO::read_polygon_soup` reads into a triangle mesh this package
/// accepts, with CGAL's standard repairs, and reports what changed.

#include <CGAL/Model_reduction/Mesh_repair_report.h>
#include <CGAL/Model_reduction/errors.h>
#include <CGAL/Model_reduction/named_function_parameters.h>

#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Projection_traits_3.h>
#include <CGAL/Surface_mesh/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Model_reduction {

namespace internal {

// A polygon of the soup being repaired, with the input polygon it comes from.
struct Traced_polygon
{
  std::vector<std::size_t> vertices;
  std::size_t origin;
};

// Drops a vertex equal to its predecessor (cyclically); true if any was dropped.
inline bool drop_consecutive_repeats(std::vector<std::size_t>& polygon)
{
  std::vector<std::size_t> kept;
  kept.reserve(polygon.size());
  for(std::size_t v : polygon)
    if(kept.empty() || kept.back() != v) kept.push_back(v);
  while(kept.size() > 1 && kept.front() == kept.back()) kept.pop_back();
  const bool changed = kept.size() != polygon.size();
  polygon.swap(kept);
  return changed;
}

// Splits a polygon without consecutive repeats that visits a vertex twice ("pinched")
// at that vertex, recursively; pieces of fewer than three vertices are dropped.
inline void split_pinched(const std::vector<std::size_t>& polygon, std::vector<std::vector<std::size_t>>& pieces)
{
  std::map<std::size_t, std::size_t> seen;
  for(std::size_t j = 0; j < polygon.size(); ++j)
  {
    const auto found = seen.find(polygon[j]);
    if(found == seen.end())
    {
      seen.emplace(polygon[j], j);
      continue;
    }
    const std::size_t i = found->second;
    std::vector<std::size_t> loop(polygon.begin() + i, polygon.begin() + j);
    std::vector<std::size_t> rest(polygon.begin(), polygon.begin() + i);
    rest.insert(rest.end(), polygon.begin() + j, polygon.end());
    if(loop.size() >= 3) split_pinched(loop, pieces);
    if(rest.size() >= 3) split_pinched(rest, pieces);
    return;
  }
  pieces.push_back(polygon);
}

// The same polygon whatever its first vertex and orientation: rotated to start at its
// smallest index, then traversed towards the smaller of that index's two neighbours.
inline std::vector<std::size_t> canonical_polygon(const std::vector<std::size_t>& polygon)
{
  const std::size_t n = polygon.size();
  const std::size_t first = static_cast<std::size_t>(std::min_element(polygon.begin(), polygon.end()) - polygon.begin());
  const bool forward = polygon[(first + 1) % n] < polygon[(first + n - 1) % n];
  std::vector<std::size_t> c(n);
  for(std::size_t k = 0; k < n; ++k) c[k] = polygon[forward ? (first + k) % n : (first + n - k) % n];
  return c;
}

template <class Point>
bool has_finite_coordinates(const Point& p)
{
  return std::isfinite(CGAL::to_double(p.x())) && std::isfinite(CGAL::to_double(p.y())) &&
         std::isfinite(CGAL::to_double(p.z()));
}

template <class Target, class Source>
Target convert_point(const Source& p, std::enable_if_t<std::is_same<Target, Source>::value>* = nullptr)
{
  return p;
}
template <class Target, class Source>
Target convert_point(const Source& p, std::enable_if_t<!std::is_same<Target, Source>::value>* = nullptr)
{
  return Target(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

// Collects the faces a triangulation creates (CGAL copies the visitor: keep a pointer).
template <class Mesh>
struct Created_faces_visitor : CGAL::Polygon_mesh_processing::Triangulate_faces::Default_visitor<Mesh>
{
  std::vector<typename Mesh::Face_index>* created;
  void after_subface_created(typename Mesh::Face_index f) { created->push_back(f); }
};

// Whether two sides of a polygon that are not neighbours meet, or two neighbouring corners
// coincide, as CGAL's constrained triangulation sees the polygon: projected along `normal`,
// with that projection's own predicates.  Where sides cross, the triangulation inserts a
// vertex without the halfedge CGAL's `triangulate_face` then dereferences (a SEGV found by
// test/fuzz's mesh target).  Quadratic in the corners, checked for 5 and more.
template <class Point, class Vector>
bool projected_sides_meet(const std::vector<Point>& p, const Vector& normal)
{
  typedef typename CGAL::Kernel_traits<Point>::Kernel Kernel;
  const CGAL::Projection_traits_3<Kernel> traits(normal);
  const auto orientation = traits.orientation_2_object();
  const auto less = traits.less_xy_2_object();
  const auto compare_x = traits.compare_x_2_object();
  const auto compare_y = traits.compare_y_2_object();
  // c, on the line through a and b, lies between them.
  const auto on_side = [&](const Point& a, const Point& b, const Point& c) {
    const Point& low = less(a, b) ? a : b;
    const Point& high = less(a, b) ? b : a;
    return !less(c, low) && !less(high, c);
  };
  const std::size_t k = p.size();
  for(std::size_t i = 0; i < k; ++i)
    if(compare_x(p[i], p[(i + 1) % k]) == CGAL::EQUAL && compare_y(p[i], p[(i + 1) % k]) == CGAL::EQUAL) return true;
  for(std::size_t i = 0; i < k; ++i)
    for(std::size_t j = i + 2; j < k; ++j)
    {
      if(i == 0 && j + 1 == k) continue; // neighbours through the last corner
      const Point &a = p[i], &b = p[(i + 1) % k], &c = p[j], &d = p[(j + 1) % k];
      const CGAL::Orientation abc = orientation(a, b, c), abd = orientation(a, b, d), cda = orientation(c, d, a),
                              cdb = orientation(c, d, b);
      if(abc != abd && cda != cdb) return true;
      if((abc == CGAL::COLLINEAR && on_side(a, b, c)) || (abd == CGAL::COLLINEAR && on_side(a, b, d)) ||
         (cda == CGAL::COLLINEAR && on_side(c, d, a)) || (cdb == CGAL::COLLINEAR && on_side(c, d, b)))
        return true;
    }
  return false;
}

// Triangulates one polygon of more than three vertices with CGAL's `triangulate_face`
// (the better diagonal of a quad, a constrained Delaunay triangulation in the
// polygon's plane otherwise, hole filling where that fails), or as a fan from its first
// vertex if CGAL cannot (a polygon without a normal: all points on one line).  Each
// polygon gets vertices of its own in `scratch`, so no other polygon can interfere.
template <class Point>
void triangulate_polygon(const std::vector<Point>& points, const std::vector<std::size_t>& polygon,
                         CGAL::Surface_mesh<Point>& scratch,
                         typename CGAL::Surface_mesh<Point>::template Property_map<
                             typename CGAL::Surface_mesh<Point>::Vertex_index, std::size_t>& original,
                         std::vector<std::array<std::size_t, 3>>& triangles)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  typedef CGAL::Surface_mesh<Point> Scratch;
  const auto fan = [&] {
    for(std::size_t k = 1; k + 1 < polygon.size(); ++k) triangles.push_back({{polygon[0], polygon[k], polygon[k + 1]}});
  };
  // CGAL's constrained triangulation dereferences a null handle on a polygon with two corners
  // at one point (found by test/fuzz's mesh target): such a polygon is cut as a fan.
  std::set<Point> distinct;
  for(std::size_t v : polygon) distinct.insert(points[v]);
  if(distinct.size() < polygon.size()) return fan();
  std::vector<typename Scratch::Vertex_index> corners;
  for(std::size_t v : polygon)
  {
    corners.push_back(scratch.add_vertex(points[v]));
    original[corners.back()] = v;
  }
  const typename Scratch::Face_index face = scratch.add_face(corners);
  std::vector<typename Scratch::Face_index> created;
  Created_faces_visitor<Scratch> visitor;
  visitor.created = &created;
  // Hole filling instead of the constrained triangulation where the latter would crash.
  bool use_cdt = true;
  if(face != Scratch::null_face() && polygon.size() >= 5)
  {
    std::vector<Point> corner_points;
    for(std::size_t v : polygon) corner_points.push_back(points[v]);
    use_cdt = !projected_sides_meet(corner_points, PMP::compute_face_normal(face, scratch));
  }
  bool done = face != Scratch::null_face() && use_cdt &&
              PMP::triangulate_face(face, scratch, CGAL::parameters::visitor(visitor));
  if(!done && face != Scratch::null_face())
  {
    created.clear();
    done = PMP::triangulate_face(face, scratch, CGAL::parameters::visitor(visitor).use_delaunay_triangulation(false));
  }
  if(done && created.size() + 2 == polygon.size())
  {
    for(typename Scratch::Face_index f : created)
    {
      const typename Scratch::Halfedge_index h = scratch.halfedge(f);
      triangles.push_back({{original[scratch.source(h)], original[scratch.target(h)],
                            original[scratch.target(scratch.next(h))]}});
    }
    return;
  }
  fan();
}

// Counts what `orient_polygon_soup` does (CGAL copies the visitor: keep pointers).
struct Orientation_visitor : CGAL::Polygon_mesh_processing::Default_orientation_visitor
{
  std::vector<char>* reversed;
  std::set<std::pair<std::size_t, std::size_t>>* non_manifold_edges;
  std::size_t* non_manifold_vertices;

  void polygon_orientation_reversed(std::size_t p) { (*reversed)[p] = 1; }
  void non_manifold_edge(std::size_t a, std::size_t b, std::size_t)
  {
    non_manifold_edges->insert(std::minmax(a, b));
  }
  void non_manifold_vertex(std::size_t, std::size_t) { ++*non_manifold_vertices; }
};

template <class FaceMap, class Face>
void put_origin(FaceMap map, Face f, std::size_t origin)
{
  put(map, f, origin);
}
template <class Face>
void put_origin(CGAL::internal_np::Param_not_found, Face, std::size_t)
{}

} // namespace internal

/// \brief Builds a triangle mesh this package accepts from a polygon soup, repairing
/// what keeps the soup from being one, and reports what changed.
///
/// `CGAL::IO::read_polygon_soup` reads any file; this function makes a mesh of it
/// that `Discrete_operators` and everything built on it accept, as far as the
/// connectivity goes (degenerate geometry is left to `use_intrinsic_mollification`).
/// The steps, each only where it is needed:
/// 1. a vertex repeated consecutively in a polygon is dropped once; a polygon that
///    visits a vertex twice ("pinched") is split there into simple polygons; polygons
///    left with fewer than three vertices are removed (degenerate), and so are polygons
///    with the same vertices as an earlier one (duplicates: the first is kept);
/// 2. polygons of more than three vertices are triangulated with
///    `CGAL::Polygon_mesh_processing::triangulate_face` (a quad along its better
///    diagonal, larger polygons by a constrained Delaunay triangulation in their plane,
///    else by hole filling; a polygon with no normal, all its points on one line, as a
///    fan of degenerate triangles);
/// 3. `CGAL::Polygon_mesh_processing::orient_polygon_soup` orients the triangles
///    consistently, reversing some, and duplicates the vertices where that is
///    impossible: non-manifold vertices (whose faces form several fans), the ends of
///    edges shared by more than two faces (which are cut apart), and the ends of the
///    edges along which a non-orientable surface, such as a Moebius strip, is cut open;
/// 4. the mesh is built and `duplicate_non_manifold_vertices` checks it once more.
///
/// Points are never merged, even when they coincide (that would change the topology of
/// a mesh with a seam); points in no polygon are kept as isolated vertices, which the
/// package ignores.  A soup that is already a mesh the package accepts comes out
/// unchanged: vertex `i` is point `i` and face `i` polygon `i`.
///
/// Faces are created in the order of the polygons they come from; the triangles of a
/// split or triangulated polygon follow each other.  A per-face quantity of the soup,
/// such as a vector or a colour per polygon, goes to the faces with `face_to_polygon_map`:
/// each triangle of a polygon gets the polygon's value.  Values of removed polygons
/// (degenerate or duplicate) have no face to go to.
///
/// \tparam PointRange a random access range of points convertible to the mesh's point type
/// \tparam PolygonRange a range of polygons, each a range of `std::size_t` indices into `points`
/// \tparam PolygonMesh a model of `MutableFaceGraph`; new vertices and faces are added to `mesh`
///         (which is normally empty)
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     the property map with the points of the vertices of `mesh`;
///     default `get(CGAL::vertex_point, mesh)`
///   \cgalParamNEnd
///   \cgalParamNBegin{face_to_polygon_map}
///     a writable face property map with `std::size_t` values, receiving for every new
///     face the index of the polygon of `polygons` it comes from; default: none
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns what was changed (`Mesh_repair_report::summary()` says it in one line)
/// \throws Invalid_mesh (`invalid_index`) for a polygon naming a point that does not
///         exist, (`non_finite_coordinate`) for a polygon with a NaN or infinite point,
///         (`non_manifold_edge`) if the repaired soup still is no mesh; `mesh` is not
///         modified then.
template <class PointRange, class PolygonRange, class PolygonMesh,
          class NamedParameters = parameters::Default_named_parameters>
Mesh_repair_report polygon_soup_to_mesh(const PointRange& points, const PolygonRange& polygons, PolygonMesh& mesh,
                                        const NamedParameters& np = parameters::default_values())
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<PolygonMesh>::face_descriptor face_descriptor;
  typedef typename CGAL::GetVertexPointMap<PolygonMesh, NamedParameters>::type Vertex_point_map;
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point;

  Vertex_point_map vpm =
      choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_property_map(CGAL::vertex_point, mesh));

  Mesh_repair_report report;
  std::vector<Point> soup_points;
  soup_points.reserve(points.size());
  for(const auto& p : points) soup_points.push_back(internal::convert_point<Point>(p));
  report.number_of_points = soup_points.size();

  // Indices and coordinates first: the geometric steps below must not see a NaN.
  std::vector<internal::Traced_polygon> traced;
  std::size_t index = 0;
  for(const auto& polygon : polygons)
  {
    internal::Traced_polygon t{std::vector<std::size_t>(polygon.begin(), polygon.end()), index};
    for(std::size_t v : t.vertices)
    {
      if(v >= soup_points.size())
        throw Invalid_mesh(Mesh_defect::invalid_index, "polygon " + std::to_string(index) + " refers to point " +
                                                           std::to_string(v) + ", but there are " +
                                                           std::to_string(soup_points.size()) + " points");
      if(!internal::has_finite_coordinates(soup_points[v]))
        throw Invalid_mesh(Mesh_defect::non_finite_coordinate, "point " + std::to_string(v) + " (in polygon " +
                                                                   std::to_string(index) + ") is not finite");
    }
    traced.push_back(std::move(t));
    ++index;
  }
  report.number_of_polygons = traced.size();

  // 1. Combinatorial clean-up, keeping the order and the origin of every polygon.
  std::vector<internal::Traced_polygon> clean;
  std::set<std::vector<std::size_t>> seen;
  for(internal::Traced_polygon& t : traced)
  {
    const bool simplified = internal::drop_consecutive_repeats(t.vertices);
    std::vector<std::vector<std::size_t>> pieces;
    if(t.vertices.size() >= 3) internal::split_pinched(t.vertices, pieces);
    if(pieces.empty())
      ++report.removed_degenerate_polygons;
    else if(simplified)
      ++report.simplified_polygons;
    if(pieces.size() > 1 || (pieces.size() == 1 && pieces[0].size() != t.vertices.size())) ++report.split_polygons;
    for(std::vector<std::size_t>& piece : pieces)
    {
      if(!seen.insert(internal::canonical_polygon(piece)).second)
      {
        ++report.removed_duplicate_polygons;
        continue;
      }
      clean.push_back({std::move(piece), t.origin});
    }
  }
  traced.clear();

  // 2. Triangles, each polygon replaced in place by its own.
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<std::size_t> origin;
  {
    CGAL::Surface_mesh<Point> scratch;
    auto original = scratch.template add_property_map<typename CGAL::Surface_mesh<Point>::Vertex_index, std::size_t>(
                               "v:mr_original_point", 0)
                        .first;
    for(const internal::Traced_polygon& t : clean)
    {
      const std::size_t before = triangles.size();
      if(t.vertices.size() == 3)
        triangles.push_back({{t.vertices[0], t.vertices[1], t.vertices[2]}});
      else
      {
        internal::triangulate_polygon(soup_points, t.vertices, scratch, original, triangles);
        ++report.triangulated_polygons;
        report.triangles_from_polygons += triangles.size() - before;
      }
      origin.resize(triangles.size(), t.origin);
    }
  }
  clean.clear();

  // 3. Orientation; vertices duplicated where the triangles cannot form a manifold.
  std::vector<char> reversed(triangles.size(), 0);
  std::set<std::pair<std::size_t, std::size_t>> non_manifold_edges;
  internal::Orientation_visitor visitor;
  visitor.reversed = &reversed;
  visitor.non_manifold_edges = &non_manifold_edges;
  visitor.non_manifold_vertices = &report.non_manifold_vertices;
  const std::size_t points_before = soup_points.size();
  PMP::orient_polygon_soup(soup_points, triangles, CGAL::parameters::visitor(visitor));
  report.duplicated_vertices = soup_points.size() - points_before;
  report.non_manifold_edges = non_manifold_edges.size();
  std::set<std::size_t> reoriented;
  for(std::size_t f = 0; f < triangles.size(); ++f)
    if(reversed[f]) reoriented.insert(origin[f]);
  report.reoriented_polygons = reoriented.size();
  if(!PMP::is_polygon_soup_a_polygon_mesh(triangles))
    throw Invalid_mesh(Mesh_defect::non_manifold_edge,
                       "the polygons do not form a manifold mesh even after CGAL's orient_polygon_soup");

  // 4. The mesh.
  auto face_map = get_parameter(np, internal_np::face_to_polygon_map);
  std::vector<vertex_descriptor> vertices;
  vertices.reserve(soup_points.size());
  for(const Point& p : soup_points)
  {
    vertices.push_back(add_vertex(mesh));
    put(vpm, vertices.back(), p);
  }
  report.faces_match_polygons = triangles.size() == report.number_of_polygons;
  for(std::size_t f = 0; f < triangles.size(); ++f)
  {
    const std::array<vertex_descriptor, 3> corners = {
        {vertices[triangles[f][0]], vertices[triangles[f][1]], vertices[triangles[f][2]]}};
    const face_descriptor face = CGAL::Euler::add_face(corners, mesh);
    if(face == boost::graph_traits<PolygonMesh>::null_face())
      throw Invalid_mesh(Mesh_defect::non_manifold_edge,
                         "triangle " + std::to_string(f) + " (from polygon " + std::to_string(origin[f]) +
                             ") cannot be added to the mesh");
    internal::put_origin(face_map, face, origin[f]);
    if(origin[f] != f) report.faces_match_polygons = false;
  }
  const std::size_t extra = PMP::duplicate_non_manifold_vertices(mesh, CGAL::parameters::vertex_point_map(vpm));
  report.duplicated_vertices += extra;
  report.number_of_vertices = static_cast<std::size_t>(num_vertices(mesh));
  report.number_of_faces = triangles.size();
  return report;
}

} // namespace Model_reduction
} // namespace CGAL

#endif
