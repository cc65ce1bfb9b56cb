// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_STREAMLINES_H
#define CGAL_TANGENT_VECTOR_FIELDS_STREAMLINES_H

/// \file Streamlines.h
/// Streamlines of a face field of any `TriangleMesh` -- a vector field, or an n-direction
/// field given by any one of its n vectors per face: one streamline from a seed, evenly
/// spaced streamlines (for an n-field, of every family: the hatching), and fur strokes.
/// Thin wrappers over `Streamline_tracer` (which works on the `Intrinsic_mesh`).
///
/// The options are plain structs (`Streamline_options`, `Evenly_spaced_options`,
/// `Fur_options`) rather than named parameters: they are shared with the compiled
/// tracer and with command-line tools, and group a dozen settings that belong
/// together.  The named parameters are those of the mesh: `vertex_point_map`,
/// `vertex_index_map`, `edge_index_map`, `face_index_map` and the intrinsic-mesh
/// options (`use_intrinsic_mollification`, ...).  Face indices in the results are
/// those of the face index map.

#include <CGAL/Tangent_vector_fields/N_field_operators.h>
#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>
#include <CGAL/Tangent_vector_fields/internal/Mesh_adapter.h>

#include <CGAL/boost/graph/iterator.h>

#include <map>
#include <memory>
#include <type_traits>

namespace CGAL {
namespace Tangent_vector_fields {

/// \brief A `Streamline_tracer` built from a mesh and a face field.
///
/// Keeps the mesh adapter so that results can be related to the mesh's faces
/// (`face(i)` is the face descriptor of index `i`).
template <class TriangleMesh>
class Mesh_streamline_tracer
{
public:
  typedef internal::Mesh_adapter<TriangleMesh> Adapter;
  typedef typename Adapter::face_descriptor face_descriptor;

  /// A vector field.
  /// \param field a face map with `Vector_3` values (projected onto the faces).
  // (Not a candidate for an integer second argument: that is the n-field constructor.)
  template <class FaceVectorMap, class NamedParameters = parameters::Default_named_parameters,
            typename std::enable_if<!std::is_arithmetic<FaceVectorMap>::value, int>::type = 0>
  Mesh_streamline_tracer(const TriangleMesh& mesh, const FaceVectorMap& field,
                         const NamedParameters& np = parameters::default_values())
    : adapter_(mesh, np), tracer_(adapter_.intrinsic_mesh(), adapter_.read_field(field))
  {}

  /// An n-direction field, as the rest of the n-field API takes it: `field` holds any one of
  /// the n vectors of each face (projected onto the face), the others are it turned by
  /// `2 pi j / n` about the face's normal, and branch `j` (`Streamline_options::branch`,
  /// `Fur_options::branch`) is the map's vector turned by `2 pi j / n`.  Streamlines stop at
  /// the interior vertices where the field has a non-zero index (`n_field_singularities`).
  /// \param n the number of vectors per face (1 vector field, 2 line field, 4 cross field...)
  /// \throws Invalid_input if `n < 1` or the field has non-finite entries.
  template <class FaceVectorMap, class NamedParameters = parameters::Default_named_parameters>
  Mesh_streamline_tracer(const TriangleMesh& mesh, int n, const FaceVectorMap& field,
                         const NamedParameters& np = parameters::default_values())
    : adapter_(mesh, np), tracer_(n_field_tracer(adapter_, n, adapter_.read_field(field)))
  {}

  const Streamline_tracer& tracer() const { return tracer_; }
  const Adapter& adapter() const { return adapter_; }
  face_descriptor face(int index) const { return adapter_.faces()[static_cast<std::size_t>(index)]; }

  /// The streamline through the point `p` of face `f` (projected onto the face).
  template <class Point_3>
  Streamline trace(face_descriptor f, const Point_3& p, const Streamline_options& options = Streamline_options()) const
  {
    const int index = face_index(f);
    return tracer_.trace_from_point(index, {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())},
                                    options);
  }

  std::vector<Streamline> evenly_spaced(const Evenly_spaced_options& options = Evenly_spaced_options()) const
  {
    return tracer_.evenly_spaced(options);
  }

  std::vector<Streamline> fur(const Fur_options& options) const { return tracer_.fur(options); }

private:
  static Streamline_tracer n_field_tracer(const Adapter& adapter, int n, const Eigen::VectorXd& vectors)
  {
    const N_field_operators operators(std::make_shared<const Operator_matrices>(adapter.intrinsic_mesh()), n);
    return Streamline_tracer(adapter.intrinsic_mesh(), vectors, n,
                             internal::n_field_stop_vertices(operators, operators.from_vectors(vectors)));
  }

  int face_index(face_descriptor f) const
  {
    const auto& faces = adapter_.faces();
    if(index_of_.empty())
    {
      for(std::size_t i = 0; i < faces.size(); ++i) index_of_.emplace(faces[i], static_cast<int>(i));
    }
    const auto it = index_of_.find(f);
    if(it == index_of_.end()) throw Invalid_input("streamline: the seed face is not a face of the mesh");
    return it->second;
  }

  Adapter adapter_;
  Streamline_tracer tracer_;
  mutable std::map<face_descriptor, int> index_of_;
};

/// \brief The streamline of `field` through the point `seed` of face `f`.
///
/// \param field a face map with `Vector_3` values.
/// \param options limits, directions and tolerances (`Streamline_options`).
template <class TriangleMesh, class FaceVectorMap, class Point_3,
          class NamedParameters = parameters::Default_named_parameters>
Streamline trace_streamline(const TriangleMesh& mesh, const FaceVectorMap& field,
                            typename boost::graph_traits<TriangleMesh>::face_descriptor f, const Point_3& seed,
                            const Streamline_options& options = Streamline_options(),
                            const NamedParameters& np = parameters::default_values())
{
  return Mesh_streamline_tracer<TriangleMesh>(mesh, field, np).trace(f, seed, options);
}

/// \brief Evenly spaced streamlines of `field` (see `Streamline_tracer::evenly_spaced`).
template <class TriangleMesh, class FaceVectorMap, class NamedParameters = parameters::Default_named_parameters>
std::vector<Streamline> evenly_spaced_streamlines(const TriangleMesh& mesh, const FaceVectorMap& field,
                                                  const Evenly_spaced_options& options = Evenly_spaced_options(),
                                                  const NamedParameters& np = parameters::default_values())
{
  return Mesh_streamline_tracer<TriangleMesh>(mesh, field, np).evenly_spaced(options);
}

/// \brief Short strokes along `field` from random roots (see `Streamline_tracer::fur`).
template <class TriangleMesh, class FaceVectorMap, class NamedParameters = parameters::Default_named_parameters>
std::vector<Streamline> fur_strokes(const TriangleMesh& mesh, const FaceVectorMap& field, const Fur_options& options,
                                    const NamedParameters& np = parameters::default_values())
{
  return Mesh_streamline_tracer<TriangleMesh>(mesh, field, np).fur(options);
}

/// \brief The streamline of the n-field `field` through the point `seed` of face `f`, along
/// vector `options.branch` of `f` (the map's vector turned by `2 pi branch / n`); it stops at
/// the field's singular vertices (see `Mesh_streamline_tracer` and `Streamline_tracer`).
///
/// \param n the number of vectors per face (n >= 1)
/// \param field a face map with `Vector_3` values: any one of the n vectors per face.
/// \param options limits, directions, tolerances and the branch (`Streamline_options`).
/// \param np the options of the mesh (`vertex_point_map`, index maps, mollification).
template <class TriangleMesh, class FaceVectorMap, class Point_3,
          class NamedParameters = parameters::Default_named_parameters>
Streamline trace_n_field_streamline(const TriangleMesh& mesh, int n, const FaceVectorMap& field,
                                    typename boost::graph_traits<TriangleMesh>::face_descriptor f, const Point_3& seed,
                                    const Streamline_options& options = Streamline_options(),
                                    const NamedParameters& np = parameters::default_values())
{
  return Mesh_streamline_tracer<TriangleMesh>(mesh, n, field, np).trace(f, seed, options);
}

/// \brief Evenly spaced streamlines of every family of the n-field `field` -- for a cross
/// field, two families crossing at right angles -- each family at the separation (see
/// `Streamline_tracer::evenly_spaced`).
///
/// \param field a face map with `Vector_3` values: any one of the n vectors per face.
template <class TriangleMesh, class FaceVectorMap, class NamedParameters = parameters::Default_named_parameters>
std::vector<Streamline> evenly_spaced_n_field_streamlines(const TriangleMesh& mesh, int n, const FaceVectorMap& field,
                                                          const Evenly_spaced_options& options = Evenly_spaced_options(),
                                                          const NamedParameters& np = parameters::default_values())
{
  return Mesh_streamline_tracer<TriangleMesh>(mesh, n, field, np).evenly_spaced(options);
}

/// \brief Fur of the n-field `field`: from each random root a stroke along each of the n
/// vectors of its face, or along the branch `options.branch` (see `Streamline_tracer::fur`).
///
/// \param field a face map with `Vector_3` values: any one of the n vectors per face.
template <class TriangleMesh, class FaceVectorMap, class NamedParameters = parameters::Default_named_parameters>
std::vector<Streamline> n_field_fur_strokes(const TriangleMesh& mesh, int n, const FaceVectorMap& field,
                                            const Fur_options& options,
                                            const NamedParameters& np = parameters::default_values())
{
  return Mesh_streamline_tracer<TriangleMesh>(mesh, n, field, np).fur(options);
}

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
