// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SPLINE_APPROXIMATION_COMPRESS_MOTION_H
#define CGAL_SPLINE_APPROXIMATION_COMPRESS_MOTION_H

/// \file compress_motion.h
/// Motion-capture compression with the fewest-knot spline fit (issue 37): every joint's rotation
/// becomes one spline curve (a unit-quaternion curve in R^4, or its Euler angles unwrapped), every
/// joint's position channels one more, each with the fewest knots that keep it within a bound in
/// degrees (rotations) or skeleton units (positions).  The compressed motion is the splines
/// resampled at every frame; the report compares what is stored with the original and measures
/// the error in degrees and, through forward kinematics, in joint positions.  With the bound at
/// the noise level the fit also regularises a jittery motion (see the tests).

#include <CGAL/Spline_approximation/Bvh_motion.h>
#include <CGAL/Spline_approximation/Spline_fit.h>

#include <Eigen/Core>

#include <cstddef>
#include <optional>
#include <vector>

namespace CGAL {
namespace Spline_approximation {

/// How a joint's rotation is fitted.
enum class Rotation_representation {
  quaternion,  ///< unit quaternions (4 channels), signs made continuous (q ~ -q), renormalised on evaluation
  euler_angles ///< the joint's angle channels as they are, unwrapped (360-degree jumps removed)
};

/// What to fit and how.
struct Motion_options
{
  int degree = 3;                                           ///< of every spline, 1 to 3
  Fit_algorithm algorithm = Fit_algorithm::greedy_removal;  ///< greedy is the fast one on thousands of frames
  double max_degrees = 1;                                   ///< > 0: every joint's rotation at every frame within this angle
  /// > 0: every position channel group (the root translation) within this distance, in skeleton
  /// units; unset: the displacement `max_degrees` causes at the end of the longest bone,
  /// `2 L sin(max_degrees / 2)`.
  std::optional<double> max_position;
  /// > 0: bound the root-mean-square angle over the frames of each joint instead of the max
  /// (`max_degrees` is then ignored).  Given the noise's RMS, this regularises a jittery
  /// motion (the discrepancy principle): a max bound lets the fit follow the noise wherever
  /// the noise is small, an RMS bound does not (measured in the tests).
  std::optional<double> rms_degrees;
  Rotation_representation representation = Rotation_representation::quaternion;
  std::size_t candidate_grid_size = 0; ///< 0: every frame a candidate knot; g: a uniform grid of g
};

/// One spline of the compressed motion: a joint's rotation or its position channels.
struct Motion_curve
{
  std::size_t joint = 0;
  bool rotation = true;            ///< else the joint's position channels
  std::vector<std::size_t> columns; ///< the channels (columns of `Bvh_motion::frames`) it stands for
  Spline_fit fit;                  ///< at parameters = frame times (quaternion: 4 columns w, x, y, z)
  double bound = 0;                ///< the max-error bound of the final fit, in the spline's own units
  int refits = 0;                  ///< how often the bound was tightened (the renormalised rotation exceeded it)
  /// Values to store: the interior knots and every control point coordinate.
  std::size_t stored_values() const
  {
    return fit.spline.number_of_interior_knots() + std::size_t(fit.spline.control_points.size());
  }
};

/// The error of one motion against another with the same skeleton and frame count.
struct Motion_error
{
  double max_degrees = 0, rms_degrees = 0;   ///< geodesic angle of R_ref^T R per joint with rotation channels, per frame
  double max_position = 0, rms_position = 0; ///< world position distance per joint (End Sites included), per frame
  Eigen::VectorXd joint_max_degrees;         ///< per joint (0 for End Sites and joints without rotation channels)
  Eigen::VectorXd joint_max_position;        ///< per joint
};

/// The compressed motion and its report.
struct Motion_compression
{
  Bvh_motion motion;               ///< the splines resampled at every frame (same skeleton and channels)
  std::vector<Motion_curve> curves;
  std::size_t stored_values = 0;   ///< knots plus control point coordinates of every curve
  std::size_t original_values = 0; ///< frames times channels
  Motion_error error;              ///< of `motion` against the input
  double seconds = 0;              ///< wall time of the fits
  double ratio() const { return stored_values > 0 ? double(original_values) / double(stored_values) : 0.0; }
};

/// The rotation and position errors of `motion` against `reference`.
/// \throws Invalid_input when the skeletons (joint count, parents, channels) or frame counts differ.
Motion_error motion_error(const Bvh_motion& reference, const Bvh_motion& motion);

/// The unit quaternions of `joint`'s rotation at every frame, one row `(w, x, y, z)` per frame,
/// each sign chosen so that consecutive rows have a non-negative dot product (the same rotation,
/// and a continuous curve to fit).
Eigen::MatrixXd continuous_quaternions(const Bvh_motion& motion, std::size_t joint);

/// Compresses `motion` (see the file's comment).  Rotation bound: the geodesic angle theta between
/// two rotations is `|q1 - q2| = 2 sin(theta / 4)` for unit quaternions on the same hemisphere, the
/// chordal bound the fit is given; the renormalised spline can exceed theta slightly, so the angle
/// reached is measured at every frame and the chordal bound tightened and the joint refitted
/// (up to 8 times) until it holds.  Euler angles: the bound on the angle vector is
/// `max_degrees / sqrt(3)` (the geodesic angle is at most the sum of the three angle errors), also verified.
/// With `rms_degrees` the same holds for the RMS over frames (the chord's RMS bound, verified in degrees).
/// \throws Invalid_input for fewer than `degree + 1` frames, a bound `<= 0` or not finite, a degree outside 1..3,
///         or (quaternions) a joint whose rotation channels are not three distinct axes or one
///         (the compressed rotation could not be written back as its channels).
Motion_compression compress_motion(const Bvh_motion& motion, const Motion_options& options);

} // namespace Spline_approximation
} // namespace CGAL

#endif
