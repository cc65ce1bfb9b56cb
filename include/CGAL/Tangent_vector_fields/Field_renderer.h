// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_FIELD_RENDERER_H
#define CGAL_TANGENT_VECTOR_FIELDS_FIELD_RENDERER_H

/// \file Field_renderer.h
/// Pictures of a mesh and its fields, drawn with Cairo into PNG and SVG files: a
/// shaded surface, coloured by a scalar quantity with a colour bar, with
/// streamlines, fur strokes, arrows or the glyphs of n-direction fields and the marks of
/// their singular vertices on top, hidden where the surface covers them.
///
/// `Field_renderer` works on an `Intrinsic_mesh` and frame coordinates;
/// `Field_picture.h` offers the same on property maps of any `TriangleMesh`.
/// Available when the package was built with Cairo (`TVF_HAS_CAIRO` is defined).

#include <CGAL/Tangent_vector_fields/Intrinsic_mesh.h>
#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>

#include <Eigen/Core>

#include <array>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

/// An sRGB colour, components in [0, 1].
struct Colour
{
  double r = 0, g = 0, b = 0;
};

/// Colour maps for scalar quantities.
enum class Colour_map {
  viridis,   ///< perceptually uniform, dark blue to yellow: magnitudes, energies
  cool_warm, ///< diverging blue - grey - red: signed quantities (divergence, curl)
  greys      ///< dark to light grey
};

/// The colour of `t` in [0, 1] (clamped) on `map`.
Colour colour_at(Colour_map map, double t);

enum class Projection { orthographic, perspective };

/// \brief Where the camera looks from.  The whole model is framed automatically.
///
/// By default the view direction comes from `azimuth` (degrees, about `up`; 0 looks
/// along `-front` where `front` is the coordinate axis, among z, x, y, first
/// orthogonal enough to `up`) and `elevation` (degrees above the horizontal plane).
/// A non-zero `view_direction` (from the camera towards the model) overrides both.
struct Camera
{
  Projection projection = Projection::perspective;
  double azimuth = 30;
  double elevation = 20;
  std::array<double, 3> view_direction = {0, 0, 0};
  std::array<double, 3> up = {0, 1, 0};
  /// Full opening angle of the perspective camera, degrees.
  double field_of_view = 30;
  /// Free border around the model, as a fraction of the image size.
  double margin = 0.04;
  /// Enlarges the model (1: it fills the image up to the margin).
  double zoom = 1;
};

/// Image, lighting and decoration settings.
struct Render_options
{
  int width = 1200;
  int height = 900;
  Camera camera;
  Colour background{1, 1, 1};
  /// Colour of the surface where no scalar quantity is shown.
  Colour surface{0.80, 0.80, 0.78};
  /// Interpolated vertex normals (true) or one normal per face.
  bool smooth_shading = true;
  /// Samples per pixel along each axis (anti-aliasing of the surface); 1 to 4.
  int supersampling = 2;
  /// Share of the light that does not depend on the normal.
  double ambient = 0.28;
  /// Strength of the specular highlights.
  double specular = 0.12;
  /// Draw the colour bar when a scalar quantity is shown.
  bool legend = true;
  /// Text in the top-left corner.
  std::string title;
};

/// How a scalar quantity is turned into colours.
struct Scalar_colouring
{
  Colour_map map = Colour_map::viridis;
  /// Range of the colour bar; NaN: automatic from the values.
  double minimum = std::numeric_limits<double>::quiet_NaN();
  double maximum = std::numeric_limits<double>::quiet_NaN();
  /// The automatic range leaves out this fraction of the values at each end (values
  /// beyond are clamped), so that a few outliers do not wash out the picture.
  double clip_fraction = 0;
  /// The automatic range is `[-m, m]`, for signed quantities on a diverging map.
  bool symmetric = false;
  /// Colours by the logarithm of the values (the automatic range from the positive values;
  /// values <= 0 take the bottom colour; the colour bar shows the middle value too), for
  /// quantities spread over orders of magnitude such as the energy density of an n-field.
  bool logarithmic = false;
  /// Caption of the colour bar.
  std::string label;
};

/// Style of streamlines and fur strokes.
struct Line_style
{
  Colour colour{0.08, 0.08, 0.08};
  /// Width in pixels of the output image.
  double width = 1.2;
  double opacity = 0.9;
  /// Width and opacity fall off along each line (fur: root thick, tip thin), so the
  /// strokes show the direction of the field.
  bool taper = false;
};

/// \brief Style of arrows and n-fold glyphs: one per cell of a screen grid, at the surface
/// point seen there.
///
/// With `symmetry` n >= 2 the field is an n-direction field: each glyph shows its n vectors
/// as n spokes from the cell centre, without heads (n = 2 a segment through the centre,
/// n = 3 a three-armed star, n = 4 a cross), each spoke half as long as the arrow of that
/// vector would be.  The glyph is the same whichever of the n vectors the field holds.
struct Arrow_style
{
  Colour colour{0.08, 0.08, 0.08};
  /// Distance between arrow centres, pixels.
  double spacing = 28;
  double width = 1.3;
  double opacity = 0.9;
  /// Arrow length proportional to the magnitude, else constant.  An arrow fills its
  /// cell at the 95th percentile of the face magnitudes; longer ones are clamped.
  bool scale_by_magnitude = true;
  /// n of an n-direction field: 1 draws arrows, n >= 2 glyphs of n spokes.
  int symmetry = 1;
};

/// \brief Style of the marks of singular vertices: a disc at each, coloured by the sign of
/// its index `k / n`, its area proportional to `|k|`.
struct Singularity_style
{
  Colour positive{0.86, 0.12, 0.10}; ///< index > 0: red
  Colour negative{0.10, 0.30, 0.90}; ///< index < 0: blue
  /// Radius of the disc of index `+-1/n`, pixels; index `k/n` gets `sqrt(|k|)` times it.
  double radius = 5;
  /// A ring around the disc (width 0: none), so that it stands out on any colour.
  Colour outline{1, 1, 1};
  double outline_width = 1;
  double opacity = 1;
  /// Writes the index next to each disc, as `k/n` ("+1/4", "-1/4"; "+1" for n = 1).
  bool labels = false;
};

/// \brief Renders a mesh, a scalar quantity and fields into PNG or SVG pictures.
///
/// The surface is rasterised with a z-buffer (`supersampling`^2 samples per pixel,
/// two-sided lighting: a key light from the upper left, a head light, ambient and a
/// specular term).  Lines are drawn with Cairo on top; each is cut into pieces about
/// one sample long, and a piece is drawn only where the z-buffer shows the surface
/// at the line's depth (within a tolerance of about two samples in depth), so lines
/// behind the surface are hidden.  In SVG files the surface is an embedded image
/// and the lines, arrows and legend are vector paths.
class Field_renderer
{
public:
  explicit Field_renderer(std::shared_ptr<const Intrinsic_mesh> mesh, const Render_options& options = Render_options());
  ~Field_renderer();
  Field_renderer(Field_renderer&&) noexcept;
  Field_renderer& operator=(Field_renderer&&) noexcept;

  const Intrinsic_mesh& mesh() const;
  Render_options& options();
  const Render_options& options() const;

  /// Colours each face by its value (`number_of_faces()` values).
  /// \throws Invalid_input for a wrong count, a `clip_fraction` outside [0, 0.5), or a
  ///         logarithmic scale that is symmetric or has a given minimum or maximum <= 0.
  void colour_faces(std::vector<double> values, const Scalar_colouring& colouring = Scalar_colouring());
  /// Colours the surface by values at the vertices, interpolated linearly in each face.
  void colour_vertices(std::vector<double> values, const Scalar_colouring& colouring = Scalar_colouring());
  /// Back to the plain surface colour.
  void clear_colours();
  /// The range of the colour bar in use (after the automatic choice); NaNs if none.
  std::pair<double, double> colour_range() const;

  /// Adds streamlines (or fur strokes) to draw over the surface.
  void add_streamlines(std::vector<Streamline> lines, const Line_style& style = Line_style());
  /// Adds arrows of a field given by its frame coordinates (`2 nf`), or the glyphs of an
  /// n-direction field if `style.symmetry` is n >= 2 (then any one of its n vectors per face).
  /// \throws Invalid_input for a wrong size, non-finite entries or a symmetry below 1.
  void add_arrows(const Eigen::VectorXd& field, const Arrow_style& style = Arrow_style());
  /// Adds the glyphs of an n-direction field: `add_arrows` with `style.symmetry = n`.
  /// `vectors`: any one of the n vectors of each face, in frame coordinates (`2 nf`), such as
  /// `N_field_operators::to_vectors(z)`.
  void add_glyphs(const Eigen::VectorXd& vectors, int n, Arrow_style style = Arrow_style());
  /// \brief Marks singular vertices: `vertex_k` holds pairs (vertex, k), the index `k / n`
  /// as `n_field_singularities` gives it; pairs with k = 0 are not drawn.
  ///
  /// A mark is drawn where the surface shows its vertex (the same test as for lines), so the
  /// singularities on the far side stay hidden.
  /// \throws Invalid_input if `n < 1`, a vertex is not one of the mesh's or lies in no face,
  ///         or the radius is not positive.
  void add_singularities(const std::vector<std::pair<int, int>>& vertex_k, int n,
                         const Singularity_style& style = Singularity_style());
  /// Removes all streamlines, arrows, glyphs and singularities.
  void clear_overlays();

  /// \throws Invalid_input if the file cannot be written, or for options no picture can have:
  ///         a size outside 16 to 16384 pixels, supersampling outside 1 to 4, a non-finite
  ///         camera or lighting setting, a zoom that is not positive, a margin outside [0, 0.5).
  void write_png(const std::string& filename) const;
  void write_svg(const std::string& filename) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
