// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_STREAMLINE_TRACER_H
#define CGAL_TANGENT_VECTOR_FIELDS_STREAMLINE_TRACER_H

/// \file Streamline_tracer.h
/// Streamlines of a piecewise-constant tangent field -- a vector field or an n-direction
/// field -- traced exactly face by face on an `Intrinsic_mesh`; evenly spaced streamlines
/// and short "fur" strokes.  `Streamlines.h` offers the same on property maps of any
/// `TriangleMesh`.

#include <CGAL/Tangent_vector_fields/Intrinsic_mesh.h>

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

class N_field_operators;
namespace internal {
struct Walker_surface;
}

/// Why one end of a streamline stopped.
enum class Streamline_stop {
  none,             ///< not traced in this direction (e.g. only forward was asked for)
  boundary,         ///< reached a boundary edge
  zero_field,       ///< entered (or started in) a face whose vector is (nearly) zero
  sink_edge,        ///< crossed an edge into a face whose vector points back across it: the two face vectors converge
  sink_vertex,      ///< reached a vertex where no incident face's vector points away from it
  maximum_length,   ///< reached the length limit
  maximum_segments, ///< reached the limit on the number of segments
  closed_loop,      ///< came back to its seed (forward direction only)
  too_close,        ///< came closer than the test distance to another streamline (evenly spaced seeding)
  stalled,          ///< many consecutive segments of negligible length (spiralling into a vertex)
  singular_vertex   ///< reached a singular vertex of the field, or converged into one (see `Streamline_tracer`)
};

/// A short name such as "boundary" or "sink_edge" (the enumerator's name).
const char* to_string(Streamline_stop stop);

/// \brief A streamline: a polyline on the surface that follows the field.
///
/// Segment `i` joins `points[i]` and `points[i+1]` inside face `faces[i]` and points
/// along the field of that face (the polyline runs in the direction of the field,
/// also for its backward part).  Consecutive segments in different faces meet on the
/// edge the two faces share, or at a vertex (see `Streamline_tracer`).  `faces` has
/// one entry per point: the last one is the face of the last segment, so every point
/// lies in its face.  Face indices are those of the mesh (the face index map).
struct Streamline
{
  std::vector<std::array<double, 3>> points;
  std::vector<int> faces;
  /// Position of the seed in `points`.
  std::size_t seed_index = 0;
  /// The vector of the seed's face the streamline leaves the seed along: `j` for the
  /// face's first vector turned by `2 pi j / n` (0 for a vector field).
  int branch = 0;
  /// Why the part before the seed stopped (traced against the field).
  Streamline_stop backward_stop = Streamline_stop::none;
  /// Why the part after the seed stopped.
  Streamline_stop forward_stop = Streamline_stop::none;
  /// True if the forward trace came back to the seed (`forward_stop == closed_loop`);
  /// the last point is then the point of the last segment nearest to the seed, within
  /// the closure tolerance of it.
  bool closed = false;

  std::size_t number_of_segments() const { return points.empty() ? 0 : points.size() - 1; }
  /// Sum of the segment lengths (in 3D).
  double length() const;
};

/// What a length option is measured in.
enum class Length_unit {
  absolute,             ///< the mesh's own units
  mean_edge_length,     ///< multiples of the mean edge length
  bounding_box_diagonal ///< fractions of the diagonal of the vertices' bounding box
};

/// Options of a single trace.
struct Streamline_options
{
  /// Longest length traced in each direction from the seed; 0 or less: no limit.
  double maximum_length = 0;
  Length_unit length_unit = Length_unit::absolute;
  /// Most segments in each direction (a guard against endless spirals).
  int maximum_segments = 100000;
  bool forward = true;  ///< trace along the field from the seed
  bool backward = true; ///< trace against the field from the seed
  /// Which of the n vectors of the seed's face to follow: the first one turned by
  /// `2 pi branch / n`, `0 <= branch < n` (a vector field has only 0).
  int branch = 0;
  /// A face whose vector is at most this times the largest face vector counts as zero.
  double zero_field_tolerance = 1e-9;
  /// Detect a loop closing at the seed: when the forward trace passes through the
  /// seed's face again within this distance of the seed (in units of the mean edge
  /// length), it stops there.  0 disables the test.
  double loop_closure_tolerance = 0.05;
};

/// Options of `Streamline_tracer::evenly_spaced` (Jobard and Lefer 1997, on the surface).
struct Evenly_spaced_options
{
  /// Distance between neighbouring streamlines, in `separation_unit`.
  double separation = 0.02;
  Length_unit separation_unit = Length_unit::bounding_box_diagonal;
  /// A streamline stops when it comes closer than `test_ratio * separation` to another
  /// one (or to a distant part of itself).
  double test_ratio = 0.5;
  /// Streamlines shorter than this times the separation are dropped.
  double minimum_length_ratio = 1.0;
  /// Stop after this many streamlines; 0: no limit.
  int maximum_streamlines = 0;
  /// Seeds the order of the random candidate seeds.
  unsigned random_seed = 1;
  /// Limits of each trace (`maximum_length` is per direction; `branch` must be 0: every
  /// family is traced).
  Streamline_options tracing;
};

/// Options of `Streamline_tracer::fur`: many short strokes from random roots.
struct Fur_options
{
  /// Length of each stroke (traced forward from its root), in `length_unit`.
  double length = 0.02;
  Length_unit length_unit = Length_unit::bounding_box_diagonal;
  /// Number of roots (one stroke per root for a vector field, see `branch`); if 0,
  /// `density` times the total area.
  int number_of_strokes = 0;
  /// Roots per unit area (in the mesh's units squared), used when `number_of_strokes` is 0.
  double density = 0;
  /// The strokes of each root: -1 (the default) one along each of the n vectors of its
  /// face, the n-fold glyph of an n-field (two opposite strokes, a line, for a line field;
  /// one stroke for a vector field); `0 <= branch < n` only along vector `branch` of the
  /// face (numbered from the face's first vector, as `Streamline_options::branch`).
  int branch = -1;
  /// Scale each stroke's length by the magnitude of the field at its root relative to
  /// the largest magnitude (`magnitude_reference`), so that the strokes show the strength of
  /// the field.
  bool scale_length_by_magnitude = false;
  /// Which largest magnitude the strokes' lengths and the zero-field tolerance are relative to.
  enum class Magnitude_reference
  {
    all_faces, ///< the largest over all faces of the field (`Streamline_tracer::maximum_magnitude`)
    roots      ///< the largest over the faces of this fur's roots (area-uniform samples of the
               ///< surface): needs only the roots' faces, so a field given on demand can tell it; no
               ///< stroke is longer than `length`
  };
  /// A tracer of a field on demand knows no largest magnitude over all faces: it needs `roots`
  /// (or `scale_length_by_magnitude` off: its zero-field tolerance is then relative to the
  /// roots' largest magnitude too).
  Magnitude_reference magnitude_reference = Magnitude_reference::all_faces;
  unsigned random_seed = 1;
  /// Threads tracing the strokes (0: one per core).  The same strokes, in the same order, for
  /// any number; a thread is used per 256 roots at most.  Each thread reads the faces its
  /// strokes reach, so a face near the strokes of two threads is read twice.  Measured on the
  /// 346k-face armadillo (4,000 strokes of a reduced field on demand, `bench_design
  /// --preview-only`): see `doc/tangent_vector_fields/bench_design_preview.txt`.
  int threads = 0;
  /// Zero-field tolerance and segment limit of each stroke (lengths and directions are set here).
  Streamline_options tracing;
};

/// \brief The vectors of a field face by face, for a tracer that reads only the faces its
/// streamlines reach (fur of a field reconstructed from a reduced basis, say, where making
/// the whole field costs far more than the strokes).
///
/// A tracer reads each face at most once per thread; fur on several threads
/// (`Fur_options::threads`) calls `face_vector` and `will_need` from all of them at once.
class Face_vector_source
{
public:
  virtual ~Face_vector_source() = default;
  /// The number of faces of the mesh.
  virtual int number_of_faces() const = 0;
  /// Frame coordinates of the vector of face `f` (for an n-field: any one of its n vectors, as
  /// the whole-field constructor of `Streamline_tracer` takes them).
  virtual std::array<double, 2> face_vector(int f) const = 0;
  /// A hint: `face_vector(f)` will be asked for soon (`f` holds one of the next roots of fur).
  /// A source whose faces wait for memory may start fetching; the default does nothing.  (Walks
  /// give no hints: prefetching both faces a walk may enter next cost the preview twice its time
  /// at 69k faces, the face not entered being fetched for nothing.)
  virtual void will_need(int f) const { (void)f; }
};

/// \brief What the streamline tracers of one mesh share whatever their field: the faces
/// around each vertex, the boundary vertices, the bounding box and the face areas.
///
/// Making it costs `O(faces)`; a tracer of a field on demand made per edit from a kept
/// surface costs `O(vertices + faces)` bytes set to zero, and reads only the faces it walks.
class Streamline_surface
{
public:
  explicit Streamline_surface(std::shared_ptr<const Intrinsic_mesh> mesh);
  const Intrinsic_mesh& mesh() const;

private:
  friend class Streamline_tracer;
  std::shared_ptr<const internal::Walker_surface> impl_;
};

/// \brief Traces streamlines of one piecewise-constant field on one mesh.
///
/// **Exact tracing.**  In a face the field is constant, so a streamline is a straight
/// segment.  The tracer follows it in the face's 2D layout (`Intrinsic_mesh::corner2_layout`,
/// in which the frame coordinates of the field are the layout coordinates) using
/// barycentric coordinates, computes exactly where it leaves the face, and continues
/// in the neighbouring face from the same point of the shared edge.  A point on an
/// edge is stored by its parameter along the edge, and its 3D position is computed
/// from the edge's two end points in both faces, so the polyline is continuous.  3D
/// positions are the barycentric combinations of the face's corners; without
/// mollification the layout is the face itself and every segment is parallel to the
/// 3D face vector.
///
/// **n-direction fields.**  An n-field has n vectors per face, at angles `2 pi j / n` from
/// a first one (`N_field_operators`); a vector field is the case `n = 1`, and both are
/// traced by the same walk.  A streamline follows one of them, its *branch* (chosen at the
/// seed, `Streamline_options::branch`), and in each face it enters takes the vector
/// closest in angle to the one it followed, carried across the shared edge (the rotation
/// that unfolds the two faces into one plane) or, through a vertex, compared in 3D: the
/// *matching* branch.  For `n = 1` the match is the face's only vector.  The backward part
/// runs against the branch, so the whole polyline runs along the field; for even n the
/// opposite vector is a branch too and both parts follow the same line.
///
/// **Stops.** A boundary edge; a face whose vector is (nearly) zero; a *sink edge*,
/// where the (matching) vector of the face beyond the edge points back across it (the
/// streamline would zig-zag on the edge forever); the length and segment limits; a closed
/// loop (the forward trace comes back to its seed on the same line); many segments of
/// negligible length; a singular vertex.
///
/// **Singular vertices.**  The field is undefined at a vertex of non-zero index and turns
/// by `2 pi k / n` around it, so no branch continues there.  A streamline stops
/// (`Streamline_stop::singular_vertex`) when it reaches such a vertex, and also when it
/// would stop by convergence -- a sink edge, a sink vertex, a stall -- at a point of a face
/// that has a singular corner: in the piecewise-constant field, that is how a streamline
/// runs into the singularity.  It is then ended at that corner (the nearest one) by a last
/// segment inside the face, the only segment that does not follow the field (unless that
/// segment would pass the length limit: the streamline then keeps its stop).  Streamlines
/// passing through the one-ring without converging go on.  The singular vertices are those
/// given to the constructor: `n_field_indices` at interior vertices for an n-field (the
/// boundary stops streamlines anyway), none for a vector field unless given.
///
/// **Vertices.**  When a segment ends within `1e-12` (barycentric) of a corner, the
/// point is put on the vertex, and the trace continues in the incident face (other
/// than the one it came from) whose (matching) vector points strictly into the face from
/// the vertex, choosing the one closest in 3D direction to the incoming segment.  If no
/// face qualifies the trace stops: with `boundary` on a boundary vertex (the field
/// leaves the surface there), else with `sink_vertex`.  Two consecutive faces of the
/// polyline share only that vertex when the trace passes through it.  A seed on a vertex
/// starts in the incident face that its own face's vector leads into best (that face itself
/// if its vector leaves the vertex into it).
///
/// The mesh is shared, so the tracer may outlive the object it came from.
class Streamline_tracer
{
public:
  /// A vector field (`n = 1`, the default) or an n-field given by one of its n vectors per
  /// face.
  /// \param field frame coordinates, `2 nf` (face `f` at rows `2f`, `2f+1`): the vector of
  ///        each face, or for an n-field any one of its n vectors; branch `j` is this vector
  ///        turned by `2 pi j / n`.
  /// \param n the number of vectors per face (1 vector field, 2 line field, 4 cross field...).
  /// \param singular_vertices the vertices where streamlines stop (see above); none by default.
  /// \throws Invalid_input if the size is wrong, an entry is not finite, `n < 1`, or a
  ///         singular vertex does not exist.
  Streamline_tracer(std::shared_ptr<const Intrinsic_mesh> mesh, const Eigen::VectorXd& field, int n = 1,
                    const std::vector<int>& singular_vertices = std::vector<int>());
  /// A field whose face vectors come from `field` when a streamline first reaches the face
  /// (see `Face_vector_source`); otherwise as the constructor above, whose field is the case of
  /// a source reading a whole vector.  The tracer's `maximum_magnitude` is the largest over the
  /// faces read so far: `fur` with `scale_length_by_magnitude` needs
  /// `Fur_options::Magnitude_reference::roots`.
  /// \throws Invalid_input if the source has another number of faces than the mesh, `n < 1`, or
  ///         a singular vertex does not exist; a trace throws it if a face vector read is not finite.
  Streamline_tracer(const Streamline_surface& surface, std::shared_ptr<const Face_vector_source> field, int n = 1,
                    const std::vector<int>& singular_vertices = std::vector<int>());
  /// An n-field in the power representation of `operators` (`z_f = r e^{i n theta}`, `2 nf`):
  /// branch `j` of face `f` is vector `j` of `operators.to_vectors(z, j)` (for `n = 1`, `z`
  /// itself), and streamlines stop at the interior vertices of non-zero index
  /// (`n_field_indices`).
  /// \throws Invalid_input if the size is wrong or an entry is not finite.
  Streamline_tracer(const N_field_operators& operators, const Eigen::VectorXd& z);
  ~Streamline_tracer();
  Streamline_tracer(Streamline_tracer&&) noexcept;
  Streamline_tracer& operator=(Streamline_tracer&&) noexcept;

  /// The number of vectors per face (1 for a vector field).
  int n() const;
  /// The families of lines of `evenly_spaced`: `n / 2` for even n, `n` for odd n.
  int number_of_families() const;
  /// The vertices where streamlines stop, in increasing order.
  const std::vector<int>& singular_vertices() const;
  const Intrinsic_mesh& mesh() const;
  /// Diagonal of the bounding box of the vertices that belong to faces.
  double bounding_box_diagonal() const;
  /// `value` converted from `unit` to the mesh's units.
  double to_absolute(double value, Length_unit unit) const;
  /// Largest magnitude of the face vectors (a field on demand: of the faces read so far).
  double maximum_magnitude() const;
  /// The faces whose vectors the tracer has read (all of them for a whole field, once traced).
  std::size_t faces_read() const;

  /// Traces from a point of face `face` given by barycentric coordinates with respect
  /// to the face's corners in local order (`Intrinsic_mesh::face_vertices`); they are
  /// clamped to be non-negative and normalised.  The streamline leaves the seed along
  /// vector `options.branch` of the face.
  /// \throws Invalid_input for a face index out of range, non-finite coordinates, a
  ///         branch outside `[0, n)`, a NaN `maximum_length`, `maximum_segments` below 1, or
  ///         a negative or non-finite `zero_field_tolerance` or `loop_closure_tolerance`.
  Streamline trace(int face, const std::array<double, 3>& barycentric,
                   const Streamline_options& options = Streamline_options()) const;
  /// Traces from the 3D point `point`, projected onto face `face` (and clamped into it).
  Streamline trace_from_point(int face, const std::array<double, 3>& point,
                              const Streamline_options& options = Streamline_options()) const;

  /// Evenly spaced streamlines: each new streamline is seeded at the separation
  /// distance beside an accepted one (walking across the field on the surface), or at
  /// random area-uniform points where no streamline has reached yet; a seed closer
  /// than 0.9 times the separation to an existing streamline is refused, and a
  /// streamline stops when it comes closer than `test_ratio` times the separation to
  /// another one.  Distances are 3D (Euclidean) distances between points of the
  /// streamlines sampled at `test_ratio / 2` times the separation, found with a
  /// uniform grid; they approximate the geodesic ones well when the separation is
  /// small compared with the curvature radii.  The result is deterministic for a
  /// given `random_seed`.
  ///
  /// For an n-field every family of lines is drawn, each at the separation: `n / 2`
  /// families for even n (a vector and its opposite are one line: two crossing families
  /// for a cross field, one for a line field), `n` for odd n.  Each random point seeds one
  /// streamline of each family (`Streamline::branch` in `[0, number_of_families())`), a seed
  /// beside a streamline continues its family, and the separation is tested only between
  /// streamlines of the same family, so that families cross.  Which family a sample belongs
  /// to is told by its direction: another streamline's sample counts when their directions
  /// are within `pi / n` of each other (up to sign for even n), half the angle between
  /// families; the branch numbers cannot tell, since each face numbers its vectors from its
  /// own first one and a streamline turning around a singularity changes family.
  /// \throws Invalid_input for a separation that is not positive, a `test_ratio` outside
  ///         `(0, 1]`, `tracing.branch` other than 0, a negative or non-finite
  ///         `minimum_length_ratio`, a negative `maximum_streamlines`, bad `tracing` options
  ///         (as `trace`), or a separation so small that the surface would take more than
  ///         1e7 streamlines (area / separation^2).
  std::vector<Streamline> evenly_spaced(const Evenly_spaced_options& options = Evenly_spaced_options()) const;

  /// Short strokes traced forward from random roots, uniformly distributed by area: per
  /// root one along each of the n vectors of its face, or one along the branch asked for
  /// (`Fur_options::branch`), consecutive in the result.  Strokes of zero length (roots in
  /// zero-field faces) are left out.  The roots depend only on the mesh and `random_seed`: a
  /// field on demand and the same field given whole give the same strokes (up to the rounding
  /// of their face vectors) for the same options.
  /// \throws Invalid_input for a length that is not positive, neither a count nor a
  ///         positive finite density, more than 1e7 strokes, a branch outside `[-1, n)`,
  ///         bad `tracing` options (as `trace`), or a field on demand with
  ///         `scale_length_by_magnitude` and `Magnitude_reference::all_faces`.
  std::vector<Streamline> fur(const Fur_options& options) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

namespace internal {

/// The vertices where the streamlines of the n-field `z` (power representation) stop: its
/// interior vertices of non-zero index (`n_field_indices`).
/// \throws Invalid_input if `z` has the wrong size or non-finite entries.
std::vector<int> n_field_stop_vertices(const N_field_operators& operators, const Eigen::VectorXd& z);

} // namespace internal

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
