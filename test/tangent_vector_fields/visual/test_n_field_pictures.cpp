// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Pictures of n-direction fields: n-fold glyphs (arrows are the glyphs of symmetry 1, a glyph
// has the shape of its n and does not depend on which of the n vectors it is given), the
// singular vertices marked where the surface shows them, and the wrappers on property maps.

#include "expect_reason.h"
#include "picture_test_support.h"
#include "scratch_path.h"
#include "test_meshes.h"

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Tangent_vector_fields/Discrete_operators.h>
#include <CGAL/Tangent_vector_fields/Field_picture.h>
#include <CGAL/Tangent_vector_fields/Field_renderer.h>
#include <CGAL/Tangent_vector_fields/N_field_singularities.h>
#include <CGAL/Tangent_vector_fields/Smoothest_n_field_solver.h>
#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/smoothest_n_field.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;
using namespace tvf_picture_test;

namespace {

Image picture_of(const TVF::Field_renderer& renderer, const std::string& name)
{
  const std::string file = scratch_path(name + ".png");
  renderer.write_png(file);
  return read_png(file);
}

// Each face's vector turned counter-clockwise in its frame by 2 pi j / n, j random per face:
// another of the n vectors of the same n-field.
Eigen::VectorXd other_vectors(const Eigen::VectorXd& x, int n, unsigned seed)
{
  std::mt19937 gen(seed);
  std::uniform_int_distribution<int> pick(1, n - 1);
  Eigen::VectorXd y(x.size());
  for(Eigen::Index f = 0; f < x.size() / 2; ++f)
  {
    const double a = 2 * M_PI * pick(gen) / n, c = std::cos(a), s = std::sin(a);
    y[2 * f] = c * x[2 * f] - s * x[2 * f + 1];
    y[2 * f + 1] = s * x[2 * f] + c * x[2 * f + 1];
  }
  return y;
}

// The reason of the Invalid_input that `f` throws ("" if it throws none).
template <class F>
std::string refusal(F f)
{
  try
  {
    f();
  }
  catch(const TVF::Invalid_input& e)
  {
    return e.what();
  }
  return "";
}

// A torus seen at an angle in perspective: glyphs foreshortened, partly hidden, of all sizes.
struct Torus_scene
{
  Mesh mesh = make_torus(40, 20);
  TVF::Discrete_operators<Mesh> ops{mesh};
  Eigen::VectorXd x = ops.to_frame_coordinates(ambient_field_map(mesh, "f:ambient", 3));
  TVF::Render_options options;

  Torus_scene()
  {
    options = front_view(300, 200);
    options.camera.view_direction = {0, 0, 0}; // azimuth and elevation
    options.camera.up = {0, 0, 1};
    options.camera.elevation = 35;
    options.camera.projection = TVF::Projection::perspective;
  }
  TVF::Field_renderer renderer() const { return TVF::Field_renderer(ops.shared_matrices()->shared_mesh(), options); }
};

bool dark(std::uint32_t p) { return Image::red(p) < 80 && Image::green(p) < 80 && Image::blue(p) < 80; }
bool reddish(std::uint32_t p) { return Image::red(p) > 180 && Image::green(p) < 80 && Image::blue(p) < 80; }
bool bluish(std::uint32_t p) { return Image::blue(p) > 180 && Image::red(p) < 80 && Image::green(p) < 120; }

// Where `front_view` (legend off) shows the point p: the bounding box of the mesh's vertices
// fills the image up to the 4% margin, its centre at the image centre.
std::array<double, 2> front_view_pixel(const TVF::Intrinsic_mesh& mesh, const std::array<double, 3>& p, int width,
                                       int height)
{
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for(int v = 0; v < mesh.number_of_vertices(); ++v)
  {
    x0 = std::min(x0, mesh.position(v)[0]);
    x1 = std::max(x1, mesh.position(v)[0]);
    y0 = std::min(y0, mesh.position(v)[1]);
    y1 = std::max(y1, mesh.position(v)[1]);
  }
  const double scale = std::min(width * 0.92 / (x1 - x0), height * 0.92 / (y1 - y0));
  return {width / 2. + scale * (p[0] - (x0 + x1) / 2), height / 2. - scale * (p[1] - (y0 + y1) / 2)};
}

// Pixels of `b` that differ from `a` within `radius` of (x, y).
int differences_near(const Image& a, const Image& b, double x, double y, double radius)
{
  int n = 0;
  for(int py = std::max(0, static_cast<int>(y - radius)); py <= std::min(a.height - 1, static_cast<int>(y + radius)); ++py)
    for(int px = std::max(0, static_cast<int>(x - radius)); px <= std::min(a.width - 1, static_cast<int>(x + radius)); ++px)
      if(std::hypot(px + 0.5 - x, py + 0.5 - y) <= radius) n += (a.at(px, py) & 0xffffff) != (b.at(px, py) & 0xffffff);
  return n;
}

} // namespace

TEST(NFieldPictures, ArrowsAreTheGlyphsOfSymmetryOne)
{
  const Torus_scene scene;
  TVF::Field_renderer plain = scene.renderer(), arrows = scene.renderer(), glyphs = scene.renderer(),
                      reversed = scene.renderer(), lines = scene.renderer(), reversed_lines = scene.renderer();
  arrows.add_arrows(scene.x);
  glyphs.add_glyphs(scene.x, 1);
  reversed.add_arrows(-scene.x);
  lines.add_glyphs(scene.x, 2);
  reversed_lines.add_glyphs(-scene.x, 2);
  const Image p = picture_of(plain, "plain"), a = picture_of(arrows, "arrows"), g = picture_of(glyphs, "glyphs1"),
              r = picture_of(reversed, "reversed"), l = picture_of(lines, "lines"),
              rl = picture_of(reversed_lines, "reversed_lines");
  EXPECT_GT(count_differences(p, a), 1000);
  EXPECT_EQ(count_differences(a, g), 0);
  // An arrow shows which way the field points (its head); a line glyph does not.
  EXPECT_GT(count_differences(a, r), 300);
  EXPECT_GT(count_differences(p, l), 1000);
  EXPECT_EQ(count_differences(l, rl), 0);
}

TEST(NFieldPictures, GlyphsDoNotDependOnWhichOfTheVectorsIsGiven)
{
  const Torus_scene scene;
  for(int n : {3, 4, 6})
  {
    TVF::Field_renderer plain = scene.renderer(), given = scene.renderer(), other = scene.renderer();
    given.add_glyphs(scene.x, n);
    other.add_glyphs(other_vectors(scene.x, n, 7 + n), n);
    const std::string name = "glyphs" + std::to_string(n);
    const Image p = picture_of(plain, "plain"), a = picture_of(given, name), b = picture_of(other, name + "_other");
    EXPECT_GT(count_differences(p, a), 1000) << "n = " << n;
    EXPECT_EQ(count_differences(a, b), 0) << "n = " << n;
  }
}

TEST(NFieldPictures, GlyphsHaveTheShapeOfTheirSymmetry)
{
  // A flat disk facing the camera, the field along x everywhere: in the cell at the image
  // centre the spokes are 0.85 * 40 / 2 = 17 pixels long.  Which directions have a spoke
  // 10 pixels from the centre (screen y points down; the disk's orientation does not matter,
  // the spokes at +-120 degrees are both there for n = 3)?
  Mesh disk = make_disk(12, 0.0, 0.2);
  TVF::Discrete_operators<Mesh> ops(disk);
  auto along_x = disk.add_property_map<Face_index, Vector_3>("f:x", Vector_3(1, 0, 0)).first;
  const Eigen::VectorXd x = ops.to_frame_coordinates(along_x);
  TVF::Arrow_style style;
  style.spacing = 40;
  style.width = 3;
  style.opacity = 1;
  const double c = 100.5, r = 10; // the centre cell spans pixels 80..119
  const double s = std::sqrt(3.) / 2;
  struct Expectation
  {
    int n;
    bool right, left, up, down, upper_left, lower_left;
  };
  for(const Expectation& e : {Expectation{1, true, true, false, false, false, false},
                              Expectation{2, true, true, false, false, false, false},
                              Expectation{3, true, false, false, false, true, true},
                              Expectation{4, true, true, true, true, false, false}})
  {
    TVF::Field_renderer renderer(ops.shared_matrices()->shared_mesh(), front_view(200, 200));
    renderer.add_glyphs(x, e.n, style);
    const Image image = picture_of(renderer, "shape" + std::to_string(e.n));
    auto at = [&](double dx, double dy) { return dark(image.at(static_cast<int>(c + dx), static_cast<int>(c + dy))); };
    EXPECT_TRUE(at(0, 0)) << "n = " << e.n;
    EXPECT_EQ(at(r, 0), e.right) << "n = " << e.n;
    EXPECT_EQ(at(-r, 0), e.left) << "n = " << e.n;
    EXPECT_EQ(at(0, -r), e.up) << "n = " << e.n;
    EXPECT_EQ(at(0, r), e.down) << "n = " << e.n;
    EXPECT_EQ(at(-r / 2, -r * s), e.upper_left) << "n = " << e.n;
    EXPECT_EQ(at(-r / 2, r * s), e.lower_left) << "n = " << e.n;
    // Nothing beyond the spokes' length (the arrow's head ends at 17 too).
    EXPECT_FALSE(at(21, 0)) << "n = " << e.n;
    EXPECT_FALSE(at(-21, 0)) << "n = " << e.n;
  }
}

TEST(NFieldPictures, GlyphsRefuseBadInput)
{
  const Torus_scene scene;
  TVF::Field_renderer renderer = scene.renderer();
  EXPECT_NE(refusal([&] { renderer.add_glyphs(scene.x, 0); }).find("symmetry of glyphs must be at least 1, not 0"),
            std::string::npos);
  TVF::Arrow_style negative;
  negative.symmetry = -2;
  EXPECT_NE(refusal([&] { renderer.add_arrows(scene.x, negative); }).find("at least 1, not -2"), std::string::npos);
  EXPECT_NE(refusal([&] { renderer.add_glyphs(scene.x.head(10), 4); }).find("2 frame coordinates per face"),
            std::string::npos);
}

TEST(NFieldPictures, SingularitiesOfTheSmoothestCrossFieldAreMarkedWhereTheSphereShowsThem)
{
  Mesh sphere = make_icosphere(3);
  TVF::Discrete_operators<Mesh> ops(sphere);
  const TVF::N_field_operators nops(ops.shared_matrices(), 4);
  const Eigen::VectorXd z = TVF::smoothest_n_field(nops);
  std::vector<std::pair<int, int>> singular;
  for(const TVF::N_field_singularity& s : TVF::n_field_singularities(nops, z)) singular.emplace_back(s.vertex, s.index);
  ASSERT_EQ(singular.size(), 8u); // eight +1/4: Poincare-Hopf with 4 chi = 8
  const int size = 300;
  TVF::Field_renderer plain(ops.shared_matrices()->shared_mesh(), front_view(size, size));
  TVF::Field_renderer marked(ops.shared_matrices()->shared_mesh(), front_view(size, size));
  TVF::Singularity_style style;
  style.radius = 5;
  marked.add_singularities(singular, 4, style);
  const Image a = picture_of(plain, "sphere_plain"), b = picture_of(marked, "sphere_singularities");
  const TVF::Intrinsic_mesh& M = ops.intrinsic_mesh();
  int front = 0, back = 0;
  std::vector<std::array<double, 2>> front_marks;
  for(const auto& s : singular)
  {
    const auto& p = M.position(s.first);
    if(p[2] > 0.3) front_marks.push_back(front_view_pixel(M, p, size, size));
  }
  for(const auto& s : singular)
  {
    const auto& p = M.position(s.first);
    const auto q = front_view_pixel(M, p, size, size);
    if(p[2] > 0.3)
    {
      // The disc is centred there: red at the vertex and two pixels around it, with its
      // white ring about 5.5 pixels out, the surface beyond.
      ++front;
      for(int dx : {-2, 0, 2})
        for(int dy : {-2, 0, 2})
          EXPECT_TRUE(reddish(b.at(static_cast<int>(q[0]) + dx, static_cast<int>(q[1]) + dy))) << "vertex " << s.first;
      EXPECT_GT(differences_near(a, b, q[0], q[1], 5), 60) << "vertex " << s.first;
    }
    else if(p[2] < -0.3)
    {
      // Behind the sphere: nothing drawn there (unless a front mark covers the spot).
      bool covered = false;
      for(const auto& m : front_marks) covered = covered || std::hypot(m[0] - q[0], m[1] - q[1]) < 14;
      if(covered) continue;
      ++back;
      EXPECT_EQ(differences_near(a, b, q[0], q[1], 8), 0) << "hidden vertex " << s.first;
    }
  }
  EXPECT_GE(front, 2);
  EXPECT_GE(back, 2);
  // Nothing but the discs changed: at most the discs of all visible marks.
  EXPECT_LE(count_differences(a, b), 8 * M_PI * 7 * 7);
}

TEST(NFieldPictures, SingularityMarksShowTheSignTheIndexAndALabel)
{
  Mesh sphere = make_icosphere(3);
  TVF::Discrete_operators<Mesh> ops(sphere);
  const TVF::Intrinsic_mesh& M = ops.intrinsic_mesh();
  // The vertex nearest the camera, and one at the back.
  int nearest = 0, farthest = 0;
  for(int v = 0; v < M.number_of_vertices(); ++v)
  {
    if(M.position(v)[2] > M.position(nearest)[2]) nearest = v;
    if(M.position(v)[2] < M.position(farthest)[2]) farthest = v;
  }
  const int size = 200;
  const auto q = front_view_pixel(M, M.position(nearest), size, size);
  auto draw = [&](std::vector<std::pair<int, int>> marks, bool labels, const std::string& name) {
    TVF::Field_renderer r(ops.shared_matrices()->shared_mesh(), front_view(size, size));
    TVF::Singularity_style style;
    style.labels = labels;
    if(!marks.empty()) r.add_singularities(marks, 4, style);
    return picture_of(r, name);
  };
  const Image plain = draw({}, false, "mark_plain");
  const Image positive = draw({{nearest, 1}}, false, "mark_positive");
  const Image negative = draw({{nearest, -1}, {farthest, -1}}, false, "mark_negative");
  const Image four = draw({{nearest, 4}}, false, "mark_four");
  const Image zero = draw({{nearest, 0}}, false, "mark_zero");
  const Image labelled = draw({{nearest, -1}}, true, "mark_labelled");
  EXPECT_TRUE(reddish(positive.at(static_cast<int>(q[0]), static_cast<int>(q[1]))));
  EXPECT_TRUE(bluish(negative.at(static_cast<int>(q[0]), static_cast<int>(q[1]))));
  // The same disc in another colour (the white ring alike), and nothing of the hidden one.
  EXPECT_EQ(count_differences(plain, negative), count_differences(plain, positive));
  int fill_changes = 0, outside = 0;
  for(std::size_t i = 0; i < plain.pixels.size(); ++i)
    if((positive.pixels[i] & 0xffffff) != (negative.pixels[i] & 0xffffff))
    {
      ++fill_changes;
      outside += (plain.pixels[i] & 0xffffff) == (positive.pixels[i] & 0xffffff);
    }
  EXPECT_GT(fill_changes, 0.8 * M_PI * 4.5 * 4.5);
  EXPECT_EQ(outside, 0);
  EXPECT_EQ(count_differences(plain, zero), 0);
  // The disc of index 4/4 has four times the area of that of 1/4 (radius 10 against 5, each
  // with its ring of width 1).
  const double ratio = double(count_differences(plain, four)) / count_differences(plain, positive);
  EXPECT_GT(ratio, 3);
  EXPECT_LT(ratio, 4.5);
  // The label "-1/4" right of the disc, in the disc's colour.
  int label_pixels = 0, blue_label_pixels = 0;
  for(int y = static_cast<int>(q[1]) - 12; y <= static_cast<int>(q[1]) + 8; ++y)
    for(int x = static_cast<int>(q[0]) + 7; x <= static_cast<int>(q[0]) + 45; ++x)
    {
      label_pixels += (labelled.at(x, y) & 0xffffff) != (negative.at(x, y) & 0xffffff);
      blue_label_pixels += bluish(labelled.at(x, y));
    }
  EXPECT_GT(label_pixels, 40);
  EXPECT_GT(blue_label_pixels, 10);

  // In SVG the discs are vector paths: the visible one only.
  TVF::Field_renderer r(ops.shared_matrices()->shared_mesh(), front_view(size, size));
  r.add_singularities({{nearest, 1}, {farthest, 1}}, 4);
  const std::string svg_file = scratch_path("marks.svg");
  r.write_svg(svg_file);
  std::ifstream in(svg_file);
  const std::string svg{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::size_t red_paths = 0;
  for(std::size_t at = svg.find("rgb(86%,12%,10%)"); at != std::string::npos; at = svg.find("rgb(86%,12%,10%)", at + 1))
    ++red_paths;
  EXPECT_EQ(red_paths, 1u);
}

TEST(NFieldPictures, SingularitiesRefuseBadInput)
{
  Mesh sphere = make_icosphere(2);
  TVF::Discrete_operators<Mesh> ops(sphere);
  TVF::Field_renderer renderer(ops.shared_matrices()->shared_mesh());
  const int nv = static_cast<int>(sphere.number_of_vertices());
  EXPECT_NE(refusal([&] { renderer.add_singularities({{0, 1}}, 0); }).find("symmetry of singularities must be at least 1, not 0"),
            std::string::npos);
  EXPECT_NE(refusal([&] { renderer.add_singularities({{nv, 1}}, 4); })
                .find("singular vertex " + std::to_string(nv) + " is not a vertex of the mesh (0 to " +
                      std::to_string(nv - 1) + ")"),
            std::string::npos);
  EXPECT_NE(refusal([&] { renderer.add_singularities({{-1, 1}}, 4); }).find("singular vertex -1 is not a vertex"),
            std::string::npos);
  TVF::Singularity_style flat;
  flat.radius = 0;
  EXPECT_NE(refusal([&] { renderer.add_singularities({{0, 1}}, 4, flat); }).find("radius of singularity marks must be positive"),
            std::string::npos);
  // A vertex in no face has no place on the surface.
  Mesh with_isolated = make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}}, {{0, 1, 2}});
  TVF::Discrete_operators<Mesh> small(with_isolated);
  TVF::Field_renderer lonely(small.shared_matrices()->shared_mesh());
  EXPECT_NE(refusal([&] { lonely.add_singularities({{3, 1}}, 4); }).find("singular vertex 3 lies in no face"),
            std::string::npos);
}

TEST(NFieldPictures, PicturesOfAnNFieldInAPropertyMap)
{
  Mesh sphere = make_icosphere(3);
  auto cross = sphere.add_property_map<Face_index, Vector_3>("f:cross", Vector_3(0, 0, 0)).first;
  const auto singular = TVF::smoothest_n_field(sphere, 4, cross);
  ASSERT_EQ(singular.size(), 8u);
  // The same cross field through another of its vectors: each turned by 90 degrees, n x v.
  auto turned = sphere.add_property_map<Face_index, Vector_3>("f:turned", Vector_3(0, 0, 0)).first;
  for(Face_index f : sphere.faces())
  {
    const Vector_3 normal = CGAL::Polygon_mesh_processing::compute_face_normal(f, sphere);
    turned[f] = CGAL::cross_product(normal, cross[f]);
  }
  TVF::Render_options options = front_view(300, 300);
  options.legend = true;
  TVF::Field_picture<Mesh> a(sphere, options), b(sphere, options);
  TVF::Scalar_colouring colouring;
  colouring.label = "energy density";
  a.colour_by_n_field_energy(cross, 4, colouring);
  b.colour_by_n_field_energy(turned, 4, colouring);
  a.add_n_field_glyphs(cross, 4);
  b.add_n_field_glyphs(turned, 4);
  EXPECT_EQ(a.add_n_field_singularities(cross, 4), singular); // what smoothest_n_field reported
  EXPECT_EQ(b.add_n_field_singularities(turned, 4), singular);
  a.write_png(scratch_path("picture_a.png"));
  b.write_png(scratch_path("picture_b.png"));
  EXPECT_EQ(count_differences(read_png(scratch_path("picture_a.png")), read_png(scratch_path("picture_b.png"))), 0);

  // The colours are the energy density: its range, largest around the singular vertices.
  TVF::Discrete_operators<Mesh> ops(sphere);
  const TVF::N_field_operators nops(ops.shared_matrices(), 4);
  const Eigen::VectorXd density = nops.energy_density(nops.from_vectors(ops.to_frame_coordinates(cross)));
  const auto range = a.renderer().colour_range();
  EXPECT_DOUBLE_EQ(range.first, density.minCoeff());
  EXPECT_DOUBLE_EQ(range.second, density.maxCoeff());
  const TVF::Intrinsic_mesh& M = ops.intrinsic_mesh();
  double around = 0;
  int count = 0;
  for(int f = 0; f < M.number_of_faces(); ++f)
    for(const auto& s : singular)
      for(int v : M.face_vertices(f))
        if(v == static_cast<int>(s.first))
        {
          around += density[f];
          ++count;
        }
  EXPECT_GT(around / count, 2 * density.mean());
  EXPECT_THROW_REASON(a.add_n_field_glyphs(cross, 0),
                      TVF::Invalid_input, "renderer: the symmetry of glyphs must be at least 1, not 0");
}

TEST(NFieldPictures, LogarithmicColourScale)
{
  // Values from 1e-3 at the bottom of the sphere to 1e3 at the top: on a logarithmic scale the
  // equator (value ~1) is in the middle of viridis (teal), on a linear one at its bottom (purple).
  Mesh sphere = make_icosphere(3);
  auto value = sphere.add_property_map<Face_index, double>("f:value", 0.).first;
  double lo = 1e300, hi = 0;
  for(Face_index f : sphere.faces())
  {
    double y = 0;
    for(Vertex_index v : vertices_around_face(sphere.halfedge(f), sphere)) y += sphere.point(v).y() / 3;
    value[f] = std::pow(10., 3 * y);
    lo = std::min(lo, value[f]);
    hi = std::max(hi, value[f]);
  }
  TVF::Field_picture<Mesh> linear(sphere, front_view(200, 200)), logarithmic(sphere, front_view(200, 200));
  TVF::Scalar_colouring log_scale;
  log_scale.logarithmic = true;
  linear.colour_faces(value);
  logarithmic.colour_faces(value, log_scale);
  EXPECT_EQ(logarithmic.renderer().colour_range(), std::make_pair(lo, hi));
  linear.write_png(scratch_path("linear.png"));
  logarithmic.write_png(scratch_path("logarithmic.png"));
  const std::uint32_t a = read_png(scratch_path("linear.png")).at(100, 100),
                      b = read_png(scratch_path("logarithmic.png")).at(100, 100);
  EXPECT_LT(Image::green(a), Image::blue(a));
  EXPECT_GT(Image::green(b), Image::red(b) + 50);

  TVF::Scalar_colouring bad = log_scale;
  bad.symmetric = true;
  EXPECT_NE(refusal([&] { logarithmic.colour_faces(value, bad); }).find("logarithmic colour scale cannot be symmetric"),
            std::string::npos);
  bad = log_scale;
  bad.minimum = 0;
  EXPECT_NE(refusal([&] { logarithmic.colour_faces(value, bad); }).find("range of a logarithmic colour scale must be positive"),
            std::string::npos);
}

TEST(NFieldPictures, ValuesEqualUpToRoundingShowOneColour)
{
  // The magnitudes of a unit n-field are 1 up to rounding: the colours must not show the rounding.
  Mesh sphere = make_icosphere(2);
  auto one = sphere.add_property_map<Face_index, double>("f:one", 1.).first;
  auto nearly_one = sphere.add_property_map<Face_index, double>("f:nearly_one", 1.).first;
  std::mt19937 gen(5);
  std::uniform_int_distribution<int> ulps(-4, 4);
  for(Face_index f : sphere.faces()) nearly_one[f] = 1 + ulps(gen) * 1.1e-16;
  TVF::Field_picture<Mesh> a(sphere, front_view(120, 120)), b(sphere, front_view(120, 120));
  a.colour_faces(one);
  b.colour_faces(nearly_one);
  const auto range = b.renderer().colour_range();
  EXPECT_LT(range.first, 1 - 1e-4);
  EXPECT_GT(range.second, 1 + 1e-4);
  a.write_png(scratch_path("one.png"));
  b.write_png(scratch_path("nearly_one.png"));
  EXPECT_EQ(count_differences(read_png(scratch_path("one.png")), read_png(scratch_path("nearly_one.png"))), 0);
}
