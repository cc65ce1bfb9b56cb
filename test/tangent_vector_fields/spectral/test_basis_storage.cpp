// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Spectral basis storage (SPEC 5): eigenfunctions in float32 against the double basis, and
// basis files that pass the size checks but are not a basis.

#include "test_meshes.h"
#include "scratch_path.h"

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>
#include <CGAL/Tangent_vector_fields/Reduced_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Spectral_basis.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;

namespace {
typedef TVF::Spectral_basis<Mesh> Basis;
} // namespace

// Eigenfunctions kept in float32: half the memory and file size; every entry is the double
// one rounded to nearest, and reconstructions, coefficients and reduced splines move only by
// that rounding (measured against the double basis).
TEST(SpectralBasis, Float32StorageHalvesTheMemoryAndAddsOnlyRounding)
{
  Mesh torus = make_torus(20, 12);
  TVF::Discrete_operators<Mesh> operators(torus);
  const auto ops = operators.shared_matrices();
  auto hodge = std::make_shared<TVF::Hodge_solver>(ops);
  TVF::Eigenfield_basis b64(hodge, TVF::Basis_request::lowest(120));
  TVF::Eigenfield_basis b32 = b64;
  b32.set_precision(TVF::Eigenfunction_precision::float32);
  ASSERT_EQ(b32.precision(), TVF::Eigenfunction_precision::float32);
  const std::size_t harmonic_bytes = sizeof(double) * b64.harmonic_fields().size();
  EXPECT_EQ(2 * (b32.memory_bytes() - harmonic_bytes), b64.memory_bytes() - harmonic_bytes);
  for(const auto& pair : {std::make_pair(&b64.exact_eigenfunctions(), &b32.exact_eigenfunctions()),
                          std::make_pair(&b64.coexact_eigenfunctions(), &b32.coexact_eigenfunctions())})
  {
    const Eigen::MatrixXd E64 = pair.first->to_double(), E32 = pair.second->to_double();
    const Eigen::ArrayXXd difference = (E32 - E64).array().abs();
    EXPECT_GT(difference.maxCoeff(), 0);                                            // really rounded
    EXPECT_LE((difference - E64.array().abs() * std::ldexp(1., -24)).maxCoeff(), 0); // to nearest
  }
  // Asked for in float32, the set-up rounds while it solves: the same functions, each entry
  // rounded once more when the mesh's scale is applied.
  TVF::Basis_request request32 = TVF::Basis_request::lowest(120);
  request32.precision = TVF::Eigenfunction_precision::float32;
  const TVF::Eigenfield_basis solved32(hodge, request32);
  ASSERT_EQ(solved32.precision(), TVF::Eigenfunction_precision::float32);
  EXPECT_EQ(solved32.memory_bytes(), b32.memory_bytes());
  EXPECT_LT((solved32.exact_eigenvalues() - b64.exact_eigenvalues()).norm(), 1e-12 * b64.exact_eigenvalues().norm());
  for(const auto& pair : {std::make_pair(&b64.exact_eigenfunctions(), &solved32.exact_eigenfunctions()),
                          std::make_pair(&b64.coexact_eigenfunctions(), &solved32.coexact_eigenfunctions())})
  {
    const Eigen::MatrixXd E64 = pair.first->to_double(), E32 = pair.second->to_double();
    EXPECT_LE(((E32 - E64).array().abs() - E64.array().abs() * std::ldexp(1., -23)).maxCoeff(), 0);
  }
  const Eigen::VectorXd& masses = ops->field_masses();
  auto relative = [&](const Eigen::VectorXd& x, const Eigen::VectorXd& reference) {
    const Eigen::VectorXd d = x - reference;
    return std::sqrt(d.dot(masses.cwiseProduct(d)) / reference.dot(masses.cwiseProduct(reference)));
  };
  std::mt19937 rng(3);
  std::normal_distribution<double> normal;
  Eigen::VectorXd a(b64.size());
  for(Eigen::Index k = 0; k < a.size(); ++k) a[k] = normal(rng);
  const Eigen::VectorXd v64 = b64.field(a), v32 = b32.field(a);
  EXPECT_GT(relative(v32, v64), 1e-10);
  EXPECT_LT(relative(v32, v64), 1e-6);
  EXPECT_LT((b32.coefficients(v64) - a).norm(), 1e-6 * a.norm());

  TVF::Reduced_spline_solver spline64(std::make_shared<TVF::Eigenfield_basis>(b64));
  TVF::Reduced_spline_solver spline32(std::make_shared<TVF::Eigenfield_basis>(b32));
  for(int f : {3, 150, 400})
  {
    const auto c = TVF::Field_constraint::vector_in_face(f, ops->mesh().from_frame(f, 1.0, 0.5));
    spline64.add(c);
    spline32.add(c);
  }
  EXPECT_LT(relative(spline32.field(), spline64.field()), 1e-5);

  // Files: about half the size; a float32 file loads as float32, entry for entry.
  const std::string p64 = scratch_path("basis_64.tvfb"), p32 = scratch_path("basis_32.tvfb");
  b64.save(p64);
  b32.save(p32);
  const auto size = [](const std::string& p) { return static_cast<double>(std::ifstream(p, std::ios::binary | std::ios::ate).tellg()); };
  EXPECT_LT(size(p32), 0.6 * size(p64));
  const TVF::Eigenfield_basis loaded = TVF::Eigenfield_basis::load(hodge, p32);
  EXPECT_EQ(loaded.precision(), TVF::Eigenfunction_precision::float32);
  EXPECT_EQ(loaded.exact_eigenfunctions().to_double(), b32.exact_eigenfunctions().to_double());
  EXPECT_EQ(loaded.coexact_eigenfunctions().to_double(), b32.coexact_eigenfunctions().to_double());
  EXPECT_EQ(loaded.field(a), v32);
  std::remove(p64.c_str());
  std::remove(p32.c_str());
}

// fuzz_tvfb: a file with an eigenvalue made 0 (sizes, marker and mesh identity intact) loaded,
// and its coefficients were infinite.  Whatever is not a basis is refused with the reason.
TEST(SpectralBasis, LoadRefusesCorruptBasesThatPassTheSizeChecks)
{
  Mesh torus = make_torus(16, 9);
  Basis basis(torus, TVF::parameters::number_of_eigenfields(30));
  const TVF::Eigenfield_basis& b = basis.basis();
  const std::string path = scratch_path("corrupt_basis.tvfb");
  basis.save(path);
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // Offsets (doc/tangent_vector_fields/manual.md): a 64-byte header, then matrices of 16 bytes of sizes and their doubles.
  const std::size_t de = b.exact_eigenfunctions().cols(), dc = b.coexact_eigenfunctions().cols();
  ASSERT_GT(de, 0u);
  // Format version 2: a precision byte before each eigenfunction matrix.
  const std::size_t exact_values = 64 + 16, exact_functions = exact_values + 8 * de + 1 + 16;
  const std::size_t exact_size = b.exact_eigenfunctions().rows() * de, coexact_size = b.coexact_eigenfunctions().rows() * dc;
  const std::size_t table = exact_functions + 8 * exact_size + 16 + 8 * dc + 1 + 16 + 8 * coexact_size + 16 +
                            8 * b.harmonic_fields().size() + 8;
  const auto load_error = [&](std::string corrupt) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << corrupt;
    try
    {
      Basis::load(torus, path);
    }
    catch(const TVF::Invalid_input& e)
    {
      return std::string(e.what());
    }
    return std::string("loaded");
  };
  const auto with_double = [&](std::size_t offset, double x) {
    std::string corrupt = bytes;
    std::memcpy(&corrupt[offset], &x, 8);
    return corrupt;
  };
  const std::string prefix = "cannot load the spectral basis from '" + path + "': ";
  EXPECT_EQ(load_error(bytes), "loaded");
  EXPECT_EQ(load_error(with_double(exact_values, 0.)), prefix + "an exact eigenvalue is not positive");
  EXPECT_EQ(load_error(with_double(exact_values, -2.)), prefix + "an exact eigenvalue is not positive");
  double first;
  std::memcpy(&first, &bytes[exact_functions], 8);
  const std::string scaled = load_error(with_double(exact_functions, 1e3 * first + 1));
  EXPECT_NE(scaled.find("instead of 1 (the file is corrupt)"), std::string::npos) << scaled;
  std::string repeated = bytes;
  repeated.replace(table + 5 * 2, 5, bytes.substr(table + 5, 5)); // element 2 := element 1
  EXPECT_EQ(load_error(repeated), prefix + "element 2 is listed twice");
  std::remove(path.c_str());
}
