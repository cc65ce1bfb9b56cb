// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Streamline_tracer: the checks of its entry points, single streamlines and fur
// strokes on the walk of streamline_walker.h.

#include "streamline_walker.h"

#include <CGAL/Tangent_vector_fields/N_field_singularities.h>
#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <string>
#include <utility>

namespace CGAL {
namespace Tangent_vector_fields {

using internal::Barycentric;
using internal::No_proximity;
using internal::Position;
using internal::V2;
using internal::V3;

const char* to_string(Streamline_stop stop)
{
  switch(stop)
  {
  case Streamline_stop::none: return "none";
  case Streamline_stop::boundary: return "boundary";
  case Streamline_stop::zero_field: return "zero_field";
  case Streamline_stop::sink_edge: return "sink_edge";
  case Streamline_stop::sink_vertex: return "sink_vertex";
  case Streamline_stop::maximum_length: return "maximum_length";
  case Streamline_stop::maximum_segments: return "maximum_segments";
  case Streamline_stop::closed_loop: return "closed_loop";
  case Streamline_stop::too_close: return "too_close";
  case Streamline_stop::stalled: return "stalled";
  case Streamline_stop::singular_vertex: return "singular_vertex";
  }
  return "unknown";
}

double Streamline::length() const
{
  double l = 0;
  for(std::size_t i = 1; i < points.size(); ++i) l += internal::distance3(points[i - 1], points[i]);
  return l;
}

namespace {

std::vector<Streamline> fur_strokes(const internal::Streamline_walker& walker, const Fur_options& o)
{
  const double length = walker.to_absolute(o.length, o.length_unit);
  if(!(length > 0) || !std::isfinite(length)) throw Invalid_input("fur: the stroke length must be positive");
  if(o.branch < -1 || o.branch >= walker.n)
    throw Invalid_input("fur: branch " + std::to_string(o.branch) + " asked of a field of " +
                        std::to_string(walker.n) + " vector(s) per face (-1: all)");
  internal::check_streamline_options(o.tracing);
  // Every stroke is kept in memory: a count beyond this is a mistake (a density in the wrong
  // unit), and llround of an infinite or huge product is undefined.
  const double max_strokes = 1e7;
  long count = o.number_of_strokes;
  if(count <= 0)
  {
    if(!(o.density > 0) || !std::isfinite(o.density))
      throw Invalid_input("fur: give number_of_strokes or a positive finite density");
    const double expected = o.density * walker.surface->total_area;
    if(!(expected <= max_strokes))
      throw Invalid_input("fur: the density gives " + internal::short_number(expected) + " strokes, more than 1e7");
    count = static_cast<long>(std::llround(expected));
  }
  if(count > max_strokes)
    throw Invalid_input("fur: " + std::to_string(count) + " strokes asked, more than 1e7");
  const int first = o.branch < 0 ? 0 : o.branch, last = o.branch < 0 ? walker.n - 1 : o.branch;
  const bool roots_reference = o.magnitude_reference == Fur_options::Magnitude_reference::roots;
  if(walker.on_demand && o.scale_length_by_magnitude && !roots_reference)
    throw Invalid_input("fur: a field given face by face knows its largest magnitude only over the faces it read: "
                        "scale the strokes by the largest magnitude at the roots (Magnitude_reference::roots)");
  // The roots depend only on the mesh and the random seed.  The magnitude the lengths and the
  // zero-field test are relative to: the largest over all faces, or over the roots' faces (a
  // field on demand reads only those before tracing): the generator then runs twice rather than
  // keeping up to 1e7 roots.
  const std::vector<double>& cumulative = walker.cumulative_areas();
  double reference = walker.maximum_magnitude;
  if(roots_reference || walker.on_demand)
  {
    reference = 0;
    // A field on demand is told the faces of the roots a few ahead (`ahead`: the same roots).
    const long lead = walker.on_demand ? 8 : 0;
    std::mt19937_64 gen(o.random_seed), ahead(o.random_seed);
    for(long i = 0; i < std::min(lead, count); ++i) walker.hint(walker.random_position(ahead, cumulative).face);
    for(long i = 0; i < count; ++i)
    {
      if(i + lead < count && lead > 0) walker.hint(walker.random_position(ahead, cumulative).face);
      reference = std::max(reference, walker.face(walker.random_position(gen, cumulative).face).magnitude);
    }
  }
  std::mt19937_64 gen(o.random_seed);
  std::vector<Streamline> strokes;
  strokes.reserve(static_cast<std::size_t>(count * (last - first + 1)));
  for(long i = 0; i < count; ++i)
  {
    Position root = walker.random_position(gen, cumulative);
    Streamline_options t = o.tracing;
    t.forward = true;
    t.backward = false;
    t.length_unit = Length_unit::absolute;
    t.maximum_length = length;
    if(o.scale_length_by_magnitude)
      t.maximum_length = length * walker.face(root.face).magnitude / std::max(reference, 1e-300);
    t.loop_closure_tolerance = 0;
    if(!(t.maximum_length > 0)) continue;
    for(int j = first; j <= last; ++j)
    {
      root.branch = j;
      No_proximity* none = nullptr;
      Streamline s = walker.trace(root, t, 0, none, none, false, nullptr, reference);
      if(s.points.size() >= 2) strokes.push_back(std::move(s));
    }
  }
  return strokes;
}

} // namespace

struct Streamline_tracer::Impl : internal::Streamline_walker
{
  using internal::Streamline_walker::Streamline_walker;
  explicit Impl(internal::Streamline_walker&& walker) : internal::Streamline_walker(std::move(walker)) {}
};

Streamline_tracer::Streamline_tracer(std::shared_ptr<const Intrinsic_mesh> mesh, const Eigen::VectorXd& field, int n,
                                     const std::vector<int>& singular_vertices)
  : impl_(std::make_unique<Impl>(std::move(mesh), field, n, singular_vertices))
{}

Streamline_surface::Streamline_surface(std::shared_ptr<const Intrinsic_mesh> mesh)
  : impl_(std::make_shared<const internal::Walker_surface>(std::move(mesh)))
{}

const Intrinsic_mesh& Streamline_surface::mesh() const { return *impl_->mesh; }

Streamline_tracer::Streamline_tracer(const Streamline_surface& surface, std::shared_ptr<const Face_vector_source> field,
                                     int n, const std::vector<int>& singular_vertices)
  : impl_(std::make_unique<Impl>(surface.impl_, std::move(field), n, singular_vertices))
{}

namespace internal {

std::vector<int> n_field_stop_vertices(const N_field_operators& operators, const Eigen::VectorXd& z)
{
  const Intrinsic_mesh& M = operators.mesh();
  if(z.size() != 2 * static_cast<Eigen::Index>(M.number_of_faces()))
    throw Invalid_input("n-field streamlines: the field has " + std::to_string(z.size()) +
                        " entries, the mesh needs " + std::to_string(2 * M.number_of_faces()));
  if(!z.allFinite()) throw Invalid_input("n-field streamlines: the field has non-finite entries");
  std::vector<int> stops;
  for(const N_field_singularity& s : n_field_singularities(operators, z))
    if(!s.on_boundary) stops.push_back(s.vertex); // the boundary stops streamlines anyway
  return stops;
}

} // namespace internal

namespace {

// The walker of an n-field in the power representation: its first vectors (for n = 1 the
// power representation is the vector itself; to_vectors would round it) and its stops.
internal::Streamline_walker n_field_walker(const N_field_operators& operators, const Eigen::VectorXd& z)
{
  const std::vector<int> stops = internal::n_field_stop_vertices(operators, z);
  return internal::Streamline_walker(operators.operators().shared_mesh(),
                                     operators.n() == 1 ? z : operators.to_vectors(z), operators.n(), stops);
}

} // namespace

Streamline_tracer::Streamline_tracer(const N_field_operators& operators, const Eigen::VectorXd& z)
  : impl_(std::make_unique<Impl>(n_field_walker(operators, z)))
{}

Streamline_tracer::~Streamline_tracer() = default;
Streamline_tracer::Streamline_tracer(Streamline_tracer&&) noexcept = default;
Streamline_tracer& Streamline_tracer::operator=(Streamline_tracer&&) noexcept = default;

const Intrinsic_mesh& Streamline_tracer::mesh() const { return *impl_->mesh; }
int Streamline_tracer::n() const { return impl_->n; }
int Streamline_tracer::number_of_families() const { return internal::number_of_families(impl_->n); }
const std::vector<int>& Streamline_tracer::singular_vertices() const { return impl_->singular_list; }
double Streamline_tracer::bounding_box_diagonal() const { return impl_->surface->diagonal; }
double Streamline_tracer::to_absolute(double value, Length_unit unit) const { return impl_->to_absolute(value, unit); }
double Streamline_tracer::maximum_magnitude() const { return impl_->maximum_magnitude; }
std::size_t Streamline_tracer::faces_read() const { return impl_->faces_read(); }

Streamline Streamline_tracer::trace(int face, const std::array<double, 3>& barycentric,
                                    const Streamline_options& options) const
{
  if(face < 0 || face >= impl_->mesh->number_of_faces())
    throw Invalid_input("streamline: face " + std::to_string(face) + " does not exist");
  for(double b : barycentric)
    if(!std::isfinite(b)) throw Invalid_input("streamline: non-finite barycentric coordinates");
  if(options.branch < 0 || options.branch >= impl_->n)
    throw Invalid_input("streamline: branch " + std::to_string(options.branch) + " asked of a field of " +
                        std::to_string(impl_->n) + " vector(s) per face");
  const Position start = impl_->start_position(face, barycentric, options.branch);
  No_proximity* none = nullptr;
  return impl_->trace(start, options, options.loop_closure_tolerance * impl_->mesh->mean_edge_length(), none,
                      none, false, nullptr);
}

Streamline Streamline_tracer::trace_from_point(int face, const std::array<double, 3>& point,
                                               const Streamline_options& options) const
{
  if(face < 0 || face >= impl_->mesh->number_of_faces())
    throw Invalid_input("streamline: face " + std::to_string(face) + " does not exist");
  // Barycentric coordinates of the projection onto the face's plane, in the face frame.
  const Intrinsic_mesh& M = *impl_->mesh;
  const auto& t = M.face_vertices(face);
  const V3& e1 = M.frame_e1(face);
  const V3& e2 = M.frame_e2(face);
  auto local = [&](const V3& p) {
    const V3 d = internal::sub3(p, M.position(t[0]));
    return V2{{internal::dot3(d, e1), internal::dot3(d, e2)}};
  };
  const V2 a = local(M.position(t[1])), b = local(M.position(t[2])), p = local(point);
  const double det = internal::cross2(a, b);
  Barycentric beta{{1. / 3, 1. / 3, 1. / 3}};
  if(std::abs(det) > 0)
  {
    const double u = internal::cross2(p, b) / det, v = internal::cross2(a, p) / det;
    beta = {1 - u - v, u, v};
  }
  return trace(face, beta, options);
}

std::vector<Streamline> Streamline_tracer::evenly_spaced(const Evenly_spaced_options& options) const
{
  return internal::evenly_spaced_streamlines(*impl_, options);
}

std::vector<Streamline> Streamline_tracer::fur(const Fur_options& options) const { return fur_strokes(*impl_, options); }

} // namespace Tangent_vector_fields
} // namespace CGAL
