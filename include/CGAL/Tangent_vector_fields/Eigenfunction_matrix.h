// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_EIGENFUNCTION_MATRIX_H
#define CGAL_TANGENT_VECTOR_FIELDS_EIGENFUNCTION_MATRIX_H

/// \file Eigenfunction_matrix.h
/// The eigenfunctions of a spectral basis (one column each), stored in double or in float32.

#include <Eigen/Core>

#include <cstddef>
#include <iosfwd>

namespace CGAL {
namespace Model_reduction {
namespace internal {
class Binary_reader; // <CGAL/Model_reduction/internal/binary_file.h>
}
} // namespace Model_reduction

namespace Tangent_vector_fields {

/// How a basis stores its eigenfunctions.
enum class Eigenfunction_precision
{
  float64, ///< double: reconstructions exact to rounding (the default)
  float32  ///< single: half the memory and file size; each entry is rounded to 24 bits, which the
           ///< gradient of a smooth eigenfunction amplifies: a field gains a relative error of 1e-5 to 2e-4
           ///< (20k to 346k faces)
};

/// \brief A dense `n x d` matrix of eigenfunctions in either precision.
///
/// Products accumulate in double whatever the storage: float32 entries are widened block
/// by block (a few hundred rows at a time, in cache), so only the storage is rounded.
class Eigenfunction_matrix
{
public:
  Eigenfunction_matrix() = default;
  explicit Eigenfunction_matrix(Eigen::MatrixXd functions) : double_(std::move(functions)) {}
  explicit Eigenfunction_matrix(Eigen::MatrixXf functions)
    : precision_(Eigenfunction_precision::float32), single_(std::move(functions))
  {
  }

  Eigen::Index rows() const { return precision_ == Eigenfunction_precision::float64 ? double_.rows() : single_.rows(); }
  Eigen::Index cols() const { return precision_ == Eigenfunction_precision::float64 ? double_.cols() : single_.cols(); }
  Eigenfunction_precision precision() const { return precision_; }
  /// Converts in place (float32: each entry rounded to nearest); the other copy is freed.
  void set_precision(Eigenfunction_precision precision);
  /// Bytes held.
  std::size_t bytes() const;

  /// Keeps the first `k` columns.
  void keep_columns(Eigen::Index k);
  /// Columns `first ... first + count - 1` as doubles.
  Eigen::MatrixXd columns(Eigen::Index first, Eigen::Index count) const
  {
    return precision_ == Eigenfunction_precision::float64 ? Eigen::MatrixXd(double_.middleCols(first, count))
                                                          : Eigen::MatrixXd(single_.middleCols(first, count).cast<double>());
  }
  /// `Phi.leftCols(C.rows()) C` (`n x m`).
  Eigen::MatrixXd times(const Eigen::MatrixXd& C) const;
  /// `Phi^T B` (`d x m`).
  Eigen::MatrixXd transpose_times(const Eigen::MatrixXd& B) const;
  /// `out += weight * Phi.row(i).head(out.size())^T`.
  void add_row(Eigen::Index i, double weight, Eigen::VectorXd& out) const;
  /// Entry `(i, j)` as a double.
  double operator()(Eigen::Index i, Eigen::Index j) const
  {
    return precision_ == Eigenfunction_precision::float64 ? double_(i, j) : static_cast<double>(single_(i, j));
  }
  bool all_finite() const;
  /// A double copy (for tests and small meshes).
  Eigen::MatrixXd to_double() const;

  /// Writes a precision byte (0: float64, 1: float32), the size, then the column-major entries.
  void write(std::ostream& out) const;
  /// Reads what `write` wrote (`rows`/`cols` < 0: any).
  static Eigenfunction_matrix read(Model_reduction::internal::Binary_reader& in, Eigen::Index rows, Eigen::Index cols, const char* what);

private:
  Eigenfunction_precision precision_ = Eigenfunction_precision::float64;
  Eigen::MatrixXd double_;
  Eigen::MatrixXf single_;
};

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
