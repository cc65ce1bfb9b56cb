// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_FIELD_PICTURE_H
#define CGAL_TANGENT_VECTOR_FIELDS_FIELD_PICTURE_H

/// \file Field_picture.h
/// Pictures of fields of any `TriangleMesh`, from property maps: a thin layer over
/// `Field_renderer`, `Streamline_tracer` and, for n-direction fields, `N_field_operators`.
/// Needs the package built with Cairo.

#if !defined(TVF_HAS_CAIRO) && !defined(TVF_DOXYGEN_RUNNING)
#error "Field_picture.h needs the package built with Cairo (libcairo2-dev); TVF_HAS_CAIRO is not defined"
#endif

#include <CGAL/Tangent_vector_fields/Field_renderer.h>
#include <CGAL/Tangent_vector_fields/N_field_singularities.h>
#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>
#include <CGAL/Tangent_vector_fields/internal/Mesh_adapter.h>

#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

/// \brief A picture of a mesh with scalar quantities and fields given as property maps.
///
/// \code
/// TVF::Field_picture<Mesh> picture(mesh);                 // default camera, 1200 x 900
/// picture.colour_vertices(divergence, {TVF::Colour_map::cool_warm});
/// picture.add_evenly_spaced_streamlines(field);          // traced and drawn
/// picture.write_png("field.png");
/// \endcode
/// n-direction fields are given as a face map holding any one of their n vectors per face
/// (as `smoothest_n_field` writes them) and n:
/// \code
/// picture.colour_by_n_field_energy(cross, 4);            // where the field turns
/// picture.add_n_field_glyphs(cross, 4);                  // a cross per grid cell
/// picture.add_n_field_singularities(cross, 4);           // red +k/4, blue -k/4
/// \endcode
/// Constructor named parameters: those of the mesh (`vertex_point_map`, index maps,
/// intrinsic-mesh options), as for `Discrete_operators`.
template <class TriangleMesh>
class Field_picture
{
public:
  typedef internal::Mesh_adapter<TriangleMesh> Adapter;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;

  template <class NamedParameters = parameters::Default_named_parameters>
  explicit Field_picture(const TriangleMesh& mesh, const Render_options& options = Render_options(),
                         const NamedParameters& np = parameters::default_values())
    : adapter_(mesh, np), renderer_(adapter_.intrinsic_mesh(), options)
  {}

  Render_options& options() { return renderer_.options(); }
  Field_renderer& renderer() { return renderer_; }
  const Adapter& adapter() const { return adapter_; }

  /// Colours the faces by a face map of numbers.
  template <class FaceScalarMap>
  void colour_faces(const FaceScalarMap& values, const Scalar_colouring& colouring = Scalar_colouring())
  {
    renderer_.colour_faces(to_vector(Adapter::read_values(adapter_.faces(), values)), colouring);
  }

  /// Colours the surface by a vertex map of numbers (interpolated in the faces).
  template <class VertexScalarMap>
  void colour_vertices(const VertexScalarMap& values, const Scalar_colouring& colouring = Scalar_colouring())
  {
    renderer_.colour_vertices(to_vector(Adapter::read_values(adapter_.vertices(), values)), colouring);
  }

  /// Colours the faces by the magnitude of a field.
  template <class FaceVectorMap>
  void colour_by_magnitude(const FaceVectorMap& field, const Scalar_colouring& colouring = Scalar_colouring())
  {
    const Eigen::VectorXd x = adapter_.read_field(field);
    std::vector<double> m(x.size() / 2);
    for(std::size_t f = 0; f < m.size(); ++f) m[f] = std::hypot(x[2 * f], x[2 * f + 1]);
    renderer_.colour_faces(std::move(m), colouring);
  }

  /// Draws arrows of a face field.
  template <class FaceVectorMap>
  void add_arrows(const FaceVectorMap& field, const Arrow_style& style = Arrow_style())
  {
    renderer_.add_arrows(adapter_.read_field(field), style);
  }

  /// Draws an n-direction field as n-fold glyphs (`Arrow_style::symmetry` = n): a segment per
  /// grid cell for n = 2, a cross for n = 4.  `field`: any one of the n vectors per face.
  template <class FaceVectorMap>
  void add_n_field_glyphs(const FaceVectorMap& field, int n, const Arrow_style& style = Arrow_style())
  {
    renderer_.add_glyphs(adapter_.read_field(field), n, style);
  }

  /// Marks the singular vertices of an n-direction field (their indices as
  /// `n_field_singularities` computes them) and returns them with their `k` (index `k / n`).
  template <class FaceVectorMap>
  std::vector<std::pair<vertex_descriptor, int>>
  add_n_field_singularities(const FaceVectorMap& field, int n, const Singularity_style& style = Singularity_style())
  {
    const auto ops = n_operators(n, N_field_boundary::free); // the index does not depend on it
    std::vector<std::pair<int, int>> marks;
    std::vector<std::pair<vertex_descriptor, int>> singular;
    for(const N_field_singularity& s : n_field_singularities(*ops, ops->from_vectors(adapter_.read_field(field))))
    {
      marks.emplace_back(s.vertex, s.index);
      singular.emplace_back(adapter_.vertices()[s.vertex], s.index);
    }
    renderer_.add_singularities(marks, n, style);
    return singular;
  }

  /// Colours the faces by the first-order smoothness energy density of an n-direction field
  /// (`N_field_operators::energy_density`: per unit area, how fast the field turns there).
  template <class FaceVectorMap>
  void colour_by_n_field_energy(const FaceVectorMap& field, int n, const Scalar_colouring& colouring = Scalar_colouring(),
                                N_field_boundary boundary = N_field_boundary::free)
  {
    const auto ops = n_operators(n, boundary);
    renderer_.colour_faces(to_vector(ops->energy_density(ops->from_vectors(adapter_.read_field(field)))), colouring);
  }

  /// Draws streamlines computed elsewhere (face indices of this mesh's face index map).
  void add_streamlines(std::vector<Streamline> lines, const Line_style& style = Line_style())
  {
    renderer_.add_streamlines(std::move(lines), style);
  }

  /// Traces evenly spaced streamlines of `field`, draws them, and returns them.
  template <class FaceVectorMap>
  std::vector<Streamline> add_evenly_spaced_streamlines(const FaceVectorMap& field,
                                                        const Evenly_spaced_options& options = Evenly_spaced_options(),
                                                        const Line_style& style = Line_style())
  {
    std::vector<Streamline> lines =
        Streamline_tracer(adapter_.intrinsic_mesh(), adapter_.read_field(field)).evenly_spaced(options);
    renderer_.add_streamlines(lines, style);
    return lines;
  }

  /// Traces fur strokes of `field`, draws them (tapered unless `style` says otherwise), and returns them.
  template <class FaceVectorMap>
  std::vector<Streamline> add_fur(const FaceVectorMap& field, const Fur_options& options, Line_style style = fur_style())
  {
    std::vector<Streamline> strokes = Streamline_tracer(adapter_.intrinsic_mesh(), adapter_.read_field(field)).fur(options);
    renderer_.add_streamlines(strokes, style);
    return strokes;
  }

  /// A tapered style for fur: thin dark strokes, root thicker than tip.
  static Line_style fur_style()
  {
    Line_style s;
    s.taper = true;
    s.width = 1.6;
    s.opacity = 0.85;
    return s;
  }

  void write_png(const std::string& filename) const { renderer_.write_png(filename); }
  void write_svg(const std::string& filename) const { renderer_.write_svg(filename); }

private:
  static std::vector<double> to_vector(const Eigen::VectorXd& x) { return std::vector<double>(x.data(), x.data() + x.size()); }

  // The operators of n-fields, on the mesh's matrices (built once, on first request).
  std::shared_ptr<const N_field_operators> n_operators(int n, N_field_boundary boundary)
  {
    if(!matrices_) matrices_ = std::make_shared<const Operator_matrices>(adapter_.intrinsic_mesh());
    N_field_options options;
    options.boundary = boundary;
    return std::make_shared<const N_field_operators>(matrices_, n, options);
  }

  Adapter adapter_;
  Field_renderer renderer_;
  std::shared_ptr<const Operator_matrices> matrices_;
};

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
