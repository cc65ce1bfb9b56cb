// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_FIELD_PICTURE_H
#define CGAL_TANGENT_VECTOR_FIELDS_FIELD_PICTURE_H

/// \file Field_picture.h
/// Pictures of fields of any `TriangleMesh`, from property maps: a thin layer over
/// `Field_renderer` and `Streamline_tracer`.  Needs the package built with Cairo.

#if !defined(TVF_HAS_CAIRO) && !defined(TVF_DOXYGEN_RUNNING)
#error "Field_picture.h needs the package built with Cairo (libcairo2-dev); TVF_HAS_CAIRO is not defined"
#endif

#include <CGAL/Tangent_vector_fields/Field_renderer.h>
#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>
#include <CGAL/Tangent_vector_fields/internal/Mesh_adapter.h>

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
/// Constructor named parameters: those of the mesh (`vertex_point_map`, index maps,
/// intrinsic-mesh options), as for `Discrete_operators`.
template <class TriangleMesh>
class Field_picture
{
public:
  typedef internal::Mesh_adapter<TriangleMesh> Adapter;

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

  Adapter adapter_;
  Field_renderer renderer_;
};

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
