// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/Intrinsic_mesh.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <utility>

namespace CGAL {
namespace Tangent_vector_fields {

namespace {

typedef Intrinsic_mesh::Vector Vector;

Vector sub(const Vector& a, const Vector& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vector add(const Vector& a, const Vector& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vector cross(const Vector& a, const Vector& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vector& a, const Vector& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vector& a) { return std::sqrt(dot(a, a)); }
Vector scaled(const Vector& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double largest_magnitude(const Vector& a) { return std::max({std::abs(a[0]), std::abs(a[1]), std::abs(a[2])}); }
// Length of `a` without squaring its coordinates: squares underflow below ~1e-154 and
// overflow above ~1e154, lengths of edges anywhere in the double range do not.
double safe_norm(const Vector& a)
{
  const double m = largest_magnitude(a);
  if(!(m > 0) || !std::isfinite(m)) return m;
  return m * norm(scaled(a, 1 / m));
}

// Union-find with path halving.
struct Disjoint_sets
{
  std::vector<int> parent;
  explicit Disjoint_sets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i)
  {
    while(parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void unite(int a, int b) { parent[find(a)] = find(b); }
};

// Area from side lengths, Kahan's stable form of Heron's formula.  Its product has the
// fourth power of the lengths: call it with lengths relative to the longest (<= 1).
double triangle_area(double a, double b, double c)
{
  if(a < b) std::swap(a, b);
  if(a < c) std::swap(a, c);
  if(b < c) std::swap(b, c);
  const double p = (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c));
  return p > 0 ? 0.25 * std::sqrt(p) : 0.;
}

[[noreturn]] void fail(Mesh_defect defect, const std::string& message)
{
  throw Invalid_mesh(defect, message);
}

} // namespace

std::string Mesh_topology::summary() const
{
  std::ostringstream out;
  out << components.size() << (components.size() == 1 ? " component" : " components")
      << ", genus " << total_genus() << ", " << number_of_boundary_loops() << " boundary loop"
      << (number_of_boundary_loops() == 1 ? "" : "s") << ", harmonic dimension " << harmonic_dimension();
  return out.str();
}

Intrinsic_mesh::Intrinsic_mesh(std::vector<Point> positions,
                               const std::vector<std::array<int, 3>>& faces,
                               const std::vector<std::array<int, 3>>& face_edges,
                               int number_of_edges,
                               const Intrinsic_mesh_options& options)
  : positions_(std::move(positions))
{
  if(faces.empty()) fail(Mesh_defect::empty, "the mesh has no faces");
  const int nv = number_of_vertices();
  for(std::size_t f = 0; f < faces.size(); ++f)
  {
    for(int k = 0; k < 3; ++k)
    {
      const int v = faces[f][k];
      if(v < 0 || v >= nv)
        fail(Mesh_defect::invalid_index, "face " + std::to_string(f) + " refers to vertex " +
                                             std::to_string(v) + ", outside [0, " + std::to_string(nv) + ")");
    }
    if(faces[f][0] == faces[f][1] || faces[f][1] == faces[f][2] || faces[f][0] == faces[f][2])
      fail(Mesh_defect::invalid_index, "face " + std::to_string(f) + " repeats a vertex");
  }
  std::vector<char> used(nv, 0);
  for(const auto& t : faces)
    for(int v : t) used[v] = 1;
  for(int v = 0; v < nv; ++v)
    if(used[v])
      for(double c : positions_[v])
        if(!std::isfinite(c))
          fail(Mesh_defect::non_finite_coordinate, "vertex " + std::to_string(v) + " has a NaN or infinite coordinate");

  build_edges(faces, face_edges, number_of_edges);
  check_vertex_manifoldness();
  compute_topology();
  compute_lengths(options);
  compute_layout_and_frames();
  if(topology_.number_of_isolated_vertices > 0)
    warnings_.push_back(std::to_string(topology_.number_of_isolated_vertices) +
                        " vertices belong to no face; they are ignored (all their values are 0)");
}

void Intrinsic_mesh::build_edges(const std::vector<std::array<int, 3>>& faces,
                                 const std::vector<std::array<int, 3>>& given_edges,
                                 int number_of_given_edges)
{
  const int nf = static_cast<int>(faces.size());
  // Edge from corner k to k+1 (input convention) for every face corner.
  std::vector<std::array<int, 3>> corner_edge(nf);
  int ne = 0;
  if(!given_edges.empty())
  {
    if(static_cast<int>(given_edges.size()) != nf)
      fail(Mesh_defect::invalid_index, "face-edge table has the wrong size");
    ne = number_of_given_edges;
    for(int f = 0; f < nf; ++f)
      for(int k = 0; k < 3; ++k)
      {
        const int e = given_edges[f][k];
        if(e < 0 || e >= ne)
          fail(Mesh_defect::invalid_index, "face " + std::to_string(f) + " refers to edge " + std::to_string(e) +
                                               ", outside [0, " + std::to_string(ne) + ")");
        corner_edge[f][k] = e;
      }
  }
  else
  {
    // Number edges by sorting the (min, max) vertex pairs of all corners.
    std::vector<std::pair<std::pair<int, int>, int>> keys;
    keys.reserve(3 * static_cast<std::size_t>(nf));
    for(int f = 0; f < nf; ++f)
      for(int k = 0; k < 3; ++k)
      {
        const int a = faces[f][k], b = faces[f][(k + 1) % 3];
        keys.push_back({{std::min(a, b), std::max(a, b)}, 3 * f + k});
      }
    std::sort(keys.begin(), keys.end());
    for(std::size_t i = 0; i < keys.size(); ++i)
    {
      if(i > 0 && keys[i].first != keys[i - 1].first) ++ne;
      corner_edge[keys[i].second / 3][keys[i].second % 3] = ne;
    }
    ++ne;
  }

  edge_vertices_.assign(ne, {-1, -1});
  edge_faces_.assign(ne, {-1, -1});
  face_vertices_.resize(nf);
  face_edges_.resize(nf);
  for(int f = 0; f < nf; ++f)
  {
    for(int k = 0; k < 3; ++k)
    {
      const int e = corner_edge[f][k];
      const int a = faces[f][k], b = faces[f][(k + 1) % 3];
      const std::string name = "edge " + std::to_string(e) + " (vertices " + std::to_string(a) + ", " +
                               std::to_string(b) + ")";
      if(edge_faces_[e][0] < 0)
      {
        edge_vertices_[e] = {a, b};
        edge_faces_[e][0] = f;
      }
      else if(edge_faces_[e][1] < 0)
      {
        const auto& ab = edge_vertices_[e];
        if(ab[0] == a && ab[1] == b)
          fail(Mesh_defect::inconsistent_orientation,
               "faces " + std::to_string(edge_faces_[e][0]) + " and " + std::to_string(f) + " traverse " + name +
                   " in the same direction");
        if(!(ab[0] == b && ab[1] == a))
          fail(Mesh_defect::invalid_index, "the edge table gives " + name + " two different pairs of end points");
        edge_faces_[e][1] = f;
      }
      else
        fail(Mesh_defect::non_manifold_edge, name + " belongs to more than two faces");
      face_edges_[f][(k + 2) % 3] = e; // the edge from corner k to k+1 is opposite corner k+2
    }
    face_vertices_[f] = faces[f];
  }
  for(int e = 0; e < ne; ++e)
    if(edge_faces_[e][0] < 0) fail(Mesh_defect::invalid_index, "edge " + std::to_string(e) + " belongs to no face");

  interior_index_.assign(ne, -1);
  for(int e = 0; e < ne; ++e)
    if(edge_faces_[e][1] >= 0)
    {
      interior_index_[e] = static_cast<int>(interior_edges_.size());
      interior_edges_.push_back(e);
    }
}

void Intrinsic_mesh::check_vertex_manifoldness() const
{
  // Corners around a vertex joined through interior edges form fans; a manifold
  // vertex has exactly one.
  const int nf = number_of_faces();
  Disjoint_sets fans(3 * static_cast<std::size_t>(nf));
  auto corner_of = [&](int f, int v) {
    for(int k = 0; k < 3; ++k)
      if(face_vertices_[f][k] == v) return 3 * f + k;
    return -1;
  };
  for(int e = 0; e < number_of_edges(); ++e)
  {
    const auto& ff = edge_faces_[e];
    if(ff[1] < 0) continue;
    for(int v : edge_vertices_[e]) fans.unite(corner_of(ff[0], v), corner_of(ff[1], v));
  }
  std::vector<int> fan_of_vertex(number_of_vertices(), -1);
  for(int c = 0; c < 3 * nf; ++c)
  {
    const int v = face_vertices_[c / 3][c % 3];
    const int root = fans.find(c);
    if(fan_of_vertex[v] < 0)
      fan_of_vertex[v] = root;
    else if(fan_of_vertex[v] != root)
      fail(Mesh_defect::non_manifold_vertex,
           "vertex " + std::to_string(v) + " is non-manifold: its faces form more than one fan");
  }
}

void Intrinsic_mesh::compute_topology()
{
  const int nv = number_of_vertices();
  Disjoint_sets sets(nv);
  for(const auto& t : face_vertices_)
  {
    sets.unite(t[0], t[1]);
    sets.unite(t[1], t[2]);
  }
  std::vector<char> used(nv, 0);
  for(const auto& t : face_vertices_)
    for(int v : t) used[v] = 1;

  vertex_component_.assign(nv, -1);
  std::vector<int> component_of_root(nv, -1);
  int nc = 0;
  for(int v = 0; v < nv; ++v)
  {
    if(!used[v])
    {
      ++topology_.number_of_isolated_vertices;
      continue;
    }
    int& c = component_of_root[sets.find(v)];
    if(c < 0) c = nc++;
    vertex_component_[v] = c;
  }
  topology_.components.assign(nc, Component_topology());
  for(int v = 0; v < nv; ++v)
    if(used[v]) ++topology_.components[vertex_component_[v]].number_of_vertices;
  for(int f = 0; f < number_of_faces(); ++f) ++topology_.components[face_component(f)].number_of_faces;
  for(int e = 0; e < number_of_edges(); ++e) ++topology_.components[edge_component(e)].number_of_edges;

  // Boundary loops: connected pieces of the boundary-edge graph (each boundary
  // vertex of a manifold mesh has exactly two boundary edges).
  Disjoint_sets loops(nv);
  std::vector<char> on_boundary(nv, 0);
  for(int e = 0; e < number_of_edges(); ++e)
    if(is_boundary_edge(e))
    {
      loops.unite(edge_vertices_[e][0], edge_vertices_[e][1]);
      on_boundary[edge_vertices_[e][0]] = on_boundary[edge_vertices_[e][1]] = 1;
    }
  for(int v = 0; v < nv; ++v)
    if(on_boundary[v] && loops.find(v) == v) ++topology_.components[vertex_component_[v]].number_of_boundary_loops;

  for(Component_topology& c : topology_.components)
  {
    const int twice_genus = 2 - c.number_of_boundary_loops - c.euler_characteristic();
    if(twice_genus < 0 || twice_genus % 2 != 0)
      fail(Mesh_defect::non_manifold_vertex,
           "a component has Euler characteristic " + std::to_string(c.euler_characteristic()) + " with " +
               std::to_string(c.number_of_boundary_loops) + " boundary loops, which no orientable surface has");
    c.genus = twice_genus / 2;
  }
}

void Intrinsic_mesh::compute_lengths(const Intrinsic_mesh_options& options)
{
  const int ne = number_of_edges();
  edge_lengths_.resize(ne);
  double sum = 0;
  for(int e = 0; e < ne; ++e)
  {
    edge_lengths_[e] = safe_norm(sub(positions_[edge_vertices_[e][1]], positions_[edge_vertices_[e][0]]));
    if(!std::isfinite(edge_lengths_[e]))
      fail(Mesh_defect::non_finite_coordinate,
           "edge " + std::to_string(e) + " (vertices " + std::to_string(edge_vertices_[e][0]) + ", " +
               std::to_string(edge_vertices_[e][1]) + ") is longer than the largest double: the coordinates are too large");
    sum += edge_lengths_[e] / ne; // divided first: the sum of large lengths must not overflow
  }
  mean_edge_length_ = sum;
  length_unit_ = sum > 0 ? std::ldexp(1., std::ilogb(sum)) : 1.;

  auto margin = [&](int f) {
    const double a = face_edge_length(f, 0), b = face_edge_length(f, 1), c = face_edge_length(f, 2);
    return std::min({b + c - a, a + c - b, a + b - c});
  };

  if(options.use_intrinsic_mollification)
  {
    if(!(options.mollification_epsilon > 0))
      throw Invalid_input("mollification_epsilon must be positive");
    const double eps = options.mollification_epsilon * mean_edge_length_;
    double delta = 0;
    for(int f = 0; f < number_of_faces(); ++f) delta = std::max(delta, eps - margin(f));
    // Adding delta to all three lengths raises every margin by delta.
    mollification_delta_ = delta;
    if(delta > 0)
      for(double& l : edge_lengths_) l += delta;
  }

  for(int f = 0; f < number_of_faces(); ++f)
  {
    const double longest =
        std::max({face_edge_length(f, 0), face_edge_length(f, 1), face_edge_length(f, 2)});
    if(!(margin(f) > options.degeneracy_tolerance * longest))
    {
      std::ostringstream msg;
      msg << "face " << f << " (vertices " << face_vertices_[f][0] << ", " << face_vertices_[f][1] << ", "
          << face_vertices_[f][2] << ") is degenerate: edge lengths " << face_edge_length(f, 0) << ", "
          << face_edge_length(f, 1) << ", " << face_edge_length(f, 2);
      // Doubles resolve a coordinate of size X to about X * 1.1e-16: a face that small
      // next to its distance from the origin has lost its shape in the rounding of its
      // coordinates, which no mollification restores.
      double coordinate = 0;
      for(int v : face_vertices_[f]) coordinate = std::max(coordinate, largest_magnitude(positions_[v]));
      const double resolution = coordinate * std::numeric_limits<double>::epsilon();
      if(!(longest > resolution / options.degeneracy_tolerance))
        msg << ", at coordinates up to " << coordinate << ", which doubles resolve only to about " << resolution
            << ": the mesh is too small for its distance from the origin (translate it towards the origin)";
      else
        msg << "; use the named parameter use_intrinsic_mollification(true) to process it";
      fail(Mesh_defect::degenerate_face, msg.str());
    }
  }
}

void Intrinsic_mesh::compute_layout_and_frames()
{
  const int nf = number_of_faces();
  face_areas_.resize(nf);
  shape_areas_.resize(nf);
  corner2_.resize(nf);
  frames_.resize(nf);
  for(int f = 0; f < nf; ++f)
  {
    // Rotate the local numbering so that the edge from corner 0 to corner 1
    // (local edge 2) is the longest: the most stable base for the layout.
    int longest = 0;
    for(int k = 1; k < 3; ++k)
      if(face_edge_length(f, k) > face_edge_length(f, longest)) longest = k;
    const int shift = (longest + 1) % 3; // new corner 0 = old corner `shift`
    const std::array<int, 3> v = face_vertices_[f], e = face_edges_[f];
    for(int k = 0; k < 3; ++k)
    {
      face_vertices_[f][k] = v[(k + shift) % 3];
      face_edges_[f][k] = e[(k + shift) % 3];
    }

    // Everything in units of the longest edge l2, so that no product of lengths under-
    // or overflows; areas and layouts are scaled back at the end.
    const double l2 = face_edge_length(f, 2);
    const double r0 = face_edge_length(f, 0) / l2, r1 = face_edge_length(f, 1) / l2;
    const double shape_area = triangle_area(r0, r1, 1.);
    shape_areas_[f] = shape_area;
    face_areas_[f] = shape_area * l2 * l2;
    corner2_[f] = {0.5 * (1 + r1 * r1 - r0 * r0) * l2, 2 * shape_area * l2};
    // Areas weigh every integral and their inverses every divergence: below the
    // smallest normal double they lose their digits (or vanish), above the largest
    // they are infinite.
    if(!(face_areas_[f] >= std::numeric_limits<double>::min()) ||
       !(face_areas_[f] <= std::numeric_limits<double>::max()))
    {
      std::ostringstream msg;
      msg << "face " << f << " has edges of length " << l2 << " and area " << face_areas_[f]
          << ", outside the range of double precision (" << std::numeric_limits<double>::min() << " to "
          << std::numeric_limits<double>::max()
          << "): the mesh is too " << (l2 < 1 ? "small" : "large") << "; scale it towards unit size";
      fail(Mesh_defect::unrepresentable_size, msg.str());
    }

    // 3D frame: e1 along corner 0 -> corner 1, e2 = n x e1 (from the differences of the
    // positions divided by their largest coordinate, for the same reason).
    const Point& p0 = positions_[face_vertices_[f][0]];
    Vector d1 = sub(positions_[face_vertices_[f][1]], p0);
    Vector d2 = sub(positions_[face_vertices_[f][2]], p0);
    const double unit = std::max(largest_magnitude(d1), largest_magnitude(d2));
    if(unit > 0)
    {
      d1 = scaled(d1, 1 / unit);
      d2 = scaled(d2, 1 / unit);
    }
    Vector n = cross(d1, d2);
    double nn = norm(n);
    if(!(nn > 1e-14 * dot(d1, d1)))
    {
      // Degenerate in 3D (only possible with mollification): borrow the normals
      // of the faces across the edges, else any direction.
      n = {0, 0, 0};
      for(int k = 0; k < 3; ++k)
        for(int g : edge_faces_[face_edges_[f][k]])
          if(g >= 0 && g != f)
          {
            const auto& t = face_vertices_[g];
            Vector a = sub(positions_[t[1]], positions_[t[0]]), b = sub(positions_[t[2]], positions_[t[0]]);
            const double m = std::max(largest_magnitude(a), largest_magnitude(b));
            if(m > 0) n = add(n, cross(scaled(a, 1 / m), scaled(b, 1 / m)));
          }
      nn = norm(n);
      if(!(nn > 0)) { n = {0, 0, 1}; nn = 1; }
    }
    n = scaled(n, 1 / nn);
    Vector e1 = sub(d1, scaled(n, dot(d1, n)));
    double l = norm(e1);
    if(!(l > 0))
    {
      e1 = std::abs(n[0]) < 0.9 ? Vector{1, 0, 0} : Vector{0, 1, 0};
      e1 = sub(e1, scaled(n, dot(e1, n)));
      l = norm(e1);
    }
    e1 = scaled(e1, 1 / l);
    frames_[f] = {e1, cross(n, e1), n};
  }
}

double Intrinsic_mesh::cotangent(int f, int k) const
{
  // In units of the longest edge (local edge 2), like the shape area.
  const double l2 = face_edge_length(f, 2);
  const double a = face_edge_length(f, k) / l2, b = face_edge_length(f, (k + 1) % 3) / l2,
               c = face_edge_length(f, (k + 2) % 3) / l2;
  return (b * b + c * c - a * a) / (4 * shape_areas_[f]);
}

std::array<double, 2> Intrinsic_mesh::to_frame(int f, const Vector& w) const
{
  return {dot(w, frames_[f][0]), dot(w, frames_[f][1])};
}

Intrinsic_mesh::Vector Intrinsic_mesh::from_frame(int f, double a, double b) const
{
  const Vector& e1 = frames_[f][0];
  const Vector& e2 = frames_[f][1];
  return {a * e1[0] + b * e2[0], a * e1[1] + b * e2[1], a * e1[2] + b * e2[2]};
}

} // namespace Tangent_vector_fields
} // namespace CGAL
