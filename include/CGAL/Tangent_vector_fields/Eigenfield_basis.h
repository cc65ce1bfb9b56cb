// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_EIGENFIELD_BASIS_H
#define CGAL_TANGENT_VECTOR_FIELDS_EIGENFIELD_BASIS_H

/// \file Eigenfield_basis.h
/// The eigenfields of the Hodge-Laplacian `L` (SPEC 5) on frame-coordinate vectors:
/// computation, storage as eigenfunctions, transforms, energies, filters,
/// compression, and a versioned file format.

#include <CGAL/Tangent_vector_fields/Eigenfunction_matrix.h>
#include <CGAL/Tangent_vector_fields/Hodge_solver.h>
#include <CGAL/Tangent_vector_fields/Operator_matrices.h>
#include <CGAL/Tangent_vector_fields/Spectral_filter.h>

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Model_reduction {
namespace internal {
class Binary_reader; // <CGAL/Model_reduction/internal/binary_file.h>
}
} // namespace Model_reduction

namespace Tangent_vector_fields {

/// The three kinds of eigenfields (SPEC 5).
enum class Eigenfield_type : std::uint8_t {
  harmonic = 0, ///< eigenvalue 0: `div = 0` and `curl* = 0`
  exact = 1,    ///< curl-free, `G phi / sqrt(lambda)` with `W phi = lambda M phi`
  coexact = 2   ///< divergence-free, `J G* psi / sqrt(mu)` with `W* psi = mu M* psi`
};

/// Which eigenfields a basis holds.
struct Basis_request
{
  enum class Mode { lowest, per_type, below_eigenvalue };
  Mode mode = Mode::lowest;
  int count = 0;           ///< `lowest`: the `count` smallest eigenvalues (harmonic fields first)
  int exact_count = 0;     ///< `per_type`: exact fields, in addition to all harmonic ones
  int coexact_count = 0;   ///< `per_type`: coexact fields, in addition to all harmonic ones
  double max_eigenvalue = 0; ///< `below_eigenvalue`: every eigenfield with eigenvalue `<= max_eigenvalue`
  /// How the eigenfunctions are kept once computed (they are computed in double).
  Eigenfunction_precision precision = Eigenfunction_precision::float64;

  static Basis_request lowest(int d)
  {
    Basis_request r;
    r.count = d;
    return r;
  }
  static Basis_request per_type(int d_exact, int d_coexact)
  {
    Basis_request r;
    r.mode = Mode::per_type;
    r.exact_count = d_exact;
    r.coexact_count = d_coexact;
    return r;
  }
  static Basis_request below(double lambda)
  {
    Basis_request r;
    r.mode = Mode::below_eigenvalue;
    r.max_eigenvalue = lambda;
    return r;
  }
};

/// Reported while a basis is computed.
struct Spectral_progress
{
  std::string stage;     ///< "counting eigenvalues", "eigenfunctions" (both problems at once), "harmonic fields", "done"
  double fraction = 0;   ///< overall progress estimate in [0, 1]
};

/// Options of the computation.
struct Basis_options
{
  /// Relative residual required of every eigenpair (on the unit-area problem).
  double tolerance = 1e-10;
  /// Vectors per Lanczos block (see `Model_reduction::Eigensolver_options::block_size`).
  int block_size = 4;
  /// When a window's Krylov basis is restarted (see `Model_reduction::Eigensolver_options::restart_per_pair`;
  /// 0: never).
  double restart_per_pair = 1.3;
  std::uint64_t seed = 1;
  /// Threads of the eigensolver (see `Model_reduction::Eigensolver_options::threads`; 0: one per core).
  int threads = 0;
  std::function<void(const Spectral_progress&)> progress;
};

/// What the computation measured: the evidence that the basis is right.
struct Basis_report
{
  double max_residual = 0;         ///< largest relative residual of an eigenpair
  double exact_complete_below = 0; ///< no exact eigenvalue below this is missing
  double coexact_complete_below = 0;
  int exact_inertia = 0, exact_expected = 0;     ///< completeness check of the exact problem
  int coexact_inertia = 0, coexact_expected = 0; ///< and of the coexact one
  /// Wall time of each part.  The exact and coexact problems are solved together on the
  /// eigensolver's threads; their joint time is shared out in proportion to the thread
  /// time each took, so that the parts add up to the whole.
  double exact_seconds = 0, coexact_seconds = 0, harmonic_seconds = 0;
};

/// Coefficients kept by `Eigenfield_basis::compress`, with the rate and the error.
struct Compressed_fields
{
  Eigen::MatrixXd coefficients; ///< `k x frames`: the `k` lowest coefficients of each field
  double ratio = 0;             ///< `2 nf / k`: doubles per field before and after
  double bits_per_face = 0;     ///< `64 k / nf`
  Eigen::VectorXd relative_errors; ///< `|v - v_k|_MX / |v|_MX` per field
};

/// \brief An `MX`-orthonormal basis of eigenfields of the Hodge-Laplacian.
///
/// Elements are sorted by eigenvalue, harmonic fields (eigenvalue 0) first; within a
/// tie exact before coexact.  The basis stores the eigenfunctions (`nv x d_exact`,
/// `ne_int x d_coexact`) and the harmonic fields, not the eigenfields: an eigenfield
/// is rebuilt by one sparse product.  Eigenproblems are solved on the mesh scaled to
/// unit area (so that tolerances are scale-free); eigenvalues and eigenfunctions are
/// returned for the mesh as given.
class Eigenfield_basis
{
public:
  typedef Eigen::VectorXd Vector;
  typedef Eigen::MatrixXd Matrix;

  /// Computes the basis described by `request`.
  /// \throws Invalid_input if the request asks for more fields than the space has.
  /// \throws Numerical_failure if an eigenpair misses the tolerance or the completeness check fails.
  Eigenfield_basis(std::shared_ptr<const Hodge_solver> solver, const Basis_request& request,
                   const Basis_options& options = Basis_options());

  /// Reads a basis saved by `save`.
  /// \throws Invalid_input if the file is unreadable, of another version, was
  ///         computed on a different mesh, or is corrupt: an exact or coexact eigenvalue
  ///         that is not positive, elements out of order or listed twice, an element
  ///         whose norm is not 1.
  static Eigenfield_basis load(std::shared_ptr<const Hodge_solver> solver, const std::string& path);
  /// Writes the basis to a binary file (format in `doc/tangent_vector_fields/manual.md`).
  void save(const std::string& path) const;

  const Operator_matrices& operators() const { return solver_->operators(); }
  /// The Hodge solver the basis was computed with (its factorisations serve the exact splines).
  std::shared_ptr<const Hodge_solver> shared_hodge_solver() const { return solver_; }

  int size() const { return static_cast<int>(order_.size()); }
  int number_of_harmonic() const { return static_cast<int>(harmonic_.cols()); }
  int number_of_exact() const { return static_cast<int>(exact_values_.size()); }
  int number_of_coexact() const { return static_cast<int>(coexact_values_.size()); }
  /// Eigenvalue of element `k` (ascending).
  double eigenvalue(int k) const { return values_[k]; }
  const Vector& eigenvalues() const { return values_; }
  Eigenfield_type type(int k) const { return order_[k].type; }
  /// Position of element `k` among the elements of its type.
  int index_in_type(int k) const { return order_[k].index; }

  /// `W phi = lambda M phi`, `M`-orthonormal columns (vertices in no face: 0).
  const Eigenfunction_matrix& exact_eigenfunctions() const { return exact_functions_; }
  const Vector& exact_eigenvalues() const { return exact_values_; }
  /// `W* psi = mu M* psi` on interior edges, `M*`-orthonormal columns.
  const Eigenfunction_matrix& coexact_eigenfunctions() const { return coexact_functions_; }
  const Vector& coexact_eigenvalues() const { return coexact_values_; }
  /// `MX`-orthonormal harmonic fields (`2nf x h`).
  const Matrix& harmonic_fields() const { return harmonic_; }
  const Basis_report& report() const { return report_; }
  /// How the eigenfunctions are stored.
  Eigenfunction_precision precision() const { return exact_functions_.precision(); }
  /// Stores the eigenfunctions in `precision` (float32: each entry rounded, half the memory;
  /// back to float64 keeps the rounded values).
  void set_precision(Eigenfunction_precision precision);
  /// Bytes held by the eigenfunctions and the harmonic fields.
  std::size_t memory_bytes() const;

  /// Element `k` as a field (`2nf`, unit norm in `MX`).
  Vector eigenfield(int k) const;
  /// `a_k = <v, Phi_k>_MX` for every element.
  Vector coefficients(const Vector& field) const;
  /// Coefficients of each column (`size() x columns`).
  Matrix coefficients(const Matrix& fields) const;
  /// `sum_k a_k Phi_k` over the first `a.size()` elements.
  Vector field(const Vector& a) const;
  /// `v - sum_k <v, Phi_k> Phi_k`: the part of `v` the basis cannot represent.
  Vector rest(const Vector& field) const;

  /// Dirichlet energy `sum lambda_k a_k^2` and biharmonic energy `sum lambda_k^2 a_k^2`.
  double dirichlet_energy(const Vector& a) const;
  double biharmonic_energy(const Vector& a) const;
  /// Energy `a_k^2` summed per type (harmonic, exact, coexact) over elements with
  /// eigenvalue in `[band_edges[i], band_edges[i+1])`: a `(bands x 3)` matrix.
  Matrix band_energies(const Vector& a, const std::vector<double>& band_edges) const;

  /// Applies `filter` (SPEC 6): the transfer functions of `sqrt(lambda)` on exact and
  /// coexact coefficients, the harmonic factor, and the rest factor on `rest(v)`.
  Vector filter(const Vector& field, const Spectral_filter& filter) const;

  /// Keeps the `k` lowest coefficients of each field (columns of `fields`).
  Compressed_fields compress(const Matrix& fields, int k) const;
  /// The fields described by compressed coefficients.
  Matrix decompress(const Compressed_fields& compressed) const;

private:
  struct Element
  {
    Eigenfield_type type;
    int index;
  };
  explicit Eigenfield_basis(std::shared_ptr<const Hodge_solver> solver);
  void merge(int count); // fills order_ and values_ with the `count` lowest elements
  void update_values();  // values_ from order_
  // After `load`: positive eigenvalues, in order, each element once and of unit norm.
  void check_loaded(Model_reduction::internal::Binary_reader& reader) const;

  std::shared_ptr<const Hodge_solver> solver_;
  Eigenfunction_matrix exact_functions_, coexact_functions_;
  Matrix harmonic_;
  Vector exact_values_, coexact_values_;
  std::vector<Element> order_;
  Vector values_;
  Basis_report report_;
};

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
