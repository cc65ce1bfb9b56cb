// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The exact face-by-face walk that every streamline is made of (private to src/visual):
// the per-face data of the field, positions in barycentric coordinates of each face's 2D
// layout, and one walk from a start point until a stop.  Evenly spaced seeding and fur
// are built on it.

#ifndef CGAL_TANGENT_VECTOR_FIELDS_SRC_VISUAL_STREAMLINE_WALKER_H
#define CGAL_TANGENT_VECTOR_FIELDS_SRC_VISUAL_STREAMLINE_WALKER_H

#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

typedef std::array<double, 2> V2;
typedef std::array<double, 3> V3;
typedef std::array<double, 3> Barycentric;

const double infinity = std::numeric_limits<double>::infinity();
// A barycentric coordinate at most this small at the end of a segment puts the point on the vertex.
const double vertex_snap = 1e-12;
// This many consecutive segments shorter than 1e-12 mean edge lengths: the trace has stalled.
const int stalled_count = 64;

inline double dot2(const V2& a, const V2& b) { return a[0] * b[0] + a[1] * b[1]; }
inline double cross2(const V2& a, const V2& b) { return a[0] * b[1] - a[1] * b[0]; }
inline double dot3(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline V3 sub3(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double distance3(const V3& a, const V3& b) { return std::sqrt(dot3(sub3(a, b), sub3(a, b))); }

// The families of lines of an n-field: n / 2 for even n (a vector and its opposite are
// one line), n for odd n.
inline int number_of_families(int n) { return n % 2 == 0 ? n / 2 : n; }

// Clamps to non-negative and normalises to sum 1.
inline Barycentric normalised(Barycentric b)
{
  double s = 0;
  for(double& x : b)
  {
    x = std::max(x, 0.);
    s += x;
  }
  if(!(s > 0)) return {1. / 3, 1. / 3, 1. / 3};
  for(double& x : b) x /= s;
  return b;
}

// Where a walk is: a face, barycentric coordinates in it, whether the point is on the
// edge it came through (local index) or on a vertex (local corner), and which of the
// face's n vectors it follows.
struct Position
{
  int face = -1;
  Barycentric beta{{1. / 3, 1. / 3, 1. / 3}};
  int entered_edge = -1; // local edge of `face` the walk entered through
  int corner = -1;       // local corner of `face` the point sits on
  int branch = 0;        // the vector of `face` followed (0 for a vector field)
  V3 point{{0, 0, 0}};
};

// One straight piece of a walk, for seeding beside accepted streamlines.
struct Segment_record
{
  int face;
  int branch;
  Barycentric start, end;
  double length;
};

struct Walk_settings
{
  double sign = 1;       // +1 along the field, -1 against it
  bool rotated = false;  // follow J v instead of v (walking across the streamlines)
  double maximum_length = infinity;
  int maximum_segments = 100000;
  double zero_threshold = 0;
  // Loop closure (forward walks from a seed).
  bool check_closure = false;
  int seed_face = -1;
  int seed_branch = 0;
  V2 seed_layout{{0, 0}};
  double closure_tolerance = 0;
  bool keep_segments = false;
};

struct Walk
{
  std::vector<V3> points; // starts with the start point
  std::vector<int> faces; // one per segment
  std::vector<Segment_record> segments;
  Streamline_stop stop = Streamline_stop::none;
  Position end;
  double length = 0;
};

// No proximity test: samples are never taken.
struct No_proximity
{
  double step() const { return infinity; }
  bool too_close(const V3&, double, const V3&) { return false; }
  bool near(const V3&, double, const V3&) const { return false; }
  void record(const V3&, double, const V3&) {}
};

/// What every walk on one mesh needs whatever the field: the faces around each vertex, the
/// boundary vertices, the bounding box and the cumulative face areas (for random seeds).
/// O(faces) to make: a `Streamline_surface` keeps one for the tracers made per edit.
struct Walker_surface
{
  explicit Walker_surface(std::shared_ptr<const Intrinsic_mesh> mesh);

  std::shared_ptr<const Intrinsic_mesh> mesh;
  std::vector<int> vertex_face_start, vertex_faces; // faces around each vertex (CSR)
  std::vector<char> boundary_vertex;
  double diagonal = 0;
  V3 box_min{{0, 0, 0}};
  double total_area = 0;
  std::vector<double> cumulative_area; // sum of the areas of faces 0 ... f
};

/// \brief The field of one mesh prepared for walking, and the walk itself.
///
/// The field has `n` vectors per face: a first one (`Face_data::direction`) and the
/// others turned from it by `2 pi j / n`; a vector field is the case `n = 1`.  A walk
/// follows one of them, its *branch*, and keeps following the one closest to it: the
/// branch is matched anew in each face it enters (`matching_branch`), after carrying the
/// vector across the edge or the vertex it came through.  For `n = 1` the match is the
/// face's only vector, so that vector fields and n-fields share every step of the walk.
///
/// The per-face data (2D layout, gradients, the field's vector) is made when a walk first
/// needs a face (`face`), from the field's `Face_vector_source`: a walk reads only the faces
/// it passes and their neighbours around the vertices it goes through.  Not thread-safe (the
/// per-face data is filled in by const members).
class Streamline_walker
{
public:
  struct Face_data
  {
    std::array<V2, 3> corner;   // the 2D layout
    std::array<V2, 3> gradient; // gradients of the barycentric coordinates
    V2 direction;               // the first vector (frame coordinates = layout coordinates)
    double magnitude;
  };

  /// `field`: one of the n vectors of each face (frame coordinates, `2 nf`);
  /// `singular_vertices`: where walks stop (see `Streamline_tracer`).
  /// \throws Invalid_input for a wrong size, non-finite entries, `n < 1` or a vertex out of range.
  Streamline_walker(std::shared_ptr<const Intrinsic_mesh> mesh, const Eigen::VectorXd& field, int n,
                    const std::vector<int>& singular_vertices);
  /// A field read face by face from `source` when a walk first needs the face;
  /// `maximum_magnitude` is then the largest over the faces read so far.
  /// \throws Invalid_input for a source of another number of faces, `n < 1` or a vertex out of
  ///         range; later, when a face is read, for a non-finite vector.
  Streamline_walker(std::shared_ptr<const Walker_surface> surface, std::shared_ptr<const Face_vector_source> source,
                    int n, const std::vector<int>& singular_vertices);

  std::shared_ptr<const Walker_surface> surface;
  std::shared_ptr<const Intrinsic_mesh> mesh;
  std::shared_ptr<const Face_vector_source> source;
  bool on_demand = false; // the field comes face by face (else it was given whole)
  int n = 1;
  std::vector<V2> turn; // (cos, sin) of 2 pi j / n
  std::vector<char> singular_vertex;
  std::vector<int> singular_list;
  // Largest magnitude of the face vectors: of all faces for a whole field, of the faces read
  // so far for a field on demand.
  mutable double maximum_magnitude = 0;

  int number_of_faces() const { return static_cast<int>(slot_.size()); }
  /// The data of face `f`, made on first use.
  const Face_data& face(int f) const
  {
    const int s = slot_[f];
    return s >= 0 ? pool_[s] : load(f);
  }
  /// Tells a field on demand that face `f` may be needed soon (nothing if it is read already).
  void hint(int f) const
  {
    if(on_demand && slot_[f] < 0) source->will_need(f);
  }
  /// Faces whose data was made (each read once from the source).
  std::size_t faces_read() const { return pool_.size() + faces_read_elsewhere; }

  double to_absolute(double value, Length_unit unit) const;

  // Vector `branch` of face `f`, at its length.
  V2 field_vector(int f, int branch) const
  {
    const V2& u = face(f).direction;
    if(branch == 0) return u;
    const V2& c = turn[branch];
    return {c[0] * u[0] - c[1] * u[1], c[1] * u[0] + c[0] * u[1]};
  }

  // The branch of face `f` whose vector is closest in angle to `reference` (layout
  // coordinates of `f`).
  int matching_branch(int f, const V2& reference) const
  {
    if(n == 1) return 0;
    const V2& u = face(f).direction;
    const double angle = std::atan2(cross2(u, reference), dot2(u, reference));
    const int j = static_cast<int>(std::lround(angle * n / (2 * M_PI)));
    return ((j % n) + n) % n;
  }

  // The two vectors of an n-field that are the same line: the branch itself and, for
  // even n, its opposite.
  bool same_line(int a, int b) const { return a == b || (n % 2 == 0 && a == (b + n / 2) % n); }

  // Vector `branch` of face `f` in 3D, of length 1 (0 where the field vanishes).
  V3 unit_tangent(int f, int branch) const
  {
    const V2 u = field_vector(f, branch);
    const double m = face(f).magnitude;
    const double k = m > 0 ? 1 / m : 0;
    return mesh->from_frame(f, k * u[0], k * u[1]);
  }

  // The branch that stands for the family of `branch` (`[0, n / 2)` for even n: a vector
  // and its opposite trace the same line).
  int family_branch(int branch) const { return n % 2 == 0 ? branch % (n / 2) : branch; }

  // The unit direction a walk moves in: the branch, against it for `sign < 0`, turned
  // by a quarter for walks across the field.
  V2 direction(int f, int branch, const Walk_settings& s) const
  {
    const V2 v = field_vector(f, branch);
    const double k = s.sign / face(f).magnitude;
    if(s.rotated) return {-k * v[1], k * v[0]};
    return {k * v[0], k * v[1]};
  }

  V3 point_of(int f, const Barycentric& b) const
  {
    const auto& t = mesh->face_vertices(f);
    const V3& p0 = mesh->position(t[0]);
    const V3& p1 = mesh->position(t[1]);
    const V3& p2 = mesh->position(t[2]);
    return {b[0] * p0[0] + b[1] * p1[0] + b[2] * p2[0], b[0] * p0[1] + b[1] * p1[1] + b[2] * p2[1],
            b[0] * p0[2] + b[1] * p1[2] + b[2] * p2[2]};
  }

  V2 layout_of(int f, const Barycentric& b) const
  {
    const Face_data& F = face(f);
    return {b[1] * F.corner[1][0] + b[2] * F.corner[2][0], b[2] * F.corner[2][1]};
  }

  int local_corner(int f, int v) const
  {
    const auto& t = mesh->face_vertices(f);
    return t[0] == v ? 0 : (t[1] == v ? 1 : (t[2] == v ? 2 : -1));
  }

  // `v` (layout coordinates of `f`) in the layout of the neighbour `g` across their
  // shared edge `e`: the rotation that takes the edge in `f`'s layout to the edge in `g`'s
  // (the unfolding of the two faces into one plane); its length is not kept.
  V2 carried_across(int f, int g, int e, const V2& v) const;

  // The face around vertex `v` (other than `exclude`) into which the walk continues from
  // the vertex, with its branch: in each face the branch closest to `reference` (the 3D
  // field vector followed so far); its direction must point strictly into the face; among
  // several faces, the one closest to `incoming` (the 3D direction of the walk so far, or
  // zero).  Face -1 if none.
  std::pair<int, int> face_leaving_vertex(int v, int exclude, const V3& incoming, const V3& reference,
                                          const Walk_settings& s) const;

  // Why a walk that cannot leave vertex `v` stops: all faces there have no field, or
  // the field leaves the surface (a boundary vertex), or the vertex is a sink.
  Streamline_stop stop_at_vertex(int v, const Walk_settings& s) const;

  // Puts `pos` on corner `m` of its face.
  void place_on_corner(Position& pos, int m) const
  {
    pos.beta = {0, 0, 0};
    pos.beta[m] = 1;
    pos.corner = m;
    pos.entered_edge = -1;
    pos.point = mesh->position(mesh->face_vertices(pos.face)[m]);
  }

  // Walks from `start` until a stop.  `proximity` is sampled every `proximity.step()`
  // of walked length and ends the walk when it reports a point too close.  Defined in
  // streamline_walker.cpp for `No_proximity` and `Separation_test`.
  template <class Proximity>
  Walk walk(Position pos, const Walk_settings& s, Proximity& proximity) const;

  Position start_position(int face, const Barycentric& beta, int branch = 0) const;
  // `zero_reference`: the magnitude the zero-field tolerance is relative to (< 0: `maximum_magnitude`).
  Walk_settings settings(const Streamline_options& o, double sign, double zero_reference = -1) const;

  // Joins a backward and a forward walk from the same seed into one streamline
  // running along the field.
  static Streamline join(const Walk* backward, const Walk& forward, const Position& seed);

  // A streamline from `start` (forward and backward as `o` asks), with the proximity
  // tests of each direction (none if null); `segments` receives the pieces in the
  // order of the streamline if asked for.
  template <class Proximity>
  Streamline trace(const Position& start, const Streamline_options& o, double closure_tolerance,
                   Proximity* forward_proximity, Proximity* backward_proximity, bool keep_segments,
                   std::vector<Segment_record>* segments, double zero_reference = -1) const;

  // A random point of the surface, uniform by area.
  Position random_position(std::mt19937_64& gen) const;

  // A walker of the same field with no face data made yet, for another thread: the face data
  // is filled in without locks, so two threads cannot share one walker.
  Streamline_walker for_another_thread() const;
  // Faces read by the walkers of other threads (`faces_read` counts them too).
  mutable std::size_t faces_read_elsewhere = 0;

private:
  Streamline_walker() = default; // for `for_another_thread`

  // A walk that ended where the field converges (a sink or a stall) in a face with a
  // singular corner went into that singularity: it is ended there, by a last segment in
  // the face, unless that would pass the length limit.  `last_branch` is the branch of
  // the last segment.
  bool end_at_singular_vertex(Walk& w, Position& pos, int& last_branch, const Walk_settings& s) const;
  void set_up(int n, const std::vector<int>& singular_vertices);
  const Face_data& load(int f) const;

  mutable std::vector<int> slot_;         // position of each face's data in pool_ (-1: not made)
  mutable std::deque<Face_data> pool_;    // stable references while it grows
};

/// Moves `gen` on past `count` calls of `random_position`.
void skip_random_positions(std::mt19937_64& gen, long count);

/// Evenly spaced streamlines (evenly_spaced_streamlines.cpp).
std::vector<Streamline> evenly_spaced_streamlines(const Streamline_walker& walker, const Evenly_spaced_options& o);

/// `x` with 3 significant digits ("1.03e+18"), for messages.
std::string short_number(double x);

/// \throws Invalid_input for options no trace can honour: a NaN length limit, fewer than one
/// segment, a tolerance that is negative or not finite.
void check_streamline_options(const Streamline_options& o);

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
