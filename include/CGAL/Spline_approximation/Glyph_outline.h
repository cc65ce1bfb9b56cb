// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SPLINE_APPROXIMATION_GLYPH_OUTLINE_H
#define CGAL_SPLINE_APPROXIMATION_GLYPH_OUTLINE_H

/// \file Glyph_outline.h
/// The outline of a font's glyph as exact Bezier contours, read through FreeType: quadratic
/// segments for TrueType fonts, cubic ones for CFF (OpenType/PostScript) fonts, lines for the
/// straight parts.  Compiled only when the build found FreeType (`TVF_HAS_FREETYPE` is then
/// defined for users of the library).

#include <CGAL/Spline_approximation/Bezier_contour.h>

#include <string>
#include <vector>

namespace CGAL {
namespace Spline_approximation {

/// DejaVu Sans from Debian's fonts-dejavu-core: the default font of `tvf fit --glyph`.
constexpr const char* default_glyph_font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

/// A glyph outline: its closed contours and the font's facts.
struct Glyph_outline
{
  std::vector<Bezier_contour> contours; ///< every one closed; y points up (font coordinates)
  std::string font_format;              ///< FreeType's name of the format: "TrueType", "CFF", ...
  int units_per_em = 0;                 ///< the font's design grid (the outline is exact in these units, then scaled)
};

/// Reads the outline of `character` (a Unicode code point) from a font file, unhinted, in font
/// units scaled by `em_size / units_per_em` (so the em square is `em_size` wide).  The control
/// points are the font's own: exact integers times that scale.
/// \throws Invalid_input if the file cannot be opened or is not a font FreeType reads, the font
///         has no glyph for the character, the glyph is not an outline (a bitmap font), or
///         `em_size` is not positive and finite.
Glyph_outline read_glyph_outline(const std::string& font_file, char32_t character, double em_size = 1000);

/// The first Unicode code point of a UTF-8 string (for a character given on a command line).
/// \throws Invalid_input if the string is empty or not valid UTF-8.
char32_t first_code_point(const std::string& utf8);

} // namespace Spline_approximation
} // namespace CGAL

#endif
