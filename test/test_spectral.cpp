// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The generalized eigensolver behind the spectral basis (SPEC 5): analytic spectra,
// agreement with dense solves, residuals, orthonormality, and the inertia count
// that proves no eigenvalue was skipped.

#include "test_meshes.h"

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>
#include <CGAL/Tangent_vector_fields/Generalized_eigensolver.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;

namespace {

struct Vertex_problem
{
  Eigen::SparseMatrix<double> A;
  Eigen::VectorXd d;
  Eigen::MatrixXd kernel;
};

Vertex_problem vertex_problem(const Mesh& mesh)
{
  TVF::Discrete_operators<Mesh> ops(mesh);
  return {ops.matrices().W(), ops.matrices().vertex_masses(), Eigen::MatrixXd::Ones(mesh.number_of_vertices(), 1)};
}

Vertex_problem edge_problem(const Mesh& mesh)
{
  TVF::Discrete_operators<Mesh> ops(mesh);
  const auto& A = ops.matrices();
  Eigen::MatrixXd kernel(A.mesh().number_of_interior_edges(), 0);
  if(ops.topology().number_of_boundary_loops() == 0) kernel = Eigen::MatrixXd::Ones(kernel.rows(), 1);
  return {A.W_star(), A.all_to_interior_edges(A.edge_masses()), kernel};
}

void expect_orthonormal(const Eigen::MatrixXd& X, const Eigen::VectorXd& d)
{
  const Eigen::MatrixXd K = X.transpose() * d.asDiagonal() * X;
  EXPECT_LT((K - Eigen::MatrixXd::Identity(X.cols(), X.cols())).cwiseAbs().maxCoeff(), 1e-10);
}

} // namespace

TEST(Eigensolver, SphereSpectrumIsLTimesLPlusOneWithMultiplicity)
{
  // Scalar eigenvalues of the unit sphere are l(l+1) with multiplicity 2l+1.  On
  // icospheres with 642 and 2562 vertices (iterative path) the cotan discretisation
  // error for l <= 6 is below 6% and 1.5% (measured 4.9% and 1.2% at l = 6) and
  // shrinks about 4x per refinement (O(h^2)).
  const int count = 48; // l = 1 .. 6
  std::vector<Eigen::VectorXd> errors;
  for(int level : {3, 4})
  {
    SCOPED_TRACE(level);
    Mesh sphere = make_icosphere(level);
    const Vertex_problem p = vertex_problem(sphere);
    TVF::Eigensolver_options options;
    options.allow_dense = false;
    const TVF::Eigenpairs e = TVF::lowest_eigenpairs(p.A, p.d, count, p.kernel, options);
    ASSERT_EQ(e.values.size(), count);
    Eigen::VectorXd error(6);
    int i = 0;
    for(int l = 1; l <= 6; ++l)
    {
      const double exact = l * (l + 1);
      // The 2l+1 copies agree much better than the discretisation error (symmetry).
      const double lo = e.values[i], hi = e.values[i + 2 * l];
      error[l - 1] = std::abs(0.5 * (lo + hi) - exact) / exact;
      EXPECT_LT(error[l - 1], level == 3 ? 6e-2 : 1.5e-2) << "l = " << l;
      if(i + 2 * l + 1 < count) EXPECT_GT(e.values[i + 2 * l + 1] - hi, 10 * (hi - lo)) << "l = " << l;
      i += 2 * l + 1;
    }
    EXPECT_LE(e.residuals.maxCoeff(), 1e-10);
    expect_orthonormal(e.vectors, p.d);
    // Sylvester: count + 1 (with the constant) eigenvalues below the gap before l = 7.
    EXPECT_EQ(TVF::count_eigenvalues_below(p.A, p.d, 0.5 * (42 + 56)), count + 1);
    errors.push_back(error);
  }
  for(int l = 1; l <= 6; ++l) EXPECT_LT(errors[1][l - 1], 0.35 * errors[0][l - 1]) << "l = " << l;
}

TEST(Eigensolver, IterativeAgreesWithDenseOnVertexAndEdgeProblems)
{
  Mesh torus = make_torus(30, 14); // 420 vertices, 1260 edges; genus 1
  Mesh disk = make_curved_disk(12); // with boundary: no kernel for the edge problem
  for(const Mesh* mesh : {&torus, &disk})
    for(int kind = 0; kind < 2; ++kind)
    {
      SCOPED_TRACE(kind == 0 ? "vertex" : "edge");
      const Vertex_problem p = kind == 0 ? vertex_problem(*mesh) : edge_problem(*mesh);
      const int count = 60;
      TVF::Eigensolver_options iterative;
      iterative.allow_dense = false;
      iterative.block_size = 8;
      const TVF::Eigenpairs a = TVF::lowest_eigenpairs(p.A, p.d, count, p.kernel, iterative);
      const TVF::Eigenpairs b = TVF::lowest_eigenpairs(p.A, p.d, count, p.kernel);
      EXPECT_LT(((a.values - b.values).array() / b.values.array()).abs().maxCoeff(), 1e-9);
      EXPECT_LE(a.residuals.maxCoeff(), 1e-10);
      EXPECT_LE(b.residuals.maxCoeff(), 1e-10);
      expect_orthonormal(a.vectors, p.d);
      expect_orthonormal(b.vectors, p.d);
      // Orthogonal to the kernel.
      if(p.kernel.cols() > 0) EXPECT_LT((p.kernel.transpose() * p.d.asDiagonal() * a.vectors).norm(), 1e-9);
    }
}

TEST(Eigensolver, InertiaCountMatchesTheComputedSpectrum)
{
  // Jittered sphere: no exact multiplicities, so every consecutive pair has a gap.
  Mesh sphere = make_icosphere(3);
  jitter_vertices(sphere, 0.1, 3);
  const Vertex_problem p = vertex_problem(sphere);
  const TVF::Eigenpairs e = TVF::lowest_eigenpairs(p.A, p.d, 40, p.kernel);
  for(int k : {1, 10, 25, 39})
  {
    const double tau = 0.5 * (e.values[k - 1] + e.values[k]);
    // k computed eigenvalues below tau, plus the constant.
    EXPECT_EQ(TVF::count_eigenvalues_below(p.A, p.d, tau), k + 1) << "k = " << k;
  }
}

TEST(Eigensolver, RefusesImpossibleRequests)
{
  Mesh torus = make_torus(8, 5);
  const Vertex_problem p = vertex_problem(torus);
  EXPECT_THROW(TVF::lowest_eigenpairs(p.A, p.d, 40, p.kernel), TVF::Invalid_input); // space has dimension 39
  EXPECT_NO_THROW(TVF::lowest_eigenpairs(p.A, p.d, 39, p.kernel));
  EXPECT_THROW(TVF::lowest_eigenpairs(p.A, p.d, -1, p.kernel), TVF::Invalid_input);
}
