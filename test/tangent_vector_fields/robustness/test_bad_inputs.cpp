// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Bad and extreme input to the spectral basis (SPEC 5, 6): degenerate meshes, awkward
// topology, requests of impossible sizes, bad fields and filters.  Each case either gives
// a finite result whose real property is checked (eigenvalues, harmonic count from the
// topology counted here) or a clear error whose type and reason are checked.  The design
// entry points are in test_bad_design.cpp, n-fields, streamlines and pictures in
// test_bad_n_fields.cpp and test_bad_streamlines.cpp.

#include "bad_input_support.h"
#include "scratch_path.h"

#include <CGAL/Tangent_vector_fields/N_field_basis.h>
#include <CGAL/Tangent_vector_fields/Spectral_basis.h>

#include <cstdio>
#include <limits>

using namespace bad_input;

namespace {

typedef TVF::Spectral_basis<Mesh> Basis;
typedef Mesh::Property_map<Face_index, Vector_3> Field;

// The basis is right for the topology counted on the mesh: harmonic count 2g + b - 1
// per component with boundary (2g closed), eigenvalues finite, >= 0 and ascending,
// eigenfields finite and MX-orthonormal.
void expect_sound_basis(const Basis& basis, int expected_harmonic, double max_residual = 1e-8)
{
  const TVF::Eigenfield_basis& b = basis.basis();
  EXPECT_EQ(b.number_of_harmonic(), expected_harmonic);
  ASSERT_TRUE(b.eigenvalues().allFinite());
  for(int k = 0; k < b.size(); ++k)
  {
    EXPECT_GE(b.eigenvalue(k), k < expected_harmonic ? 0. : 1e-12 * b.eigenvalues().maxCoeff()) << k;
    if(k > 0) EXPECT_GE(b.eigenvalue(k), b.eigenvalue(k - 1) * (1 - 1e-12)) << k;
  }
  Eigen::MatrixXd U(2 * basis.operators().intrinsic_mesh().number_of_faces(), b.size());
  for(int k = 0; k < b.size(); ++k) U.col(k) = b.eigenfield(k);
  ASSERT_TRUE(U.allFinite());
  const Eigen::VectorXd& mx = basis.operators().shared_matrices()->field_masses();
  const Eigen::MatrixXd gram = U.transpose() * mx.asDiagonal() * U;
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(b.size(), b.size())).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_LT(b.report().max_residual, max_residual);
}

// Harmonic dimension from the counts made by the test (one component).
int harmonic_of(const Mesh& mesh)
{
  const auto [chi, b] = euler_and_boundary_loops(mesh);
  // chi = 2 - 2g - b.
  const int g = (2 - b - chi) / 2;
  return b == 0 ? 2 * g : 2 * g + b - 1;
}

} // namespace

TEST(BadBasis, EmptyMeshAndNonFiniteCoordinatesAreRefused)
{
  Mesh empty;
  expect_defect(TVF::Mesh_defect::empty, [&] { Basis b(empty, TVF::parameters::number_of_eigenfields(4)); });
  Mesh mesh = make_icosphere(1);
  mesh.point(Vertex_index(7)) = Point_3(std::numeric_limits<double>::infinity(), 0, 0);
  expect_defect(TVF::Mesh_defect::non_finite_coordinate,
                [&] { Basis b(mesh, TVF::parameters::number_of_eigenfields(4)); }, "vertex 7");
}

TEST(BadBasis, ZeroAreaFaceIsRefusedUnlessMollified)
{
  // Vertex 0 of the fan moved onto the midpoint of edge 1-2: face 0 has area 0.
  Mesh mesh = make_disk(3);
  const auto h = mesh.halfedge(Face_index(0));
  const Vertex_index a = mesh.source(h), b = mesh.target(h), c = mesh.target(mesh.next(h));
  mesh.point(c) = CGAL::midpoint(mesh.point(a), mesh.point(b));
  expect_defect(TVF::Mesh_defect::degenerate_face, [&] { Basis x(mesh, TVF::parameters::number_of_eigenfields(6)); },
                "use_intrinsic_mollification");
  const Basis basis(mesh, TVF::parameters::number_of_eigenfields(6).use_intrinsic_mollification(true));
  expect_sound_basis(basis, 0);
}

TEST(BadBasis, SingleTriangleHasTwoExactFieldsAndNoMore)
{
  // nv = 3, no interior edge, a disk: the space of 2 fields is spanned by 2 exact ones.
  const Mesh mesh = single_triangle();
  const Basis basis(mesh, TVF::parameters::number_of_eigenfields(2));
  EXPECT_EQ(basis.basis().number_of_exact(), 2);
  EXPECT_EQ(basis.basis().number_of_coexact(), 0);
  expect_sound_basis(basis, 0);
  expect_error<TVF::Invalid_input>([&] { Basis b(mesh, TVF::parameters::number_of_eigenfields(3)); }, "2");
  expect_error<TVF::Invalid_input>([&] { Basis b(mesh, TVF::parameters::number_of_coexact_eigenfields(1)); },
                                   "coexact");
}

TEST(BadBasis, RequestsOfImpossibleSizeAreRefused)
{
  const Mesh mesh = make_icosphere(1); // 80 faces, 160 fields
  expect_error<TVF::Invalid_input>([&] { Basis b(mesh, TVF::parameters::number_of_eigenfields(-1)); }, "-1");
  expect_error<TVF::Invalid_input>([&] { Basis b(mesh, TVF::parameters::number_of_eigenfields(161)); }, "160");
  expect_error<TVF::Invalid_input>(
      [&] { Basis b(mesh, TVF::parameters::number_of_eigenfields(std::numeric_limits<int>::max())); }, "160");
  expect_error<TVF::Invalid_input>([&] { Basis b(mesh, TVF::parameters::number_of_exact_eigenfields(-2)); }, "-2");
  for(double tol : {0., -1e-10, std::nan(""), 1.5})
    expect_error<TVF::Invalid_input>(
        [&] { Basis b(mesh, TVF::parameters::number_of_eigenfields(4).eigensolver_tolerance(tol)); }, "tolerance");
  expect_error<TVF::Invalid_input>(
      [&] { Basis b(mesh, TVF::parameters::maximum_eigenvalue(std::numeric_limits<double>::infinity())); },
      "eigenvalue");
}

TEST(BadBasis, EmptyRequestsGiveAnEmptyBasisThatStillTransforms)
{
  // Size 0: a valid empty basis; a field is all rest, and filtering keeps exactly the rest
  // factor times it.  A negative eigenvalue bound is no request at all.
  Mesh mesh = make_icosphere(1);
  expect_error<TVF::Invalid_input>([&] { Basis b(mesh, TVF::parameters::maximum_eigenvalue(-1.)); },
                                   "must be finite and non-negative");
  {
    const Basis basis(mesh, TVF::parameters::number_of_eigenfields(0));
    EXPECT_EQ(basis.size(), 0);
    const Eigen::VectorXd v = random_field(mesh.number_of_faces(), 3);
    EXPECT_EQ(basis.basis().coefficients(v).size(), 0);
    EXPECT_LT((basis.basis().rest(v) - v).norm(), 1e-14 * v.norm());
    TVF::Spectral_filter half;
    half.rest_factor = 0.5;
    EXPECT_LT((basis.basis().filter(v, half) - 0.5 * v).norm(), 1e-14 * v.norm());
  }
}

TEST(BadBasis, AwkwardTopologiesGiveTheHarmonicCountOfTheirTopology)
{
  // Every vertex on the boundary (an annulus band and an open strip), high genus (a slab
  // with 3 holes), genus 0 plus a component 1e-6 as large: harmonic count 2g + b - 1 from
  // the counts made here, eigenvalues >= 0.
  const Mesh band = boundary_only_band(12), strip = boundary_only_strip(10), slab = holed_slab(7, 3);
  EXPECT_EQ(harmonic_of(band), 1);
  EXPECT_EQ(harmonic_of(strip), 0);
  EXPECT_EQ(harmonic_of(slab), 6);
  for(const Mesh* mesh : {&band, &strip, &slab})
  {
    SCOPED_TRACE(mesh->number_of_faces());
    const int h = harmonic_of(*mesh);
    const Basis basis(*mesh, TVF::parameters::number_of_eigenfields(h + 10));
    expect_sound_basis(basis, h);
    EXPECT_EQ(basis.basis().report().exact_inertia, basis.basis().report().exact_expected);
  }
  const Mesh pair = sphere_with_tiny_companion(1e-6);
  const Basis basis(pair, TVF::parameters::number_of_eigenfields(30));
  expect_sound_basis(basis, 0);
  // The lowest fields live on the big sphere: eigenvalues of the tiny one are 1e12 larger.
  EXPECT_LT(basis.eigenvalue(29), 100);
}

TEST(BadBasis, NeedlesCapsAndLonelyVerticesGiveAccurateBases)
{
  // A needle (short edge 1e-7 of the others) and a lonely vertex: extreme but valid.
  Mesh mesh = make_disk(4);
  const auto h = mesh.halfedge(Face_index(5));
  const Vertex_index a = mesh.source(h), b = mesh.target(h);
  mesh.point(b) = mesh.point(a) + 1e-7 * (mesh.point(b) - mesh.point(a));
  const Vertex_index lonely = mesh.add_vertex(Point_3(9, 9, 9));
  const Basis basis(mesh, TVF::parameters::number_of_eigenfields(20));
  // Cotangents of 1e7 at the needle: the residual's roundoff floor is eps 1e7 / lambda.
  expect_sound_basis(basis, 0, 1e-6);
  EXPECT_EQ(basis.basis().exact_eigenfunctions().to_double().row(static_cast<int>(lonely)).norm(), 0.);
}

TEST(BadBasis, BadFieldsAndArgumentsOfTransformsAreRefused)
{
  Mesh mesh = make_torus(10, 6);
  const Basis basis(mesh, TVF::parameters::number_of_eigenfields(12));
  const TVF::Eigenfield_basis& b = basis.basis();
  const int nf = mesh.number_of_faces();
  Eigen::VectorXd v = random_field(nf, 1);
  Eigen::VectorXd nan_field = v;
  nan_field[7] = std::nan("");
  expect_error<TVF::Invalid_input>([&] { b.coefficients(nan_field); }, "non-finite");
  expect_error<TVF::Invalid_input>([&] { b.coefficients(Eigen::VectorXd(v.head(2 * nf - 2))); }, "frame coordinates");
  expect_error<TVF::Invalid_input>([&] { b.rest(nan_field); }, "non-finite");
  expect_error<TVF::Invalid_input>([&] { b.field(Eigen::VectorXd::Ones(13)); }, "13");
  Eigen::VectorXd a = Eigen::VectorXd::Ones(12);
  a[3] = HUGE_VAL;
  expect_error<TVF::Invalid_input>([&] { b.field(a); }, "non-finite");
  expect_error<TVF::Invalid_input>([&] { b.eigenfield(12); }, "12");
  expect_error<TVF::Invalid_input>([&] { b.eigenfield(-1); }, "-1");
  expect_error<TVF::Invalid_input>([&] { b.dirichlet_energy(Eigen::VectorXd::Ones(13)); }, "13");
  expect_error<TVF::Invalid_input>([&] { b.biharmonic_energy(a); }, "non-finite");
  expect_error<TVF::Invalid_input>([&] { b.band_energies(b.coefficients(v), {2, 1}); }, "ascending");
  expect_error<TVF::Invalid_input>([&] { b.band_energies(b.coefficients(v), {0, std::nan(""), 9}); }, "ascending");
  // Compression to more coefficients than the basis has, or fewer than none; fields with
  // NaN.  Keeping none is valid: nothing is kept, each field is all error.
  Eigen::MatrixXd fields(2 * nf, 2);
  fields << v, 2 * v;
  expect_error<TVF::Invalid_input>([&] { b.compress(fields, 13); }, "13");
  expect_error<TVF::Invalid_input>([&] { b.compress(fields, -1); }, "-1");
  const TVF::Compressed_fields none = b.compress(fields, 0);
  EXPECT_EQ(none.coefficients.rows(), 0);
  EXPECT_DOUBLE_EQ(none.relative_errors[0], 1.);
  EXPECT_DOUBLE_EQ(none.relative_errors[1], 1.);
  fields(3, 1) = std::nan("");
  expect_error<TVF::Invalid_input>([&] { b.compress(fields, 4); }, "non-finite");
  // A field with a large normal component: the basis sees its tangent part only.
  Field tangent = field_map(mesh, "tangent"), lifted = field_map(mesh, "lifted");
  for(Face_index f : mesh.faces())
  {
    const auto& n = basis.operators().intrinsic_mesh().normal(static_cast<int>(f));
    const Vector_3 normal(n[0], n[1], n[2]), w(1, 2, 3);
    tangent[f] = w - (w * normal) * normal;
    lifted[f] = tangent[f] + 50 * normal;
  }
  const Eigen::VectorXd ct = basis.coefficients(tangent), cl = basis.coefficients(lifted);
  EXPECT_LT((ct - cl).norm(), 1e-12 * ct.norm());
  EXPECT_GT(ct.norm(), 0.);
  // A field map with a NaN vector, through the generic interface: the output is untouched.
  Field in = field_map(mesh, "in", Vector_3(1, 0, 0)), out = field_map(mesh, "out", Vector_3(7, 7, 7));
  in[Face_index(4)] = Vector_3(0, std::nan(""), 0);
  expect_error<TVF::Invalid_input>([&] { basis.filter(in, TVF::Spectral_filter::low_pass(0.1), out); },
                                   "non-finite");
  for(Face_index f : mesh.faces()) EXPECT_EQ(out[f], Vector_3(7, 7, 7));
}

TEST(BadBasis, FiltersThatWouldMakeNonFiniteFieldsAreRefused)
{
  // A negative diffusion time blows the high frequencies up past the doubles; a NaN time
  // or factor is no filter: either would write NaN or infinity into the output.
  Mesh mesh = make_icosphere(2);
  const Basis basis(mesh, TVF::parameters::number_of_eigenfields(40));
  const Eigen::VectorXd v = random_field(mesh.number_of_faces(), 2);
  for(const TVF::Spectral_filter& f : {TVF::Spectral_filter::low_pass(std::nan("")),
                                      TVF::Spectral_filter::low_pass(-1e6)})
    expect_error<TVF::Invalid_input>([&] { basis.basis().filter(v, f); }, "filter");
  // The sphere has no harmonic field, and 40 elements leave a rest: bad factors are
  // refused whether or not they would touch the field.
  for(int which : {0, 1})
  {
    TVF::Spectral_filter bad_factor;
    (which == 0 ? bad_factor.harmonic_factor : bad_factor.rest_factor) = std::nan("");
    expect_error<TVF::Invalid_input>([&] { basis.basis().filter(v, bad_factor); }, "factors must be finite");
  }
  // Finite factors of 1e300 on a field of size 1e10 overflow (in the coefficients or in
  // the sum, whichever comes first): refused, not written as infinities.
  TVF::Spectral_filter huge = TVF::Spectral_filter::from_transfer([](double) { return 1e300; });
  huge.rest_factor = 1e300;
  const Eigen::VectorXd big = 1e10 * v;
  expect_error<TVF::Invalid_input>([&] { basis.basis().filter(big, huge); }, "finite");
  // An extreme but finite sharpening stays finite and multiplies the coefficients exactly.
  const Eigen::VectorXd w = basis.basis().filter(v, TVF::Spectral_filter::high_pass(1));
  ASSERT_TRUE(w.allFinite());
  const Eigen::VectorXd a = basis.basis().coefficients(v), c = basis.basis().coefficients(w);
  for(int k = 0; k < basis.size(); ++k)
    EXPECT_NEAR(c[k], a[k] * (2 - std::exp(-basis.eigenvalue(k))), 1e-9 * a.norm()) << k;
}

TEST(BadBasis, SavingToAnUnwritablePathAndLoadingGarbageAreClearErrors)
{
  const Mesh mesh = make_icosphere(1);
  const Basis basis(mesh, TVF::parameters::number_of_eigenfields(6));
  expect_error<TVF::Invalid_input>([&] { basis.save("/nonexistent-folder/basis.tvfb"); }, "/nonexistent-folder");
  const std::string path = scratch_path("bad_basis_garbage.tvfb");
  {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    std::fputs("TVFB but not really a basis file at all", f);
    std::fclose(f);
  }
  expect_error<TVF::Invalid_input>([&] { Basis::load(mesh, path); }, path);
  std::remove(path.c_str());
}

TEST(BadBasis, NFieldBasisOfImpossibleSizesIsRefused)
{
  const Mesh mesh = make_icosphere(1);
  const auto matrices = TVF::Discrete_operators<Mesh>(mesh).shared_matrices();
  auto ops = std::make_shared<const TVF::N_field_operators>(matrices, 4);
  expect_error<TVF::Invalid_input>([&] { TVF::N_field_basis b(ops, -2); }, "asked for -2 elements");
  expect_error<TVF::Invalid_input>([&] { TVF::N_field_basis b(ops, 0); }, "asked for 0 elements");
  expect_error<TVF::Invalid_input>([&] { TVF::N_field_basis b(ops, 161); }, "dimension 160");
  // INT_MAX is odd: rounding it up to a pair must not wrap around past the size check.
  expect_error<TVF::Invalid_input>([&] { TVF::N_field_basis b(ops, std::numeric_limits<int>::max()); },
                                   "dimension 160");
  expect_error<TVF::Invalid_input>([&] { TVF::N_field_basis b(nullptr, 4); }, "no operators");
  TVF::Basis_options nan_tolerance;
  nan_tolerance.tolerance = std::nan("");
  expect_error<TVF::Invalid_input>([&] { TVF::N_field_basis b(ops, 4, nan_tolerance); }, "tolerance");
  // An odd size is rounded up to the pair (z, iz): eigenvalues >= 0, MX-orthonormal fields.
  const TVF::N_field_basis odd(ops, 5);
  EXPECT_EQ(odd.size(), 6);
  ASSERT_TRUE(odd.fields().allFinite());
  for(int k = 0; k < odd.size(); ++k) EXPECT_GE(odd.eigenvalue(k), 0);
  const Eigen::MatrixXd gram = odd.fields().transpose() * ops->masses().asDiagonal() * odd.fields();
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(6, 6)).cwiseAbs().maxCoeff(), 1e-8);
  // Transforms refuse what they cannot represent.
  Eigen::VectorXd z = Eigen::VectorXd::Ones(160);
  z[1] = std::nan("");
  expect_error<TVF::Invalid_input>([&] { odd.coefficients(z); }, "non-finite");
  expect_error<TVF::Invalid_input>([&] { odd.field(Eigen::VectorXd::Ones(7)); }, "7 coefficients");
  expect_error<TVF::Invalid_input>([&] { odd.energy(Eigen::VectorXd::Ones(7), 2); }, "7 coefficients");
  expect_error<TVF::Invalid_input>([&] { odd.energy(Eigen::VectorXd::Ones(6), 0); }, "m must be at least 1");
}
