// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_REDUCED_FACE_VECTORS_H
#define CGAL_TANGENT_VECTOR_FIELDS_REDUCED_FACE_VECTORS_H

/// \file Reduced_face_vectors.h
/// The field `U a` of a reduced spline face by face (rows `2f, 2f+1`), for streamline tracers
/// that read only the faces their strokes reach (`Face_vector_source`).

#include <CGAL/Model_reduction/internal/huge_pages.h>
#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>

#include <Eigen/Core>

#include <array>
#include <atomic>
#include <cstddef>
#include <memory>

namespace CGAL {
namespace Tangent_vector_fields {

/// \brief The first `d` eigenfields of an `Eigenfield_basis` face by face: the two rows
/// `U_f` (`2 x d`) of each face `f`, next to each other in memory.
///
/// The basis stores eigenfunctions, not eigenfields: the field of a face needs the potentials of
/// its three vertices and its edges, each a row of `d` entries spread over the basis' columns
/// (a cache line apart), or, copied by rows, a few rows of kilobytes in random places.  Read in
/// the order a streamline walks, each such row costs about a microsecond of memory latency, as
/// much as reading the whole basis in order costs per row.  Here a face is one block of `2 d`
/// entries: `U_f a` is two dot products over one contiguous block, which a prefetch brings in at
/// once (`Reduced_face_vectors::will_need`).
///
/// Memory: `2 nf d` entries, in float32 by default (at 346k faces and d = 1000: 2.8 GB, the size
/// of the basis' eigenfunctions in double); made once (the eigenfields in blocks of columns,
/// seconds at 346k faces) and shared by every field of the same basis and size.  float32
/// entries of the eigenfields themselves (not of the eigenfunctions, whose gradients amplify
/// rounding) give face vectors within about 1e-7 relative of `Eigenfield_basis::field`;
/// `Eigenfunction_precision::float64` within rounding, at twice the memory.  On Linux the block
/// is mapped with 2 MB pages where the system grants them (a face read in random order then
/// costs no page walk).
class Eigenfield_rows
{
public:
  /// `d`: the first `d` elements of `basis` (0: all).
  /// \throws Invalid_input if `d` exceeds the basis.
  Eigenfield_rows(std::shared_ptr<const Eigenfield_basis> basis, int d,
                  Eigenfunction_precision precision = Eigenfunction_precision::float32);
  ~Eigenfield_rows();
  Eigenfield_rows(const Eigenfield_rows&) = delete;
  Eigenfield_rows& operator=(const Eigenfield_rows&) = delete;

  const Eigenfield_basis& basis() const { return *basis_; }
  int size() const { return d_; }
  int number_of_faces() const { return nf_; }
  Eigenfunction_precision precision() const { return precision_; }
  /// Bytes held.
  std::size_t bytes() const { return bytes_; }

  /// `U_f a` (frame coordinates of face `f`) for `a.size() <= size()` coefficients, with rows in
  /// float64 (the first) or float32 (the second: `a` rounded to float32 too, the sum in double).
  std::array<double, 2> face_vector(int f, const Eigen::VectorXd& a) const;
  std::array<double, 2> face_vector(int f, const Eigen::VectorXf& a) const;
  /// Starts fetching the block of face `f`.
  void prefetch(int f) const;

private:
  const void* block(int f) const;

  std::shared_ptr<const Eigenfield_basis> basis_;
  int d_ = 0, nf_ = 0;
  Eigenfunction_precision precision_;
  std::unique_ptr<Model_reduction::internal::Mapped_array<float>> rows32_; // one of the two
  std::unique_ptr<Model_reduction::internal::Mapped_array<double>> rows64_;
  std::size_t bytes_ = 0;
};

/// \brief The field `U a` of a reduced vector-field spline (`Reduced_spline_solver`), face by
/// face: a `Face_vector_source` for a `Streamline_tracer` that reads only the faces its
/// streamlines reach.  `O(d)` per face, from the face's block of `Eigenfield_rows`.
class Reduced_face_vectors : public Face_vector_source
{
public:
  explicit Reduced_face_vectors(std::shared_ptr<const Eigenfield_rows> rows);

  /// The coefficients of the field (`a.size() <= rows.size()`, as
  /// `Reduced_spline_solver::coefficients`); resets the count.
  /// \throws Invalid_input for more coefficients than the rows have, or non-finite ones.
  void set_coefficients(const Eigen::VectorXd& a);

  int number_of_faces() const override { return rows_->number_of_faces(); }
  std::array<double, 2> face_vector(int f) const override;
  void will_need(int f) const override { rows_->prefetch(f); }

  /// Faces asked for since `set_coefficients` (each call counts).
  std::size_t faces_asked() const { return faces_asked_.load(std::memory_order_relaxed); }

private:
  std::shared_ptr<const Eigenfield_rows> rows_;
  Eigen::VectorXd a_;
  Eigen::VectorXf a32_;
  mutable std::atomic<std::size_t> faces_asked_{0}; // counted from every tracing thread
};

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
