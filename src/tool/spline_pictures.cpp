// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Pictures of a fit: one frame (the bounding box of data and fit at one scale), drawn as SVG
// text or with Cairo into a PNG.

#include "spline_pictures.h"
#include "tool.h"

#include <CGAL/Model_reduction/Vtk_polydata.h>
#include <CGAL/Model_reduction/errors.h>

#ifdef TVF_HAS_CAIRO
#include <cairo.h>
#endif

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>

namespace tvf_tool {

namespace {

constexpr double picture_size = 800, picture_margin = 20;

// Data coordinates to picture coordinates (y up unless the data's y points down).
class Frame
{
public:
  Frame(const std::vector<Fit_picture_curve>& curves, bool y_down) : y_down_(y_down)
  {
    for(const Fit_picture_curve& c : curves)
      for(const Eigen::MatrixXd* P : {&c.samples, &c.fit})
        for(Eigen::Index i = 0; i < P->rows(); ++i)
          for(int k = 0; k < 2; ++k)
          {
            lo_[k] = std::min(lo_[k], coordinate(*P, i, k));
            hi_[k] = std::max(hi_[k], coordinate(*P, i, k));
          }
    const double extent = std::max({hi_[0] - lo_[0], hi_[1] - lo_[1], 1e-300});
    scale_ = (picture_size - 2 * picture_margin) / extent;
  }
  double x(const Eigen::MatrixXd& P, Eigen::Index i) const { return picture_margin + scale_ * (coordinate(P, i, 0) - lo_[0]); }
  double y(const Eigen::MatrixXd& P, Eigen::Index i) const
  {
    const double from_bottom = scale_ * (coordinate(P, i, 1) - lo_[1]);
    return y_down_ ? picture_margin + from_bottom : picture_size - picture_margin - from_bottom;
  }

private:
  static double coordinate(const Eigen::MatrixXd& P, Eigen::Index i, int k) { return k < P.cols() ? P(i, k) : 0.; }
  double lo_[2] = {HUGE_VAL, HUGE_VAL}, hi_[2] = {-HUGE_VAL, -HUGE_VAL};
  double scale_ = 1;
  bool y_down_;
};

} // namespace

void write_fit_svg(const std::string& path, const std::vector<Fit_picture_curve>& curves, bool y_down)
{
  const Frame frame(curves, y_down);
  std::ofstream out(path);
  if(!out) throw Tool_error("cannot open '" + path + "' for writing: " + std::strerror(errno));
  CGAL::Model_reduction::internal::prepare_exact_output(out);
  out.precision(8);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << picture_size << "\" height=\"" << picture_size
      << "\" viewBox=\"0 0 " << picture_size << " " << picture_size << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  auto polyline = [&](const Eigen::MatrixXd& P, bool closed, const char* colour, double width) {
    out << (closed ? "<polygon" : "<polyline") << " fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"" << width
        << "\" points=\"";
    for(Eigen::Index i = 0; i < P.rows(); ++i) out << frame.x(P, i) << "," << frame.y(P, i) << " ";
    out << "\"/>\n";
  };
  for(const Fit_picture_curve& c : curves) polyline(c.samples, c.closed, "#999999", 3);
  for(const Fit_picture_curve& c : curves) polyline(c.fit, c.closed, "#1f5fbf", 1.5);
  for(const Fit_picture_curve& c : curves)
    for(Eigen::Index i = 0; i < c.knots.rows(); ++i)
      out << "<circle cx=\"" << frame.x(c.knots, i) << "\" cy=\"" << frame.y(c.knots, i) << "\" r=\"4\" fill=\"#d62728\"/>\n";
  out << "</svg>\n";
  out.close();
  if(!out) throw Tool_error("writing '" + path + "' failed");
}

void write_fit_png(const std::string& path, const std::vector<Fit_picture_curve>& curves, bool y_down)
{
#ifdef TVF_HAS_CAIRO
  const Frame frame(curves, y_down);
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, int(picture_size), int(picture_size));
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  auto polyline = [&](const Eigen::MatrixXd& P, bool closed, double r, double g, double b, double width) {
    for(Eigen::Index i = 0; i < P.rows(); ++i)
      (i == 0 ? cairo_move_to : cairo_line_to)(cr, frame.x(P, i), frame.y(P, i));
    if(closed) cairo_close_path(cr);
    cairo_set_source_rgb(cr, r, g, b);
    cairo_set_line_width(cr, width);
    cairo_stroke(cr);
  };
  for(const Fit_picture_curve& c : curves) polyline(c.samples, c.closed, 0.6, 0.6, 0.6, 3);
  for(const Fit_picture_curve& c : curves) polyline(c.fit, c.closed, 0.12, 0.37, 0.75, 1.5);
  cairo_set_source_rgb(cr, 0.84, 0.15, 0.16);
  for(const Fit_picture_curve& c : curves)
    for(Eigen::Index i = 0; i < c.knots.rows(); ++i)
    {
      cairo_new_sub_path(cr);
      cairo_arc(cr, frame.x(c.knots, i), frame.y(c.knots, i), 4, 0, 2 * M_PI);
    }
  cairo_fill(cr);
  const cairo_status_t status = cairo_surface_write_to_png(surface, path.c_str());
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
  if(status != CAIRO_STATUS_SUCCESS)
    throw Tool_error("cannot write '" + path + "': " + cairo_status_to_string(status));
#else
  (void)curves, (void)y_down;
  throw Tool_error("'" + path + "': this tvf was built without Cairo (TVF_USE_CAIRO), so it writes no PNG; use .svg");
#endif
}

void write_error_chart(const std::string& path, const CGAL::Model_reduction::Line_chart& chart)
{
  try
  {
    CGAL::Model_reduction::write_svg_line_chart(path, chart);
  }
  catch(const CGAL::Model_reduction::Invalid_input& e)
  {
    throw Tool_error("'" + path + "': " + one_line(e.what()));
  }
}

} // namespace tvf_tool
