// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Pictures of n-direction fields: n-fold glyphs (arrows are the glyphs of symmetry 1, a glyph
// has the shape of its n and does not depend on which of the n vectors it is given).

#include "picture_test_support.h"
#include "test_meshes.h"

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>
#include <CGAL/Tangent_vector_fields/Field_renderer.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;
using namespace tvf_picture_test;

namespace {

std::string temporary_path(const std::string& name) { return ::testing::TempDir() + "tvf_npictures_" + name; }

Image picture_of(const TVF::Field_renderer& renderer, const std::string& name)
{
  const std::string file = temporary_path(name + ".png");
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
