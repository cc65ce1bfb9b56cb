// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "mode_pictures.h"

#ifdef TVF_HAS_CAIRO
#include <CGAL/Tangent_vector_fields/Field_renderer.h>
#include <cairo.h>
#include <unistd.h>
#endif

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace tvf_tool {

namespace VM = CGAL::Vibration_modes;

namespace {

#ifdef TVF_HAS_CAIRO
// Mode i as a renderer: the mesh moved by `scale` times the mode, coloured by |u| (scalar
// modes: the mesh at rest coloured by the values).
TVF::Field_renderer mode_renderer(const Tool_mesh& mesh, const VM::Modes& modes, Eigen::Index i, double scale,
                                  const TVF::Render_options& options)
{
  const TVF::Intrinsic_mesh& m = mesh.intrinsic();
  const int n = m.number_of_vertices();
  const bool scalar = modes.vectors.rows() == n;
  std::vector<std::array<int, 3>> faces(std::size_t(m.number_of_faces()));
  for(int f = 0; f < m.number_of_faces(); ++f) faces[std::size_t(f)] = m.face_vertices(f);
  const Eigen::VectorXd u = modes.vectors.col(i);
  std::vector<TVF::Intrinsic_mesh::Point> moved(static_cast<std::size_t>(n));
  std::vector<double> values(static_cast<std::size_t>(n), 0.0);
  for(int v = 0; v < n; ++v)
  {
    moved[std::size_t(v)] = m.position(v);
    if(scalar)
    {
      values[std::size_t(v)] = u[v];
      continue;
    }
    for(int c = 0; c < 3; ++c) moved[std::size_t(v)][std::size_t(c)] += scale * u[3 * v + c];
    values[std::size_t(v)] = u.segment<3>(3 * v).norm();
  }
  TVF::Field_renderer renderer(std::make_shared<const TVF::Intrinsic_mesh>(moved, faces), options);
  TVF::Scalar_colouring colouring;
  colouring.map = scalar ? TVF::Colour_map::cool_warm : TVF::Colour_map::viridis;
  colouring.symmetric = scalar;
  colouring.label = scalar ? "mode " + std::to_string(i + 1) : "|u| of mode " + std::to_string(i + 1);
  renderer.colour_vertices(values, colouring);
  return renderer;
}

double mode_scale(const Tool_mesh& mesh, const VM::Modes& modes, double displacement)
{
  const double largest = modes.vectors.cwiseAbs().maxCoeff();
  return largest > 0 ? displacement * mesh.bounding_box_diagonal() / largest : 0;
}
#endif

#ifndef TVF_HAS_CAIRO
[[noreturn]] void no_cairo(const std::string& what)
{
  throw Tool_error("'" + what + "': this tvf was built without Cairo (TVF_USE_CAIRO)");
}
#endif

} // namespace

void write_mode_pictures(const std::string& prefix, const Tool_mesh& mesh, const VM::Modes& modes, double displacement)
{
#ifdef TVF_HAS_CAIRO
  const double scale = mode_scale(mesh, modes, displacement);
  for(Eigen::Index i = 0; i < modes.vectors.cols(); ++i)
  {
    char name[32];
    std::snprintf(name, sizeof name, "_%02ld.png", long(i + 1));
    mode_renderer(mesh, modes, i, scale, TVF::Render_options()).write_png(prefix + name);
  }
  say("wrote %ld pictures %s_01.png ...\n", long(modes.vectors.cols()), prefix.c_str());
#else
  (void)mesh, (void)modes, (void)displacement;
  no_cairo("--pictures " + prefix);
#endif
}

void write_contact_sheet(const std::string& path, const Tool_mesh& mesh, const VM::Modes& modes, int count, int columns,
                         int cell, double displacement)
{
#ifdef TVF_HAS_CAIRO
  const int rows = (count + columns - 1) / columns;
  const int width = columns * cell, height = rows * (cell + contact_sheet_caption);
  cairo_surface_t* sheet = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
  cairo_t* cr = cairo_create(sheet);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  const double scale = mode_scale(mesh, modes, displacement);
  TVF::Render_options options;
  options.width = options.height = cell;
  options.legend = false; // one scale per cell: the caption says what is shown
  // Field_renderer draws into files: each cell goes through a scratch PNG.
  const std::string scratch = (std::filesystem::temp_directory_path() /
                               ("tvf_contact_sheet_" + std::to_string(long(getpid())) + ".png")).string();
  std::string failure;
  for(int i = 0; i < count && failure.empty(); ++i)
  {
    try
    {
      mode_renderer(mesh, modes, i, scale, options).write_png(scratch);
    }
    catch(const std::exception& e)
    {
      failure = e.what();
      break;
    }
    cairo_surface_t* image = cairo_image_surface_create_from_png(scratch.c_str());
    const double x = (i % columns) * cell, y = (i / columns) * (cell + contact_sheet_caption);
    cairo_set_source_surface(cr, image, x, y);
    cairo_paint(cr);
    cairo_surface_destroy(image);
    char caption[96];
    std::snprintf(caption, sizeof caption, "mode %d   %s %.4g", i + 1,
                  modes.objectives.size() > 0 ? "energy" : "\u03bb", modes.energies[i]); // lambda: the eigenvalue
    cairo_save(cr);
    cairo_rectangle(cr, x, y + cell, cell, contact_sheet_caption); // a long caption stays in its cell
    cairo_clip(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, std::min(15.0, cell / 13.0));
    cairo_move_to(cr, x + 8, y + cell + 0.7 * contact_sheet_caption);
    cairo_show_text(cr, caption);
    cairo_restore(cr);
  }
  std::filesystem::remove(scratch);
  const cairo_status_t status = failure.empty() ? cairo_surface_write_to_png(sheet, path.c_str()) : CAIRO_STATUS_SUCCESS;
  cairo_destroy(cr);
  cairo_surface_destroy(sheet);
  if(!failure.empty()) throw Tool_error("'" + path + "': " + one_line(failure));
  if(status != CAIRO_STATUS_SUCCESS) throw Tool_error("cannot write '" + path + "': " + cairo_status_to_string(status));
  say("wrote %s (%d x %d: %d modes in %d x %d cells of %d px)\n", path.c_str(), width, height, count, rows, columns,
      cell);
#else
  (void)mesh, (void)modes, (void)count, (void)columns, (void)cell, (void)displacement;
  no_cairo("--contact-sheet " + path);
#endif
}

void write_segment_picture(const std::string& path, const Tool_mesh& mesh, const std::vector<int>& label, int segments)
{
#ifdef TVF_HAS_CAIRO
  const TVF::Intrinsic_mesh& m = mesh.intrinsic();
  std::vector<double> face_label(std::size_t(m.number_of_faces()));
  for(int f = 0; f < m.number_of_faces(); ++f)
  {
    // The label of most of the face's corners; of the first corner if all three differ.
    const auto c = m.face_vertices(f);
    const int a = label[std::size_t(c[0])], b = label[std::size_t(c[1])], d = label[std::size_t(c[2])];
    face_label[std::size_t(f)] = (b == d && b != a) ? b : a;
  }
  TVF::Field_renderer renderer(mesh.shared_intrinsic());
  TVF::Scalar_colouring colouring;
  colouring.minimum = -1;
  colouring.maximum = std::max(1, segments - 1);
  colouring.label = "segment (-1: none)";
  renderer.colour_faces(face_label, colouring);
  try
  {
    if(extension(path) == "svg") renderer.write_svg(path);
    else renderer.write_png(path);
  }
  catch(const std::exception& e)
  {
    throw Tool_error(about(path, one_line(e.what())));
  }
  say("wrote %s\n", path.c_str());
#else
  (void)mesh, (void)label, (void)segments;
  no_cairo("--picture " + path);
#endif
}

} // namespace tvf_tool
