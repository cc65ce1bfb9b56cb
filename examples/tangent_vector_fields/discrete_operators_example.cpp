// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The discrete operators as property maps: the gradient of the height function,
// its divergence (a discrete Laplacian of the height) and curl (zero), the rotated
// gradient (divergence-free), and the masses that integrate them.  Then the operators as
// matrices: the lowest eigenvalues of the vertex Laplacian (W, M) and of the edge one
// (W*, M*), both in one call of the eigensolver, checked by Sylvester's inertia count.
//
// Usage: discrete_operators_example [mesh]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>
#include <CGAL/Model_reduction/Generalized_eigensolver.h>

#include <cmath>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex_index;
typedef Mesh::Face_index Face_index;
typedef Mesh::Edge_index Edge_index;
namespace TVF = CGAL::Tangent_vector_fields;
namespace MR = CGAL::Model_reduction;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : TVF_DEFAULT_MESH;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(input, mesh) || is_empty(mesh))
  {
    std::cerr << "error: cannot read '" << input << "'\n";
    return 1;
  }
  try
  {
    TVF::Discrete_operators<Mesh> ops(mesh);

    auto height = mesh.add_property_map<Vertex_index, double>("v:height").first;
    for(Vertex_index v : mesh.vertices()) height[v] = mesh.point(v).z();

    auto gradient = mesh.add_property_map<Face_index, K::Vector_3>("f:gradient").first;
    ops.gradient(height, gradient);

    auto divergence = mesh.add_property_map<Vertex_index, double>("v:divergence").first;
    auto curl = mesh.add_property_map<Vertex_index, double>("v:curl").first;
    ops.divergence(gradient, divergence);
    ops.curl(gradient, curl);

    auto rotated = mesh.add_property_map<Face_index, K::Vector_3>("f:rotated").first;
    ops.rotate(gradient, rotated);
    auto rotated_divergence = mesh.add_property_map<Vertex_index, double>("v:rotated_divergence").first;
    ops.divergence(rotated, rotated_divergence);

    auto mass = mesh.add_property_map<Vertex_index, double>("v:mass").first;
    ops.vertex_masses(mass);

    // The divergence of a gradient integrates to zero (the weak divergence includes
    // the boundary flux at boundary vertices); the curl of a gradient and the
    // divergence of a rotated gradient vanish at interior vertices.
    double area = 0, integral_div = 0, max_div = 0, max_curl = 0, max_rot_div = 0;
    for(Vertex_index v : mesh.vertices())
    {
      area += mass[v];
      integral_div += mass[v] * divergence[v];
      max_div = std::max(max_div, std::abs(divergence[v]));
      if(CGAL::is_border(v, mesh)) continue;
      max_curl = std::max(max_curl, std::abs(curl[v]));
      max_rot_div = std::max(max_rot_div, std::abs(rotated_divergence[v]));
    }
    std::cout << "mesh " << input << ": " << ops.topology().summary() << ", area " << area << '\n'
              << "  max |div grad z| = " << max_div << ", integral of div grad z = " << integral_div << '\n'
              << "  max |curl grad z| = " << max_curl << " (interior vertices: zero up to roundoff)\n"
              << "  max |div J grad z| = " << max_rot_div << " (interior vertices: zero up to roundoff)\n";
    // Self-check, so that running the example also tests it.
    if(!(max_curl <= 1e-9 * max_div && max_rot_div <= 1e-9 * max_div && std::abs(integral_div) <= 1e-9 * max_div * area))
    {
      std::cerr << "error: an identity failed\n";
      return 2;
    }

    // The kernels: the constants on the vertices, and on the interior edges when the
    // surface is closed (with a boundary the edge problem has zero boundary values).
    if(ops.topology().number_of_components() != 1)
    {
      std::cout << "  eigenvalues: skipped (the kernels below assume one connected component)\n";
      return 0;
    }
    const TVF::Operator_matrices& m = ops.matrices();
    const Eigen::VectorXd edge_masses = m.all_to_interior_edges(m.edge_masses());
    const Eigen::MatrixXd vertex_kernel = Eigen::MatrixXd::Ones(m.W().rows(), 1);
    const Eigen::MatrixXd edge_kernel = Eigen::MatrixXd::Ones(m.W_star().rows(), ops.topology().number_of_boundary_loops() == 0);
    const int count = 20;
    const std::vector<MR::Eigenpairs> pairs = MR::lowest_eigenpairs_of_each(
        {{m.W(), m.vertex_masses(), count + 1, vertex_kernel}, {m.W_star(), edge_masses, count + 1, edge_kernel}});
    const char* name[] = {"vertex (W, M)", "edge (W*, M*)"};
    const Eigen::SparseMatrix<double>* A[] = {&m.W(), &m.W_star()};
    const Eigen::VectorXd* D[] = {&m.vertex_masses(), &edge_masses};
    const Eigen::Index kernel[] = {vertex_kernel.cols(), edge_kernel.cols()};
    for(int k = 0; k < 2; ++k)
    {
      const MR::Eigenpairs& e = pairs[k];
      // Sylvester: exactly `count` eigenvalues (and the kernel) below a shift between the
      // 20th and the 21st, counted by an LDL^T factorisation, independently of the solver.
      const double shift = 0.5 * (e.values[count - 1] + e.values[count]);
      const int below = MR::count_eigenvalues_below(*A[k], *D[k], shift) - static_cast<int>(kernel[k]);
      std::cout << "  lowest eigenvalues of the " << name[k] << " problem: " << e.values[0] << " .. "
                << e.values[count - 1] << ", largest relative residual " << e.residuals.maxCoeff() << ", " << below
                << " eigenvalues below " << shift << " (inertia)\n";
      if(below != count || !(e.residuals.maxCoeff() <= 1e-10))
      {
        std::cerr << "error: the " << name[k] << " eigenpairs failed their check\n";
        return 2;
      }
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
