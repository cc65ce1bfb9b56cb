// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/N_field_basis.h>
#include <CGAL/Model_reduction/Generalized_eigensolver.h>
#include <CGAL/Model_reduction/internal/huge_pages.h>
#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/internal/basis_file.h>
#include <CGAL/Tangent_vector_fields/internal/scalar_eigenproblem.h>

#include <chrono>
#include <cmath>
#include <complex>
#include <fstream>

namespace CGAL {
namespace Tangent_vector_fields {

namespace {

const char file_magic[8] = {'T', 'V', 'F', 'N', 'F', 'I', 'E', 'L'};
// 2: the prescribed singularities of the connection; 3: the mesh identity read from each face's
// smallest corner (`legacy_mesh_identity` before)
const std::uint32_t file_version = 3;

double total_area(const Intrinsic_mesh& mesh)
{
  double area = 0;
  for(int f = 0; f < mesh.number_of_faces(); ++f) area += mesh.face_area(f);
  return area;
}

// The real layout of n-fields (face f at rows 2f, 2f + 1: real and imaginary part) is the
// memory layout of an array of std::complex<double>: a field is either, without a copy.
Eigen::Map<const Eigen::VectorXcd> as_complex(const Eigen::Ref<const Eigen::VectorXd>& z)
{
  return Eigen::Map<const Eigen::VectorXcd>(reinterpret_cast<const std::complex<double>*>(z.data()), z.size() / 2);
}
Eigen::Map<const Eigen::VectorXd> as_real(const Eigen::Ref<const Eigen::VectorXcd>& z)
{
  return Eigen::Map<const Eigen::VectorXd>(reinterpret_cast<const double*>(z.data()), 2 * z.size());
}

} // namespace

N_field_basis::N_field_basis(std::shared_ptr<const N_field_operators> operators) : operators_(std::move(operators))
{
  if(!operators_) throw Invalid_input("n-field basis: no operators given");
}

N_field_basis::N_field_basis(std::shared_ptr<const N_field_operators> operators, int count,
                             const Basis_options& options)
  : N_field_basis(std::move(operators))
{
  const auto start = std::chrono::steady_clock::now();
  const N_field_operators& ops = *operators_;
  const int dimension = static_cast<int>(ops.masses().size());
  if(count < 1) throw Invalid_input("n-field basis: asked for " + std::to_string(count) + " elements");
  // Checked before rounding up to a pair: ++INT_MAX would overflow past the check.
  if(count > dimension)
    throw Invalid_input("n-field basis: asked for " + std::to_string(count) + " elements but the space has dimension " +
                        std::to_string(dimension));
  if(count % 2) ++count; // the dimension 2 nf is even
  const Matrix& kernel = ops.kernel();
  kernel_dimension_ = static_cast<int>(std::min<Eigen::Index>(kernel.cols(), count));
  const int wanted = count - kernel_dimension_;

  // The problem on the mesh scaled to unit area: S_n does not change, the masses do.
  const double area = total_area(ops.mesh());
  Model_reduction::Eigensolver_options eigen_options = internal::eigensolver_options(options);
  if(options.progress)
    eigen_options.progress = [&](const Model_reduction::Eigensolver_progress& e) {
      const double f = e.wanted > 0 ? std::min(1., double(e.converged) / e.wanted) : 1.;
      options.progress({"n-field eigenpairs", f});
    };
  // S_n commutes with J (z -> i z per face): in its real form every eigenvalue comes twice,
  // (phi, J phi).  The complex form (Hermitian, nf x nf) has each once, with half the
  // unknowns: half the vectors to find and orthogonalise, a quarter of the entries to factor.
  // Its mass per face is the real form's mass of either of the face's two rows.
  const Vector unit_mass = ops.masses() / area;
  const Eigen::Index nf = unit_mass.size() / 2;
  const Vector face_mass = Eigen::Map<const Vector, 0, Eigen::InnerStride<2>>(unit_mass.data(), nf);
  // One complex column per pair (p, J p) of the kernel.
  Eigen::MatrixXcd complex_kernel(nf, kernel.cols() / 2);
  for(Eigen::Index j = 0; j < complex_kernel.cols(); ++j) complex_kernel.col(j) = as_complex(kernel.col(2 * j));
  const int pairs_wanted = wanted / 2; // wanted is even: count is, and the kernel comes in pairs
  Model_reduction::Complex_eigenpairs pairs =
      Model_reduction::lowest_eigenpairs(ops.complex_S(), face_mass, pairs_wanted, complex_kernel, eigen_options);

  fields_.resize(dimension, count);
  values_.resize(count);
  const double scale = 1 / std::sqrt(area); // unit-area MX-orthonormal -> MX-orthonormal
  fields_.leftCols(kernel_dimension_) = kernel.leftCols(kernel_dimension_);
  values_.head(kernel_dimension_).setZero();
  // Each complex eigenvector z gives the real pair (z, i z): MX-orthonormal, since the real
  // inner product of two fields is the real part of their Hermitian one.
  for(int k = 0; k < pairs_wanted; ++k)
  {
    const Eigen::Index column = kernel_dimension_ + 2 * k;
    fields_.col(column) = as_real(pairs.vectors.col(k)) * scale;
    fields_.col(column + 1) = Operator_matrices::rotate(fields_.col(column));
    values_[column] = values_[column + 1] = pairs.values[k] / area;
    // Each complex vector's pages go back once converted: the fields take twice its memory, and
    // with all of both held the peak was 527 MB instead of 375 MB (rocker arm, 1,000 elements).
    Model_reduction::internal::discard_pages(pairs.vectors.col(k).data(), sizeof(std::complex<double>) * nf);
  }

  report_.max_residual = pairs.residuals.size() ? pairs.residuals.maxCoeff() : 0.;
  report_.complete_below = pairs.complete_below / area;
  // Counted in the real form, where each complex eigenvalue (and kernel column) is two.
  report_.inertia = 2 * pairs.completeness.inertia;
  report_.expected = 2 * pairs.completeness.expected;
  report_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

N_field_basis::Vector N_field_basis::coefficients(const Vector& z) const
{
  if(z.size() != fields_.rows())
    throw Invalid_input("n-field basis: the field has " + std::to_string(z.size()) + " values, the basis " +
                        std::to_string(fields_.rows()));
  if(!z.allFinite()) throw Invalid_input("n-field basis: the field has non-finite entries");
  return fields_.transpose() * operators_->masses().cwiseProduct(z);
}

N_field_basis::Vector N_field_basis::field(const Vector& a) const
{
  if(a.size() > size())
    throw Invalid_input("n-field basis: " + std::to_string(a.size()) + " coefficients for a basis of " +
                        std::to_string(size()));
  if(!a.allFinite()) throw Invalid_input("n-field basis: the coefficients have non-finite entries");
  return fields_.leftCols(a.size()) * a;
}

double N_field_basis::energy(const Vector& a, int m) const
{
  if(m < 1) throw Invalid_input("n-field basis energy: m must be at least 1");
  if(a.size() > size())
    throw Invalid_input("n-field basis energy: " + std::to_string(a.size()) + " coefficients for a basis of " +
                        std::to_string(size()));
  double e = 0;
  for(Eigen::Index k = 0; k < a.size(); ++k) e += std::pow(values_[k], m) * a[k] * a[k];
  return e;
}

void N_field_basis::save(const std::string& path) const
{
  using internal::write_matrix;
  using internal::write_value;
  std::ofstream out(path, std::ios::binary);
  if(!out) throw Invalid_input("cannot write the n-field basis to '" + path + "'");
  internal::write_header(out, file_magic, file_version, internal::mesh_identity(operators_->mesh()));
  write_value<std::int32_t>(out, n());
  write_value<std::int32_t>(out, static_cast<std::int32_t>(operators_->options().boundary));
  // The connection: a basis of another set of prescribed singularities spans other fields.
  const auto& singularities = operators_->options().singularities;
  write_value<std::int32_t>(out, static_cast<std::int32_t>(singularities.size()));
  for(const auto& [v, k] : singularities)
  {
    write_value<std::int32_t>(out, v);
    write_value<std::int32_t>(out, k);
  }
  write_value<std::int32_t>(out, kernel_dimension_);
  write_matrix(out, values_);
  write_matrix(out, fields_);
  for(double x : {report_.max_residual, report_.complete_below, report_.seconds}) write_value(out, x);
  for(int x : {report_.inertia, report_.expected}) write_value<std::int32_t>(out, x);
  out.write(file_magic, sizeof(file_magic));
  if(!out) throw Invalid_input("writing the n-field basis to '" + path + "' failed");
}

N_field_basis N_field_basis::load(std::shared_ptr<const N_field_operators> operators, const std::string& path)
{
  N_field_basis basis(std::move(operators));
  std::uint64_t bytes = 0;
  std::ifstream in = internal::open_binary_file(path, "n-field basis", bytes);
  internal::Binary_reader r(in, path, bytes, "n-field basis");
  const N_field_operators& ops = basis.operators();
  r.expect_header(file_magic, 2, file_version, [&](std::uint32_t v) {
    return v < 3 ? internal::legacy_mesh_identity(ops.mesh()) : internal::mesh_identity(ops.mesh());
  });
  const std::int32_t n = r.value<std::int32_t>();
  if(n != ops.n()) r.fail("it holds " + std::to_string(n) + "-fields, not " + std::to_string(ops.n()) + "-fields");
  if(r.value<std::int32_t>() != static_cast<std::int32_t>(ops.options().boundary))
    r.fail("it was computed with another boundary condition");
  const std::int32_t count = r.value<std::int32_t>();
  if(count < 0 || count > ops.mesh().number_of_vertices()) r.fail("the file is corrupt (singularity count)");
  std::vector<std::pair<int, int>> singularities(count);
  for(auto& [v, k] : singularities)
  {
    v = r.value<std::int32_t>();
    k = r.value<std::int32_t>();
  }
  if(singularities != ops.options().singularities)
    r.fail("it was computed for a connection with " + std::to_string(count) +
           " prescribed singularities, not these " + std::to_string(ops.options().singularities.size()) +
           " (a basis belongs to one set of prescribed singularities)");
  basis.kernel_dimension_ = r.value<std::int32_t>();
  basis.values_ = r.matrix(-1, 1, "eigenvalues");
  basis.fields_ = r.matrix(ops.masses().size(), basis.values_.size(), "eigenfields");
  if(basis.kernel_dimension_ < 0 || basis.kernel_dimension_ > basis.size()) r.fail("inconsistent kernel dimension");
  N_field_basis_report& rep = basis.report_;
  for(double* x : {&rep.max_residual, &rep.complete_below, &rep.seconds}) *x = r.value<double>();
  for(int* x : {&rep.inertia, &rep.expected}) *x = r.value<std::int32_t>();
  r.expect_magic(file_magic, "the file is corrupt (no end marker)");
  if(!basis.values_.allFinite() || !basis.fields_.allFinite()) r.fail("the file holds non-finite numbers");
  // A basis comes in pairs (z, i z), each element of unit norm in the masses (as computed, to
  // roundoff): a corrupt number in a field changes its norm (as Eigenfield_basis::load checks).
  if(basis.size() % 2 != 0) r.fail("an odd number of elements (they come in pairs z, i z)");
  const Vector& masses = ops.masses();
  for(int k = 0; k < basis.size(); ++k)
  {
    const double norm = basis.fields_.col(k).cwiseAbs2().dot(masses);
    if(!(std::abs(norm - 1) <= 1e-6))
      r.fail("element " + std::to_string(k) + " has norm " + std::to_string(std::sqrt(norm)) +
             " instead of 1 (the file is corrupt)");
  }
  return basis;
}

} // namespace Tangent_vector_fields
} // namespace CGAL
