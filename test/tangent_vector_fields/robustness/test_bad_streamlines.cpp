// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Bad and extreme input to streamlines and pictures: seeds outside the mesh, zero and NaN
// fields, limits and tolerances that are zero, negative or NaN, line counts that would never
// end, degenerate meshes, pictures of no size or a NaN camera.

#include "bad_input_support.h"
#include "scratch_path.h"

#include <CGAL/Tangent_vector_fields/Streamlines.h>
#ifdef TVF_HAS_CAIRO
#include <CGAL/Tangent_vector_fields/Field_picture.h>
#endif

#include <algorithm>
#include <cstdio>
#include <limits>

using namespace bad_input;

namespace {

typedef Mesh::Property_map<Face_index, Vector_3> Field;
typedef TVF::Mesh_streamline_tracer<Mesh> Tracer;

// A field swirling about the z axis, tangent to the faces (projected by the tracer).
Field swirl(Mesh& mesh, const std::string& name)
{
  Field f = mesh.add_property_map<Face_index, Vector_3>("f:" + name).first;
  for(Face_index face : mesh.faces())
  {
    const Point_3 c = CGAL::centroid(mesh.point(mesh.target(mesh.halfedge(face))),
                                     mesh.point(mesh.target(mesh.next(mesh.halfedge(face)))),
                                     mesh.point(mesh.source(mesh.halfedge(face))));
    f[face] = Vector_3(-c.y(), c.x(), 0.3);
  }
  return f;
}

// Whether `p` lies in face `f`: in its plane and with barycentric coordinates >= -1e-9.
bool in_face(const TVF::Intrinsic_mesh& m, int f, const std::array<double, 3>& p)
{
  const auto& t = m.face_vertices(f);
  const auto& n = m.normal(f);
  // Signed areas of the sub-triangles against the face normal.
  double area[3], total = 0;
  for(int k = 0; k < 3; ++k)
  {
    const auto& a = m.position(t[(k + 1) % 3]);
    const auto& b = m.position(t[(k + 2) % 3]);
    const double u[3] = {a[0] - p[0], a[1] - p[1], a[2] - p[2]}, v[3] = {b[0] - p[0], b[1] - p[1], b[2] - p[2]};
    area[k] = n[0] * (u[1] * v[2] - u[2] * v[1]) + n[1] * (u[2] * v[0] - u[0] * v[2]) + n[2] * (u[0] * v[1] - u[1] * v[0]);
    total += area[k];
  }
  const auto& c = m.position(t[0]);
  const double height = n[0] * (p[0] - c[0]) + n[1] * (p[1] - c[1]) + n[2] * (p[2] - c[2]);
  return std::abs(height) <= 1e-9 * m.mean_edge_length() && std::min({area[0], area[1], area[2]}) / total >= -1e-9;
}

// Every point of `line` is finite and lies in its face.
void expect_on_mesh(const Tracer& tracer, const TVF::Streamline& line)
{
  const TVF::Intrinsic_mesh& m = tracer.tracer().mesh();
  ASSERT_EQ(line.points.size(), line.faces.size());
  for(std::size_t i = 0; i < line.points.size(); ++i)
  {
    const auto& p = line.points[i];
    ASSERT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
    const int f = line.faces[i];
    ASSERT_TRUE(f >= 0 && f < m.number_of_faces());
    EXPECT_TRUE(in_face(m, f, p)) << "point " << i << " outside face " << f;
  }
}

} // namespace

TEST(BadStreamlines, SeedsOutsideTheMeshAreRefusedOrClampedIntoTheFace)
{
  Mesh mesh = make_icosphere(2);
  const Field field = swirl(mesh, "swirl");
  const Tracer tracer(mesh, field);
  expect_error<TVF::Invalid_input>([&] { tracer.trace(Face_index(320), Point_3(0, 0, 1)); },
                                   "the seed face is not a face of the mesh");
  expect_error<TVF::Invalid_input>([&] { tracer.tracer().trace(-1, {1, 0, 0}); }, "face -1 does not exist");
  expect_error<TVF::Invalid_input>([&] { tracer.tracer().trace(320, {1, 0, 0}); }, "face 320 does not exist");
  expect_error<TVF::Invalid_input>([&] { tracer.tracer().trace(3, {0.5, std::nan(""), 0.5}); }, "non-finite");
  expect_error<TVF::Invalid_input>([&] { tracer.trace(Face_index(3), Point_3(0, HUGE_VAL, 0)); }, "non-finite");
  // A seed 100 units away from its face: projected and clamped into the face.
  TVF::Streamline_options options;
  options.maximum_length = 1;
  const TVF::Streamline line = tracer.trace(Face_index(7), Point_3(100, -50, 30), options);
  // (The seed may land on a corner: its first segment may then run in a neighbouring face.)
  EXPECT_TRUE(in_face(tracer.tracer().mesh(), 7, line.points[line.seed_index]));
  expect_on_mesh(tracer, line);
  EXPECT_GT(line.length(), 0.);
  EXPECT_LE(line.length(), 2 + 1e-9); // at most the limit of 1 in each direction
}

TEST(BadStreamlines, ZeroAndNonFiniteFieldsGiveNoLinesOrClearErrors)
{
  Mesh mesh = make_torus(16, 8);
  const Field zero = mesh.add_property_map<Face_index, Vector_3>("f:zero", Vector_3(0, 0, 0)).first;
  const Tracer tracer(mesh, zero);
  const TVF::Streamline line = tracer.trace(Face_index(0), Point_3(1, 0, 0));
  EXPECT_EQ(line.points.size(), 1u);
  EXPECT_EQ(line.forward_stop, TVF::Streamline_stop::zero_field);
  EXPECT_EQ(line.backward_stop, TVF::Streamline_stop::zero_field);
  EXPECT_TRUE(tracer.evenly_spaced().empty());
  TVF::Fur_options fur;
  fur.number_of_strokes = 50;
  EXPECT_TRUE(tracer.fur(fur).empty());
  // The smoothest n-field interface with the zero field: no singular vertex to stop at, no line.
  EXPECT_TRUE(TVF::evenly_spaced_n_field_streamlines(mesh, 4, zero).empty());

  Field bad = mesh.add_property_map<Face_index, Vector_3>("f:bad", Vector_3(1, 0, 0)).first;
  bad[Face_index(11)] = Vector_3(std::nan(""), 0, 0);
  expect_error<TVF::Invalid_input>([&] { Tracer t(mesh, bad); }, "non-finite");
  expect_error<TVF::Invalid_input>([&] { Tracer t(mesh, 4, bad); }, "non-finite");
  expect_error<TVF::Invalid_input>([&] { TVF::fur_strokes(mesh, bad, fur); }, "non-finite");
  expect_error<TVF::Invalid_input>([&] { Tracer t(mesh, 0, zero); }, "n must be at least 1 (got 0)");
}

TEST(BadStreamlines, LimitsAndTolerancesThatNoTraceCanHonourAreRefused)
{
  Mesh mesh = make_icosphere(2);
  const Field field = swirl(mesh, "swirl");
  const Tracer tracer(mesh, field);
  const double nan = std::nan("");
  auto refused = [&](const std::function<void(TVF::Streamline_options&)>& set, const std::string& phrase) {
    TVF::Streamline_options o;
    set(o);
    expect_error<TVF::Invalid_input>([&] { tracer.tracer().trace(5, {0.2, 0.3, 0.5}, o); }, phrase);
    TVF::Evenly_spaced_options e;
    set(e.tracing);
    expect_error<TVF::Invalid_input>([&] { tracer.evenly_spaced(e); }, phrase);
    TVF::Fur_options f;
    f.number_of_strokes = 10;
    set(f.tracing);
    expect_error<TVF::Invalid_input>([&] { tracer.fur(f); }, phrase);
  };
  refused([&](TVF::Streamline_options& o) { o.maximum_length = nan; }, "maximum_length is NaN");
  refused([&](TVF::Streamline_options& o) { o.maximum_segments = 0; }, "maximum_segments must be at least 1");
  refused([&](TVF::Streamline_options& o) { o.maximum_segments = -5; }, "maximum_segments must be at least 1");
  refused([&](TVF::Streamline_options& o) { o.zero_field_tolerance = nan; }, "zero_field_tolerance");
  refused([&](TVF::Streamline_options& o) { o.zero_field_tolerance = -1; }, "zero_field_tolerance");
  refused([&](TVF::Streamline_options& o) { o.loop_closure_tolerance = nan; }, "loop_closure_tolerance");
  refused([&](TVF::Streamline_options& o) { o.loop_closure_tolerance = -0.1; }, "loop_closure_tolerance");

  // Documented limits that are valid: a negative length is no limit, one segment is one segment.
  TVF::Streamline_options o;
  o.maximum_length = -1;
  o.maximum_segments = 1;
  const TVF::Streamline one = tracer.tracer().trace(5, {0.2, 0.3, 0.5}, o);
  EXPECT_LE(one.number_of_segments(), 2u);
  expect_on_mesh(tracer, one);

  // Evenly spaced: separations and ratios.
  for(double separation : {0., -0.1, nan, HUGE_VAL})
  {
    TVF::Evenly_spaced_options e;
    e.separation = separation;
    expect_error<TVF::Invalid_input>([&] { tracer.evenly_spaced(e); }, "separation must be positive");
  }
  for(double ratio : {0., 1.5, nan})
  {
    TVF::Evenly_spaced_options e;
    e.test_ratio = ratio;
    expect_error<TVF::Invalid_input>([&] { tracer.evenly_spaced(e); }, "test_ratio");
  }
  TVF::Evenly_spaced_options e;
  e.minimum_length_ratio = nan;
  expect_error<TVF::Invalid_input>([&] { tracer.evenly_spaced(e); }, "minimum_length_ratio");
  e = TVF::Evenly_spaced_options();
  e.maximum_streamlines = -1;
  expect_error<TVF::Invalid_input>([&] { tracer.evenly_spaced(e); }, "maximum_streamlines");
  // Fur: lengths, densities.
  for(double length : {0., -1., nan})
  {
    TVF::Fur_options f;
    f.number_of_strokes = 10;
    f.length = length;
    expect_error<TVF::Invalid_input>([&] { tracer.fur(f); }, "stroke length must be positive");
  }
  for(double density : {0., -3., nan, HUGE_VAL})
  {
    TVF::Fur_options f;
    f.density = density;
    expect_error<TVF::Invalid_input>([&] { tracer.fur(f); }, "positive finite density");
  }
}

TEST(BadStreamlines, HugeLineCountsAreRefusedInsteadOfRunningForEver)
{
  Mesh mesh = make_icosphere(2);
  const Field field = swirl(mesh, "swirl");
  const Tracer tracer(mesh, field);
  TVF::Fur_options fur;
  fur.number_of_strokes = std::numeric_limits<int>::max();
  expect_error<TVF::Invalid_input>([&] { tracer.fur(fur); }, "more than 1e7");
  fur.number_of_strokes = 0;
  fur.density = 1e12;
  expect_error<TVF::Invalid_input>([&] { tracer.fur(fur); }, "more than 1e7");
  // A separation of 1e-9 diagonals would take ~1e18 streamlines; even three of them would be
  // sampled 1e9 times each.
  TVF::Evenly_spaced_options e;
  e.separation = 1e-9;
  expect_error<TVF::Invalid_input>([&] { tracer.evenly_spaced(e); }, "separation is too small");
  e.maximum_streamlines = 3;
  expect_error<TVF::Invalid_input>([&] { tracer.evenly_spaced(e); }, "separation is too small");
  // A small but sane separation with a limit: the lines come, on the mesh.
  e.separation = 1e-3;
  e.tracing.maximum_length = 0.2;
  const std::vector<TVF::Streamline> lines = tracer.evenly_spaced(e);
  EXPECT_EQ(lines.size(), 3u);
  for(const TVF::Streamline& l : lines) expect_on_mesh(tracer, l);
}

TEST(BadStreamlines, DegenerateMeshesTraceFiniteLinesOnTheMesh)
{
  // One triangle, every vertex on the boundary, a needle of 1e-7, a lonely vertex, a
  // component 1e-6 as large: lines stay in their faces and end for a stated reason.
  Mesh triangle = single_triangle(), band = boundary_only_band(16), needle = make_disk(4),
       pair = sphere_with_tiny_companion(1e-6), lonely = make_torus(12, 6);
  {
    const auto h = needle.halfedge(Face_index(5));
    needle.point(needle.target(h)) = needle.point(needle.source(h)) + 1e-7 * (needle.point(needle.target(h)) -
                                                                              needle.point(needle.source(h)));
  }
  lonely.add_vertex(Point_3(9, 9, 9));
  for(Mesh* mesh : {&triangle, &band, &needle, &pair, &lonely})
  {
    SCOPED_TRACE(mesh->number_of_faces());
    const Field field = swirl(*mesh, "swirl");
    const Tracer tracer(*mesh, field);
    for(int f : {0, static_cast<int>(mesh->number_of_faces()) - 1})
    {
      const TVF::Streamline line = tracer.tracer().trace(f, {0.3, 0.3, 0.4});
      expect_on_mesh(tracer, line);
      EXPECT_NE(line.forward_stop, TVF::Streamline_stop::none);
    }
    TVF::Evenly_spaced_options e;
    e.separation = 0.1;
    for(const TVF::Streamline& l : tracer.evenly_spaced(e)) expect_on_mesh(tracer, l);
    TVF::Fur_options fur;
    fur.number_of_strokes = 20;
    for(const TVF::Streamline& l : tracer.fur(fur)) expect_on_mesh(tracer, l);
  }
}

#ifdef TVF_HAS_CAIRO
TEST(BadPictures, EmptyMeshesAndImpossibleImagesAreRefused)
{
  Mesh empty;
  expect_defect(TVF::Mesh_defect::empty, [&] { TVF::Field_picture<Mesh> p(empty); });
  Mesh mesh = make_icosphere(1);
  const std::string path = scratch_path("bad_picture.png");
  auto refused = [&](const std::function<void(TVF::Render_options&)>& set, const std::string& phrase) {
    TVF::Render_options o;
    o.width = 64;
    o.height = 48;
    set(o);
    TVF::Field_picture<Mesh> picture(mesh, o);
    std::remove(path.c_str());
    expect_error<TVF::Invalid_input>([&] { picture.write_png(path); }, phrase);
    expect_error<TVF::Invalid_input>([&] { picture.write_svg(path + ".svg"); }, phrase);
    EXPECT_EQ(std::fopen(path.c_str(), "rb"), nullptr) << "a refused picture was written";
  };
  refused([](TVF::Render_options& o) { o.width = 0; }, "image size");
  refused([](TVF::Render_options& o) { o.height = -10; }, "image size");
  refused([](TVF::Render_options& o) { o.width = 100000; }, "image size");
  refused([](TVF::Render_options& o) { o.supersampling = 0; }, "supersampling");
  refused([](TVF::Render_options& o) { o.supersampling = 9; }, "supersampling");
  refused([](TVF::Render_options& o) { o.camera.azimuth = std::nan(""); }, "finite");
  refused([](TVF::Render_options& o) { o.camera.view_direction = {HUGE_VAL, 0, 0}; }, "finite");
  refused([](TVF::Render_options& o) { o.camera.field_of_view = std::nan(""); }, "finite");
  refused([](TVF::Render_options& o) { o.camera.zoom = 0; }, "zoom");
  refused([](TVF::Render_options& o) { o.camera.zoom = std::nan(""); }, "zoom");
  refused([](TVF::Render_options& o) { o.camera.margin = 0.5; }, "margin");
  refused([](TVF::Render_options& o) { o.camera.up = {0, 0, 0}; }, "up vector");
}

TEST(BadPictures, BadFieldsAreRefusedAndDegenerateValuesAreDrawn)
{
  Mesh mesh = make_icosphere(1);
  TVF::Render_options o;
  o.width = 64;
  o.height = 48;
  TVF::Field_picture<Mesh> picture(mesh, o);
  Field bad = mesh.add_property_map<Face_index, Vector_3>("f:bad", Vector_3(1, 0, 0)).first;
  bad[Face_index(2)] = Vector_3(0, 0, std::nan(""));
  expect_error<TVF::Invalid_input>([&] { picture.add_arrows(bad); }, "non-finite");
  expect_error<TVF::Invalid_input>([&] { picture.add_n_field_glyphs(bad, 4); }, "non-finite");
  expect_error<TVF::Invalid_input>([&] { picture.add_n_field_singularities(bad, 4); }, "non-finite");
  expect_error<TVF::Invalid_input>([&] { picture.add_evenly_spaced_streamlines(bad); }, "non-finite");
  expect_error<TVF::Invalid_input>([&] { picture.renderer().colour_faces(std::vector<double>(3, 1.)); },
                                   "expected one value per face (80), got 3");
  // A constant colour (an empty range), a NaN value and a zero field: drawn, not refused.
  std::vector<double> values(80, 5.);
  values[4] = std::nan("");
  picture.renderer().colour_faces(values);
  const Field zero = mesh.add_property_map<Face_index, Vector_3>("f:zero", Vector_3(0, 0, 0)).first;
  picture.add_arrows(zero);
  EXPECT_TRUE(picture.add_evenly_spaced_streamlines(zero).empty());
  const std::string path = scratch_path("bad_values.png");
  picture.write_png(path);
  std::FILE* f = std::fopen(path.c_str(), "rb");
  ASSERT_NE(f, nullptr);
  std::fseek(f, 0, SEEK_END);
  EXPECT_GT(std::ftell(f), 100);
  std::fclose(f);
  std::remove(path.c_str());
}
#endif
