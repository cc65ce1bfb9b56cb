// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Bad and extreme input (SPEC 9): clear errors, never a crash or a NaN; stiff
// triangles, mollification, vertices in no face, field files.  Soups that need
// repair are in test/model_reduction/test_mesh_repair.cpp, every mesh of CGAL's data tree in test_data_tree.cpp.

#include "bad_input_support.h"
#include "expect_reason.h"
#include "hodge_checks.h"
#include "test_meshes.h"

#include <CGAL/Tangent_vector_fields/face_field_io.h>
#include <CGAL/Tangent_vector_fields/field_files.h>
#include <CGAL/Tangent_vector_fields/hodge_decomposition.h>

#include <CGAL/Surface_mesh/IO/PLY.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <functional>
#include <sstream>

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;

namespace {

using bad_input::expect_defect;
using bad_input::field_map;

typedef Mesh::Property_map<Face_index, Vector_3> Field;

// A fan of triangles around vertex 0 with one triangle squeezed: vertex 2 moves
// to a fraction `t` of the way from vertex 1 towards vertex 3 on a circle, making
// needle (t small: short edge 1-2) or cap triangles.
Mesh fan_with_squeezed_triangle(double t)
{
  std::vector<Point_3> p = {{0, 0, 0.2}};
  const int n = 7;
  for(int i = 0; i < n; ++i)
  {
    const double a = 2 * M_PI * i / n;
    p.emplace_back(std::cos(a), std::sin(a), 0.1 * (i % 2));
  }
  // Replace vertex 2 by a point between 1 and 3.
  p[2] = CGAL::ORIGIN + ((1 - t) * (p[1] - CGAL::ORIGIN) + t * (p[3] - CGAL::ORIGIN));
  std::vector<std::array<int, 3>> f;
  for(int i = 0; i < n; ++i) f.push_back({0, 1 + i, 1 + (i + 1) % n});
  return make_mesh(p, f);
}

} // namespace

TEST(BadInput, EmptyMesh)
{
  Mesh mesh;
  expect_defect(TVF::Mesh_defect::empty, [&] { TVF::Discrete_operators<Mesh> ops(mesh); });
}

TEST(BadInput, NonTriangleFace)
{
  Mesh mesh;
  auto a = mesh.add_vertex(Point_3(0, 0, 0)), b = mesh.add_vertex(Point_3(1, 0, 0)),
       c = mesh.add_vertex(Point_3(1, 1, 0)), d = mesh.add_vertex(Point_3(0, 1, 0));
  mesh.add_face(a, b, c, d);
  const std::string msg = expect_defect(TVF::Mesh_defect::non_triangle_face, [&] { TVF::Discrete_operators<Mesh> ops(mesh); });
  EXPECT_NE(msg.find("4 vertices"), std::string::npos) << msg;
}

TEST(BadInput, NonManifoldAndMisorientedSoups)
{
  const std::vector<std::array<double, 3>> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {2, 2, 0}, {3, 2, 0}};
  // Three faces on edge (0, 1).
  expect_defect(TVF::Mesh_defect::non_manifold_edge,
                [&] { TVF::Intrinsic_mesh m(p, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}); });
  // Two faces traversing edge (0, 1) in the same direction.
  expect_defect(TVF::Mesh_defect::inconsistent_orientation, [&] { TVF::Intrinsic_mesh m(p, {{0, 1, 2}, {0, 1, 3}}); });
  // Two triangles touching at vertex 2 only: a bowtie.
  expect_defect(TVF::Mesh_defect::non_manifold_vertex, [&] { TVF::Intrinsic_mesh m(p, {{0, 1, 2}, {2, 5, 6}}); });
  // Vertex index out of range and repeated vertex.
  expect_defect(TVF::Mesh_defect::invalid_index, [&] { TVF::Intrinsic_mesh m(p, {{0, 1, 9}}); });
  expect_defect(TVF::Mesh_defect::invalid_index, [&] { TVF::Intrinsic_mesh m(p, {{0, 1, 1}}); });
}

TEST(BadInput, NonManifoldVertexInSurfaceMesh)
{
  // Surface_mesh accepts two fans glued at one vertex; we refuse it.
  Mesh mesh;
  std::vector<Vertex_index> v;
  for(const Point_3& q : {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0, 1, 0), Point_3(-1, 0, 0), Point_3(0, -1, 0)})
    v.push_back(mesh.add_vertex(q));
  ASSERT_NE(mesh.add_face(v[0], v[1], v[2]), Mesh::null_face());
  ASSERT_NE(mesh.add_face(v[0], v[3], v[4]), Mesh::null_face());
  expect_defect(TVF::Mesh_defect::non_manifold_vertex, [&] { TVF::Discrete_operators<Mesh> ops(mesh); });
}

TEST(BadInput, GarbageInSurfaceMesh)
{
  Mesh mesh = make_torus(8, 6);
  mesh.remove_face(*mesh.faces().begin());
  ASSERT_TRUE(mesh.has_garbage());
  const std::string msg = expect_defect(TVF::Mesh_defect::garbage, [&] { TVF::Discrete_operators<Mesh> ops(mesh); });
  EXPECT_NE(msg.find("collect_garbage"), std::string::npos);
  mesh.collect_garbage();
  EXPECT_NO_THROW(TVF::Discrete_operators<Mesh> ops(mesh));
}

TEST(BadInput, NonFiniteCoordinates)
{
  for(double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL})
  {
    Mesh mesh = make_icosphere(1);
    mesh.point(Vertex_index(5)) = Point_3(0, bad, 0);
    const std::string msg =
        expect_defect(TVF::Mesh_defect::non_finite_coordinate, [&] { TVF::Discrete_operators<Mesh> ops(mesh); });
    EXPECT_NE(msg.find("vertex 5"), std::string::npos) << msg;
  }
}

TEST(BadInput, NonFiniteFieldLeavesOutputsUntouched)
{
  Mesh mesh = make_torus(8, 6);
  Field v = field_map(mesh, "v", Vector_3(1, 0, 0)), e = field_map(mesh, "e", Vector_3(7, 7, 7));
  v[Face_index(3)] = Vector_3(std::nan(""), 0, 0);
  EXPECT_THROW_REASON(TVF::hodge_decomposition(mesh, v, TVF::parameters::exact_part_map(e)), TVF::Invalid_input,
                      "NaN or infinite");
  for(Face_index f : mesh.faces()) EXPECT_EQ(e[f], Vector_3(7, 7, 7));
}

TEST(Degenerate, CollapsedEdgesAreRefusedByDefaultAndFiniteWithMollification)
{
  for(double fraction : {0.0, 1e-12})
  {
    SCOPED_TRACE(fraction);
    // Move vertex 2 of the fan onto (or within 1e-12 of) vertex 1.
    Mesh mesh = fan_with_squeezed_triangle(fraction);
    Field v = field_map(mesh, "v", Vector_3(1, 0.5, 0)), h = field_map(mesh, "h"), e = field_map(mesh, "e"),
          c = field_map(mesh, "c");
    const std::string msg = expect_defect(TVF::Mesh_defect::degenerate_face, [&] {
      TVF::hodge_decomposition(mesh, v, TVF::parameters::exact_part_map(e));
    });
    EXPECT_NE(msg.find("use_intrinsic_mollification"), std::string::npos);

    TVF::Hodge_decomposition<Mesh> hodge(mesh, TVF::parameters::use_intrinsic_mollification(true));
    EXPECT_GT(hodge.operators().intrinsic_mesh().mollification_delta(), 0);
    hodge(v, TVF::parameters::exact_part_map(e).coexact_part_map(c).harmonic_part_map(h));
    for(Face_index f : mesh.faces())
      for(const Vector_3& w : {e[f], c[f], h[f]})
        EXPECT_TRUE(std::isfinite(w.x()) && std::isfinite(w.y()) && std::isfinite(w.z()));
    expect_sound_hodge_parts(hodge.solver(), random_field(mesh.number_of_faces(), 1), 1e-9);
  }
}

TEST(Degenerate, ZeroAreaFaceOfCollinearVertices)
{
  // Triangle 0-1-2 with vertex 0 moved to the midpoint of edge 1-2: collinear
  // vertices, all edges non-zero, area exactly zero.
  Mesh mesh = fan_with_squeezed_triangle(0.5);
  mesh.point(Vertex_index(0)) = CGAL::midpoint(mesh.point(Vertex_index(1)), mesh.point(Vertex_index(2)));
  expect_defect(TVF::Mesh_defect::degenerate_face, [&] { TVF::Discrete_operators<Mesh> ops(mesh); });
  EXPECT_NO_THROW(TVF::Discrete_operators<Mesh> ops(mesh, TVF::parameters::use_intrinsic_mollification(true)));
}

namespace {
// Torus with vertex 0 pulled towards the midpoint of the opposite edge of one of
// its faces, leaving a cap whose height is `eta` times the original distance.
Mesh torus_with_cap(double eta)
{
  Mesh torus = make_torus(20, 10);
  const auto h = torus.halfedge(Vertex_index(0));
  const Point_3 b = torus.point(torus.source(h)), c = torus.point(torus.target(torus.next(torus.opposite(h))));
  const Point_3 mid = CGAL::midpoint(b, c);
  torus.point(Vertex_index(0)) = mid + eta * (torus.point(Vertex_index(0)) - mid);
  return torus;
}
} // namespace

TEST(Stiff, NeedleAndCapTrianglesDecomposeAccurately)
{
  // Needles: a short edge down to 1e-8 of the others (triangle-inequality margin ~ t).
  // Roundoff in a face with cotangents ~1/t limits the identities to ~eps/t: 1e-10
  // down to t = 1e-6, and 1e-8 at t = 1e-8 (measured 3e-10 to 5e-10 there).
  for(double t : {1e-2, 1e-4, 1e-6, 1e-8})
  {
    SCOPED_TRACE(t);
    Mesh needle = fan_with_squeezed_triangle(t);
    TVF::Hodge_decomposition<Mesh> a(needle);
    expect_sound_hodge_parts(a.solver(), random_field(needle.number_of_faces(), 2), t >= 1e-6 ? 1e-10 : 1e-8);
  }
  // Caps: an angle near pi, relative height down to 1e-4 (margin ~ height^2 ~ 1e-8).
  for(double eta : {1e-2, 1e-3, 1e-4})
  {
    SCOPED_TRACE(eta);
    Mesh torus = torus_with_cap(eta);
    TVF::Hodge_decomposition<Mesh> d(torus);
    expect_sound_hodge_parts(d.solver(), random_field(torus.number_of_faces(), 3), 1e-10);
    EXPECT_EQ(d.solver().harmonic_basis().cols(), 2);
  }
}

TEST(Stiff, CapsBeyondTheLengthPrecisionAreRefused)
{
  // Relative height 1e-6: margin ~1e-12, below what edge lengths in double resolve
  // (its area from lengths would carry a relative error ~1e-4): refused, or mollified.
  Mesh torus = torus_with_cap(1e-6);
  expect_defect(TVF::Mesh_defect::degenerate_face, [&] { TVF::Discrete_operators<Mesh> ops(torus); });
  TVF::Hodge_decomposition<Mesh> d(torus, TVF::parameters::use_intrinsic_mollification(true));
  expect_sound_hodge_parts(d.solver(), random_field(torus.number_of_faces(), 3), 1e-10);
  EXPECT_EQ(d.solver().harmonic_basis().cols(), 2);
}

TEST(Robustness, VerticesInNoFaceAreIgnoredWithAWarning)
{
  Mesh mesh = make_torus(10, 6);
  const Vertex_index lonely = mesh.add_vertex(Point_3(5, 5, 5));
  TVF::Hodge_decomposition<Mesh> hodge(mesh);
  ASSERT_EQ(hodge.operators().intrinsic_mesh().warnings().size(), 1u);
  EXPECT_NE(hodge.operators().intrinsic_mesh().warnings()[0].find("1 vertices"), std::string::npos);
  Field v = field_map(mesh, "v", Vector_3(1, 2, 3)), e = field_map(mesh, "e");
  auto f = mesh.add_property_map<Vertex_index, double>("v:f", 42).first;
  hodge(v, TVF::parameters::exact_part_map(e).potential_map(f));
  EXPECT_EQ(f[lonely], 0.);
  expect_sound_hodge_parts(hodge.solver(), random_field(mesh.number_of_faces(), 4), 1e-10);
  EXPECT_EQ(hodge.solver().harmonic_basis().cols(), 2);
}

TEST(Robustness, SeveralComponentsOfDifferentTopology)
{
  // Sphere + torus + annulus as one mesh: dim H = 0 + 2 + 1.
  Mesh mesh = make_icosphere(2);
  Mesh torus = make_torus(16, 8), annulus = make_curved_disk(5, 0.4);
  transform(torus, 1, {1, 0, 0, 0, 1, 0, 0, 0, 1}, Vector_3(4, 0, 0));
  transform(annulus, 1, {1, 0, 0, 0, 1, 0, 0, 0, 1}, Vector_3(0, 4, 0));
  mesh.join(torus);
  mesh.join(annulus);
  TVF::Hodge_decomposition<Mesh> hodge(mesh);
  EXPECT_EQ(hodge.topology().number_of_components(), 3);
  EXPECT_EQ(hodge.harmonic_dimension(), 3);
  EXPECT_EQ(hodge.solver().harmonic_basis().cols(), 3);
  expect_sound_hodge_parts(hodge.solver(), random_field(mesh.number_of_faces(), 5), 1e-10);
}

TEST(FieldFiles, TextRoundTripIsExactAndErrorsAreClear)
{
  Mesh mesh = make_torus(9, 5);
  Field v = field_map(mesh, "v"), w = field_map(mesh, "w");
  std::mt19937 gen(1);
  std::normal_distribution<double> N;
  for(Face_index f : mesh.faces()) v[f] = Vector_3(N(gen), N(gen), N(gen));
  std::stringstream file;
  TVF::write_face_field(file, mesh, v);
  TVF::read_face_field(file, mesh, w);
  for(Face_index f : mesh.faces()) EXPECT_EQ(v[f], w[f]);

  auto expect_bad = [&](const std::string& text, const std::string& words) {
    std::istringstream in(text);
    Field untouched = field_map(mesh, "u", Vector_3(9, 9, 9));
    try
    {
      TVF::read_face_field(in, mesh, untouched);
      ADD_FAILURE() << "accepted: " << text.substr(0, 40);
    }
    catch(const TVF::Invalid_input& e)
    {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
    for(Face_index f : mesh.faces()) EXPECT_EQ(untouched[f], Vector_3(9, 9, 9));
  };
  expect_bad("hello", "header");
  expect_bad("TVF_FACE_FIELD 1\nfaces 3\n1 2 3\n", "mesh has");
  expect_bad("TVF_FACE_FIELD 1\nfaces " + std::to_string(mesh.number_of_faces()) + "\n1 2 3\n", "missing");
  expect_bad("TVF_FACE_FIELD 1\n# comment\nfaces " + std::to_string(mesh.number_of_faces()) + "\nnan 2 3\n",
             "vector 0");
}

TEST(FieldFiles, PlyRoundTripThroughCgalIO)
{
  Mesh mesh = make_torus(9, 5);
  Field v = field_map(mesh, "v");
  std::mt19937 gen(2);
  std::normal_distribution<double> N;
  for(Face_index f : mesh.faces()) v[f] = Vector_3(N(gen), N(gen), N(gen));
  TVF::add_face_field_properties(mesh, "velocity", v);
  std::stringstream ply;
  ASSERT_TRUE(CGAL::IO::write_PLY(ply, mesh, CGAL::parameters::use_binary_mode(false).stream_precision(17)));
  Mesh back;
  ASSERT_TRUE(CGAL::IO::read_PLY(ply, back));
  ASSERT_EQ(back.number_of_faces(), mesh.number_of_faces());
  Field w = field_map(back, "w");
  ASSERT_TRUE(TVF::face_field_from_properties(back, "velocity", w));
  for(Face_index f : mesh.faces()) EXPECT_EQ(v[f], w[f]);
  EXPECT_FALSE(TVF::face_field_from_properties(back, "absent", w));
}

// --- Field files on hostile input (regressions of test/fuzz, doc/fuzzing.md) --------------------

namespace {

// The message of the Invalid_input that reading `text` with `read` throws ("" if none).
template <class Read>
std::string field_file_error(const std::string& text, Read read)
{
  std::istringstream in(text);
  try
  {
    read(in);
  }
  catch(const TVF::Invalid_input& e)
  {
    return e.what();
  }
  return "";
}

// A triangle as VTK PolyData, with `connectivity`, `offsets` and the `<Piece>` attributes given.
std::string triangle_vtp(const std::string& connectivity, const std::string& offsets,
                         const std::string& piece = "NumberOfPoints=\"3\" NumberOfPolys=\"1\"")
{
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\">\n<PolyData>\n<Piece " + piece +
         ">\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 0"
         "</DataArray>\n</Points>\n<Polys>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">" +
         connectivity + "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" + offsets +
         "</DataArray>\n</Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n";
}

} // namespace

// fuzz_rawfield: a header announcing 3.2 billion vectors allocated them all (77 GB) before reading one.
TEST(FieldFiles, RawFieldCountBeyondItsNumbersIsRefusedWithoutAllocatingIt)
{
  const auto read = [](std::istream& in) { TVF::read_raw_field(in); };
  EXPECT_EQ(field_file_error("1 1000000000000\n1 0 0\n", read), "raw field: face 1 is missing or unreadable");
  EXPECT_EQ(field_file_error("2147483647 1\n1 0 0\n", read), "raw field: face 0 is missing or unreadable");
  std::istringstream good("2 1\n1 0 0 0 1 0\n");
  EXPECT_EQ(TVF::read_raw_field(good).vectors.size(), 2u);
}

// fuzz_vtp: a file that ends inside an end tag sent the reader back to its first byte, forever.
TEST(FieldFiles, VtkFileEndingInsideAnEndTagIsRefused)
{
  const auto read = [](std::istream& in) { TVF::read_vtk_polydata(in); };
  const std::string whole = triangle_vtp("0 1 2", "3");
  const std::size_t cut = whole.find("</DataArray>") + std::string("</DataArray").size();
  EXPECT_EQ(field_file_error(whole.substr(0, cut), read), "VTK PolyData: unterminated </DataArray>");
}

// fuzz_vtp: a connectivity entry of 9.2e15 was cast to int (undefined behaviour); 1.5 was
// taken as point 1, "3x" as 3 points.
TEST(FieldFiles, VtkIndicesAndCountsMustBeWholeNumbers)
{
  const auto read = [](std::istream& in) { TVF::read_vtk_polydata(in); };
  std::istringstream good(triangle_vtp("0 1 2", "3"));
  EXPECT_EQ(TVF::read_vtk_polydata(good).polygons, std::vector<std::vector<int>>({{0, 1, 2}}));
  EXPECT_EQ(field_file_error(triangle_vtp("0 1 9.2e15", "3"), read),
            "VTK PolyData: the connectivity of <Polys> holds 9200000000000000.000000, not a point index");
  EXPECT_EQ(field_file_error(triangle_vtp("0 1.5 2", "3"), read),
            "VTK PolyData: the connectivity of <Polys> holds 1.500000, not a point index");
  EXPECT_EQ(field_file_error(triangle_vtp("0 1 2", "1e300"), read), "VTK PolyData: bad offsets in <Polys>");
  EXPECT_EQ(field_file_error(triangle_vtp("0 1 2", "2.5"), read), "VTK PolyData: bad offsets in <Polys>");
  EXPECT_EQ(field_file_error(triangle_vtp("0 1 2", "3", "NumberOfPoints=\"3x\" NumberOfPolys=\"1\""), read),
            "VTK PolyData: NumberOfPoints=\"3x\" is not a count");
}
