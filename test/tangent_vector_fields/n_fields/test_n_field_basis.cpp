// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// n-direction fields (SPEC 10), the spectral basis: the spectrum of L_n on icospheres against
// the continuous operator, pairs, residuals and values against a dense solve of the real form,
// the eigenspaces of the complex solve against those of the real form's, the kernel, files.

#include "n_field_test_support.h"
#include "scratch_path.h"

#include <CGAL/Model_reduction/Generalized_eigensolver.h>
#include <CGAL/Tangent_vector_fields/N_field_basis.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <tuple>

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;
using namespace nfield_test;

namespace MR = CGAL::Model_reduction;

TEST(NFieldBasis, SpectrumOfIcospheresApproachesTwiceTheConnectionLaplacian)
{
  // Measured (SPEC 10 left it open): on the unit sphere the multiplets of L_n approach
  // 2 (l(l+1) - n^2), twice the connection (Bochner) Laplacian of spin-n sections, with
  // multiplicity 2(2l+1), l >= n.  The factor 2: w_e = 3|e|^2/(A_f + A_g) is twice |e| over
  // the centroids' distance across e.  Multiplet means at l = n, levels 2, 3, 4, 5, 6
  // (n = 4): 8.104, 8.045, 8.030, 8.027, 8.026; the two-point weights are not consistent
  // on the icosphere's uneven triangles, so the error levels off near 0.3% and multiplets
  // with l > n stay split by ~2-4% (doc/tangent_vector_fields/manual.md).  Checked here: the multiplet structure,
  // the identified limit (means within 0.6% at level 4), and the lowest multiplet's error
  // shrinking (n = 4: 0.104, 0.045, 0.030 at levels 2, 3, 4).
  for(int n : {1, 2, 4})
  {
    std::vector<double> lowest_error;
    for(int level : {2, 3, 4})
    {
      const auto nops = n_field_operators(make_icosphere(level), n);
      int count = 0;
      for(int l = n; l < n + 3; ++l) count += 2 * (2 * l + 1);
      const TVF::N_field_basis basis(nops, count + 2);
      EXPECT_EQ(basis.kernel_dimension(), 0);
      const double scale = 1; // the vertices lie on the unit sphere
      const double tolerance = level < 4 ? 0.03 : 0.006; // measured worst: 2.7% (level 2), 0.45% (level 4)
      int k = 0;
      for(int l = n; l < n + 3; ++l)
      {
        const int multiplicity = 2 * (2 * l + 1);
        const double expected = 2. * (l * (l + 1) - n * n);
        double mean = 0;
        for(int j = 0; j < multiplicity; ++j) mean += basis.eigenvalue(k + j) * scale / multiplicity;
        EXPECT_NEAR(mean, expected, tolerance * expected) << "n = " << n << ", level " << level << ", l = " << l;
        // A gap separates the multiplet from the next one.
        EXPECT_LT(basis.eigenvalue(k + multiplicity - 1) * scale, 2. * ((l + 1) * (l + 2) - n * n) * 0.95);
        if(l == n) lowest_error.push_back(std::abs(mean - expected));
        k += multiplicity;
      }
    }
    EXPECT_LT(lowest_error[1], lowest_error[0]) << "n = " << n;
    EXPECT_LT(lowest_error[2], lowest_error[1]) << "n = " << n;
  }
}

TEST(NFieldBasis, PairsOrthonormalResidualsAndDenseAgreement)
{
  // 1,536 unknowns: above the eigensolver's dense threshold, small enough for a dense check.
  Mesh torus = make_torus(24, 16);
  jitter_vertices(torus, 0.05, 11);
  for(int n : {1, 3})
  {
    const auto nops = n_field_operators(torus, n);
    const TVF::N_field_basis basis(nops, 40);
    ASSERT_EQ(basis.size(), 40);
    const Eigen::VectorXd& mass = nops->masses();
    const Eigen::MatrixXd& X = basis.fields();
    EXPECT_LT((X.transpose() * mass.asDiagonal() * X - Eigen::MatrixXd::Identity(40, 40)).cwiseAbs().maxCoeff(), 1e-10);
    const Eigen::MatrixXd J = nops->operators().J();
    for(int j = 0; j < 40; j += 2)
    {
      EXPECT_EQ((X.col(j + 1) - J * X.col(j)).cwiseAbs().maxCoeff(), 0.);
      EXPECT_EQ(basis.eigenvalue(j), basis.eigenvalue(j + 1));
    }
    for(int j = 0; j < 40; ++j)
    {
      const Eigen::VectorXd r = nops->S() * X.col(j) - basis.eigenvalue(j) * mass.cwiseProduct(X.col(j));
      EXPECT_LT(r.cwiseQuotient(mass.cwiseSqrt()).norm() / basis.eigenvalue(j), 1e-8) << "element " << j;
    }
    const Eigen::MatrixXd S = nops->S();
    const Eigen::VectorXd d = mass.cwiseSqrt().cwiseInverse();
    const Eigen::VectorXd lambda =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(d.asDiagonal() * S * d.asDiagonal()).eigenvalues();
    for(int j = 0; j < 40; ++j) EXPECT_NEAR(basis.eigenvalue(j), lambda[j], 1e-9 * lambda[j]);
    EXPECT_EQ(basis.report().inertia, basis.report().expected);
    // Energies through the basis equal those through the operators.
    const Eigen::VectorXd a = Eigen::VectorXd::LinSpaced(40, 1, 2);
    const Eigen::VectorXd z = basis.field(a);
    EXPECT_NEAR(basis.energy(a, 1), nops->dirichlet_energy(z), 1e-9 * basis.energy(a, 1));
    EXPECT_NEAR(basis.energy(a, 2), nops->m_harmonic_energy(z, 2), 1e-9 * basis.energy(a, 2));
    EXPECT_NEAR(basis.energy(a, 3), nops->m_harmonic_energy(z, 3), 1e-9 * basis.energy(a, 3));
  }
}

TEST(NFieldBasis, ComplexSolveSpansTheRealFormsEigenspaces)
{
  // The basis comes from the complex form of S_n (one unknown per face); here it is held
  // against the real form's own solve (2nf unknowns, each eigenvalue twice): the same values and
  // the same spaces.  Both meshes have more than the 1,500 faces up to which the eigensolver
  // solves densely, so the complex pairs come from spectrum slicing: a cube (n = 4: a pair of
  // parallel fields, handed to the solver as one complex kernel column; octahedral symmetry,
  // repeated eigenvalues) and a jittered torus (n = 3: a connection no gauge makes real).
  const Mesh torus = [] {
    Mesh m = make_torus(32, 28); // 1,792 faces
    jitter_vertices(m, 0.05, 13);
    return m;
  }();
  const Mesh cube = make_cube(12); // 1,728 faces
  for(const auto& [mesh, n, kernel] : {std::make_tuple(&cube, 4, 2), std::make_tuple(&torus, 3, 0)})
  {
    SCOPED_TRACE("n = " + std::to_string(n));
    const auto nops = n_field_operators(*mesh, n);
    ASSERT_GT(nops->mesh().number_of_faces(), 1500);
    const int count = 60, wanted = count - kernel;
    const TVF::N_field_basis basis(nops, count);
    ASSERT_EQ(basis.kernel_dimension(), kernel);
    const Eigen::VectorXd& mass = nops->masses();
    MR::Eigensolver_options real_form;
    real_form.allow_dense = false;
    const MR::Eigenpairs reference = MR::lowest_eigenpairs(nops->S(), mass, wanted + 10, nops->kernel(), real_form);
    const Eigen::VectorXd values = basis.eigenvalues().tail(wanted);
    const Eigen::VectorXd truth = reference.values.head(wanted);
    EXPECT_LT(((values - truth).array() / truth.array()).abs().maxCoeff(), 1e-9);
    // The spaces of the lowest k pairs, k at the widest relative gap of the real form's values
    // up to `wanted`: the principal angles between the two, cos = the singular values of
    // F^T MX V, are below residual / gap (1e-10 / 1e-3 here; cos > 1 - 1e-12).
    int k = 2;
    for(int j = 2; j <= wanted; j += 2)
      if((truth[j] - truth[j - 1]) / truth[j] > (truth[k] - truth[k - 1]) / truth[k]) k = j;
    EXPECT_GT((truth[k] - truth[k - 1]) / truth[k], 1e-3);
    const Eigen::MatrixXd F = basis.fields().middleCols(kernel, k), V = reference.vectors.leftCols(k);
    const Eigen::VectorXd cosines = Eigen::JacobiSVD<Eigen::MatrixXd>(F.transpose() * mass.asDiagonal() * V).singularValues();
    EXPECT_GT(cosines.minCoeff(), 1 - 1e-10) << "k = " << k;
    // The kernel and the pairs (z, i z), MX-orthonormal, with their residuals on the real S_n.
    const Eigen::MatrixXd& X = basis.fields();
    EXPECT_LT((X.transpose() * mass.asDiagonal() * X - Eigen::MatrixXd::Identity(count, count)).cwiseAbs().maxCoeff(), 1e-10);
    if(kernel > 0) EXPECT_LT((nops->S() * X.leftCols(kernel)).norm(), 1e-10 * nops->S().norm());
    for(int j = kernel; j < count; j += 2)
    {
      EXPECT_EQ((X.col(j + 1) - TVF::Operator_matrices::rotate(X.col(j))).cwiseAbs().maxCoeff(), 0.);
      EXPECT_EQ(basis.eigenvalue(j), basis.eigenvalue(j + 1));
      const Eigen::VectorXd r = nops->S() * X.col(j) - basis.eigenvalue(j) * mass.cwiseProduct(X.col(j));
      EXPECT_LT(r.cwiseQuotient(mass.cwiseSqrt()).norm() / basis.eigenvalue(j), 1e-9) << "element " << j;
    }
    // Completeness, reported in the real form's count: twice the complex form's, as the
    // inertias of the two forms at a shift in the gap show.
    EXPECT_EQ(basis.report().inertia, basis.report().expected);
    EXPECT_GE(basis.report().expected, count);
    EXPECT_EQ(basis.report().expected % 2, 0);
    const double tau = 0.5 * (truth[k - 1] + truth[k]);
    const Eigen::VectorXd face_mass = nops->face_areas();
    EXPECT_EQ(MR::count_eigenvalues_below(nops->S(), mass, tau), kernel + k);
    EXPECT_EQ(2 * MR::count_eigenvalues_below(nops->complex_S(), face_mass, tau), kernel + k);
  }
}

TEST(NFieldBasis, KernelFirstOnTheCubeAndFilesRoundTrip)
{
  const Mesh cube = make_cube(4);
  const auto nops = n_field_operators(cube, 4);
  const TVF::N_field_basis basis(nops, 11); // rounded up to 12
  ASSERT_EQ(basis.size(), 12);
  EXPECT_EQ(basis.kernel_dimension(), 2);
  EXPECT_EQ(basis.eigenvalue(0), 0.);
  EXPECT_GT(basis.eigenvalue(2), 0.);

  const std::string path = scratch_path("cube4.tvfn");
  basis.save(path);
  const TVF::N_field_basis loaded = TVF::N_field_basis::load(nops, path);
  EXPECT_EQ(loaded.kernel_dimension(), 2);
  EXPECT_EQ((loaded.fields() - basis.fields()).cwiseAbs().maxCoeff(), 0.);
  EXPECT_EQ((loaded.eigenvalues() - basis.eigenvalues()).cwiseAbs().maxCoeff(), 0.);

  auto load_error = [&](std::shared_ptr<const TVF::N_field_operators> ops, const std::string& file) {
    try
    {
      TVF::N_field_basis::load(ops, file);
    }
    catch(const TVF::Invalid_input& e)
    {
      return std::string(e.what());
    }
    return std::string("loaded");
  };
  EXPECT_NE(load_error(n_field_operators(cube, 2), path).find("holds 4-fields, not 2-fields"), std::string::npos);
  EXPECT_NE(load_error(n_field_operators(cube, 4, TVF::N_field_boundary::zero), path).find("boundary condition"),
            std::string::npos);
  EXPECT_NE(load_error(n_field_operators(make_cube(3), 4), path).find("other connectivity"), std::string::npos);
  {
    // Another connection: a prescribed singularity changes S_n, so the basis does not fit.
    TVF::Discrete_operators<Mesh> ops(cube);
    TVF::N_field_options prescribed;
    prescribed.singularities = {{5, 1}};
    const auto with_singularity = std::make_shared<const TVF::N_field_operators>(ops.shared_matrices(), 4, prescribed);
    EXPECT_NE(load_error(with_singularity, path).find("0 prescribed singularities, not these 1"), std::string::npos)
        << load_error(with_singularity, path);
  }
  Mesh bigger = make_cube(4);
  transform(bigger, 2.0);
  EXPECT_NE(load_error(n_field_operators(bigger, 4), path).find("other edge lengths"), std::string::npos);
  {
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(path + ".cut", std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size() / 2));
  }
  EXPECT_NE(load_error(nops, path + ".cut").find("truncated"), std::string::npos);
  EXPECT_NE(load_error(nops, path + ".missing").find("cannot open"), std::string::npos);
}
