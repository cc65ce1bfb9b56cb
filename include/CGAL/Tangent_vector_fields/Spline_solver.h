// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_SPLINE_SOLVER_H
#define CGAL_TANGENT_VECTOR_FIELDS_SPLINE_SOLVER_H

/// \file Spline_solver.h
/// Splines (SPEC 7, and SPEC 10 for n-fields): minimise `E_B(x) + omega E_D(x)` subject
/// to hard constraints `C~ x = c`.  This header holds what every reduced and full solver
/// shares, for vector fields and n-fields alike: the constraint set and its edits, the
/// small range-space system, and the report.

#include <CGAL/Tangent_vector_fields/Field_constraint.h>
#include <CGAL/Tangent_vector_fields/internal/Constraint_system.h>

#include <Eigen/Core>

#include <limits>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

namespace internal {
/// The length unit a spline solver measures its mesh in: the mesh's `length_unit()`
/// for vector fields; 1 (the mesh as given) for other operators.
inline double spline_length_unit(const Operator_matrices& ops) { return ops.mesh().length_unit(); }
template <class Operators>
double spline_length_unit(const Operators&) { return 1.; }
} // namespace internal

/// Handle of a constraint in a solver; stays valid until the constraint is removed.
typedef int Constraint_id;

/// Options shared by the spline solvers.
struct Spline_options
{
  /// Tension `omega` of `E_B + omega E_D`, for the mesh scaled to unit total area
  /// (so that the result does not depend on the mesh's scale).  0: pure biharmonic.
  double omega = 0;
  /// Eigenvalue given to the harmonic fields, for the mesh scaled to unit area.  0 (the
  /// default): harmonic fields carry no energy and the constraints alone determine them
  /// (the exact minimiser).  On surfaces with handles or holes far from every
  /// constraint that can make the harmonic part huge (a warning says "weakly
  /// determined"); a positive value (the thesis: a tenth of the lowest non-zero
  /// eigenvalue, about 2.5 on a unit-area sphere) gives them the energy
  /// `lambda_h^2 + omega lambda_h` per unit coefficient, in the reduced and the full solver alike.
  double harmonic_eigenvalue = 0;
  /// A new constraint row whose `sin^2` angle to the span of the others (in the
  /// metric of the energy) is below this is refused as dependent.  Double precision
  /// leaves about 1e-16 for exact repeats; 1e-10 also catches rows a basis cannot tell apart.
  double dependency_tolerance = 1e-10;
  /// Rows above the dependency tolerance but below this are accepted with a warning
  /// (meeting them costs a large energy: the field may swing wildly between them).
  double warning_tolerance = 1e-6;
};

/// What a solve found besides the field.
struct Spline_report
{
  int constraints = 0;
  int rows = 0;
  /// Smallest `sin^2` angle of a row to the span of the earlier rows (1: orthogonal, 0: dependent).
  double smallest_independence = 1;
  /// Harmonic directions that no constraint determines; they are set to zero.
  int undetermined_harmonic = 0;
  /// Largest `|C~_i x - c_i|`, relative to the largest `|c|` (or absolute if all are 0).
  double constraint_residual = 0;
  /// `E_B(x) + omega_eff E_D(x)` of the solution, for the mesh as given (n-field splines
  /// with a soft alignment add its term, see `N_field_alignment`).
  double energy = 0;
  /// A guaranteed upper bound on `|x - x*|_E / |x*|_E`: the error of this answer `x` against
  /// the exact spline `x*` of the same constraints, in the energy norm `|v|_E^2 = E_B(v) +
  /// omega E_D(v)`, relative to the exact spline's.  0 for full-resolution solvers (they are
  /// exact).  For a reduced spline it follows from the basis alone (SPEC 7; see
  /// `relative_error_bound` in Spline_error_bound_impl.h): the pull-backs' part outside the basis
  /// is bounded by the lowest energy missing from it.  NaN when no bound is known: an
  /// alignment term, or a basis that does not say which eigenvalues it lacks.
  double error_bound = 0;
  std::vector<std::string> warnings;
};

/// An error bound above this is reported among the warnings: the reduced answer may be far
/// from the spline asked for (the energy-norm error can reach a tenth of the field's).
constexpr double error_bound_warning = 0.1;

/// \brief Common part of the spline solvers, for a kind of constraint and the operators
/// of the fields it constrains (vector fields: `Spline_solver`; n-fields: `N_field_spline_solver`).
///
/// `Constraint` provides `describe()` and `same_rows_as(other)`; the free functions
/// `constraint_rows(const Operators&, const Constraint&)` and
/// `constraint_values(const Operators&, const Constraint&)` give its rows and their values;
/// `Operators` provides `face_areas()`.
///
/// The range-space method: each constraint row `r_i` is pulled back once to
/// `y_i = Q^+ r_i^T` (the energy's pseudo-inverse on the fields orthogonal to the
/// harmonic ones), `K_ij = r_i y_j`; the spline is `x = sum mu_i y_i + U_h z` with
/// `(mu, z)` from the small system of `internal::Constraint_system`.
///
/// Harmonic fields (genus > 0, boundaries) have zero energy.  They are solved for
/// separately, not penalised: the spline is the exact minimiser of `E_B + omega E_D`;
/// harmonic directions the constraints do not determine are set to zero (the
/// minimum-norm minimiser) and counted in the report.
///
/// Editing: `change` with the same kind and place of constraint only changes values
/// (one back-substitution at the next solve); `add` appends rows to the small Cholesky
/// factor, `remove` re-triangularises it: neither refactors from scratch.
template <class Constraint, class Operators>
class Basic_spline_solver
{
protected:
  struct Row
  {
    Constraint_row row;
    Eigen::VectorXd representation; // solver-specific form of the row (may be empty)
    Eigen::VectorXd y;              // pull-back Q^+ r^T
    Eigen::VectorXd harmonic;       // r U_h
    double scale = 1;               // the row as given is `scale` times `row` (a power of two)
  };

public:
  typedef Constraint Constraint_type;

  virtual ~Basic_spline_solver();

  /// Adds a constraint.
  /// \throws Invalid_input for a malformed constraint (see `constraint_rows`).
  /// \throws Infeasible_constraints if its rows depend on those already present.
  Constraint_id add(const Constraint& constraint);
  /// Adds several constraints with one batch of pull-backs (faster for the full solver).
  /// All or nothing: on an exception none of them is added.
  std::vector<Constraint_id> add(const std::vector<Constraint>& constraints);
  /// Replaces a constraint.  Same kind and place: only the values change.
  void change(Constraint_id id, const Constraint& constraint);
  void remove(Constraint_id id);
  void clear();

  bool contains(Constraint_id id) const { return entries_.count(id) > 0; }
  const Constraint& constraint(Constraint_id id) const;
  std::vector<Constraint_id> constraint_ids() const;
  int number_of_constraints() const { return static_cast<int>(entries_.size()); }
  int number_of_rows() const { return static_cast<int>(rows_.size()); }
  /// Dimension of the harmonic fields the solver represents.
  int harmonic_dimension() const { return harmonic_dimension_; }

  /// Changes the tension (`options().omega`): every row is pulled back again and the
  /// small system rebuilt (the full solver also refactors its energy).
  void set_omega(double omega);
  /// `omega` for the mesh as given (`options.omega / area`).
  double effective_omega() const { return omega_ / length_unit_ / length_unit_; }
  const Spline_options& options() const { return options_; }
  const Operators& operators() const { return *operators_; }

  /// The spline as frame coordinates (`2nf`); solves if constraints changed.
  virtual Eigen::VectorXd field() const = 0;
  /// The report of the last solve (solves if needed; made on request, as it costs about
  /// as much as a solve).
  const Spline_report& report() const;

  /// The row values of constraint `id` as the solver holds them (`constraint_values`).
  /// \throws Invalid_input for an unknown id.
  Eigen::VectorXd values(Constraint_id id) const;
  /// The change of `solution` per unit change of each row value of constraint `id`
  /// (columns, in the solver's space: coefficients or frame coordinates).  The spline is
  /// affine in the values: solution(c + t e_k) = solution(c) + t column k, exactly.
  /// \throws Invalid_input for an unknown id.
  Eigen::MatrixXd value_response(Constraint_id id) const;
  /// `field()` while only the values of constraint `id` change (a drag).  The first call
  /// after any other change of the constraint set (or of another constraint's values)
  /// reconstructs the field and its response to each of `id`'s values in one pass (1 + rows
  /// fields: about the cost of `field()` for a basis, which reads its eigenfunctions once);
  /// later calls cost one product of the responses with the change of the values,
  /// `O(rows 2nf)`, instead of a reconstruction.  Equal to `field()` up to rounding.
  Eigen::VectorXd field_after_value_edit(Constraint_id id) const;

  /// Constraints whose rows are pulled back but not yet added (see `prepare`).
  struct Prepared
  {
    std::vector<Constraint> constraints;
    std::vector<Row> rows;
    std::vector<int> owner; // the constraint of each row
    long energy_version = -1;
  };
  /// The costly half of `add`: the constraints' rows and their pull-backs, without changing
  /// the solver.  It reads only the energy and its factorisations, never the constraint set,
  /// so a worker thread may run it while this thread edits the constraints and solves (not
  /// while it changes the energy: `set_omega`).
  /// \throws Invalid_input for a malformed constraint.
  Prepared prepare(const std::vector<Constraint>& constraints) const;
  /// The cheap half: adds prepared constraints (all or nothing, like `add`).  `values` may
  /// replace the constraints (the same rows, other values: edits made meanwhile).
  /// \throws Invalid_input if the energy changed since `prepare` (`set_omega`), or if a
  ///         replacement has other rows.
  /// \throws Infeasible_constraints as `add`.
  std::vector<Constraint_id> add_prepared(Prepared prepared,
                                          const std::vector<Constraint>& values = std::vector<Constraint>());

protected:
  Basic_spline_solver(std::shared_ptr<const Operators> operators, int harmonic_dimension,
                const Spline_options& options);
  /// Fills `representation`, `y` and `harmonic` of every row.
  virtual void pull_back(std::vector<Row>& rows) const = 0;
  /// `r y` for a row and a vector of the solver's space.
  virtual double apply(const Row& row, const Eigen::VectorXd& y) const = 0;
  /// Energy of a solution in the solver's space.
  virtual double energy(const Eigen::VectorXd& solution) const = 0;
  /// Places harmonic coefficients `z` into a solution of the solver's space.
  virtual void add_harmonic(const Eigen::VectorXd& z, Eigen::VectorXd& solution) const = 0;
  /// Dimension of the solver's space (basis size, or `2nf`).
  virtual int space_dimension() const = 0;
  /// Extra text for dependency errors (e.g. "the basis has only d fields").
  virtual std::string dependency_hint() const { return std::string(); }
  /// Called when `omega` changed, before the rows are pulled back again.
  virtual void energy_changed() {}
  /// What the zero-energy fields are called in messages ("harmonic", "parallel").
  virtual std::string kernel_noun() const { return "harmonic"; }
  /// The minimiser without constraints, in the solver's space: empty (zero) unless the
  /// energy has a linear term (a soft alignment to a guide field); the spline is then this
  /// plus a combination of the pull-backs.
  virtual const Eigen::VectorXd& unconstrained_minimiser() const { return no_offset_; }
  /// For the error bound: the smallest energy `D_k` of a field the solver cannot represent, in
  /// the solver's units (infinity: none is missing, the solver is exact; NaN or 0: unknown).
  virtual double lowest_missing_energy() const { return std::numeric_limits<double>::infinity(); }
  /// For the error bound: the mass `MX` of each coordinate of the field space (`2nf`), in the
  /// solver's units, in which the solver's representation of a row is orthonormal.
  virtual Eigen::VectorXd field_masses() const { return Eigen::VectorXd(); }
  /// `representation` of rows `a` and `b` as the solver's own coefficients (reduced solvers:
  /// the row on each basis element); their dot product is the rows' product on the basis.
  virtual double represented_product(const Row& a, const Row& b) const { return a.representation.dot(b.representation); }

  /// The fields (frame or power coordinates, `2nf` rows) of solutions of the solver's
  /// space (columns): the identity for full-resolution solvers, the basis for reduced ones.
  virtual Eigen::MatrixXd fields_of(const Eigen::MatrixXd& solutions) const { return solutions; }

  /// The solution in the solver's space (coefficients or frame coordinates).
  const Eigen::VectorXd& solution() const;

  std::shared_ptr<const Operators> operators_;
  Spline_options options_;
  // The solver works on the mesh measured in `length_unit_` (a power of two near its
  // edge length, `internal::spline_length_unit`): lengths, areas and energies stay
  // near 1 whatever the mesh's size, where E_B alone (~size^-4 per unit area) would
  // under- or overflow.  `omega_`, the energies and the pull-backs are in that unit.
  double length_unit_ = 1;
  double omega_ = 0;          // effective omega for the mesh measured in length_unit_
  double harmonic_scale_ = 0; // energy of a unit field of frequency 1/area
  double harmonic_penalty_ = 0; // energy per unit harmonic coefficient (from options.harmonic_eigenvalue)

private:
  struct Entry
  {
    Constraint constraint;
    int first_row;
    int row_count;
  };
  // Pulls back and appends the rows of `constraints`, under the ids given; all or nothing.
  void insert(const std::vector<Constraint>& constraints, const std::vector<Constraint_id>& ids);
  // Appends pulled-back rows under the ids given; all or nothing.
  void append(Prepared& prepared, const std::vector<Constraint_id>& ids);
  long energy_version_ = 0; // counts changes of the energy (omega)
  void set_scales();
  void solve() const;
  void make_report() const;
  // Spline_report::error_bound of the current solution (Spline_error_bound_impl.h).
  double relative_error_bound() const;
  // sum_i y_i weights(i, k) for each column k of `weights` (one row per constraint row).
  Eigen::MatrixXd combined_pull_backs(const Eigen::MatrixXd& weights) const;

  std::map<Constraint_id, Entry> entries_;
  std::vector<Row> rows_;
  Constraint_id next_id_ = 0;
  std::unique_ptr<internal::Constraint_system> system_;
  // Counts changes of the constraint set other than value edits of `edit_cache_.id`.
  long version_ = 0;
  struct Value_edit_cache
  {
    Constraint_id id = -1;
    long version = -1;
    Eigen::VectorXd values;    // the constraint's values when the field was made
    Eigen::VectorXd field;     // field() at those values
    Eigen::MatrixXd responses; // its change per unit change of each value
  };
  mutable Value_edit_cache edit_cache_;
  // The small system of the error bound (the rows' Gram matrix enlarged by the bound on their
  // part outside the basis), grown with the rows appended since and rebuilt only when rows were
  // dropped (value edits do not change it).
  long rows_dropped_ = 0; // counts removals of rows (remove, clear, a new energy)
  mutable long bound_dropped_ = -1;
  mutable std::unique_ptr<internal::Constraint_system> bound_system_;
  mutable std::vector<std::vector<std::pair<int, double>>> bound_entries_; // the rows' entries, sorted
  int harmonic_dimension_;
  mutable bool solved_ = false, reported_ = false;
  mutable Eigen::VectorXd solution_;
  mutable Spline_report report_;
  const Eigen::VectorXd no_offset_;
};

/// The tangent vector field spline solvers' common part.
typedef Basic_spline_solver<Field_constraint, Operator_matrices> Spline_solver;
extern template class Basic_spline_solver<Field_constraint, Operator_matrices>;

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
