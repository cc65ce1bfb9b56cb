// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a walk starts from: the surface data every walker of a mesh shares, the walker's
// field and its per-face data made on first use, and the start points of walks.

#include "streamline_walker.h"

#include <CGAL/Tangent_vector_fields/errors.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {
Walker_surface::Walker_surface(std::shared_ptr<const Intrinsic_mesh> m) : mesh(std::move(m))
{
  const Intrinsic_mesh& M = *mesh;
  const int nf = M.number_of_faces();
  const int nv = M.number_of_vertices();
  cumulative_area.resize(nf);
  for(int f = 0; f < nf; ++f) cumulative_area[f] = total_area += M.face_area(f);

  vertex_face_start.assign(nv + 1, 0);
  for(int f = 0; f < nf; ++f)
    for(int v : M.face_vertices(f)) ++vertex_face_start[v + 1];
  for(int v = 0; v < nv; ++v) vertex_face_start[v + 1] += vertex_face_start[v];
  vertex_faces.resize(vertex_face_start[nv]);
  std::vector<int> fill(vertex_face_start.begin(), vertex_face_start.end() - 1);
  for(int f = 0; f < nf; ++f)
    for(int v : M.face_vertices(f)) vertex_faces[fill[v]++] = f;

  boundary_vertex.assign(nv, 0);
  for(int e = 0; e < M.number_of_edges(); ++e)
    if(M.is_boundary_edge(e))
      for(int v : M.edge_vertices(e)) boundary_vertex[v] = 1;

  V3 lo{{infinity, infinity, infinity}}, hi{{-infinity, -infinity, -infinity}};
  for(int v = 0; v < nv; ++v)
  {
    if(M.is_isolated_vertex(v)) continue;
    for(int i = 0; i < 3; ++i)
    {
      lo[i] = std::min(lo[i], M.position(v)[i]);
      hi[i] = std::max(hi[i], M.position(v)[i]);
    }
  }
  box_min = lo;
  diagonal = distance3(lo, hi);
}

namespace {

// A whole field as a source: face f at rows 2f, 2f + 1.
class Vector_source : public Face_vector_source
{
public:
  explicit Vector_source(const Eigen::VectorXd& x) : x_(x) {}
  int number_of_faces() const override { return static_cast<int>(x_.size() / 2); }
  std::array<double, 2> face_vector(int f) const override { return {x_[2 * f], x_[2 * f + 1]}; }

private:
  Eigen::VectorXd x_;
};

} // namespace

Streamline_walker::Streamline_walker(std::shared_ptr<const Intrinsic_mesh> m, const Eigen::VectorXd& field,
                                     int n_vectors, const std::vector<int>& singular_vertices)
{
  const int nf = m->number_of_faces();
  if(n_vectors < 1) throw Invalid_input("streamlines: n must be at least 1 (got " + std::to_string(n_vectors) + ")");
  if(field.size() != 2 * static_cast<Eigen::Index>(nf))
    throw Invalid_input("streamlines: the field has " + std::to_string(field.size()) +
                        " frame coordinates, the mesh needs " + std::to_string(2 * nf));
  if(!field.allFinite()) throw Invalid_input("streamlines: the field has non-finite entries");
  surface = std::make_shared<const Walker_surface>(std::move(m));
  mesh = surface->mesh;
  source = std::make_shared<const Vector_source>(field);
  for(int f = 0; f < nf; ++f) maximum_magnitude = std::max(maximum_magnitude, std::hypot(field[2 * f], field[2 * f + 1]));
  set_up(n_vectors, singular_vertices);
}

Streamline_walker::Streamline_walker(std::shared_ptr<const Walker_surface> s,
                                     std::shared_ptr<const Face_vector_source> field, int n_vectors,
                                     const std::vector<int>& singular_vertices)
  : surface(std::move(s)), mesh(surface->mesh), source(std::move(field)), on_demand(true)
{
  if(!source) throw Invalid_input("streamlines: no field given");
  if(source->number_of_faces() != mesh->number_of_faces())
    throw Invalid_input("streamlines: the field has " + std::to_string(source->number_of_faces()) +
                        " faces, the mesh " + std::to_string(mesh->number_of_faces()));
  if(n_vectors < 1) throw Invalid_input("streamlines: n must be at least 1 (got " + std::to_string(n_vectors) + ")");
  set_up(n_vectors, singular_vertices);
}

void Streamline_walker::set_up(int n_vectors, const std::vector<int>& singular_vertices)
{
  n = n_vectors;
  turn.resize(n);
  for(int j = 0; j < n; ++j) turn[j] = {std::cos(2 * M_PI * j / n), std::sin(2 * M_PI * j / n)};
  slot_.assign(mesh->number_of_faces(), -1);
  const int nv = mesh->number_of_vertices();
  singular_vertex.assign(nv, 0);
  for(int v : singular_vertices)
  {
    if(v < 0 || v >= nv)
      throw Invalid_input("streamlines: singular vertex " + std::to_string(v) + " does not exist (the mesh has " +
                          std::to_string(nv) + " vertices)");
    if(!singular_vertex[v]) singular_list.push_back(v);
    singular_vertex[v] = 1;
  }
  std::sort(singular_list.begin(), singular_list.end());
}

const Streamline_walker::Face_data& Streamline_walker::load(int f) const
{
  const Intrinsic_mesh& M = *mesh;
  Face_data F;
  const double l2 = M.face_edge_length(f, 2);
  F.corner = {V2{{0, 0}}, V2{{l2, 0}}, M.corner2_layout(f)};
  const double twice_area = l2 * F.corner[2][1];
  for(int k = 0; k < 3; ++k)
  {
    const V2& a = F.corner[(k + 1) % 3];
    const V2& b = F.corner[(k + 2) % 3];
    F.gradient[k] = {(a[1] - b[1]) / twice_area, (b[0] - a[0]) / twice_area};
  }
  const std::array<double, 2> v = source->face_vector(f);
  if(!std::isfinite(v[0]) || !std::isfinite(v[1]))
    throw Invalid_input("streamlines: the vector of face " + std::to_string(f) + " is not finite");
  F.direction = {v[0], v[1]};
  F.magnitude = std::hypot(v[0], v[1]);
  maximum_magnitude = std::max(maximum_magnitude, F.magnitude);
  slot_[f] = static_cast<int>(pool_.size());
  pool_.push_back(F);
  return pool_.back();
}

double Streamline_walker::to_absolute(double value, Length_unit unit) const
{
  switch(unit)
  {
  case Length_unit::absolute: return value;
  case Length_unit::mean_edge_length: return value * mesh->mean_edge_length();
  case Length_unit::bounding_box_diagonal: return value * surface->diagonal;
  }
  return value;
}

Position Streamline_walker::start_position(int face, const Barycentric& beta, int branch) const
{
  Position pos;
  pos.face = face;
  pos.branch = branch;
  pos.beta = normalised(beta);
  for(int k = 0; k < 3; ++k)
    if(pos.beta[k] >= 1 - vertex_snap)
    {
      place_on_corner(pos, k);
      return pos;
    }
  pos.point = point_of(face, pos.beta);
  return pos;
}
namespace {

// The three uniform numbers of one random position: `skip_random_positions` draws them too, so
// that a generator moved on by it gives the positions that follow.
std::array<double, 3> random_draws(std::mt19937_64& gen)
{
  std::uniform_real_distribution<double> u(0, 1);
  const double a = u(gen), b = u(gen), c = u(gen);
  return {a, b, c};
}

} // namespace

Position Streamline_walker::random_position(std::mt19937_64& gen) const
{
  const std::array<double, 3> draw = random_draws(gen);
  const std::vector<double>& cumulative = surface->cumulative_area;
  const double a = draw[0] * cumulative.back();
  const int f = std::min(static_cast<int>(std::upper_bound(cumulative.begin(), cumulative.end(), a) - cumulative.begin()),
                         number_of_faces() - 1);
  const double r1 = std::sqrt(draw[1]), r2 = draw[2];
  return start_position(f, {1 - r1, r1 * (1 - r2), r1 * r2});
}

void skip_random_positions(std::mt19937_64& gen, long count)
{
  for(long i = 0; i < count; ++i) random_draws(gen);
}

Streamline_walker Streamline_walker::for_another_thread() const
{
  Streamline_walker w;
  w.surface = surface;
  w.mesh = mesh;
  w.source = source;
  w.on_demand = on_demand;
  w.n = n;
  w.turn = turn;
  w.singular_vertex = singular_vertex;
  w.singular_list = singular_list;
  // A whole field's largest magnitude is known; a field on demand's is of the faces read.
  w.maximum_magnitude = on_demand ? 0 : maximum_magnitude;
  w.slot_.assign(slot_.size(), -1);
  return w;
}


} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL
