// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Glyph outlines through FreeType, loaded unscaled and unhinted (FT_LOAD_NO_SCALE): the points
// are the font's integer design coordinates, so the Bezier segments are the font's exact truth.
// FT_Outline_Decompose turns TrueType's implied on-curve points into explicit quadratic segments.

#include <CGAL/Spline_approximation/Glyph_outline.h>
#include <CGAL/Spline_approximation/errors.h>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#include FT_FONT_FORMATS_H

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>

namespace CGAL {
namespace Spline_approximation {
namespace {

struct Library_deleter { void operator()(FT_Library l) const { FT_Done_FreeType(l); } };
struct Face_deleter { void operator()(FT_Face f) const { FT_Done_Face(f); } };

// What the decomposition callbacks build: the contours, the pen, and the scale.
struct Outline_builder
{
  std::vector<Bezier_contour> contours;
  Eigen::RowVector2d pen = Eigen::RowVector2d::Zero();
  double scale = 1;

  Eigen::RowVector2d at(const FT_Vector* v) const { return Eigen::RowVector2d(double(v->x), double(v->y)) * scale; }
  void add(int degree, std::initializer_list<const FT_Vector*> points)
  {
    Bezier_segment s;
    s.degree = degree;
    s.control_points.row(0) = pen;
    int i = 1;
    for(const FT_Vector* p : points) s.control_points.row(i++) = at(p);
    contours.back().segments.push_back(s);
    pen = s.end();
  }
};

int move_to(const FT_Vector* to, void* user)
{
  Outline_builder& b = *static_cast<Outline_builder*>(user);
  b.contours.emplace_back();
  b.contours.back().closed = true; // FreeType's contours are closed: it emits the closing segment itself
  b.pen = b.at(to);
  return 0;
}
int line_to(const FT_Vector* to, void* user) { static_cast<Outline_builder*>(user)->add(1, {to}); return 0; }
int conic_to(const FT_Vector* c, const FT_Vector* to, void* user) { static_cast<Outline_builder*>(user)->add(2, {c, to}); return 0; }
int cubic_to(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user)
{
  static_cast<Outline_builder*>(user)->add(3, {c1, c2, to});
  return 0;
}

std::string code_point_name(char32_t c)
{
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "U+%04X", unsigned(c));
  return buffer;
}

} // namespace

char32_t first_code_point(const std::string& s)
{
  if(s.empty()) throw Invalid_input("glyph: an empty string has no character");
  const unsigned char c0 = static_cast<unsigned char>(s[0]);
  const int length = c0 < 0x80 ? 1 : (c0 >> 5) == 0x6 ? 2 : (c0 >> 4) == 0xE ? 3 : (c0 >> 3) == 0x1E ? 4 : 0;
  if(length == 0 || s.size() < std::size_t(length)) throw Invalid_input("glyph: '" + s + "' is not valid UTF-8");
  char32_t c = length == 1 ? c0 : c0 & (0x7F >> length);
  for(int i = 1; i < length; ++i) {
    const unsigned char ci = static_cast<unsigned char>(s[std::size_t(i)]);
    if((ci >> 6) != 0x2) throw Invalid_input("glyph: '" + s + "' is not valid UTF-8");
    c = (c << 6) | (ci & 0x3F);
  }
  return c;
}

Glyph_outline read_glyph_outline(const std::string& font_file, char32_t character, double em_size)
{
  if(!(em_size > 0 && std::isfinite(em_size)))
    throw Invalid_input("glyph: the em size must be positive and finite");
  if(!std::ifstream(font_file)) // FreeType's error codes do not say "no such file"; the system does
    throw Invalid_input("cannot open font file '" + font_file + "': " + std::strerror(errno));
  FT_Library raw_library = nullptr;
  if(FT_Init_FreeType(&raw_library) != 0) throw Invalid_input("glyph: FreeType failed to start");
  std::unique_ptr<FT_LibraryRec_, Library_deleter> library(raw_library);
  FT_Face raw_face = nullptr;
  if(FT_New_Face(library.get(), font_file.c_str(), 0, &raw_face) != 0)
    throw Invalid_input("'" + font_file + "' is not a font FreeType can read");
  std::unique_ptr<FT_FaceRec_, Face_deleter> face(raw_face);
  const FT_UInt index = FT_Get_Char_Index(face.get(), FT_ULong(character));
  if(index == 0) throw Invalid_input("the font '" + font_file + "' has no glyph for " + code_point_name(character));
  if(!FT_IS_SCALABLE(face.get()) || face->units_per_EM == 0)
    throw Invalid_input("the font '" + font_file + "' has no outlines (a bitmap font)");
  if(FT_Load_Glyph(face.get(), index, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) != 0 ||
     face->glyph->format != FT_GLYPH_FORMAT_OUTLINE)
    throw Invalid_input("glyph " + code_point_name(character) + " of '" + font_file + "' has no outline");
  Outline_builder builder;
  builder.scale = em_size / double(face->units_per_EM);
  FT_Outline_Funcs funcs;
  funcs.move_to = move_to;
  funcs.line_to = line_to;
  funcs.conic_to = conic_to;
  funcs.cubic_to = cubic_to;
  funcs.shift = 0;
  funcs.delta = 0;
  if(FT_Outline_Decompose(&face->glyph->outline, &funcs, &builder) != 0)
    throw Invalid_input("glyph " + code_point_name(character) + " of '" + font_file + "': a malformed outline");
  Glyph_outline out;
  for(Bezier_contour& c : builder.contours)
    if(!c.segments.empty()) out.contours.push_back(std::move(c));
  const char* format = FT_Get_Font_Format(face.get());
  out.font_format = format ? format : "";
  out.units_per_em = int(face->units_per_EM);
  return out;
}

} // namespace Spline_approximation
} // namespace CGAL
