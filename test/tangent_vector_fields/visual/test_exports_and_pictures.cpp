// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Showing fields: the export formats and their round trips, charts, and pictures (the
// surface, hidden lines, colour maps, arrows and fur).

#include "expect_reason.h"
#include "scratch_path.h"
#include "test_meshes.h"
#include "visual_test_support.h"

#include <CGAL/Tangent_vector_fields/Streamlines.h>
#include <CGAL/Tangent_vector_fields/field_export.h>
#include <CGAL/Model_reduction/svg_chart.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <sstream>

namespace TVF = CGAL::Tangent_vector_fields;
namespace MR = CGAL::Model_reduction;
using namespace tvf_test;

// ---------------------------------------------------------------------------
// Exports

namespace {

std::vector<std::string> lines_of(const std::string& filename)
{
  std::ifstream in(filename);
  std::vector<std::string> lines;
  for(std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

} // namespace

TEST(Exports, VtpRoundTripIsExact)
{
  Mesh sphere = make_icosphere(2);
  jitter_vertices(sphere, 0.3, 2);
  Field wind = ambient_field_map(sphere, "wind", 3);
  Field gust = ambient_field_map(sphere, "gust", 4);
  const std::string file = scratch_path("fields.vtp");
  TVF::write_vtp(file, sphere, std::vector<std::pair<std::string, Field>>{{"wind", wind}, {"gust", gust}});
  Field wind_back = field_map(sphere, "wind_back"), gust_back = field_map(sphere, "gust_back");
  TVF::read_vtp(file, sphere, "wind", wind_back);
  TVF::read_vtp(file, sphere, "gust", gust_back);
  for(Face_index f : sphere.faces())
  {
    EXPECT_EQ(wind_back[f], wind[f]);
    EXPECT_EQ(gust_back[f], gust[f]);
  }
  // The geometry and connectivity come back too, and the file names its active vectors.
  std::ifstream in(file);
  const TVF::Vtk_polydata data = TVF::read_vtk_polydata(in);
  ASSERT_EQ(data.points.size(), sphere.number_of_vertices());
  for(Vertex_index v : sphere.vertices())
    EXPECT_EQ(data.points[std::size_t(v)], (P3{sphere.point(v).x(), sphere.point(v).y(), sphere.point(v).z()}));
  ASSERT_EQ(data.polygons.size(), sphere.number_of_faces());
  for(Face_index f : sphere.faces())
  {
    std::vector<int> corners;
    for(Vertex_index v : vertices_around_face(sphere.halfedge(f), sphere)) corners.push_back(int(std::size_t(v)));
    EXPECT_EQ(data.polygons[std::size_t(f)], corners);
  }
  bool header = false, active = false;
  for(const std::string& line : lines_of(file))
  {
    header = header || line.find("<VTKFile type=\"PolyData\"") != std::string::npos;
    active = active || line.find("<CellData Vectors=\"wind\">") != std::string::npos;
  }
  EXPECT_TRUE(header);
  EXPECT_TRUE(active);
  EXPECT_THROW_REASON(TVF::read_vtp(file, sphere, "missing", wind_back),
                      TVF::Invalid_input, "has no 3-component cell array 'missing'");
  Mesh other = make_icosphere(1);
  Field other_field = field_map(other, "x");
  EXPECT_THROW_REASON(TVF::read_vtp(file, other, "wind", other_field),
                      TVF::Invalid_input, "polygons, the mesh 80 faces");
}

TEST(Exports, VtpReaderRefusesWhatItCannotRead)
{
  auto read = [](const std::string& text) {
    std::istringstream in(text);
    return TVF::read_vtk_polydata(in);
  };
  const std::string head = "<VTKFile type=\"PolyData\" version=\"0.1\"><PolyData><Piece NumberOfPoints=\"1\" "
                           "NumberOfPolys=\"0\"><Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" ";
  const TVF::Vtk_polydata ok = read(head + "format=\"ascii\">1 2.5 -3</DataArray></Points></Piece></PolyData></VTKFile>");
  ASSERT_EQ(ok.points.size(), 1u);
  EXPECT_EQ(ok.points[0], (P3{1, 2.5, -3}));
  EXPECT_THROW_REASON(read(head + "format=\"binary\">AAAA</DataArray></Points></Piece></PolyData></VTKFile>"),
                      TVF::Invalid_input, "data arrays in format 'binary' are not read (only ascii)");
  EXPECT_THROW_REASON(read(head + "format=\"ascii\">1 2</DataArray></Points></Piece></PolyData></VTKFile>"),
                      TVF::Invalid_input, "has a partial tuple");
  EXPECT_THROW_REASON(read("<VTKFile type=\"UnstructuredGrid\"></VTKFile>"),
                      TVF::Invalid_input, "VTK file of type 'UnstructuredGrid', expected PolyData");
  EXPECT_THROW_REASON(read("not xml at all"), TVF::Invalid_input, "not a VTK PolyData file");
}

TEST(Exports, RawFieldRoundTripIsExactAndFollowsDirectionalsLayout)
{
  Mesh torus = make_torus(12, 8);
  Field field = ambient_field_map(torus, "wind", 9);
  const std::string file = scratch_path("wind.rawfield");
  TVF::write_raw_field(file, torus, field);
  const std::vector<std::string> lines = lines_of(file);
  ASSERT_EQ(lines.size(), torus.number_of_faces() + 1);
  EXPECT_EQ(lines[0], "1 " + std::to_string(torus.number_of_faces()));
  {
    std::istringstream first(lines[1]);
    double x, y, z;
    first >> x >> y >> z;
    const Vector_3& w = field[*torus.faces().begin()];
    EXPECT_EQ(Vector_3(x, y, z), w);
  }
  Field back = field_map(torus, "back");
  TVF::read_raw_field(file, torus, back);
  for(Face_index f : torus.faces()) EXPECT_EQ(back[f], field[f]);

  // Degree 2: pick either vector of each face.
  TVF::Raw_field two;
  two.degree = 2;
  for(Face_index f : torus.faces())
  {
    two.vectors.push_back({field[f].x(), field[f].y(), field[f].z()});
    two.vectors.push_back({-field[f].y(), field[f].x(), 0.25});
  }
  const std::string file2 = scratch_path("two.rawfield");
  {
    std::ofstream out(file2);
    TVF::write_raw_field(out, two);
  }
  TVF::read_raw_field(file2, torus, back, 1);
  for(Face_index f : torus.faces()) EXPECT_EQ(back[f], Vector_3(-field[f].y(), field[f].x(), 0.25));
  EXPECT_THROW_REASON(TVF::read_raw_field(file2, torus, back, 2),
                      TVF::Invalid_input, "has 2 vectors per face; direction 2 does not exist");
  Mesh other = make_torus(10, 8);
  Field other_field = field_map(other, "x");
  EXPECT_THROW_REASON(TVF::read_raw_field(file, other, other_field), TVF::Invalid_input, "has 192 faces, the mesh 160");
  std::istringstream truncated("1 3\n1 2 3\n4 5 6\n");
  EXPECT_THROW_REASON(TVF::read_raw_field(truncated), TVF::Invalid_input, "raw field: face 2 is missing or unreadable");
  std::istringstream extra("1 1\n1 2 3\n4\n");
  EXPECT_THROW_REASON(TVF::read_raw_field(extra), TVF::Invalid_input, "raw field: more numbers than 1 faces");
}

TEST(Exports, StreamlinesAsObjPlyAndVtpKeepEveryPoint)
{
  Mesh sphere = make_icosphere(3);
  Field field = field_map(sphere, "rotation");
  rotated_height_gradient(sphere, field);
  TVF::Mesh_streamline_tracer<Mesh> tracer(sphere, field);
  TVF::Evenly_spaced_options options;
  options.separation = 0.1;
  const std::vector<TVF::Streamline> lines = tracer.evenly_spaced(options);
  ASSERT_GT(lines.size(), 3u);
  std::vector<P3> all;
  std::size_t segments = 0, closed = 0;
  for(const auto& s : lines)
  {
    all.insert(all.end(), s.points.begin(), s.points.end());
    segments += s.number_of_segments();
    closed += s.closed;
  }
  EXPECT_GT(closed, 0u); // the level circles close

  // OBJ: vertices, and one polyline per streamline (closed ones repeat their first index).
  const std::string obj = scratch_path("lines.obj");
  TVF::write_streamlines_obj(obj, lines);
  std::vector<P3> points;
  std::vector<std::vector<std::size_t>> polylines;
  for(const std::string& line : lines_of(obj))
  {
    std::istringstream in(line);
    std::string tag;
    in >> tag;
    if(tag == "v")
    {
      P3 p;
      in >> p[0] >> p[1] >> p[2];
      points.push_back(p);
    }
    else if(tag == "l")
    {
      polylines.emplace_back();
      for(std::size_t i; in >> i;) polylines.back().push_back(i);
    }
  }
  EXPECT_EQ(points, all);
  ASSERT_EQ(polylines.size(), lines.size());
  std::size_t base = 1;
  for(std::size_t l = 0; l < lines.size(); ++l)
  {
    ASSERT_EQ(polylines[l].size(), lines[l].points.size() + (lines[l].closed ? 1 : 0));
    EXPECT_EQ(polylines[l].front(), base);
    if(lines[l].closed) EXPECT_EQ(polylines[l].back(), base);
    base += lines[l].points.size();
  }

  // PLY: header with edge elements, vertices with face and streamline, one edge per segment.
  const std::string ply = scratch_path("lines.ply");
  TVF::write_streamlines_ply(ply, lines);
  const std::vector<std::string> text = lines_of(ply);
  const auto end_header = std::find(text.begin(), text.end(), "end_header");
  ASSERT_NE(end_header, text.end());
  EXPECT_NE(std::find(text.begin(), end_header, "element vertex " + std::to_string(all.size())), end_header);
  EXPECT_NE(std::find(text.begin(), end_header, "element edge " + std::to_string(segments + closed)), end_header);
  EXPECT_NE(std::find(text.begin(), end_header, "property int vertex1"), end_header);
  std::size_t row = static_cast<std::size_t>(end_header - text.begin()) + 1;
  for(std::size_t l = 0; l < lines.size(); ++l)
    for(std::size_t i = 0; i < lines[l].points.size(); ++i, ++row)
    {
      std::istringstream in(text[row]);
      P3 p;
      int face, line;
      in >> p[0] >> p[1] >> p[2] >> face >> line;
      EXPECT_EQ(p, lines[l].points[i]);
      EXPECT_EQ(face, lines[l].faces[i]);
      EXPECT_EQ(line, static_cast<int>(l));
    }
  EXPECT_EQ(text.size() - row, segments + closed);

  // VTP polylines, read back with the package's reader.
  const std::string vtp = scratch_path("lines.vtp");
  TVF::write_streamlines_vtp(vtp, lines);
  std::ifstream in(vtp);
  const TVF::Vtk_polydata data = TVF::read_vtk_polydata(in);
  EXPECT_EQ(data.points, all);
  ASSERT_EQ(data.lines.size(), lines.size());
  const TVF::Vtk_polydata::Array* faces = data.find_point_array("face");
  ASSERT_NE(faces, nullptr);
  for(std::size_t i = 0, l = 0; l < lines.size(); ++l)
    for(int f : lines[l].faces) EXPECT_EQ(faces->values[i++], f);
}

// ---------------------------------------------------------------------------
// Charts

TEST(Charts, SvgLineChartHasOneCurvePerSeriesOnLogAxes)
{
  MR::Line_chart chart;
  chart.title = "error against time";
  chart.series.push_back({"elephant", {0.01, 0.1, 1, 10}, {1e-2, 1e-4, 1e-6, 1e-8}});
  chart.series.push_back({"bunny <69k>", {0.02, 0.3, 2}, {3e-3, 2e-5, -1}}); // the last point cannot be drawn
  const std::string file = scratch_path("chart.svg");
  MR::write_svg_line_chart(file, chart);
  std::ifstream in(file);
  const std::string svg{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_EQ(svg.compare(0, 5, "<?xml"), 0);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("bunny &lt;69k&gt;"), std::string::npos); // names are escaped
  EXPECT_NE(svg.find("10<tspan"), std::string::npos);         // log ticks as powers of ten
  // Parse the polylines: one per series, x growing to the right, smaller errors lower.
  std::vector<std::vector<std::pair<double, double>>> curves;
  for(std::size_t at = svg.find("<polyline"); at != std::string::npos; at = svg.find("<polyline", at + 1))
  {
    const std::size_t start = svg.find("points=\"", at) + 8, end = svg.find('"', start);
    std::istringstream points(svg.substr(start, end - start));
    curves.emplace_back();
    double x, y;
    char comma;
    while(points >> x >> comma >> y) curves.back().emplace_back(x, y);
  }
  ASSERT_EQ(curves.size(), 2u);
  EXPECT_EQ(curves[0].size(), 4u);
  EXPECT_EQ(curves[1].size(), 2u);
  for(const auto& c : curves)
    for(std::size_t i = 1; i < c.size(); ++i)
    {
      EXPECT_GT(c[i].first, c[i - 1].first);
      EXPECT_GT(c[i].second, c[i - 1].second); // SVG y grows downwards
      EXPECT_GE(c[i].first, 0);
      EXPECT_LE(c[i].first, chart.width);
    }
  // Equal steps in log10 are equal steps on the page.
  EXPECT_NEAR(curves[0][1].first - curves[0][0].first, curves[0][2].first - curves[0][1].first, 0.02);
  EXPECT_NEAR(curves[0][1].second - curves[0][0].second, curves[0][2].second - curves[0][1].second, 0.02);
  MR::Line_chart bad;
  bad.series.push_back({"x", {1, 2}, {1}});
  std::ostringstream sink;
  EXPECT_THROW_REASON(MR::write_svg_line_chart(sink, bad),
                      TVF::Invalid_input, "chart: series 'x' has 2 x and 1 y values");
}

// ---------------------------------------------------------------------------
// Pictures

#ifdef TVF_HAS_CAIRO
#include "picture_test_support.h"

#include <CGAL/Tangent_vector_fields/Field_picture.h>

using namespace tvf_picture_test;

TEST(Pictures, SphereFillsTheMiddleAndLeavesTheCornersEmpty)
{
  Mesh sphere = make_icosphere(3);
  TVF::Field_picture<Mesh> picture(sphere, front_view(240, 160));
  const std::string file = scratch_path("sphere.png");
  picture.write_png(file);
  const Image image = read_png(file);
  ASSERT_EQ(image.width, 240);
  ASSERT_EQ(image.height, 160);
  EXPECT_NE(image.at(120, 80) & 0xffffff, white);
  for(auto c : {std::make_pair(0, 0), std::make_pair(239, 0), std::make_pair(0, 159), std::make_pair(239, 159)})
    EXPECT_EQ(image.at(c.first, c.second) & 0xffffff, white);
  // The disc covers pi r^2 pixels, r = half the usable height (margin 4%).
  int covered = 0;
  for(std::uint32_t p : image.pixels) covered += (p & 0xffffff) != white;
  const double r = 160 * (1 - 2 * 0.04) / 2;
  EXPECT_NEAR(covered, M_PI * r * r, 0.05 * M_PI * r * r);
  // Left and right of the disc are empty; lit from the upper left, so brighter there.
  EXPECT_EQ(image.at(120 - static_cast<int>(r) - 3, 80) & 0xffffff, white);
  EXPECT_EQ(image.at(120 + static_cast<int>(r) + 3, 80) & 0xffffff, white);
  EXPECT_GT(Image::green(image.at(120 - 30, 80 - 30)), Image::green(image.at(120 + 30, 80 + 30)));
}

TEST(Pictures, LinesBehindTheSurfaceAreHidden)
{
  Mesh sphere = make_icosphere(4);
  Field field = field_map(sphere, "rotation");
  rotated_height_gradient(sphere, field);
  TVF::Mesh_streamline_tracer<Mesh> tracer(sphere, field);
  // Level circles of J grad z: one on the front half (z = 0.5, facing the camera),
  // one on the back (z = -0.5).
  auto circle_at = [&](double z) {
    for(Face_index f : sphere.faces())
    {
      std::vector<Point_3> p;
      for(Vertex_index v : vertices_around_face(sphere.halfedge(f), sphere)) p.push_back(sphere.point(v));
      const Point_3 m = CGAL::centroid(p[0], p[1], p[2]);
      if(std::abs(m.z() - z) < 0.02) return tracer.trace(f, m);
    }
    return TVF::Streamline();
  };
  const TVF::Streamline front = circle_at(0.5), back = circle_at(-0.5);
  ASSERT_TRUE(front.closed);
  ASSERT_TRUE(back.closed);
  TVF::Line_style red;
  red.colour = {1, 0, 0};
  red.width = 2;
  red.opacity = 1;
  TVF::Field_picture<Mesh> plain(sphere, front_view(200, 200));
  TVF::Field_picture<Mesh> with_back(sphere, front_view(200, 200));
  with_back.add_streamlines({back}, red);
  TVF::Field_picture<Mesh> with_front(sphere, front_view(200, 200));
  with_front.add_streamlines({front}, red);
  plain.write_png(scratch_path("plain.png"));
  with_back.write_png(scratch_path("back.png"));
  with_front.write_png(scratch_path("front.png"));
  const Image a = read_png(scratch_path("plain.png")), b = read_png(scratch_path("back.png")),
              c = read_png(scratch_path("front.png"));
  EXPECT_EQ(count_differences(a, b), 0);
  // The front circle (radius sqrt(3)/2 in a unit sphere of radius 92 pixels) is drawn:
  // a red ring of about 2 pi 80 pixels' length and 2 pixels' width.
  const int changed = count_differences(a, c);
  EXPECT_GT(changed, 2 * M_PI * 80 * 1.5);
  int red_pixels = 0;
  for(std::uint32_t p : c.pixels) red_pixels += Image::red(p) > 200 && Image::green(p) < 80 && Image::blue(p) < 80;
  EXPECT_GT(red_pixels, 2 * M_PI * 80);
  // On the ring: the pixel at distance 0.866 r from the centre, above it.
  const double r = 200 * (1 - 2 * 0.04) / 2;
  EXPECT_GT(Image::red(c.at(100, static_cast<int>(std::lround(100 - 0.866 * r)))), 150);
}

TEST(Pictures, ColourMapRangeAndLegend)
{
  EXPECT_NEAR(TVF::colour_at(TVF::Colour_map::viridis, 0).r, 68 / 255., 1e-12);
  EXPECT_NEAR(TVF::colour_at(TVF::Colour_map::viridis, 1).g, 231 / 255., 1e-12);
  EXPECT_NEAR(TVF::colour_at(TVF::Colour_map::cool_warm, 0.5).b, 221 / 255., 1e-12);
  EXPECT_NEAR(TVF::colour_at(TVF::Colour_map::cool_warm, -3).b, 192 / 255., 1e-12); // clamped

  Mesh sphere = make_icosphere(3);
  auto height = sphere.add_property_map<Face_index, double>("f:height", 0.).first;
  for(Face_index f : sphere.faces())
  {
    double y = 0;
    for(Vertex_index v : vertices_around_face(sphere.halfedge(f), sphere)) y += sphere.point(v).y() / 3;
    height[f] = y;
  }
  TVF::Render_options options = front_view(400, 300);
  options.legend = true;
  TVF::Field_picture<Mesh> picture(sphere, options);
  TVF::Scalar_colouring colouring;
  colouring.label = "height";
  picture.colour_faces(height, colouring);
  const auto range = picture.renderer().colour_range();
  double lo = 1e300, hi = -1e300;
  for(Face_index f : sphere.faces())
  {
    lo = std::min(lo, height[f]);
    hi = std::max(hi, height[f]);
  }
  EXPECT_EQ(range.first, lo);
  EXPECT_EQ(range.second, hi);
  const std::string file = scratch_path("height.png");
  picture.write_png(file);
  const Image image = read_png(file);
  // Model left of the legend: high values (yellow) at the top, low (purple) at the bottom.
  const int cx = (400 - std::max(110, 400 / 9)) / 2;
  const std::uint32_t top = image.at(cx, 40), bottom = image.at(cx, 260);
  EXPECT_GT(Image::red(top) + Image::green(top), 2 * Image::blue(top));
  EXPECT_GT(Image::blue(bottom), Image::green(bottom));
  // The colour bar: yellow at its top, purple at its bottom, right of the model.
  bool yellow = false, purple = false;
  for(int x = 400 - 110; x < 400; ++x)
  {
    const std::uint32_t t = image.at(x, static_cast<int>(0.2 * 300) + 3), b = image.at(x, static_cast<int>(0.8 * 300) - 3);
    yellow = yellow || (Image::red(t) > 200 && Image::green(t) > 200 && Image::blue(t) < 90);
    purple = purple || (Image::red(b) < 90 && Image::green(b) < 30 && Image::blue(b) > 60);
  }
  EXPECT_TRUE(yellow);
  EXPECT_TRUE(purple);

  // Symmetric range with clipping: [-m, m] from the 10% / 90% quantiles.
  TVF::Scalar_colouring signed_colouring;
  signed_colouring.map = TVF::Colour_map::cool_warm;
  signed_colouring.symmetric = true;
  signed_colouring.clip_fraction = 0.1;
  picture.colour_faces(height, signed_colouring);
  const auto clipped = picture.renderer().colour_range();
  EXPECT_EQ(clipped.first, -clipped.second);
  EXPECT_LT(clipped.second, hi);
  EXPECT_GT(clipped.second, 0.5 * hi);
  std::vector<double> wrong(3, 0.);
  EXPECT_THROW_REASON(picture.renderer().colour_faces(wrong), TVF::Invalid_input, "renderer: expected one value per");
}

TEST(Pictures, ArrowsFurAndSvg)
{
  Mesh torus = make_torus(40, 20);
  Field field = field_map(torus, "rotation");
  rotated_height_gradient(torus, field);
  TVF::Render_options options = front_view(300, 200);
  options.camera.view_direction = {0, 0, 0}; // azimuth and elevation
  options.camera.up = {0, 0, 1};
  options.camera.elevation = 35;
  options.camera.projection = TVF::Projection::perspective;
  TVF::Field_picture<Mesh> plain(torus, options), arrows(torus, options), fur(torus, options);
  arrows.add_arrows(field);
  TVF::Fur_options hair;
  hair.number_of_strokes = 800;
  hair.length = 0.05;
  const auto strokes = fur.add_fur(field, hair);
  EXPECT_GT(strokes.size(), 700u);
  plain.write_png(scratch_path("torus.png"));
  arrows.write_png(scratch_path("torus_arrows.png"));
  fur.write_png(scratch_path("torus_fur.png"));
  const Image a = read_png(scratch_path("torus.png")), b = read_png(scratch_path("torus_arrows.png")),
              c = read_png(scratch_path("torus_fur.png"));
  ASSERT_EQ(a.width, 300);
  EXPECT_NE(a.at(150, 100 - 55) & 0xffffff, white); // the front of the ring
  EXPECT_EQ(a.at(2, 2) & 0xffffff, white);
  EXPECT_GT(count_differences(a, b), 1000);
  EXPECT_GT(count_differences(a, c), 1000);
  // Overlays stay on the surface: no changed pixel is more than a few pixels away from it.
  int stray = 0;
  for(int y = 0; y < 200; ++y)
    for(int x = 0; x < 300; ++x)
    {
      if((a.at(x, y) & 0xffffff) == (c.at(x, y) & 0xffffff)) continue;
      bool near_surface = false;
      for(int dy = -3; dy <= 3 && !near_surface; ++dy)
        for(int dx = -3; dx <= 3 && !near_surface; ++dx)
        {
          const int u = std::min(std::max(x + dx, 0), 299), v = std::min(std::max(y + dy, 0), 199);
          near_surface = (a.at(u, v) & 0xffffff) != white;
        }
      stray += !near_surface;
    }
  EXPECT_EQ(stray, 0);

  const std::string svg_file = scratch_path("torus.svg");
  fur.write_svg(svg_file);
  std::ifstream in(svg_file);
  const std::string svg{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("width=\"300"), std::string::npos);
  EXPECT_NE(svg.find("<image"), std::string::npos); // the surface
  EXPECT_NE(svg.find("<path"), std::string::npos);  // the strokes, as vectors
  EXPECT_THROW_REASON(fur.write_png("/nonexistent-folder/x.png"),
                      TVF::Invalid_input, "cannot write '/nonexistent-folder/x.png'");
}
#endif
