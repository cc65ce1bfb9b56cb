// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Spectral basis files (.tvfb): save, and a load that refuses what is not a basis.

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/internal/basis_file.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <utility>

namespace CGAL {
namespace Tangent_vector_fields {

namespace {

const char file_magic[8] = {'T', 'V', 'F', 'B', 'A', 'S', 'I', 'S'};
// 2: eigenfunctions in double or float32 (a precision byte); 3: the mesh identity read from each
// face's smallest corner (`legacy_mesh_identity` before)
const std::uint32_t file_version = 3;

// The squared MX norms of the columns of `A F` scaled by 1 / values, a few columns at a time
// (a basis of many elements on a large mesh would not fit at once).
Eigen::VectorXd squared_field_norms(const Eigen::SparseMatrix<double>& A, const Eigenfunction_matrix& F,
                                    const Eigen::VectorXd& values, const Eigen::VectorXd& masses)
{
  Eigen::VectorXd norms(F.cols());
  const Eigen::Index block = 32;
  for(Eigen::Index j = 0; j < F.cols(); j += block)
  {
    const Eigen::Index b = std::min(block, F.cols() - j);
    const Eigen::MatrixXd fields = A * F.columns(j, b);
    for(Eigen::Index c = 0; c < b; ++c) norms[j + c] = fields.col(c).cwiseAbs2().dot(masses) / values[j + c];
  }
  return norms;
}

} // namespace

void Eigenfield_basis::save(const std::string& path) const
{
  using internal::write_matrix;
  using internal::write_value;
  std::ofstream out(path, std::ios::binary);
  if(!out) throw Invalid_input("cannot write the spectral basis to '" + path + "'");
  const Intrinsic_mesh& mesh = operators().mesh();
  internal::write_header(out, file_magic, file_version, internal::mesh_identity(mesh));
  write_matrix(out, exact_values_);
  exact_functions_.write(out);
  write_matrix(out, coexact_values_);
  coexact_functions_.write(out);
  write_matrix(out, harmonic_);
  write_value<std::int64_t>(out, size());
  for(const Element& e : order_)
  {
    write_value<std::uint8_t>(out, static_cast<std::uint8_t>(e.type));
    write_value<std::int32_t>(out, e.index);
  }
  const Basis_report& r = report_;
  for(double x : {r.max_residual, r.exact_complete_below, r.coexact_complete_below, r.exact_seconds,
                  r.coexact_seconds, r.harmonic_seconds})
    write_value(out, x);
  for(int x : {r.exact_inertia, r.exact_expected, r.coexact_inertia, r.coexact_expected})
    write_value<std::int32_t>(out, x);
  write_value(out, file_magic);
  if(!out) throw Invalid_input("writing the spectral basis to '" + path + "' failed");
}

Eigenfield_basis Eigenfield_basis::load(std::shared_ptr<const Hodge_solver> solver, const std::string& path)
{
  Eigenfield_basis basis(std::move(solver));
  std::uint64_t bytes = 0;
  std::ifstream in = internal::open_binary_file(path, "spectral basis", bytes);
  internal::Binary_reader r(in, path, bytes, "spectral basis");
  const Intrinsic_mesh& mesh = basis.operators().mesh();
  const std::uint32_t version = r.expect_header(file_magic, 1, file_version, [&](std::uint32_t v) {
    return v < 3 ? internal::legacy_mesh_identity(mesh) : internal::mesh_identity(mesh);
  });
  const Eigen::Index nv = mesh.number_of_vertices(), ne = mesh.number_of_interior_edges(), nf = mesh.number_of_faces();
  basis.exact_values_ = r.matrix(-1, 1, "exact eigenvalues");
  auto functions = [&](Eigen::Index rows, Eigen::Index cols, const char* what) {
    // Version 1 stored double eigenfunctions without a precision byte.
    return version == 1 ? Eigenfunction_matrix(r.matrix(rows, cols, what)) : Eigenfunction_matrix::read(r, rows, cols, what);
  };
  basis.exact_functions_ = functions(nv, basis.exact_values_.size(), "exact eigenfunctions");
  basis.coexact_values_ = r.matrix(-1, 1, "coexact eigenvalues");
  basis.coexact_functions_ = functions(ne, basis.coexact_values_.size(), "coexact eigenfunctions");
  basis.harmonic_ = r.matrix(2 * nf, -1, "harmonic fields");
  const std::int64_t count = r.value<std::int64_t>();
  if(count < 0 || count > basis.number_of_harmonic() + basis.number_of_exact() + basis.number_of_coexact())
    r.fail("inconsistent element count");
  for(std::int64_t k = 0; k < count; ++k)
  {
    const std::uint8_t type = r.value<std::uint8_t>();
    const std::int32_t index = r.value<std::int32_t>();
    const int available = type == 0 ? basis.number_of_harmonic() : type == 1 ? basis.number_of_exact()
                        : type == 2 ? basis.number_of_coexact() : -1;
    if(index < 0 || index >= available) r.fail("inconsistent element table");
    basis.order_.push_back({static_cast<Eigenfield_type>(type), index});
  }
  Basis_report& rep = basis.report_;
  for(double* x : {&rep.max_residual, &rep.exact_complete_below, &rep.coexact_complete_below, &rep.exact_seconds,
                   &rep.coexact_seconds, &rep.harmonic_seconds})
    *x = r.value<double>();
  for(int* x : {&rep.exact_inertia, &rep.exact_expected, &rep.coexact_inertia, &rep.coexact_expected})
    *x = r.value<std::int32_t>();
  r.expect_magic(file_magic, "the file is corrupt (no end marker)");
  basis.update_values();
  if(!basis.values_.allFinite() || !basis.exact_functions_.all_finite() || !basis.coexact_functions_.all_finite() ||
     !basis.harmonic_.allFinite())
    r.fail("the file holds non-finite numbers");
  basis.check_loaded(r);
  return basis;
}

void Eigenfield_basis::check_loaded(Model_reduction::internal::Binary_reader& r) const
{
  // The exact and coexact eigenvalues are divided by their square roots: positive.
  if(exact_values_.size() > 0 && !(exact_values_.minCoeff() > 0)) r.fail("an exact eigenvalue is not positive");
  if(coexact_values_.size() > 0 && !(coexact_values_.minCoeff() > 0)) r.fail("a coexact eigenvalue is not positive");
  std::set<std::pair<int, int>> listed;
  for(int k = 0; k < size(); ++k)
  {
    if(!listed.insert({static_cast<int>(order_[k].type), order_[k].index}).second)
      r.fail("element " + std::to_string(k) + " is listed twice");
    if(k > 0 && values_[k] < values_[k - 1]) r.fail("the elements are not in increasing order of eigenvalue");
  }
  // Every element of unit norm in MX (as computed, to roundoff): a corrupt number in an
  // eigenfunction or a harmonic field changes it.  One sparse product per element, as for
  // the coefficients of one field.
  const Operator_matrices& ops = operators();
  const Vector& masses = ops.field_masses();
  const Vector norms[3] = {harmonic_.cwiseAbs2().transpose() * masses,
                           squared_field_norms(ops.G(), exact_functions_, exact_values_, masses),
                           squared_field_norms(ops.G_star_interior(), coexact_functions_, coexact_values_, masses)};
  for(int k = 0; k < size(); ++k)
  {
    const double norm = norms[static_cast<int>(order_[k].type)][order_[k].index];
    if(!(std::abs(norm - 1) <= 1e-6))
      r.fail("element " + std::to_string(k) + " has norm " + std::to_string(std::sqrt(norm)) +
             " instead of 1 (the file is corrupt)");
  }
}

} // namespace Tangent_vector_fields
} // namespace CGAL
