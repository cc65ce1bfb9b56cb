// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/Field_constraint.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace CGAL {
namespace Tangent_vector_fields {

namespace {

std::string vector_text(const std::array<double, 3>& v)
{
  std::ostringstream s;
  s << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")";
  return s.str();
}

void check_index(int i, int n, const char* what, const Field_constraint& c)
{
  if(i < 0 || i >= n)
    throw Invalid_input(std::string(what) + " index " + std::to_string(i) + " out of range [0, " + std::to_string(n) +
                        ") in constraint: " + c.describe());
}

void check_finite(const Field_constraint& c)
{
  bool ok = std::isfinite(c.value);
  for(int k = 0; k < 3; ++k) ok = ok && std::isfinite(c.vector[k]) && std::isfinite(c.barycentric[k]);
  if(!ok) throw Invalid_input("non-finite number in constraint: " + c.describe());
}

// Barycentric coordinates must describe a point of the (closed) face.
void check_barycentric(const Field_constraint& c)
{
  if(!is_point_of_face(c.barycentric))
    throw Invalid_input("barycentric coordinates must be non-negative and sum to 1: " + c.describe());
}

// Sums weighted rows, merging repeated indices.
Constraint_row combine(const std::vector<std::pair<double, Constraint_row>>& parts)
{
  std::map<int, double> sum;
  for(const auto& p : parts)
    for(const auto& e : p.second.entries) sum[e.first] += p.first * e.second;
  Constraint_row row;
  row.entries.assign(sum.begin(), sum.end());
  return row;
}

// Row of div_h at vertex v: -(1/M_v) sum_i G(i, v) MX_i x_i.
Constraint_row divergence_row(const Operator_matrices& ops, int v)
{
  const double mass = ops.vertex_masses()[v];
  Constraint_row row;
  for(Operator_matrices::Sparse_matrix::InnerIterator it(ops.G(), v); it; ++it)
    row.entries.emplace_back(static_cast<int>(it.row()), -it.value() * ops.field_masses()[it.row()] / mass);
  return row;
}

// Row of curl*_h at edge e: (1/M*_e) sum_i G*(i, e) (J MX x)_i, with (J y)_{2f} = -y_{2f+1}
// and (J y)_{2f+1} = y_{2f}.
Constraint_row curl_row(const Operator_matrices& ops, int e)
{
  const double mass = ops.edge_masses()[e];
  std::map<int, double> sum;
  for(Operator_matrices::Sparse_matrix::InnerIterator it(ops.G_star(), e); it; ++it)
  {
    const int i = static_cast<int>(it.row());
    const int partner = (i % 2 == 0) ? i + 1 : i - 1;
    const double sign = (i % 2 == 0) ? -1 : 1;
    sum[partner] += sign * it.value() * ops.field_masses()[partner] / mass;
  }
  Constraint_row row;
  row.entries.assign(sum.begin(), sum.end());
  return row;
}

// Frame coordinates of the constraint's vector projected onto its face.
std::array<double, 2> projected_vector(const Intrinsic_mesh& mesh, const Field_constraint& c)
{
  check_index(c.face, mesh.number_of_faces(), "face", c);
  // Divided by its largest coordinate first: the squares (and even the sum) of a finite
  // vector near the largest double may overflow, its direction does not.
  const double largest = std::max({std::abs(c.vector[0]), std::abs(c.vector[1]), std::abs(c.vector[2])});
  if(largest == 0) return {0., 0.};
  const std::array<double, 3> direction = {c.vector[0] / largest, c.vector[1] / largest, c.vector[2] / largest};
  const std::array<double, 2> a = mesh.to_frame(c.face, direction);
  const double length = std::hypot(direction[0], direction[1], direction[2]);
  // A vector nearly normal to its face has a meaningless direction after projection.
  if(std::hypot(a[0], a[1]) <= 1e-8 * length)
    throw Invalid_input("the vector is normal to its face (nothing is left after projecting it onto the face): " +
                        c.describe());
  const std::array<double, 2> projected = {a[0] * largest, a[1] * largest};
  if(!std::isfinite(projected[0]) || !std::isfinite(projected[1]))
    throw Invalid_input("the vector's projection onto its face is not finite in double precision: " + c.describe());
  return projected;
}

} // namespace

bool Field_constraint::same_rows_as(const Field_constraint& other) const
{
  if(kind != other.kind || face != other.face || vertex != other.vertex || edge != other.edge) return false;
  switch(kind)
  {
  case Constraint_kind::vector: return true;
  case Constraint_kind::direction: return false; // the direction is the row itself
  default: return vertex >= 0 || edge >= 0 || barycentric == other.barycentric;
  }
}

std::vector<double> constraint_values(const Intrinsic_mesh& mesh, const Field_constraint& c)
{
  check_finite(c);
  switch(c.kind)
  {
  case Constraint_kind::vector:
  {
    const std::array<double, 2> a = projected_vector(mesh, c);
    return {a[0], a[1]};
  }
  case Constraint_kind::direction: return {0.0};
  default: return {c.value};
  }
}

Field_constraint Field_constraint::boundary_alignment(const Intrinsic_mesh& mesh, int edge)
{
  if(edge < 0 || edge >= mesh.number_of_edges())
    throw Invalid_input("edge index " + std::to_string(edge) + " out of range for a boundary alignment");
  if(!mesh.is_boundary_edge(edge))
    throw Invalid_input("edge " + std::to_string(edge) + " is not a boundary edge: it cannot take a boundary alignment");
  const auto& ends = mesh.edge_vertices(edge);
  const auto& p = mesh.position(ends[0]);
  const auto& q = mesh.position(ends[1]);
  return direction_in_face(mesh.edge_faces(edge)[0], {{q[0] - p[0], q[1] - p[1], q[2] - p[2]}});
}

namespace {
// A divergence or curl constraint is at its vertex or edge unless it names a face: so that a
// negative vertex or edge index is reported as such, not as a point of face -1.
bool at_element(int element, int face) { return element >= 0 || face < 0; }
} // namespace

std::string Field_constraint::describe() const
{
  std::ostringstream s;
  const std::string point = "face " + std::to_string(face) + " at barycentric " + vector_text(barycentric);
  switch(kind)
  {
  case Constraint_kind::vector: s << "vector " << vector_text(vector) << " in face " << face; break;
  case Constraint_kind::direction: s << "direction " << vector_text(vector) << " in face " << face; break;
  case Constraint_kind::divergence:
    s << "divergence " << value << (at_element(vertex, face) ? " at vertex " + std::to_string(vertex) : " in " + point);
    break;
  case Constraint_kind::curl:
    s << "curl " << value << (at_element(edge, face) ? " at edge " + std::to_string(edge) : " in " + point);
    break;
  }
  return s.str();
}

bool is_point_of_face(const std::array<double, 3>& b)
{
  return std::isfinite(b[0] + b[1] + b[2]) && std::min({b[0], b[1], b[2]}) >= -1e-9 &&
         std::abs(b[0] + b[1] + b[2] - 1) <= 1e-9;
}

std::array<double, 3> barycentric_coordinates(const Intrinsic_mesh& mesh, int face, const std::array<double, 3>& point)
{
  if(face < 0 || face >= mesh.number_of_faces())
    throw Invalid_input("face index " + std::to_string(face) + " out of range for a point");
  if(!std::isfinite(point[0]) || !std::isfinite(point[1]) || !std::isfinite(point[2]))
    throw Invalid_input("non-finite point in face " + std::to_string(face));
  // In the face's own frame, corner 0 at the origin, corner 1 at (l, 0), corner 2 at (x, y).
  const auto& o = mesh.position(mesh.face_vertices(face)[0]);
  const std::array<double, 2> p = mesh.to_frame(face, {{point[0] - o[0], point[1] - o[1], point[2] - o[2]}});
  const auto& q1 = mesh.position(mesh.face_vertices(face)[1]);
  const auto& q2 = mesh.position(mesh.face_vertices(face)[2]);
  const std::array<double, 2> a = mesh.to_frame(face, {{q1[0] - o[0], q1[1] - o[1], q1[2] - o[2]}});
  const std::array<double, 2> b = mesh.to_frame(face, {{q2[0] - o[0], q2[1] - o[1], q2[2] - o[2]}});
  const double det = a[0] * b[1] - a[1] * b[0];
  double w1 = (p[0] * b[1] - p[1] * b[0]) / det, w2 = (a[0] * p[1] - a[1] * p[0]) / det;
  double w0 = 1 - w1 - w2;
  // Clamp into the face and renormalise.
  w0 = std::max(w0, 0.), w1 = std::max(w1, 0.), w2 = std::max(w2, 0.);
  const double sum = w0 + w1 + w2;
  return {{w0 / sum, w1 / sum, w2 / sum}};
}

std::array<double, 3> barycentric_in_face_order(const Intrinsic_mesh& mesh, int face, const std::array<int, 3>& vertices,
                                                const std::array<double, 3>& weights)
{
  if(face < 0 || face >= mesh.number_of_faces())
    throw Invalid_input("face index " + std::to_string(face) + " out of range for a point");
  std::array<double, 3> out{{0, 0, 0}};
  std::array<bool, 3> used{{false, false, false}};
  for(int k = 0; k < 3; ++k)
  {
    int found = -1;
    for(int j = 0; j < 3; ++j)
      if(!used[j] && mesh.face_vertices(face)[j] == vertices[k]) found = j;
    if(found < 0)
      throw Invalid_input("vertex " + std::to_string(vertices[k]) + " is not a vertex of face " + std::to_string(face));
    used[found] = true;
    out[found] = weights[k];
  }
  return out;
}

std::vector<Constraint_row> constraint_rows(const Operator_matrices& ops, const Field_constraint& c)
{
  const Intrinsic_mesh& mesh = ops.mesh();
  check_finite(c);
  std::vector<Constraint_row> rows;
  // Only divergence and curl rows need it (a sum over all faces: not for vector edits).
  auto length_scale = [&ops]() { return std::sqrt(ops.face_areas().sum()); };
  switch(c.kind)
  {
  case Constraint_kind::vector:
  case Constraint_kind::direction:
  {
    const std::array<double, 2> a = projected_vector(mesh, c);
    if(c.kind == Constraint_kind::vector)
    {
      for(int k = 0; k < 2; ++k)
      {
        Constraint_row row;
        row.entries.emplace_back(2 * c.face + k, 1.0);
        row.value = a[k];
        rows.push_back(row);
      }
    }
    else
    {
      const double projected = std::hypot(a[0], a[1]);
      if(projected == 0) throw Invalid_input("a direction constraint needs a non-zero direction: " + c.describe());
      // The component along the in-plane normal J d of the direction vanishes.
      Constraint_row row;
      row.entries.emplace_back(2 * c.face, -a[1] / projected);
      row.entries.emplace_back(2 * c.face + 1, a[0] / projected);
      rows.push_back(row);
    }
    break;
  }
  case Constraint_kind::divergence:
  {
    Constraint_row row;
    if(at_element(c.vertex, c.face))
    {
      check_index(c.vertex, mesh.number_of_vertices(), "vertex", c);
      if(mesh.is_isolated_vertex(c.vertex))
        throw Invalid_input("vertex " + std::to_string(c.vertex) + " is in no face: it has no divergence");
      row = divergence_row(ops, c.vertex);
    }
    else
    {
      check_index(c.face, mesh.number_of_faces(), "face", c);
      check_barycentric(c);
      std::vector<std::pair<double, Constraint_row>> parts;
      for(int k = 0; k < 3; ++k) parts.emplace_back(c.barycentric[k], divergence_row(ops, mesh.face_vertices(c.face)[k]));
      row = combine(parts);
    }
    row.value = c.value;
    row.unit_area_scale = length_scale();
    rows.push_back(row);
    break;
  }
  case Constraint_kind::curl:
  {
    Constraint_row row;
    if(at_element(c.edge, c.face))
    {
      check_index(c.edge, mesh.number_of_edges(), "edge", c);
      row = curl_row(ops, c.edge);
    }
    else
    {
      check_index(c.face, mesh.number_of_faces(), "face", c);
      check_barycentric(c);
      // Crouzeix-Raviart interpolation: the edge opposite corner k has the basis function 1 - 2 b_k.
      std::vector<std::pair<double, Constraint_row>> parts;
      for(int k = 0; k < 3; ++k) parts.emplace_back(1 - 2 * c.barycentric[k], curl_row(ops, mesh.face_edges(c.face)[k]));
      row = combine(parts);
    }
    row.value = c.value;
    row.unit_area_scale = length_scale();
    rows.push_back(row);
    break;
  }
  }
  return rows;
}

} // namespace Tangent_vector_fields
} // namespace CGAL
