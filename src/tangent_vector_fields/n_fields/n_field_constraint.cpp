// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/N_field_constraint.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <sstream>

namespace CGAL {
namespace Tangent_vector_fields {

namespace {

[[noreturn]] void refuse(const N_field_constraint& c, int n, const std::string& why)
{
  std::ostringstream s;
  s << "n-field constraint \"" << c.describe() << "\" (n = " << n << "): " << why;
  throw Invalid_input(s.str());
}

// The power e^{i n theta} (times the length) of a vector given in 3D, in its face's frame.
std::complex<double> face_power(const N_field_operators& ops, const N_field_constraint& c, bool unit)
{
  const Intrinsic_mesh& mesh = ops.mesh();
  if(c.face < 0 || c.face >= mesh.number_of_faces()) refuse(c, ops.n(), "no such face");
  for(double x : c.vector)
    if(!std::isfinite(x)) refuse(c, ops.n(), "the vector is not finite");
  // Divided by its largest coordinate first: the squares (and even the length) of a
  // finite vector near the largest double may overflow, its direction does not.
  const double largest = std::max({std::abs(c.vector[0]), std::abs(c.vector[1]), std::abs(c.vector[2])});
  if(largest == 0 && c.kind == N_field_constraint_kind::vector) return {0, 0};
  if(largest == 0) refuse(c, ops.n(), "the direction is zero");
  const double relative = std::hypot(c.vector[0] / largest, c.vector[1] / largest, c.vector[2] / largest);
  const double length = largest * relative;
  const std::array<double, 3> unit_vector = {c.vector[0] / largest / relative, c.vector[1] / largest / relative,
                                             c.vector[2] / largest / relative};
  const auto ab = mesh.to_frame(c.face, unit_vector);
  const double in_plane = std::hypot(ab[0], ab[1]);
  if(!(in_plane > 1e-12)) refuse(c, ops.n(), "the vector is normal to its face");
  const double magnitude = unit ? 1. : length * in_plane;
  if(!std::isfinite(magnitude)) refuse(c, ops.n(), "the vector's length is not finite in double precision");
  return std::polar(magnitude, ops.n() * std::atan2(ab[1], ab[0]));
}

// The field at the constraint's point as complex weights on face values (in the face's
// frame): z_f + sum over interior edges of (1/3 - b_k) (rho^n z_g - z_f).
std::vector<std::pair<int, std::complex<double>>> point_weights(const N_field_operators& ops, const N_field_constraint& c)
{
  if(!is_point_of_face(c.barycentric)) refuse(c, ops.n(), "barycentric coordinates must be non-negative and sum to 1");
  std::vector<std::pair<int, std::complex<double>>> weights{{c.face, 1.}};
  if(!c.is_at_point()) return weights;
  const Intrinsic_mesh& mesh = ops.mesh();
  for(int k = 0; k < 3; ++k)
  {
    const int e = mesh.face_edges(c.face)[k];
    const double t = 1. / 3 - c.barycentric[k];
    if(mesh.is_boundary_edge(e) || t == 0) continue;
    const auto& faces = mesh.edge_faces(e);
    const int g = faces[0] == c.face ? faces[1] : faces[0];
    weights.front().second -= t;
    weights.emplace_back(g, t * std::polar(1., ops.n() * ops.transport_angle(e, g)));
  }
  return weights;
}

// Rows Re and Im of sum_h a_h z_h (a complex weight times x + i y).
void add_complex_rows(const std::vector<std::pair<int, std::complex<double>>>& weights, Constraint_row& re,
                      Constraint_row& im)
{
  auto add = [](Constraint_row& row, int i, double x) {
    if(x != 0) row.entries.emplace_back(i, x);
  };
  for(const auto& [h, a] : weights)
  {
    add(re, 2 * h, a.real());
    add(re, 2 * h + 1, -a.imag());
    add(im, 2 * h, a.imag());
    add(im, 2 * h + 1, a.real());
  }
}

struct Ring
{
  N_field_operators::Vertex_fan fan;
  double phi = 0; // turning per face
};

Ring singularity_ring(const N_field_operators& ops, const N_field_constraint& c)
{
  const Intrinsic_mesh& mesh = ops.mesh();
  if(c.vertex < 0 || c.vertex >= mesh.number_of_vertices()) refuse(c, ops.n(), "no such vertex");
  Ring ring;
  ring.fan = ops.vertex_fan(c.vertex);
  if(ring.fan.faces.empty()) refuse(c, ops.n(), "the vertex is in no face");
  if(ring.fan.on_boundary) refuse(c, ops.n(), "the vertex is on the boundary");
  const int m = static_cast<int>(ring.fan.faces.size());
  ring.phi = (2 * M_PI * c.index - ops.n() * ops.vertex_curvatures()[c.vertex]) / m;
  if(!(std::abs(ring.phi) < M_PI))
    refuse(c, ops.n(), "its " + std::to_string(m) + " faces cannot show a turning of " + std::to_string(c.index) +
                           " periods (at most " + std::to_string((m - 1) / 2) + " on a flat vertex)");
  return ring;
}

} // namespace

bool N_field_constraint::same_rows_as(const N_field_constraint& other) const
{
  if(kind != other.kind) return false;
  switch(kind)
  {
  case N_field_constraint_kind::vector: return face == other.face && barycentric == other.barycentric;
  case N_field_constraint_kind::direction: return false; // the row itself holds the direction
  case N_field_constraint_kind::singularity:
    return vertex == other.vertex && index == other.index && face == other.face;
  }
  return false;
}

std::string N_field_constraint::describe() const
{
  std::ostringstream s;
  switch(kind)
  {
  case N_field_constraint_kind::vector:
  case N_field_constraint_kind::direction:
    s << (kind == N_field_constraint_kind::vector ? "vector (" : "direction (") << vector[0] << ", " << vector[1]
      << ", " << vector[2] << ") in face " << face;
    if(is_at_point()) s << " at barycentric (" << barycentric[0] << ", " << barycentric[1] << ", " << barycentric[2] << ")";
    break;
  case N_field_constraint_kind::singularity:
    s << "singularity of index " << index << "/n at vertex " << vertex;
    if(face >= 0) s << " anchored by (" << vector[0] << ", " << vector[1] << ", " << vector[2] << ") in face " << face;
    break;
  }
  return s.str();
}

std::vector<double> constraint_values(const N_field_operators& ops, const N_field_constraint& c)
{
  switch(c.kind)
  {
  case N_field_constraint_kind::vector:
  {
    const std::complex<double> w = face_power(ops, c, false);
    point_weights(ops, c); // checks the point
    return {w.real(), w.imag()};
  }
  case N_field_constraint_kind::direction:
    face_power(ops, c, true);
    point_weights(ops, c);
    return {0.};
  case N_field_constraint_kind::singularity:
  {
    std::vector<double> values(2 * (singularity_ring(ops, c).fan.faces.size() - 1), 0.);
    if(c.is_anchored())
    {
      const std::complex<double> w = face_power(ops, c, false);
      values.push_back(w.real());
      values.push_back(w.imag());
    }
    return values;
  }
  }
  return {};
}

std::vector<Constraint_row> constraint_rows(const N_field_operators& ops, const N_field_constraint& c)
{
  std::vector<Constraint_row> rows;
  switch(c.kind)
  {
  case N_field_constraint_kind::vector:
  {
    const std::complex<double> w = face_power(ops, c, false);
    rows.resize(2);
    add_complex_rows(point_weights(ops, c), rows[0], rows[1]);
    rows[0].value = w.real();
    rows[1].value = w.imag();
    break;
  }
  case N_field_constraint_kind::direction:
  {
    // Im(conj(w) z) = Re(w) Im(z) - Im(w) Re(z) = 0, z the field at the point.
    const std::complex<double> w = face_power(ops, c, true);
    Constraint_row re, im;
    add_complex_rows(point_weights(ops, c), re, im);
    rows.resize(1);
    for(const auto& e : re.entries) rows[0].entries.emplace_back(e.first, -w.imag() * e.second);
    for(const auto& e : im.entries) rows[0].entries.emplace_back(e.first, w.real() * e.second);
    break;
  }
  case N_field_constraint_kind::singularity:
  {
    // z_{i+1} - e^{i phi} rho_i^n z_i = 0 for consecutive faces (the closing relation is implied).
    const Ring ring = singularity_ring(ops, c);
    const auto& faces = ring.fan.faces;
    for(std::size_t i = 0; i + 1 < faces.size(); ++i)
    {
      const int f = faces[i], g = faces[i + 1];
      const std::complex<double> a =
          std::polar(1., ring.phi + ops.n() * ops.transport_angle(ring.fan.edges[i], f));
      // Re: x_g - (Re a x_f - Im a y_f);  Im: y_g - (Im a x_f + Re a y_f).
      Constraint_row re, im;
      re.entries = {{2 * g, 1.}, {2 * f, -a.real()}, {2 * f + 1, a.imag()}};
      im.entries = {{2 * g + 1, 1.}, {2 * f, -a.imag()}, {2 * f + 1, -a.real()}};
      rows.push_back(std::move(re));
      rows.push_back(std::move(im));
    }
    if(c.is_anchored())
    {
      if(std::find(faces.begin(), faces.end(), c.face) == faces.end())
        refuse(c, ops.n(), "the anchor face is not around the vertex");
      const std::complex<double> w = face_power(ops, c, false);
      if(w == std::complex<double>(0, 0)) refuse(c, ops.n(), "the anchor vector is zero");
      Constraint_row re, im;
      re.entries = {{2 * c.face, 1.}};
      re.value = w.real();
      im.entries = {{2 * c.face + 1, 1.}};
      im.value = w.imag();
      rows.push_back(std::move(re));
      rows.push_back(std::move(im));
    }
    break;
  }
  }
  return rows;
}

} // namespace Tangent_vector_fields
} // namespace CGAL
