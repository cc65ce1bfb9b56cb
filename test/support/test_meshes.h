// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Small meshes generated in code for the tests, and access to real meshes.

#ifndef TVF_TEST_MESHES_H
#define TVF_TEST_MESHES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cmath>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace tvf_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef Mesh::Vertex_index Vertex_index;
typedef Mesh::Face_index Face_index;
typedef Mesh::Edge_index Edge_index;

/// Mesh from a point list and triangles.
Mesh make_mesh(const std::vector<Point_3>& points, const std::vector<std::array<int, 3>>& triangles);

/// Icosahedron subdivided `levels` times, projected onto the unit sphere.
Mesh make_icosphere(int levels);

/// Torus with `n` x `m` quads split into triangles, radii R and r; grid parameters
/// jittered by `jitter` (fraction of a cell) so that the mesh is irregular.
Mesh make_torus(int n, int m, double R = 1.0, double r = 0.4, double jitter = 0.25, unsigned seed = 1);

/// Irregular triangulated disk (genus 0, one boundary loop) of radius 1, or an
/// annulus (inner radius `hole_radius` > 0), with `rings` rings of vertices.
Mesh make_disk(int rings, double hole_radius = 0.0, double jitter = 0.25, unsigned seed = 2);

/// A curved (non-planar) patch: the disk lifted onto z = 0.3 sin(2x) cos(3y).
Mesh make_curved_disk(int rings, double hole_radius = 0.0);

/// Applies p -> s * R p + t to every vertex.
void transform(Mesh& mesh, double scale, const std::array<double, 9>& rotation = {1, 0, 0, 0, 1, 0, 0, 0, 1},
               const Vector_3& translation = Vector_3(0, 0, 0));

/// A rotation matrix (row-major) about axis `axis` by `angle`.
std::array<double, 9> rotation_matrix(Vector_3 axis, double angle);

/// Moves every vertex by a random vector of length up to `amount` times the mean edge length.
void jitter_vertices(Mesh& mesh, double amount, unsigned seed);

/// CGAL's data tree (`meshes/...`) if unpacked, else empty.
std::string cgal_data_dir();
/// The reason to give in GTEST_SKIP when `cgal_data_dir()` is empty: where it was looked for and how to get it.
std::string cgal_data_missing();
/// `../shared/data` if present, else empty.
std::string shared_data_dir();
/// Reads a mesh; false if the file is absent or unreadable.
bool read_mesh(const std::string& path, Mesh& mesh);

/// A smooth ambient field projected to the faces: a + B p at the face centroid.
std::vector<Vector_3> ambient_linear_field(const Mesh& mesh, unsigned seed);
/// The same field stored in a new face property map `f:<name>`.
Mesh::Property_map<Face_index, Vector_3> ambient_field_map(Mesh& mesh, const std::string& name, unsigned seed);

/// Largest `|a_f - b_f|` over the faces, relative to the largest `|b_f|`.
double largest_relative_difference(const std::vector<Vector_3>& a, const std::vector<Vector_3>& b);
/// The vectors a writer puts into a face map (`write(map)`), in face order; the map is removed after.
template <class Write>
std::vector<Vector_3> face_vectors(Mesh& mesh, const Write& write)
{
  auto map = mesh.add_property_map<Face_index, Vector_3>("f:tvf_test_vectors", Vector_3(0, 0, 0)).first;
  write(map);
  std::vector<Vector_3> v(map.begin(), map.end());
  mesh.remove_property_map(map);
  return v;
}

/// A white-noise field in frame coordinates (`2 nf` standard normal entries).
Eigen::VectorXd random_field(int number_of_faces, unsigned seed);

/// A polygon soup, as `CGAL::IO::read_polygon_soup` reads it.
struct Polygon_soup
{
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
};

/// The faces of `mesh` as a soup (points in vertex order, polygons in face order).
Polygon_soup mesh_to_soup(const Mesh& mesh);

/// A torus of `n` x `m` quads (not triangulated), radii R and r: every quad is planar
/// in no particular way, so each triangulation is as good as the other.
Polygon_soup make_quad_torus(int n, int m, double R = 1.0, double r = 0.4);

/// The triangles of `mesh` as a soup with a random half of them (never the first)
/// reversed; `reversed[i]` says whether polygon `i` was.
Polygon_soup shuffled_orientation_soup(const Mesh& mesh, unsigned seed, std::vector<bool>& reversed);

/// Two cones of `n` triangles each, apex to apex: a double cone whose apex (point 0)
/// is a non-manifold vertex (its faces form two fans); each cone is open at its base.
Polygon_soup make_double_cone(int n);

/// A Moebius strip of `n` quads, each split into two triangles (a non-orientable surface).
Polygon_soup make_moebius_strip(int n);

/// A generalised eigenproblem `A x = lambda diag(d) x` with a basis of its kernel, assembled
/// here from the geometry alone, so that the shared eigensolver is tested without any chapter.
struct Sparse_eigenproblem
{
  Eigen::SparseMatrix<double> A;
  Eigen::VectorXd d;
  Eigen::MatrixXd kernel;
};

/// Cotangent Laplacian on the vertices and a third of the adjacent faces' area as mass;
/// kernel: the constants (one connected component, every vertex in a face assumed).
Sparse_eigenproblem cotan_vertex_problem(const Mesh& mesh);

/// Crouzeix-Raviart Laplacian on the interior edges (basis function `1 - 2 lambda_a` for the
/// edge opposite vertex `a`, so four times the cotangent stiffness of the vertices facing
/// each other), a third of the adjacent faces' area as mass; kernel: the constants on a
/// closed mesh, none with a boundary (the functions vanish on boundary edges).
Sparse_eigenproblem crouzeix_raviart_edge_problem(const Mesh& mesh);

/// Components, boundary loops and total genus, from CGAL's own functions and Euler's formula.
struct Mesh_counts
{
  int components = 0;
  int boundary_loops = 0;
  int genus = 0;
};
Mesh_counts count_topology(const Mesh& mesh);

} // namespace tvf_test

#endif
