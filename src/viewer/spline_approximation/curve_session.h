// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Chapter 6 in the viewer: the `curve` session kind.  The page sends a stroke (the points a
// person drew, in order); the session keeps it and fits it with the fewest knots within a
// tolerance (`fit_spline`), so that a tolerance, degree or closed change re-fits without the
// points being sent again (doc/viewer/protocol.md).  Needs no mesh and no basis.

#ifndef TVF_VIEWER_CURVE_SESSION_H
#define TVF_VIEWER_CURVE_SESSION_H

#include "session_kind.h"

#include <CGAL/Spline_approximation/Spline_fit.h>

#include <Eigen/Core>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>

namespace tvf_viewer {

/// Limits on what a page may send.
struct Curve_limits
{
  std::size_t max_message_bytes = 1 << 20;
  int max_json_depth = 8; ///< a stroke is an array of arrays: depth 3
  std::size_t max_points = 10000;
  std::size_t max_curve_samples = 4096; ///< samples of the drawn curve (knots come on top)
};

/// How the kept stroke is fitted; `fit` and `stroke` messages change any of these.
struct Curve_settings
{
  int degree = 3;
  bool rms = false; ///< the bound is on the root-mean-square error, else on the largest
  /// In the stroke's units; unset: 0.5 % of the stroke's bounding-box diagonal.
  std::optional<double> tolerance;
  CGAL::Spline_approximation::Fit_algorithm algorithm = CGAL::Spline_approximation::Fit_algorithm::greedy_removal;
  bool closed = false;
};

/// One page's stroke and its fit.
struct Request; // messages.h

class Curve_session : public Session
{
public:
  explicit Curve_session(Curve_limits limits = Curve_limits());

  /// Answers `hello`, `stroke`, `fit`, `clear` and `ping`; anything else, and any bad
  /// message, gets an `error` naming the reason and leaves the session as it was.
  void handle_text(const std::string& text, const Send& send) override;

  /// The points kept (one row each), empty before the first stroke.
  const Eigen::MatrixXd& stroke() const { return stroke_; }
  const Curve_settings& settings() const { return settings_; }

private:
  void hello(Request& r);
  void take_stroke(Request& r);
  void refit(Request& r);
  void clear(Request& r);
  /// The settings of `r` over the current ones (all or nothing: throws on a bad member).
  Curve_settings read_settings(const Request& r) const;
  /// Fits `points` with `settings` and sends the `curve` message (empty without points).
  void answer(Request& r, const Eigen::MatrixXd& points, const Curve_settings& settings);
  std::string info_json() const;

  Curve_limits limits_;
  Eigen::MatrixXd stroke_;
  Curve_settings settings_;
};

/// The `curve` kind for `Session_kinds` (never the first: it needs no mesh, the other kinds do).
class Curve_kind : public Session_kind
{
public:
  explicit Curve_kind(Curve_limits limits = Curve_limits()) : limits_(limits) {}
  std::string name() const override { return "curve"; }
  std::unique_ptr<Session> open() const override { return std::make_unique<Curve_session>(limits_); }

private:
  Curve_limits limits_;
};

} // namespace tvf_viewer

#endif
