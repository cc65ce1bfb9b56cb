// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The spectral basis of every mesh of CGAL's data tree that the golden table processes
// (robustness/cgal_data_tree.golden): the 40 lowest eigenfields (fewer where the mesh has
// fewer), checked here and not by the eigensolver's own numbers.  Real meshes have what
// generated ones lack: angles of 0.02 degrees, needles next to large faces, many small
// components.  This found two failures the generated meshes did not: camel.off (0.23 degree
// angles: Lanczos pairs stuck above the tolerance) and ALSTOM_TEST4.off (0.02 degrees, six
// components: dense pairs that inverse iteration could not clean).

#include "test_meshes.h"

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>
#include <CGAL/Model_reduction/Generalized_eigensolver.h>
#include <CGAL/Tangent_vector_fields/Spectral_basis.h>
#include <CGAL/Model_reduction/polygon_soup_to_mesh.h>

#include <CGAL/IO/polygon_soup_io.h>

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace TVF = CGAL::Tangent_vector_fields;
namespace MR = CGAL::Model_reduction;
using namespace tvf_test;

namespace {

typedef Eigen::SparseMatrix<double> Sparse_matrix;

// The largest relative residual |M^-1/2 (A f - l M f)| / (l |M^1/2 f|) of the columns of
// `F` (entries of `unknowns` only: vertices in no face are zero) and the largest deviation
// of F^T M F from the identity.
void check_pairs(const Sparse_matrix& A, const Eigen::VectorXd& m, const Eigen::VectorXd& values,
                 const Eigen::MatrixXd& F, double& residual, double& orthonormality)
{
  residual = orthonormality = 0;
  if(F.cols() == 0) return;
  for(Eigen::Index k = 0; k < F.cols(); ++k)
  {
    const Eigen::VectorXd f = F.col(k);
    Eigen::VectorXd r = A * f - values[k] * m.cwiseProduct(f);
    for(Eigen::Index i = 0; i < r.size(); ++i) r[i] = m[i] > 0 ? r[i] / std::sqrt(m[i]) : r[i];
    residual = std::max(residual, r.norm() / (values[k] * m.cwiseSqrt().cwiseProduct(f).norm()));
  }
  const Eigen::MatrixXd gram = F.transpose() * m.asDiagonal() * F;
  orthonormality = (gram - Eigen::MatrixXd::Identity(F.cols(), F.cols())).cwiseAbs().maxCoeff();
}

// Completeness by Sylvester's inertia, independent of how the pairs were found: nothing
// below the largest value was missed.  `kernel`: zero eigenvalues outside the basis.
void expect_complete(const Sparse_matrix& A, const Eigen::VectorXd& m, const Eigen::VectorXd& values, int kernel)
{
  if(values.size() == 0) return;
  const double last = values[values.size() - 1];
  // Vertices in no face have zero mass: they are left out (their rows are empty).
  std::vector<int> keep;
  for(Eigen::Index i = 0; i < m.size(); ++i)
    if(m[i] > 0) keep.push_back(static_cast<int>(i));
  Sparse_matrix P(keep.size(), m.size());
  for(std::size_t j = 0; j < keep.size(); ++j) P.insert(static_cast<Eigen::Index>(j), keep[j]) = 1;
  const Sparse_matrix Ak = P * A * P.transpose();
  const Eigen::VectorXd mk = P * m;
  // A cluster of equal eigenvalues may be cut by the request: hence the two bounds.
  EXPECT_LE(MR::count_eigenvalues_below(Ak, mk, last * (1 - 1e-8)) - kernel, values.size() - 1)
      << "an eigenvalue below the largest one found was missed";
  EXPECT_GE(MR::count_eigenvalues_below(Ak, mk, last * (1 + 1e-8)) - kernel, values.size())
      << "fewer eigenvalues up to the largest one found than were found";
}

} // namespace

TEST(DataTree, BasisOfEveryProcessedMesh)
{
  const std::string dir = cgal_data_dir();
  if(dir.empty()) GTEST_SKIP() << cgal_data_missing();
  std::ifstream table(TVF_GOLDEN_TABLE);
  ASSERT_TRUE(table) << "cannot read " << TVF_GOLDEN_TABLE;
  int meshes = 0;
  for(std::string line; std::getline(table, line);)
  {
    if(line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    std::string name, outcome;
    row >> name >> outcome;
    if(outcome != "processed" && outcome != "mollified") continue;
    SCOPED_TRACE(name);
    std::vector<Point_3> points;
    std::vector<std::vector<std::size_t>> polygons;
    ASSERT_TRUE(CGAL::IO::read_polygon_soup(dir + "/" + name, points, polygons, CGAL::parameters::verbose(false)));
    Mesh mesh;
    MR::polygon_soup_to_mesh(points, polygons, mesh);
    const int count = std::min(40, 2 * static_cast<int>(mesh.number_of_faces()));
    try
    {
      const TVF::Spectral_basis<Mesh> spectral(mesh, TVF::parameters::number_of_eigenfields(count)
                                                         .use_intrinsic_mollification(outcome == "mollified"));
      const TVF::Eigenfield_basis& basis = spectral.basis();
      const TVF::Operator_matrices& ops = basis.operators();
      ASSERT_EQ(basis.size(), count);
      EXPECT_EQ(basis.number_of_harmonic(), std::min(count, ops.mesh().topology().harmonic_dimension()));
      EXPECT_TRUE(basis.eigenvalues().allFinite());
      // The solver asks 1e-10 where double precision allows; 1e-7 is far above what any
      // pair here reaches and far below the 1e-2 of a pair with a few correct digits.
      double residual = 0, orthonormality = 0;
      check_pairs(ops.W(), ops.vertex_masses(), basis.exact_eigenvalues(),
                  basis.exact_eigenfunctions().to_double(), residual, orthonormality);
      EXPECT_LT(residual, 1e-7) << "exact";
      EXPECT_LT(orthonormality, 1e-8) << "exact";
      const Eigen::VectorXd edge_masses = ops.all_to_interior_edges(ops.edge_masses());
      check_pairs(ops.W_star(), edge_masses, basis.coexact_eigenvalues(), basis.coexact_eigenfunctions().to_double(),
                  residual, orthonormality);
      EXPECT_LT(residual, 1e-7) << "coexact";
      EXPECT_LT(orthonormality, 1e-8) << "coexact";
      const TVF::Mesh_topology& topology = ops.mesh().topology();
      int closed = 0;
      for(int c = 0; c < topology.number_of_components(); ++c) closed += topology.components[c].is_closed();
      expect_complete(ops.W(), ops.vertex_masses(), basis.exact_eigenvalues(), topology.number_of_components());
      expect_complete(ops.W_star(), edge_masses, basis.coexact_eigenvalues(), closed);
      ++meshes;
    }
    catch(const std::exception& e)
    {
      ADD_FAILURE() << "the basis failed: " << e.what();
    }
  }
  EXPECT_GT(meshes, 100);
  std::cout << "bases of " << meshes << " meshes checked" << std::endl;
}

// CGAL's camel has needle triangles, whose tiny masses leave windows' pairs just short of
// their tolerance: windows are polished (shifted next to a Ritz value) and some rerun
// refined.  A rerun once used the shift a failed polish had left factored, and found more
// eigenvalues in its window than the inertia allows (seen in the editor's server, 300
// eigenfields).  Checked here: residuals, orthonormality and completeness by the inertia.
TEST(DataTree, BasisOfManyWindowsOnNeedleTriangles)
{
  const std::string dir = cgal_data_dir();
  if(dir.empty()) GTEST_SKIP() << cgal_data_missing();
  Mesh mesh;
  ASSERT_TRUE(read_mesh(dir + "/meshes/camel.off", mesh));
  TVF::Discrete_operators<Mesh> operators(mesh);
  const auto hodge = std::make_shared<TVF::Hodge_solver>(operators.shared_matrices());
  const TVF::Operator_matrices& ops = *operators.shared_matrices();
  for(const auto precision : {TVF::Eigenfunction_precision::float64, TVF::Eigenfunction_precision::float32})
  {
    const bool single = precision == TVF::Eigenfunction_precision::float32;
    SCOPED_TRACE(single ? "float32" : "double");
    TVF::Basis_request request = TVF::Basis_request::lowest(300);
    request.precision = precision; // float32: rounded while the windows run
    const TVF::Eigenfield_basis basis(hodge, request);
    ASSERT_EQ(basis.size(), 300);
    // float32 functions: the residual of a rounded vector says nothing (the operator
    // amplifies the rounding by up to lambda_max / lambda); orthonormality keeps 1e-6.
    double residual = 0, orthonormality = 0;
    check_pairs(ops.W(), ops.vertex_masses(), basis.exact_eigenvalues(), basis.exact_eigenfunctions().to_double(),
                residual, orthonormality);
    if(!single) EXPECT_LT(residual, 1e-7) << "exact";
    EXPECT_LT(orthonormality, single ? 1e-6 : 1e-8) << "exact";
    const Eigen::VectorXd edge_masses = ops.all_to_interior_edges(ops.edge_masses());
    check_pairs(ops.W_star(), edge_masses, basis.coexact_eigenvalues(), basis.coexact_eigenfunctions().to_double(),
                residual, orthonormality);
    if(!single) EXPECT_LT(residual, 1e-7) << "coexact";
    EXPECT_LT(orthonormality, single ? 1e-6 : 1e-8) << "coexact";
    expect_complete(ops.W(), ops.vertex_masses(), basis.exact_eigenvalues(), 1);
    expect_complete(ops.W_star(), edge_masses, basis.coexact_eigenvalues(), 1);
  }
}
