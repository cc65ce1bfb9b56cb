// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tetrahedra of a closed surface by CGAL's Mesh_3 (a polyhedral domain with its sharp edges as
// features), and the surface's vertices embedded in them.  The only Mesh_3 translation unit.

#include <CGAL/Projective_dynamics/tetrahedralize.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/make_mesh_3.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <unordered_map>

namespace CGAL {
namespace Projective_dynamics {

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface> Domain;
typedef CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type Triangulation;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Triangulation, Domain::Corner_index, Domain::Curve_index> Complex;
typedef CGAL::Mesh_criteria_3<Triangulation> Criteria;
typedef std::vector<K::Triangle_3>::const_iterator Facet_iterator;
typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Facet_iterator>>> Facet_tree;

K::Point_3 point_3(const Point& p) { return K::Point_3(p[0], p[1], p[2]); }

// The closed, outward oriented surface, or the reason it is refused.
Surface checked_surface(const std::vector<Point>& points, const std::vector<Triangle>& triangles)
{
  if(points.empty() || triangles.empty()) throw Invalid_input("tetrahedralize: the surface is empty");
  for(std::size_t v = 0; v < points.size(); ++v)
    for(double x : points[v])
      if(!std::isfinite(x)) throw Invalid_input("tetrahedralize: vertex " + std::to_string(v) + " has a non-finite coordinate");
  std::vector<std::vector<std::size_t>> polygons;
  polygons.reserve(triangles.size());
  for(std::size_t f = 0; f < triangles.size(); ++f)
  {
    for(int v : triangles[f])
      if(v < 0 || std::size_t(v) >= points.size())
        throw Invalid_input("tetrahedralize: triangle " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                            " of " + std::to_string(points.size()));
    polygons.push_back({std::size_t(triangles[f][0]), std::size_t(triangles[f][1]), std::size_t(triangles[f][2])});
  }
  std::vector<K::Point_3> soup_points;
  for(const Point& p : points) soup_points.push_back(point_3(p));
  if(!Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
    throw Invalid_input("tetrahedralize: the surface is not an oriented 2-manifold (an edge of more than two triangles, "
                        "a vertex whose triangles do not form one fan, or neighbours of opposite orientations)");
  Surface surface;
  Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup_points, polygons, surface);
  std::size_t border = 0;
  for(auto h : halfedges(surface))
    if(is_border(h, surface)) ++border;
  if(border > 0)
    throw Invalid_input("tetrahedralize: the surface is open (" + std::to_string(border) +
                        " border edges): a solid needs a closed surface");
  if(Polygon_mesh_processing::does_self_intersect(surface))
    throw Invalid_input("tetrahedralize: the surface intersects itself: a solid needs a surface that bounds a volume");
  if(!Polygon_mesh_processing::is_outward_oriented(surface)) Polygon_mesh_processing::reverse_face_orientations(surface);
  return surface;
}

std::array<double, 4> barycentric(const std::array<K::Point_3, 4>& c, const K::Point_3& p)
{
  const double volume = CGAL::volume(c[0], c[1], c[2], c[3]);
  std::array<double, 4> w{};
  for(int k = 0; k < 4; ++k)
  {
    std::array<K::Point_3, 4> d = c;
    d[std::size_t(k)] = p;
    w[std::size_t(k)] = CGAL::volume(d[0], d[1], d[2], d[3]) / volume;
  }
  return w;
}

} // namespace

Positions Surface_embedding::embed(const Positions& x) const
{
  Positions q(Eigen::Index(weights.size()), 3);
  for(std::size_t i = 0; i < weights.size(); ++i)
  {
    Eigen::RowVector3d p = Eigen::RowVector3d::Zero();
    for(int k = 0; k < 4; ++k)
    {
      const int v = corners[i][std::size_t(k)];
      if(v < 0 || v >= x.rows())
        throw Invalid_input("surface embedding: vertex " + std::to_string(v) + " of " + std::to_string(x.rows()) + " positions");
      p += weights[i][std::size_t(k)] * x.row(v);
    }
    q.row(Eigen::Index(i)) = p;
  }
  return q;
}

Tetrahedralized_surface tetrahedralize(const std::vector<Point>& points, const std::vector<Triangle>& triangles,
                                       const Tetrahedralization_options& options)
{
  if(!(options.cell_size > 0) || !(options.facet_distance > 0) || !std::isfinite(options.cell_size) ||
     !std::isfinite(options.facet_distance))
    throw Invalid_input("tetrahedralize: the cell size and the facet distance must be positive and finite");
  if(!(options.feature_angle >= 0 && options.feature_angle <= 180))
    throw Invalid_input("tetrahedralize: the feature angle must lie in [0, 180] degrees");
  Surface surface = checked_surface(points, triangles);
  const CGAL::Bbox_3 box = Polygon_mesh_processing::bbox(surface);
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));

  Domain domain(surface);
  if(options.feature_angle > 0) domain.detect_features(options.feature_angle);
  const double size = options.cell_size * diagonal;
  const Criteria criteria(CGAL::parameters::edge_size = size, CGAL::parameters::facet_angle = 25,
                          CGAL::parameters::facet_size = size,
                          CGAL::parameters::facet_distance = options.facet_distance * diagonal,
                          CGAL::parameters::cell_radius_edge_ratio = 3, CGAL::parameters::cell_size = size);
  // No perturbation (slow); the default sliver exudation stays (thin tetrahedra make stiff,
  // badly conditioned strain elements).
  const Complex complex = CGAL::make_mesh_3<Complex>(domain, criteria, CGAL::parameters::no_perturb());

  Tetrahedralized_surface out;
  std::unordered_map<Triangulation::Vertex_handle, int> vertex_index;
  std::map<Triangulation::Cell_handle, int> cell_index;
  for(auto c = complex.cells_in_complex_begin(); c != complex.cells_in_complex_end(); ++c)
  {
    Tetrahedron t{};
    for(int k = 0; k < 4; ++k)
    {
      const auto v = c->vertex(k);
      auto found = vertex_index.find(v);
      if(found == vertex_index.end())
      {
        const K::Point_3& p = v->point().point();
        found = vertex_index.emplace(v, int(out.mesh.points.size())).first;
        out.mesh.points.push_back({p.x(), p.y(), p.z()});
      }
      t[std::size_t(k)] = found->second;
    }
    if(signed_volume(out.mesh.points, t) < 0) std::swap(t[2], t[3]);
    cell_index.emplace(Triangulation::Cell_handle(c), int(out.mesh.tetrahedra.size()));
    out.mesh.tetrahedra.push_back(t);
  }
  if(out.mesh.tetrahedra.empty())
    throw Numerical_failure("tetrahedralize: Mesh_3 made no tetrahedron (a cell size too large for the surface?)");
  out.mesh.triangles = boundary_triangles(out.mesh.points, out.mesh.tetrahedra);

  // The boundary facets, each with its tetrahedron, for the vertices that lie outside.
  std::vector<K::Triangle_3> facets;
  std::vector<int> facet_tetrahedron;
  {
    std::map<std::array<int, 3>, int> count;
    for(std::size_t t = 0; t < out.mesh.tetrahedra.size(); ++t)
      for(int k = 0; k < 4; ++k)
      {
        std::array<int, 3> f{};
        for(int j = 0, m = 0; j < 4; ++j)
          if(j != k) f[std::size_t(m++)] = out.mesh.tetrahedra[t][std::size_t(j)];
        std::sort(f.begin(), f.end());
        auto [it, inserted] = count.emplace(f, int(t));
        if(!inserted) it->second = -1; // shared by two tetrahedra: interior
      }
    for(const auto& [f, t] : count)
      if(t >= 0)
      {
        facets.emplace_back(point_3(out.mesh.points[std::size_t(f[0])]), point_3(out.mesh.points[std::size_t(f[1])]),
                            point_3(out.mesh.points[std::size_t(f[2])]));
        facet_tetrahedron.push_back(t);
      }
  }
  Facet_tree tree(facets.begin(), facets.end());
  tree.accelerate_distance_queries();

  const Triangulation& tr = complex.triangulation();
  const auto weighted = tr.geom_traits().construct_weighted_point_3_object();
  Surface_embedding& e = out.surface;
  for(const Point& point : points)
  {
    const K::Point_3 p = point_3(point);
    const auto located = tr.locate(weighted(p));
    auto inside = cell_index.find(located);
    int t = -1;
    if(inside != cell_index.end()) t = inside->second;
    else
    {
      const auto nearest = tree.closest_point_and_primitive(p);
      t = facet_tetrahedron[std::size_t(nearest.second - facets.begin())];
      out.largest_outside_distance =
          std::max(out.largest_outside_distance, std::sqrt(CGAL::squared_distance(p, nearest.first)) / diagonal);
    }
    const Tetrahedron& corners = out.mesh.tetrahedra[std::size_t(t)];
    std::array<K::Point_3, 4> c;
    for(int k = 0; k < 4; ++k) c[std::size_t(k)] = point_3(out.mesh.points[std::size_t(corners[std::size_t(k)])]);
    e.tetrahedra.push_back(t);
    e.corners.push_back(corners);
    e.weights.push_back(barycentric(c, p));
  }
  return out;
}

} // namespace Projective_dynamics
} // namespace CGAL
