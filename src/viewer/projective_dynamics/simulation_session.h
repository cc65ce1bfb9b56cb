// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Chapter 3 in the viewer: the `simulation` session kind.  The served surface, as a shell or
// a solid, falls onto a floor in real time (hyper-reduced Projective Dynamics by default);
// the page grabs, drags and pokes it and changes its stiffness while it moves.  After the
// mesh, each step sends only the surface's positions and the step's timings
// (doc/viewer/protocol.md).

#ifndef TVF_VIEWER_SIMULATION_SESSION_H
#define TVF_VIEWER_SIMULATION_SESSION_H

#include "session_kind.h"
#include "messages.h"
#include "simulation_body.h"

#include <chrono>
#include <memory>
#include <optional>
#include <string>

namespace tvf_viewer {

/// Limits on what a page may send.
struct Simulation_limits
{
  std::size_t max_message_bytes = 1 << 16;
  int max_json_depth = 4;
  int max_steps = 1000; ///< of one `step` message
  double frame_hz = 60; ///< steps per second of wall time while playing, at most
};

/// One page's simulation.
struct Request; // messages.h

class Simulation_session : public Session
{
public:
  Simulation_session(std::shared_ptr<const Simulation_surface> surface, Simulation_limits limits);

  /// Answers `hello`, `play`, `pause`, `step`, `reset`, `drop`, `grab`, `move`, `release`,
  /// `poke`, `stiffness`, `time_step` and `ping`; anything else, and any bad message, gets an
  /// `error` naming the reason and leaves the simulation as it was.
  void handle_text(const std::string& text, const Send& send) override;
  /// Steps while playing, at most `frame_hz` times a second of wall time.
  bool refining() override { return playing_ && body_ != nullptr; }
  void poll(const Send& send, std::chrono::milliseconds budget) override;

private:
  void hello(Request& r);
  void grab(Request& r);
  void poke(Request& r);
  /// One step and its frame (`interval_ms` < 0: not paced); false if it blew up (then
  /// paused, the state before the step kept, and an `error` sent).
  bool step_and_send(const Send& send, double interval_ms, const std::string& echo);
  void send_frame(const Send& send, double simulation_ms, double interval_ms, const std::string& echo);
  /// The surface vertex a message names: `vertex`, or the nearest to `point`.
  int vertex_of(const Json& tree) const;
  std::string state_json() const;
  /// Starts again from `q` at rest (velocities zero, grab released).
  void restart(const PD::Positions& q);

  std::shared_ptr<const Simulation_surface> surface_;
  Simulation_limits limits_;
  std::unique_ptr<Simulation_body> body_;
  bool playing_ = false;
  long long steps_ = 0;
  double time_ = 0, time_step_ = 1.0 / 60;
  std::optional<int> grabbed_;             ///< the surface vertex held
  Eigen::RowVector3d grab_offset_ = Eigen::RowVector3d::Zero(); ///< simulated minus surface vertex
  PD::Positions drawn_;                    ///< the surface now
  Clock::time_point next_due_, last_frame_;
  bool paced_ = false;                     ///< last_frame_ is a paced frame
};

/// The `simulation` kind for `Session_kinds` (never the first: the field kinds are the default).
class Simulation_kind : public Session_kind
{
public:
  explicit Simulation_kind(std::shared_ptr<const Simulation_surface> surface, Simulation_limits limits = Simulation_limits())
    : surface_(std::move(surface)), limits_(limits)
  {}
  std::string name() const override { return "simulation"; }
  std::unique_ptr<Session> open() const override { return std::make_unique<Simulation_session>(surface_, limits_); }

private:
  std::shared_ptr<const Simulation_surface> surface_;
  Simulation_limits limits_;
};

} // namespace tvf_viewer

#endif
