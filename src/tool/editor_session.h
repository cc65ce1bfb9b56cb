// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The field editor's sessions (`tvf serve`): what the server does with a message of the
// page, independent of the transport (doc/editor_protocol.md).  The transport (Boost.Beast,
// serve_command.cpp) hands every complete text message to `Editor_session::handle_text`
// and sends what comes back through `Send`.

#ifndef TVF_TOOL_EDITOR_SESSION_H
#define TVF_TOOL_EDITOR_SESSION_H

#include <CGAL/Tangent_vector_fields/Field_constraint.h>
#include <CGAL/Tangent_vector_fields/Operator_matrices.h>

#include <Eigen/Core>

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace CGAL {
namespace Tangent_vector_fields {
class Eigenfield_basis;
class Hodge_solver;
class Reduced_spline_solver;
class Full_spline_solver;
} // namespace Tangent_vector_fields
} // namespace CGAL

namespace tvf_tool {

namespace TVF = CGAL::Tangent_vector_fields;

/// A message to the page: JSON text, or a binary message (header and arrays).
struct Outgoing
{
  bool binary = false;
  std::string data;
};
typedef std::function<void(const Outgoing&)> Send;

/// Limits on what a page may ask for.
struct Editor_limits
{
  std::size_t max_message_bytes = 1 << 20;
  int max_json_depth = 32;
  int max_constraints = 1000;
  int max_strokes = 200000;
};

/// What the sessions share: the mesh, its Hodge solver and the basis, which a background
/// job computes or loads while the first pages wait (they see its progress).
class Editor_model
{
public:
  Editor_model(std::shared_ptr<const TVF::Operator_matrices> matrices, std::shared_ptr<TVF::Hodge_solver> hodge,
               std::string name, double diagonal, int initial_basis_size, Editor_limits limits);
  ~Editor_model();

  // Called by the job that provides the basis.
  void set_progress(const std::string& stage, double fraction);
  void set_basis(std::shared_ptr<const TVF::Eigenfield_basis> basis);
  void set_failure(const std::string& reason);

  struct Status
  {
    bool ready = false, failed = false;
    std::string stage, error;
    double fraction = 0;
  };
  /// The state of the basis, after waiting at most `timeout` for it to become ready.
  Status wait(std::chrono::milliseconds timeout) const;

  const TVF::Operator_matrices& matrices() const { return *matrices_; }
  std::shared_ptr<const TVF::Operator_matrices> shared_matrices() const { return matrices_; }
  std::shared_ptr<const TVF::Hodge_solver> hodge() const { return hodge_; }
  /// Null until ready.
  std::shared_ptr<const TVF::Eigenfield_basis> basis() const;
  const std::string& name() const { return name_; }
  double diagonal() const { return diagonal_; }
  int initial_basis_size() const { return initial_basis_size_; }
  const Editor_limits& limits() const { return limits_; }
  /// The full-resolution solves share the Hodge solver's factorisations (CHOLMOD's
  /// workspace is not thread-safe): one session at a time.
  std::mutex& full_solver_mutex() const { return full_mutex_; }
  /// The binary `mesh` message (made once).
  const Outgoing& mesh_message() const;

private:
  std::shared_ptr<const TVF::Operator_matrices> matrices_;
  std::shared_ptr<TVF::Hodge_solver> hodge_;
  std::string name_;
  double diagonal_;
  int initial_basis_size_;
  Editor_limits limits_;
  mutable std::mutex mutex_, full_mutex_;
  mutable std::condition_variable changed_;
  Status status_;
  std::shared_ptr<const TVF::Eigenfield_basis> basis_;
  mutable std::unique_ptr<Outgoing> mesh_message_;
  mutable std::once_flag mesh_once_;
};

/// One page's editing session: its constraints, tension, basis size, solver and display.
class Editor_session
{
public:
  explicit Editor_session(std::shared_ptr<const Editor_model> model);
  ~Editor_session();

  /// Answers a text message (possibly with several messages: progress, then the field).
  /// Bad messages get an `error` answer and leave the session as it was; this never throws
  /// for anything the page sends (only if `send` throws, e.g. the connection dropped).
  void handle_text(const std::string& text, const Send& send);
  /// Binary messages and messages over the size limit are refused with an `error`.
  void refuse_binary(std::size_t bytes, const Send& send);
  void refuse_oversized(std::size_t bytes, const Send& send);

private:
  struct Request;
  struct Entry;
  void dispatch(Request& request);
  void hello(Request& request);
  void add(Request& request);
  void change(Request& request);
  void remove(Request& request);
  void clear(Request& request);
  void load(Request& request);
  void save(Request& request);
  void set_omega(Request& request);
  void set_basis_size(Request& request);
  void set_solver(Request& request);
  void set_display(Request& request);

  void require_ready(const Request& request) const;
  std::string info_json() const;
  void send_field(Request& request);
  // The full solver, caught up with the constraints (progress through `request`).
  void sync_full(Request& request);
  // The reduced field after a value edit of constraint `id` (already applied to the solver),
  // from the field's cached linear response to that constraint's values; false if the
  // constraint has no such values (a direction).
  bool value_edit_field(int id, const TVF::Field_constraint& constraint, Eigen::VectorXd& field);

  std::shared_ptr<const Editor_model> model_;
  std::unique_ptr<TVF::Reduced_spline_solver> reduced_;
  std::unique_ptr<TVF::Full_spline_solver> full_;
  std::map<int, Entry> entries_; // by session id
  // Fast value edits (a drag of a vector's tip): the field is affine in one constraint's
  // values, so with its response fields cached an edit costs O(nf) instead of a
  // reconstruction, O(d nf).  Valid while the constraint set's structure (rows, omega,
  // basis size) is unchanged: `structure_` counts its changes.
  struct Value_responses
  {
    int id = -1;
    long structure = -1;
    std::vector<double> parameters;
    Eigen::VectorXd field;     // the reduced field at `parameters`
    Eigen::MatrixXd responses; // its change per unit change of each parameter
  } responses_;
  long structure_ = 0;
  Eigen::VectorXd edited_field_; // set by a fast value edit for send_field
  bool has_edited_field_ = false;
  double edited_field_ms_ = 0;
  int next_id_ = 0;
  double omega_ = 0;
  bool use_full_ = false;
  struct Display
  {
    std::string lines = "fur", scalar = "none";
    int strokes = 4000;
    double length = 0.02, separation = 0.03;
  } display_;
};

} // namespace tvf_tool

#endif
