// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Curves with exact Bezier truth: the subpaths of SVG path data (a file given, or a C^2 cubic
// path written here) fitted by cubic splines at their Bezier parameters, which recovers the
// joints as knots; then, where FreeType was found, the contours of a glyph of DejaVu Sans fitted
// by polylines (degree 1), whose knots are the glyph's corners.
//
// Usage: fit_svg_and_glyph [file.svg] [character]

#include <CGAL/Spline_approximation/Spline_fit.h>
#include <CGAL/Spline_approximation/Svg_paths.h>
#ifdef TVF_HAS_FREETYPE
#include <CGAL/Spline_approximation/Glyph_outline.h>
#endif

#include <iostream>
#include <string>

namespace SA = CGAL::Spline_approximation;

namespace {

// Fits every contour within `max_error` at the samples' Bezier parameters and prints the knots.
void fit_contours(const std::vector<SA::Bezier_contour>& contours, int degree, double max_error)
{
  for(std::size_t i = 0; i < contours.size(); ++i) {
    const SA::Sampled_contour s = SA::sample_contour(contours[i], 16);
    SA::Fit_options o;
    o.degree = degree;
    o.algorithm = SA::Fit_algorithm::greedy_removal;
    o.max_error = max_error;
    o.closed_curve = s.closed;
    const SA::Spline_fit fit = SA::fit_spline(s.points, s.parameters, o);
    std::cout << "  contour " << i + 1 << (s.closed ? " (closed)" : " (open)") << ": " << contours[i].segments.size()
              << " segments, " << s.points.rows() << " samples -> " << fit.number_of_knots() << " knots, max error "
              << fit.max_error << "\n    knots:";
    const Eigen::VectorXd knots = fit.spline.interior_knots();
    for(Eigen::Index k = 0; k < knots.size(); ++k) std::cout << " " << knots[k];
    std::cout << "\n";
  }
}

} // namespace

int main(int argc, char** argv)
{
  try {
    // The Bezier form of a uniform cubic B-spline: C^2 at its joints (S reflects the last control point).
    const std::string drawing = "<svg><path d=\"M 19 24 C 26 28 34 26 40 19 S 50 0 57 -3 S 74 0 80 10\"/></svg>";
    const SA::Svg_paths svg = argc > 1 ? SA::read_svg_paths(argv[1]) : SA::parse_svg_paths(drawing, "the drawing");
    std::cout << "SVG: " << svg.path_elements << " path elements, " << svg.contours.size()
              << " subpaths, cubic fit within 1e-9 at Bezier parameters\n";
    fit_contours(svg.contours, 3, 1e-9);
#ifdef TVF_HAS_FREETYPE
    const std::string character = argc > 2 ? argv[2] : "E";
    const SA::Glyph_outline glyph = SA::read_glyph_outline(SA::default_glyph_font, SA::first_code_point(character), 1000);
    std::cout << "glyph '" << character << "' (" << glyph.font_format << "): " << glyph.contours.size()
              << " contours, polyline fit within 1e-9\n";
    fit_contours(glyph.contours, 1, 1e-9);
#else
    std::cout << "glyphs: this build has no FreeType\n";
#endif
  } catch(const SA::Invalid_input& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
