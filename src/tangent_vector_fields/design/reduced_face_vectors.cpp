// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The reduced field face by face: the eigenfields' rows of each face in one block.

#include <CGAL/Tangent_vector_fields/Reduced_face_vectors.h>
#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/internal/Basis_rows.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>


namespace CGAL {
namespace Tangent_vector_fields {

Eigenfield_rows::Eigenfield_rows(std::shared_ptr<const Eigenfield_basis> basis, int d, Eigenfunction_precision precision)
  : basis_(std::move(basis)), precision_(precision)
{
  if(!basis_) throw Invalid_input("eigenfield rows: no basis given");
  d_ = internal::checked_basis_size(*basis_, d);
  nf_ = basis_->operators().mesh().number_of_faces();
  const bool single = precision_ == Eigenfunction_precision::float32;
  const std::size_t count = std::size_t(2) * nf_ * d_;
  bytes_ = count * (single ? sizeof(float) : sizeof(double));
  // Mapped from the system with 2 MB pages where granted (a face read in random order then costs
  // no page walk), and given back at once when the rows go.
  if(single) rows32_ = std::make_unique<Model_reduction::internal::Mapped_array<float>>(count);
  else rows64_ = std::make_unique<Model_reduction::internal::Mapped_array<double>>(count);
  void* const data = single ? static_cast<void*>(rows32_->data()) : static_cast<void*>(rows64_->data());
  // The eigenfields of each type a block of eigenfunctions at a time (as Eigenfield_basis::decompress
  // makes them: G phi / sqrt(lambda), J G* psi / sqrt(mu), the harmonic fields), each written into
  // the faces' blocks at its position k in the basis: face f holds row 2f, then row 2f + 1.
  const Operator_matrices& ops = basis_->operators();
  std::vector<int> exact_position(basis_->number_of_exact(), -1), coexact_position(basis_->number_of_coexact(), -1);
  Eigen::Index exact_used = 0, coexact_used = 0;
  for(int k = 0; k < d_; ++k)
  {
    const int i = basis_->index_in_type(k);
    if(basis_->type(k) == Eigenfield_type::exact) exact_position[i] = k, exact_used = std::max<Eigen::Index>(exact_used, i + 1);
    if(basis_->type(k) == Eigenfield_type::coexact)
      coexact_position[i] = k, coexact_used = std::max<Eigen::Index>(coexact_used, i + 1);
  }
  // Row by row (a row's entries lie within one block of memory), not field by field.
  auto store = [&](const Eigen::MatrixXd& fields, const std::vector<int>& positions) {
    for(Eigen::Index r = 0; r < fields.rows(); ++r)
      for(Eigen::Index q = 0; q < fields.cols(); ++q)
      {
        if(positions[q] < 0) continue;
        if(single) static_cast<float*>(data)[r * d_ + positions[q]] = static_cast<float>(fields(r, q));
        else static_cast<double*>(data)[r * d_ + positions[q]] = fields(r, q);
      }
  };
  const Eigen::Index step = 64;
  for(Eigen::Index i = 0; i < exact_used; i += step)
  {
    const Eigen::Index count = std::min(step, exact_used - i);
    Eigen::MatrixXd phi = basis_->exact_eigenfunctions().columns(i, count);
    for(Eigen::Index q = 0; q < count; ++q) phi.col(q) /= std::sqrt(basis_->exact_eigenvalues()[i + q]);
    store(ops.G() * phi, std::vector<int>(exact_position.begin() + i, exact_position.begin() + i + count));
  }
  for(Eigen::Index i = 0; i < coexact_used; i += step)
  {
    const Eigen::Index count = std::min(step, coexact_used - i);
    Eigen::MatrixXd psi = basis_->coexact_eigenfunctions().columns(i, count);
    for(Eigen::Index q = 0; q < count; ++q) psi.col(q) /= std::sqrt(basis_->coexact_eigenvalues()[i + q]);
    const Eigen::MatrixXd g = ops.G_star_interior() * psi;
    Eigen::MatrixXd fields(g.rows(), count);
    for(Eigen::Index q = 0; q < count; ++q) fields.col(q) = ops.rotate(g.col(q));
    store(fields, std::vector<int>(coexact_position.begin() + i, coexact_position.begin() + i + count));
  }
  for(int k = 0; k < d_; ++k)
    if(basis_->type(k) == Eigenfield_type::harmonic)
      store(basis_->harmonic_fields().col(basis_->index_in_type(k)), std::vector<int>{k});
}

Eigenfield_rows::~Eigenfield_rows() = default;

const void* Eigenfield_rows::block(int f) const
{
  const std::size_t entry = precision_ == Eigenfunction_precision::float32 ? sizeof(float) : sizeof(double);
  const void* data = rows32_ ? static_cast<const void*>(rows32_->data()) : static_cast<const void*>(rows64_->data());
  return static_cast<const char*>(data) + std::size_t(2) * f * d_ * entry;
}

void Eigenfield_rows::prefetch(int f) const
{
#if defined(__GNUC__)
  const char* c = static_cast<const char*>(block(f));
  const std::size_t bytes = std::size_t(2) * d_ * (precision_ == Eigenfunction_precision::float32 ? sizeof(float) : sizeof(double));
  for(std::size_t i = 0; i < bytes; i += 64) __builtin_prefetch(c + i);
#else
  (void)f;
#endif
}

// The dot products go to the BLAS where Eigen is bound to it (EIGEN_USE_BLAS, which declares
// the Fortran symbols: OpenBLAS at run time on Debian, with the vector kernels of the machine that
// the portable build of this file cannot use); dsdot is a float dot product summed in double.
std::array<double, 2> Eigenfield_rows::face_vector(int f, const Eigen::VectorXd& a) const
{
  int k = static_cast<int>(a.size()), one = 1;
  if(k == 0) return {0, 0};
  const double* u = static_cast<const double*>(block(f));
#if defined(EIGEN_USE_BLAS)
  double* x = const_cast<double*>(a.data());
  return {ddot_(&k, const_cast<double*>(u), &one, x, &one), ddot_(&k, const_cast<double*>(u + d_), &one, x, &one)};
#else
  return {Eigen::Map<const Eigen::VectorXd>(u, k).dot(a), Eigen::Map<const Eigen::VectorXd>(u + d_, k).dot(a)};
#endif
}

std::array<double, 2> Eigenfield_rows::face_vector(int f, const Eigen::VectorXf& a) const
{
  int k = static_cast<int>(a.size()), one = 1;
  if(k == 0) return {0, 0};
  const float* u = static_cast<const float*>(block(f));
#if defined(EIGEN_USE_BLAS)
  float* x = const_cast<float*>(a.data());
  return {dsdot_(&k, const_cast<float*>(u), &one, x, &one), dsdot_(&k, const_cast<float*>(u + d_), &one, x, &one)};
#else
  return {Eigen::Map<const Eigen::VectorXf>(u, k).cast<double>().dot(a.cast<double>()),
          Eigen::Map<const Eigen::VectorXf>(u + d_, k).cast<double>().dot(a.cast<double>())};
#endif
}

Reduced_face_vectors::Reduced_face_vectors(std::shared_ptr<const Eigenfield_rows> rows) : rows_(std::move(rows))
{
  if(!rows_) throw Invalid_input("reduced face vectors: no eigenfield rows given");
}

void Reduced_face_vectors::set_coefficients(const Eigen::VectorXd& a)
{
  if(a.size() > rows_->size())
    throw Invalid_input("reduced face vectors: " + std::to_string(a.size()) + " coefficients for rows of " +
                        std::to_string(rows_->size()) + " elements");
  if(!a.allFinite()) throw Invalid_input("reduced face vectors: the coefficients have non-finite entries");
  a_ = a;
  a32_ = a.cast<float>();
  faces_asked_ = 0;
}

std::array<double, 2> Reduced_face_vectors::face_vector(int f) const
{
  faces_asked_.fetch_add(1, std::memory_order_relaxed);
  return rows_->precision() == Eigenfunction_precision::float32 ? rows_->face_vector(f, a32_) : rows_->face_vector(f, a_);
}

} // namespace Tangent_vector_fields
} // namespace CGAL
