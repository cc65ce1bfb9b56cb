// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Tetrahedral meshes: the generators against exact volumes and the divergence theorem, Medit
// files read back as written, and every malformed file refused with its line.

#include "expect_reason.h"
#include "scratch_path.h"

#include <CGAL/Projective_dynamics/Tet_mesh.h>
#include <CGAL/Projective_dynamics/errors.h>
#include <CGAL/Projective_dynamics/medit_io.h>
#include <CGAL/Projective_dynamics/mesh_generators.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace PD = CGAL::Projective_dynamics;

namespace {

// Volume enclosed by closed oriented triangles: sum of (a x b . c) / 6 (divergence theorem);
// positive only if every triangle faces out.
double enclosed_volume(const PD::Tet_mesh& m)
{
  double v = 0;
  for(const auto& f : m.triangles)
  {
    const auto &a = m.points[f[0]], &b = m.points[f[1]], &c = m.points[f[2]];
    v += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
  }
  return v;
}

PD::Tet_mesh read_text(const std::string& text) // a Medit file given as text
{
  std::istringstream in(text);
  return PD::read_medit(in, "test.mesh");
}

const char* header = "MeshVersionFormatted 1\nDimension 3\n";

} // namespace

TEST(Tet_mesh, BoxCountsVolumesAndOutwardBoundary)
{
  const PD::Tet_mesh m = PD::make_tet_box(3, 2, 4, {-1, 0, 0.5}, {2, 1, 1.5});
  EXPECT_EQ(m.points.size(), 4u * 3 * 5);
  EXPECT_EQ(m.tetrahedra.size(), 6u * 3 * 2 * 4);
  double volume = 0;
  for(const auto& t : m.tetrahedra)
  {
    EXPECT_GT(PD::signed_volume(m.points, t), 0);
    volume += PD::signed_volume(m.points, t);
  }
  EXPECT_NEAR(volume, 3.0 * 1 * 1, 1e-12); // the box's volume: the tets tile it
  // Boundary: two triangles per boundary square, 2 (3*2 + 2*4 + 3*4) squares.
  EXPECT_EQ(m.triangles.size(), 2u * 2 * (3 * 2 + 2 * 4 + 3 * 4));
  EXPECT_NEAR(enclosed_volume(m), 3.0, 1e-12); // outward, closed
  EXPECT_NO_THROW(PD::check_tet_mesh(m));
  // Each interior edge of a conforming tiling: edges = V + F - T - 1 (Euler for a ball).
  const auto edges = PD::unique_edges(m.tetrahedra);
  std::vector<std::array<int, 3>> faces;
  for(const auto& t : m.tetrahedra)
    for(int o = 0; o < 4; ++o)
    {
      std::array<int, 3> f;
      for(int i = 0, k = 0; i < 4; ++i)
        if(i != o) f[k++] = t[i];
      std::sort(f.begin(), f.end());
      faces.push_back(f);
    }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  EXPECT_EQ(long(m.points.size()) - long(edges.size()) + long(faces.size()) - long(m.tetrahedra.size()), 1);
}

TEST(Tet_mesh, RodAndChain)
{
  const PD::Tet_mesh rod = PD::make_tet_rod(10, 2, 5.0, 1.0);
  EXPECT_EQ(rod.tetrahedra.size(), 6u * 10 * 2 * 2);
  EXPECT_NEAR(enclosed_volume(rod), 5.0, 1e-12);
  const PD::Spring_chain chain = PD::make_spring_chain(4, 0.5, {1, 2, 3});
  ASSERT_EQ(chain.points.size(), 5u);
  EXPECT_DOUBLE_EQ(chain.points[4][2], 1.0);
  EXPECT_EQ(chain.edges.back(), (PD::Edge{3, 4}));
  EXPECT_THROW_REASON(PD::make_tet_box(0, 1, 1, {0, 0, 0}, {1, 1, 1}), PD::Invalid_input, "at least one cell");
  EXPECT_THROW_REASON(PD::make_spring_chain(0, 1), PD::Invalid_input, "at least one spring");
}

TEST(Tet_mesh, MeditRoundTripIsExact)
{
  PD::Tet_mesh m = PD::make_tet_box(2, 2, 1, {0, 0, 0}, {1.0 / 3, 0.7, 1e-3});
  const std::string path = tvf_test::scratch_path("box.mesh");
  PD::write_medit(path, m);
  const PD::Tet_mesh r = PD::read_medit(path);
  EXPECT_EQ(r.points, m.points); // 17 digits: the same doubles
  EXPECT_EQ(r.tetrahedra, m.tetrahedra);
  EXPECT_EQ(r.triangles, m.triangles);
}

TEST(Tet_mesh, MeditReadsOtherSectionsAndComments)
{
  const PD::Tet_mesh m = read_text(std::string(header) +
                                   "# a comment\nVertices\n4\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1 # ref\n"
                                   "Edges\n1\n1 2 0\nCorners 1 1\nTetrahedra\n1\n1 2 3 4 7\nEnd\n");
  ASSERT_EQ(m.points.size(), 4u);
  ASSERT_EQ(m.tetrahedra.size(), 1u);
  EXPECT_EQ(m.tetrahedra[0], (PD::Tetrahedron{0, 1, 2, 3}));
  EXPECT_TRUE(m.triangles.empty());
}

TEST(Tet_mesh, MalformedMeditFilesNameTheLine)
{
  const std::string four_vertices = "Vertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"; // lines 3-8
  EXPECT_THROW_REASON(read_text("Vertices 0\n"), PD::Invalid_input, "line 1: not a Medit mesh");
  EXPECT_THROW_REASON(read_text("MeshVersionFormatted 1\nDimension 2\n"), PD::Invalid_input,
                      "line 2: dimension 2: only 3 is supported");
  EXPECT_THROW_REASON(read_text(std::string(header) + "Vertices\n2\n0 0 0 0\n1 x 0 0\n"), PD::Invalid_input,
                      "line 6: 'x' is not a coordinate");
  EXPECT_THROW_REASON(read_text(std::string(header) + "Vertices\n2\n0 0 0 0\n1 nan 0 0\n"), PD::Invalid_input,
                      "line 6: a non-finite value 'nan'");
  EXPECT_THROW_REASON(read_text(std::string(header) + four_vertices + "Tetrahedra\n1\n1 2 3 5 0\n"), PD::Invalid_input,
                      "line 11: vertex index 5 of tetrahedron 1 is outside [1, 4]");
  EXPECT_THROW_REASON(read_text(std::string(header) + four_vertices + "Tetrahedra\n2\n1 2 3 4 0\n"), PD::Invalid_input,
                      "the file ends where a vertex index was expected");
  EXPECT_THROW_REASON(read_text(std::string(header) + four_vertices + "Pyramids\n1\n"), PD::Invalid_input,
                      "line 9: unknown section 'Pyramids'");
  EXPECT_THROW_REASON(read_text(std::string(header) + "Vertices\n-3\n"), PD::Invalid_input,
                      "line 4: the number of vertices -3 is out of range");
  EXPECT_THROW_REASON(read_text(std::string(header) + "Tetrahedra\n0\n"), PD::Invalid_input, "line 3: Tetrahedra before Vertices");
  EXPECT_THROW_REASON(PD::read_medit(std::string("/nonexistent/x.mesh")), PD::Invalid_input, "cannot open");
}

TEST(Tet_mesh, ChecksNameTheBadElement)
{
  PD::Tet_mesh m = PD::make_tet_box(2, 1, 1, {0, 0, 0}, {1, 1, 1});
  EXPECT_THROW_REASON(PD::check_tet_mesh(PD::Tet_mesh{}), PD::Invalid_mesh, "empty");
  PD::Tet_mesh flat = m;
  flat.tetrahedra[5] = {0, 1, 2, 3}; // four vertices of the grid's bottom face: coplanar
  EXPECT_THROW_REASON(PD::check_tet_mesh(flat), PD::Invalid_mesh, "tetrahedron 5 has (nearly) zero volume");
  PD::Tet_mesh bad = m;
  bad.tetrahedra[2][3] = 99;
  EXPECT_THROW_REASON(PD::check_tet_mesh(bad), PD::Invalid_mesh, "tetrahedron 2 has vertex index 99");
  bad = m;
  bad.tetrahedra[1][3] = bad.tetrahedra[1][0];
  EXPECT_THROW_REASON(PD::check_tet_mesh(bad), PD::Invalid_mesh, "tetrahedron 1 repeats vertex");
  bad = m;
  bad.points[3][1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW_REASON(PD::check_tet_mesh(bad), PD::Invalid_mesh, "vertex 3 has a non-finite coordinate");
}
