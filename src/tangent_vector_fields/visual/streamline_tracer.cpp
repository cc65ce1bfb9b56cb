// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Streamline_tracer: the checks of its entry points, single streamlines and fur
// strokes on the walk of streamline_walker.h.

#include "streamline_walker.h"

#include <CGAL/Tangent_vector_fields/N_field_singularities.h>
#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <CGAL/Model_reduction/internal/Thread_pool.h>

#include <algorithm>
#include <functional>
#include <iterator>
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

// Fur on several threads only past this many roots per thread: starting a thread costs about
// as much as tracing a few strokes, and each thread reads its roots' faces anew.
const long roots_per_thread = 256;

std::vector<Streamline> fur_strokes(const internal::Streamline_walker& walker, const Fur_options& o)
{
  const double length = walker.to_absolute(o.length, o.length_unit);
  if(!(length > 0) || !std::isfinite(length)) throw Invalid_input("fur: the stroke length must be positive");
  if(o.branch < -1 || o.branch >= walker.n)
    throw Invalid_input("fur: branch " + std::to_string(o.branch) + " asked of a field of " +
                        std::to_string(walker.n) + " vector(s) per face (-1: all)");
  if(o.threads < 0) throw Invalid_input("fur: threads must be 0 (one per core) or more, not " + std::to_string(o.threads));
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

  // The strokes are independent: thread t traces roots [start[t], start[t + 1]) with its own
  // walker (whose face data needs no lock), from the generator moved on past the roots before
  // them, so that any number of threads gives the same strokes.  A field on demand spends most
  // of the time waiting for memory (the rows of each face), which two threads wait for at once.
  const int threads = static_cast<int>(
    std::min<long>(Model_reduction::internal::thread_count(o.threads), std::max(1L, count / roots_per_thread)));
  std::vector<long> start(threads + 1);
  for(int t = 0; t <= threads; ++t) start[t] = count * t / threads;
  std::vector<internal::Streamline_walker> others;
  for(int t = 1; t < threads; ++t) others.push_back(walker.for_another_thread());
  Model_reduction::internal::Thread_pool pool(threads);
  auto run = [&](const std::function<void(int, const internal::Streamline_walker&, std::mt19937_64&)>& body) {
    auto one = [&](int t) {
      std::mt19937_64 gen(o.random_seed);
      internal::skip_random_positions(gen, start[t]);
      body(t, t == 0 ? walker : others[t - 1], gen);
    };
    if(threads == 1) return one(0);
    // The pool cuts [0, count) as `start` does: range [b, e) is thread t's.
    pool.run(static_cast<std::size_t>(count), [&](std::size_t b, std::size_t) {
      one(static_cast<int>(std::lower_bound(start.begin(), start.end(), static_cast<long>(b)) - start.begin()));
    });
  };

  // The roots depend only on the mesh and the random seed.  The magnitude the lengths and the
  // zero-field test are relative to: the largest over all faces, or over the roots' faces (a
  // field on demand reads only those before tracing): the generator then runs twice rather than
  // keeping up to 1e7 roots.
  double reference = walker.maximum_magnitude;
  if(roots_reference || walker.on_demand)
  {
    std::vector<double> largest(threads, 0);
    run([&](int t, const internal::Streamline_walker& w, std::mt19937_64& gen) {
      // A field on demand is told the faces of the roots a few ahead (`ahead`: the same roots).
      const long lead = w.on_demand ? 8 : 0, end = start[t + 1];
      std::mt19937_64 ahead = gen;
      for(long i = start[t]; i < std::min(start[t] + lead, end); ++i) w.hint(w.random_position(ahead).face);
      for(long i = start[t]; i < end; ++i)
      {
        if(i + lead < end && lead > 0) w.hint(w.random_position(ahead).face);
        largest[t] = std::max(largest[t], w.face(w.random_position(gen).face).magnitude);
      }
    });
    reference = *std::max_element(largest.begin(), largest.end());
  }
  std::vector<std::vector<Streamline>> parts(threads);
  run([&](int t, const internal::Streamline_walker& w, std::mt19937_64& gen) {
    std::vector<Streamline>& strokes = parts[t];
    strokes.reserve(static_cast<std::size_t>((start[t + 1] - start[t]) * (last - first + 1)));
    for(long i = start[t]; i < start[t + 1]; ++i)
    {
      Position root = w.random_position(gen);
      Streamline_options s = o.tracing;
      s.forward = true;
      s.backward = false;
      s.length_unit = Length_unit::absolute;
      s.maximum_length = length;
      if(o.scale_length_by_magnitude)
        s.maximum_length = length * w.face(root.face).magnitude / std::max(reference, 1e-300);
      s.loop_closure_tolerance = 0;
      if(!(s.maximum_length > 0)) continue;
      for(int j = first; j <= last; ++j)
      {
        root.branch = j;
        No_proximity* none = nullptr;
        Streamline stroke = w.trace(root, s, 0, none, none, false, nullptr, reference);
        if(stroke.points.size() >= 2) strokes.push_back(std::move(stroke));
      }
    }
  });
  for(const internal::Streamline_walker& w : others)
  {
    walker.maximum_magnitude = std::max(walker.maximum_magnitude, w.maximum_magnitude);
    walker.faces_read_elsewhere += w.faces_read();
  }
  std::vector<Streamline> strokes = std::move(parts[0]);
  for(int t = 1; t < threads; ++t)
    strokes.insert(strokes.end(), std::make_move_iterator(parts[t].begin()), std::make_move_iterator(parts[t].end()));
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
