// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/Eigenfunction_matrix.h>
#include <CGAL/Tangent_vector_fields/internal/basis_file.h>

#include <algorithm>
#include <cstdint>
#include <ostream>

namespace CGAL {
namespace Tangent_vector_fields {

namespace {
// Rows widened at a time: 256 rows of 1000 columns are 2 MB of doubles, about a core's cache.
Eigen::Index block_rows(Eigen::Index cols) { return std::max<Eigen::Index>(16, (1 << 18) / std::max<Eigen::Index>(cols, 1)); }
} // namespace

void Eigenfunction_matrix::set_precision(Eigenfunction_precision precision)
{
  if(precision == precision_) return;
  if(precision == Eigenfunction_precision::float32)
  {
    single_ = double_.cast<float>();
    double_ = Eigen::MatrixXd();
  }
  else
  {
    double_ = single_.cast<double>();
    single_ = Eigen::MatrixXf();
  }
  precision_ = precision;
}

std::size_t Eigenfunction_matrix::bytes() const
{
  return sizeof(double) * static_cast<std::size_t>(double_.size()) + sizeof(float) * static_cast<std::size_t>(single_.size());
}

void Eigenfunction_matrix::keep_columns(Eigen::Index k)
{
  if(precision_ == Eigenfunction_precision::float64) double_.conservativeResize(Eigen::NoChange, k);
  else single_.conservativeResize(Eigen::NoChange, k);
}

Eigen::MatrixXd Eigenfunction_matrix::times(const Eigen::MatrixXd& C) const
{
  const Eigen::Index k = C.rows();
  if(precision_ == Eigenfunction_precision::float64) return double_.leftCols(k) * C;
  Eigen::MatrixXd result(single_.rows(), C.cols());
  const Eigen::Index step = block_rows(k);
  Eigen::MatrixXd block;
  for(Eigen::Index i = 0; i < single_.rows(); i += step)
  {
    const Eigen::Index n = std::min(step, single_.rows() - i);
    block = single_.block(i, 0, n, k).cast<double>();
    result.middleRows(i, n).noalias() = block * C;
  }
  return result;
}

Eigen::MatrixXd Eigenfunction_matrix::transpose_times(const Eigen::MatrixXd& B) const
{
  if(precision_ == Eigenfunction_precision::float64) return double_.transpose() * B;
  Eigen::MatrixXd result = Eigen::MatrixXd::Zero(single_.cols(), B.cols());
  const Eigen::Index step = block_rows(single_.cols());
  Eigen::MatrixXd block;
  for(Eigen::Index i = 0; i < single_.rows(); i += step)
  {
    const Eigen::Index n = std::min(step, single_.rows() - i);
    block = single_.middleRows(i, n).cast<double>();
    result.noalias() += block.transpose() * B.middleRows(i, n);
  }
  return result;
}

void Eigenfunction_matrix::add_row(Eigen::Index i, double weight, Eigen::VectorXd& out) const
{
  const Eigen::Index k = out.size();
  if(precision_ == Eigenfunction_precision::float64) out += weight * double_.row(i).head(k).transpose();
  else out += weight * single_.row(i).head(k).transpose().cast<double>();
}

bool Eigenfunction_matrix::all_finite() const
{
  return precision_ == Eigenfunction_precision::float64 ? double_.allFinite() : single_.allFinite();
}

Eigen::MatrixXd Eigenfunction_matrix::to_double() const
{
  return precision_ == Eigenfunction_precision::float64 ? double_ : Eigen::MatrixXd(single_.cast<double>());
}

void Eigenfunction_matrix::write(std::ostream& out) const
{
  internal::write_value<std::uint8_t>(out, precision_ == Eigenfunction_precision::float64 ? 0 : 1);
  internal::write_value<std::int64_t>(out, rows());
  internal::write_value<std::int64_t>(out, cols());
  if(precision_ == Eigenfunction_precision::float64)
    out.write(reinterpret_cast<const char*>(double_.data()), sizeof(double) * double_.size());
  else
    out.write(reinterpret_cast<const char*>(single_.data()), sizeof(float) * single_.size());
}

Eigenfunction_matrix Eigenfunction_matrix::read(Model_reduction::internal::Binary_reader& in, Eigen::Index rows, Eigen::Index cols,
                                                const char* what)
{
  const std::uint8_t precision = in.value<std::uint8_t>();
  if(precision > 1) in.fail(std::string("the ") + what + " have an unknown precision");
  Eigenfunction_matrix m;
  if(precision == 0)
    m.double_ = in.matrix(rows, cols, what);
  else
  {
    m.precision_ = Eigenfunction_precision::float32;
    m.single_ = in.float_matrix(rows, cols, what);
  }
  return m;
}

} // namespace Tangent_vector_fields
} // namespace CGAL
