// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The field sessions of the viewer (`tvf serve`): what the server does with a message of the
// page when the session designs tangent vector fields or n-direction fields, independent of
// the transport (doc/viewer/protocol.md).  The two session kinds (field_kinds.h) open these.

#ifndef TVF_VIEWER_SESSION_H
#define TVF_VIEWER_SESSION_H

#include "field_design.h"
#include "session_kind.h"

#include <CGAL/Tangent_vector_fields/Operator_matrices.h>

#include <Eigen/Core>

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace CGAL {
namespace Tangent_vector_fields {
class Eigenfield_basis;
class Eigenfield_rows;
class Hodge_solver;
class Streamline_surface;
class N_field_basis;
class N_field_operators;
} // namespace Tangent_vector_fields
} // namespace CGAL

namespace tvf_viewer {

namespace TVF = CGAL::Tangent_vector_fields;

/// Limits on what a page may ask for.
struct Field_limits
{
  std::size_t max_message_bytes = 1 << 20;
  int max_json_depth = 32;
  int max_constraints = 1000;
  int max_strokes = 200000;
  int max_n = 12; ///< n-fields of n = 1 ... max_n
};

/// What the sessions share: the mesh, its Hodge solver and the basis, which a background
/// job computes or loads while the first pages wait (they see its progress), and the bases of
/// n-fields, each made by a background job when a page first asks for its n.
class Field_model : public std::enable_shared_from_this<Field_model>
{
public:
  Field_model(std::shared_ptr<const TVF::Operator_matrices> matrices, std::shared_ptr<TVF::Hodge_solver> hodge,
               std::string name, double diagonal, int initial_basis_size, Field_limits limits);
  ~Field_model();

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

  /// Makes (computes or loads) the basis of n-fields for `n`, reporting progress.
  typedef std::function<std::shared_ptr<const TVF::N_field_basis>(
      std::shared_ptr<const TVF::N_field_operators>, const std::function<void(const std::string&, double)>&)>
      N_field_basis_source;
  /// How n-field bases are made (`tvf serve`: loaded from or saved next to the basis file);
  /// by default the `initial` count of elements is computed.
  void set_n_field_basis_source(N_field_basis_source source);
  /// The state of the basis of n-fields, after starting its job if no page asked for this n
  /// before and waiting at most `timeout` for it.
  Status wait_n_field(int n, std::chrono::milliseconds timeout) const;
  /// Null until ready.
  std::shared_ptr<const TVF::N_field_basis> n_field_basis(int n) const;

  const TVF::Operator_matrices& matrices() const { return *matrices_; }
  std::shared_ptr<const TVF::Operator_matrices> shared_matrices() const { return matrices_; }
  std::shared_ptr<const TVF::Hodge_solver> hodge() const { return hodge_; }
  /// Null until ready.
  std::shared_ptr<const TVF::Eigenfield_basis> basis() const;
  const std::string& name() const { return name_; }
  double diagonal() const { return diagonal_; }
  int initial_basis_size() const { return initial_basis_size_; }
  const Field_limits& limits() const { return limits_; }
  /// The binary `mesh` message (made once).
  const Outgoing& mesh_message() const;
  /// What streamline tracers of the mesh share (made once, on first use).
  std::shared_ptr<const TVF::Streamline_surface> streamline_surface() const;
  /// The basis' first `d` eigenfields face by face (float32), for preview strokes through the
  /// faces they reach only (`2 nf d` floats, as much memory as those eigenfunctions in double),
  /// kept while a session of that size holds them.  Made on first request: at once if they take
  /// less than 64 MB, else by a background job (seconds at 346k faces), and null until it is
  /// done (the sessions send no preview meanwhile).  Null until the basis is ready.
  std::shared_ptr<const TVF::Eigenfield_rows> eigenfield_rows(int d) const;

private:
  std::shared_ptr<const TVF::Operator_matrices> matrices_;
  std::shared_ptr<TVF::Hodge_solver> hodge_;
  std::string name_;
  double diagonal_;
  int initial_basis_size_;
  Field_limits limits_;
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  Status status_;
  std::shared_ptr<const TVF::Eigenfield_basis> basis_;
  struct N_field_space
  {
    Status status;
    std::shared_ptr<const TVF::N_field_basis> basis;
  };
  mutable std::map<int, N_field_space> n_fields_; // by n, guarded by mutex_
  N_field_basis_source n_field_source_;
  mutable std::unique_ptr<Outgoing> mesh_message_;
  mutable std::once_flag mesh_once_;
  mutable std::shared_ptr<const TVF::Streamline_surface> surface_;   // guarded by mutex_
  struct Rows_slot
  {
    std::weak_ptr<const TVF::Eigenfield_rows> rows;
    std::shared_future<std::shared_ptr<const TVF::Eigenfield_rows>> job; // valid while being made
  };
  mutable std::map<int, Rows_slot> rows_; // by d, guarded by rows_mutex_
  mutable std::mutex rows_mutex_;
};

/// One page's editing session: its design (vector field or n-field), its display, and the
/// messages of the page.  It starts, at its `hello`, with the design of its kind (`kind`:
/// "vector_field", or "n_field" with `start_n`); `set_n` changes the design later.
class Field_session : public Session
{
public:
  explicit Field_session(std::shared_ptr<const Field_model> model, std::string kind = "vector_field", int start_n = 1);
  ~Field_session() override;

  /// Answers a text message (possibly with several messages: progress, then the field).
  /// Bad messages get an `error` answer and leave the session as it was; this never throws
  /// for anything the page sends (only if `send` throws, e.g. the connection dropped).
  void handle_text(const std::string& text, const Send& send) override;

  /// Exact answers are on and the last field sent was the reduced one: the transport calls
  /// `poll` while no message of the page waits.
  bool refining() override;
  /// Waits at most `timeout` for the exact answer and sends it (a `field` with `refined`,
  /// echoing the edit it completes), or a `refinement_failed` message if it cannot be had.
  void poll(const Send& send, std::chrono::milliseconds timeout) override;
  /// Says so when the page leaves while its exact answer was being computed.
  std::string farewell() override;
  /// The constraints of the design, and how many of them still lack their exact pull-back.
  int constraints() const;
  int pending_pull_backs();

private:
  struct Request;
  void dispatch(Request& request);
  void hello(Request& request);
  void wait_n_field(Request& request, int n);
  void set_n(Request& request);
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
  /// Sends the field (first, unless `refined`, the `preview` strokes where the design has them).
  void send_field(Request& request, bool refined = false);
  void send_preview(Request& request);

  std::shared_ptr<const Field_model> model_;
  std::string kind_;
  int start_n_;
  struct
  {
    bool has_id = false;
    long long id = 0;
    std::chrono::steady_clock::time_point received;
  } last_edit_;                // the edit whose exact field is still to come
  bool awaiting_exact_ = false; // the last field sent was the reduced one
  std::unique_ptr<Field_design> design_; // null until hello
  Display_settings display_;
};

} // namespace tvf_viewer

#endif
