// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What an editing session designs: vector fields (n = 1: tangent vector field splines with
// vectors, directions, divergences and curls) or n-direction fields (n > 1: n-field splines
// with vectors, directions and singularities).  The session handles messages the same way for
// both; an `Field_design` holds the constraints and the reduced (and, on request, the full)
// solver of one kind, and turns its field into what the page draws.

#ifndef TVF_VIEWER_DESIGN_H
#define TVF_VIEWER_DESIGN_H

#include <CGAL/Tangent_vector_fields/Refining_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Spline_solver.h>
#include <CGAL/Tangent_vector_fields/Streamlines.h>
#include <CGAL/Tangent_vector_fields/internal/constraint_json.h>

#include <Eigen/Core>

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace tvf_viewer {

namespace TVF = CGAL::Tangent_vector_fields;
class Field_model;

/// The display settings of a session (`set_display`).
struct Display_settings
{
  std::string lines = "fur", scalar = "none";
  int strokes = 4000;
  double length = 0.02, separation = 0.03;
};

/// The field a session shows, with what the page reports about it.
struct Design_field
{
  Eigen::VectorXd x; ///< frame coordinates (n = 1) or the power representation (n > 1), `2nf`
  TVF::Spline_report report;
  bool exact = false; ///< the full-resolution spline; else the reduced one
  int pending = 0;    ///< constraints still without their full pull-back
  double solve_ms = 0, reconstruct_ms = 0, full_ms = 0;
  /// Once both answers of this constraint set are known: |x_reduced - x_exact| / |x_exact|
  /// in MX, and the largest angle between their directions (radians); -1: not known.
  double difference = -1, largest_angle = -1;
};

/// The strokes of the reduced answer traced through the faces they reach only, without the
/// whole field: what the `preview` message sends before the `field`.
struct Design_preview
{
  std::vector<TVF::Streamline> strokes;
  TVF::Spline_report report; ///< of the reduced solver
  double solve_ms = 0;       ///< the reduced coefficients (and the report)
  double lines_ms = 0;       ///< the face vectors the strokes reach, and the strokes
  std::size_t faces_read = 0;
};

class Field_design
{
public:
  virtual ~Field_design() = default;

  /// 1 for vector fields.
  virtual int n() const = 0;
  /// The energy's order m (n-fields; 2 for vector fields: E_B).
  virtual int order() const = 0;
  virtual int available() const = 0;   ///< elements of the basis
  virtual int basis_size() const = 0;  ///< elements the reduced solver uses
  virtual int kernel_dimension() const = 0; ///< harmonic (n = 1) or parallel fields
  virtual double omega() const = 0;
  /// Exact answers on: the full pull-backs are computed on a worker thread.
  virtual bool full() const = 0;
  /// Session ids of the constraints, increasing.
  virtual std::vector<int> ids() const = 0;

  // Edits; each leaves the design unchanged if it throws (Message_error, Invalid_input).
  // `solve_ms` receives the time the reduced solver took for the edit (the full pull-backs
  // are the worker's).
  virtual int add(const TVF::internal::Json& constraint, double& solve_ms) = 0;
  virtual void change(int id, const TVF::internal::Json& constraint, double& solve_ms) = 0;
  virtual void remove(int id) = 0;
  virtual void clear() = 0;
  /// A whole constraint file object of the design's kind; all or nothing.  Returns the new ids
  /// in file order.
  virtual std::vector<int> load(const TVF::internal::Json& file) = 0;
  /// The constraint file of the session (JSON text).
  virtual std::string save() const = 0;
  virtual void set_omega(double omega) = 0;
  virtual void set_basis_size(int size) = 0;
  /// Exact answers on (the full pull-backs on a worker thread: answers are reduced until
  /// every constraint has one) or off (the full solver and its pull-backs are dropped).
  virtual void set_full(bool full) = 0;
  /// Waits at most `timeout` for the exact answer; true once it is there.
  virtual bool wait_exact(std::chrono::milliseconds timeout) = 0;
  /// Why the exact answer cannot be had (empty if it can).
  virtual std::string refinement_error() = 0;
  /// Which answer the design gives now (exact, or reduced with its pending pull-backs).
  virtual TVF::Spline_answer answer() = 0;

  /// The field to show (after a value edit of one constraint: from its cached response).
  virtual Design_field field() = 0;

  // What the page draws of a field `x` of this design.
  /// The field as 3D vectors per face (n-fields: the first of the n vectors), and its largest length.
  virtual std::vector<float> vectors(const Eigen::VectorXd& x, double& magnitude_max) const = 0;
  /// "divergence", "curl" (vector fields, per vertex) or "energy" (n-fields: the first-order
  /// energy density, per face); `Message_error` for a scalar the design does not have.
  virtual Eigen::VectorXd scalar(const std::string& kind, const Eigen::VectorXd& x) const = 0;
  /// Whether `kind` is one of the design's scalars (checked by `set_display`).
  virtual bool has_scalar(const std::string& kind) const = 0;
  /// Fur (n-fields: strokes along every branch) or evenly spaced streamlines (every family).
  virtual std::vector<TVF::Streamline> lines(const Eigen::VectorXd& x, const Display_settings& display) const = 0;
  /// Fur of the reduced answer of the current constraints through the faces it reaches only
  /// (vector fields; the same strokes as `lines` of the reduced field, up to rounding).  False,
  /// and `out` untouched, when there is none: a display other than fur, an n-field (not yet:
  /// its strokes stop at singular vertices, whose index needs the field around them), or a
  /// basis not ready.
  virtual bool preview(const Display_settings& display, Design_preview& out) = 0;
  /// `(vertex, k)` of every vertex where the field has index `k / n != 0` (n-fields only).
  virtual std::vector<std::pair<int, int>> singularities(const Eigen::VectorXd& x) const = 0;
};

/// Vector-field splines over the model's basis.
std::unique_ptr<Field_design> make_vector_design(std::shared_ptr<const Field_model> model, int basis_size, double omega);
/// n-field splines of order `order` over the model's basis of n-fields (`Field_model::n_field_basis`).
std::unique_ptr<Field_design> make_n_field_design(std::shared_ptr<const Field_model> model, int n, int order,
                                                   int basis_size, double omega);

} // namespace tvf_viewer

#endif
