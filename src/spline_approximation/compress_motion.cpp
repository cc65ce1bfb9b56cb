// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Motion compression: one fewest-knot spline per joint rotation and per group of position
// channels, the rotation bound verified on the renormalised result.

#include <CGAL/Spline_approximation/compress_motion.h>

#include <chrono>
#include <cmath>
#include <string>

namespace CGAL {
namespace Spline_approximation {
namespace {

constexpr double pi = 3.14159265358979323846;

// The geodesic angle in degrees between two rotations; atan2 keeps it accurate down to 1e-12
// degrees, where acos of the dot product would lose half the digits.
double angle_between(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
  const Eigen::Quaterniond d = a.conjugate() * b;
  return 2 * std::atan2(d.vec().norm(), std::abs(d.w())) * 180 / pi;
}

// The chordal distance of unit quaternions on one hemisphere whose rotations differ by `degrees`.
double chord_for(double degrees) { return 2 * std::sin(degrees * pi / 180 / 4); }

std::vector<std::size_t> columns_of(const Bvh_joint& joint, bool rotation)
{
  std::vector<std::size_t> c;
  for(std::size_t i = 0; i < joint.channels.size(); ++i)
    if(is_rotation(joint.channels[i]) == rotation) c.push_back(joint.first_channel + i);
  return c;
}

Eigen::MatrixXd gather(const Eigen::MatrixXd& frames, const std::vector<std::size_t>& columns)
{
  Eigen::MatrixXd G(frames.rows(), Eigen::Index(columns.size()));
  for(std::size_t i = 0; i < columns.size(); ++i) G.col(Eigen::Index(i)) = frames.col(Eigen::Index(columns[i]));
  return G;
}

// The value nearest `reference` among `angle + 360 k`: written angles stay on the original's branch.
double nearest_turn(double angle, double reference) { return angle + 360 * std::round((reference - angle) / 360); }

void check_options(const Bvh_motion& motion, const Motion_options& o)
{
  if(o.degree < 1 || o.degree > 3)
    throw Invalid_input("compress_motion: the degree must be 1, 2 or 3, not " + std::to_string(o.degree));
  if(!(o.max_degrees > 0 && std::isfinite(o.max_degrees)))
    throw Invalid_input("compress_motion: the rotation bound in degrees must be finite and > 0");
  if(o.rms_degrees && !(*o.rms_degrees > 0 && std::isfinite(*o.rms_degrees)))
    throw Invalid_input("compress_motion: the RMS rotation bound in degrees must be finite and > 0");
  if(o.max_position && !(*o.max_position > 0 && std::isfinite(*o.max_position)))
    throw Invalid_input("compress_motion: the position bound must be finite and > 0");
  if(motion.number_of_frames() < o.degree + 1)
    throw Invalid_input("compress_motion: the motion has " + std::to_string(motion.number_of_frames()) +
                        " frames; a spline of degree " + std::to_string(o.degree) + " needs at least " +
                        std::to_string(o.degree + 1));
  check_bvh_motion(motion, "compress_motion");
  if(o.representation == Rotation_representation::quaternion)
    for(const Bvh_joint& j : motion.joints) {
      const std::vector<std::size_t> r = columns_of(j, true);
      if(r.empty()) continue;
      try {
        euler_angles(Eigen::Quaterniond::Identity(), j.channels);
      } catch(const Invalid_input&) {
        throw Invalid_input("compress_motion: joint '" + j.name + "' has " + std::to_string(r.size()) +
                            " rotation channels that are not three distinct axes or one; the fitted quaternion "
                            "could not be written back as its channels (fit its Euler angles instead)");
      }
    }
}

// The longest bone: the default position bound is the displacement the rotation bound causes there.
double longest_bone(const Bvh_motion& motion)
{
  double L = 0;
  for(const Bvh_joint& j : motion.joints)
    if(j.parent >= 0) L = std::max(L, j.offset.norm());
  return L > 0 ? L : 1.0;
}

// The worst (or root-mean-square) geodesic angle of the joint's rotation between two motions over the frames.
double angle_error(const Bvh_motion& a, const Bvh_motion& b, std::size_t joint, bool rms)
{
  double worst = 0, sum = 0;
  for(Eigen::Index f = 0; f < a.number_of_frames(); ++f) {
    const double angle = angle_between(local_rotation(a, joint, f), local_rotation(b, joint, f));
    worst = std::max(worst, angle);
    sum += angle * angle;
  }
  return rms ? std::sqrt(sum / double(a.number_of_frames())) : worst;
}

// Fits `samples` within `bound`, writes the resampled values through `store`, and tightens the
// bound while `error_after_store()` (in degrees) exceeds `target` (a few refits at most).
// `rms`: the bound is on the root-mean-square error, else on the max.
template <class Store, class Measure>
Motion_curve fit_within(const Eigen::MatrixXd& samples, const Eigen::VectorXd& t, const Motion_options& o, bool rms,
                        double bound, double target, const Store& store, const Measure& error_after_store)
{
  Motion_curve curve;
  Fit_options f;
  f.degree = o.degree;
  f.algorithm = o.algorithm;
  f.candidate_grid_size = o.candidate_grid_size;
  for(int attempt = 0;; ++attempt) {
    (rms ? f.rms_error : f.max_error) = bound;
    curve.fit = fit_spline(samples, t, f);
    curve.bound = bound;
    curve.refits = attempt;
    store(curve.fit.spline.evaluate(curve.fit.parameters));
    const double reached = error_after_store();
    if(reached <= target || attempt == 8 || !curve.fit.within_bound) break; // a bound not met stays not met
    // The bound was met in the fitted space but not in degrees: shrink it by the overshoot, and by 10 % at least.
    bound *= std::min(0.9, target / reached);
  }
  return curve;
}

} // namespace

Eigen::MatrixXd continuous_quaternions(const Bvh_motion& motion, std::size_t joint)
{
  Eigen::MatrixXd Q(motion.number_of_frames(), 4);
  for(Eigen::Index f = 0; f < motion.number_of_frames(); ++f) {
    const Eigen::Quaterniond q = local_rotation(motion, joint, f);
    Q.row(f) << q.w(), q.x(), q.y(), q.z();
    if(f > 0 && Q.row(f).dot(Q.row(f - 1)) < 0) Q.row(f) *= -1; // q and -q are one rotation
  }
  return Q;
}

Motion_error motion_error(const Bvh_motion& reference, const Bvh_motion& motion)
{
  if(reference.joints.size() != motion.joints.size() || reference.number_of_frames() != motion.number_of_frames())
    throw Invalid_input("motion error: the motions differ in joint count or frame count");
  for(std::size_t j = 0; j < reference.joints.size(); ++j)
    if(reference.joints[j].parent != motion.joints[j].parent || reference.joints[j].channels != motion.joints[j].channels)
      throw Invalid_input("motion error: the skeletons differ at joint " + std::to_string(j));
  Motion_error e;
  const std::size_t n = reference.joints.size();
  const Eigen::Index frames = reference.number_of_frames();
  e.joint_max_degrees = Eigen::VectorXd::Zero(Eigen::Index(n));
  e.joint_max_position = Eigen::VectorXd::Zero(Eigen::Index(n));
  double sum_degrees = 0, sum_position = 0;
  std::size_t rotating = 0;
  for(std::size_t j = 0; j < n; ++j) {
    if(columns_of(reference.joints[j], true).empty()) continue;
    ++rotating;
    for(Eigen::Index f = 0; f < frames; ++f) {
      const double a = angle_between(local_rotation(reference, j, f), local_rotation(motion, j, f));
      e.joint_max_degrees[Eigen::Index(j)] = std::max(e.joint_max_degrees[Eigen::Index(j)], a);
      sum_degrees += a * a;
    }
  }
  const Eigen::MatrixXd P = joint_positions(reference), Q = joint_positions(motion);
  for(std::size_t j = 0; j < n; ++j)
    for(Eigen::Index f = 0; f < frames; ++f) {
      const double d = (P.block<1, 3>(f, Eigen::Index(3 * j)) - Q.block<1, 3>(f, Eigen::Index(3 * j))).norm();
      e.joint_max_position[Eigen::Index(j)] = std::max(e.joint_max_position[Eigen::Index(j)], d);
      sum_position += d * d;
    }
  e.max_degrees = n > 0 ? e.joint_max_degrees.maxCoeff() : 0;
  e.max_position = n > 0 ? e.joint_max_position.maxCoeff() : 0;
  e.rms_degrees = rotating > 0 && frames > 0 ? std::sqrt(sum_degrees / double(rotating * std::size_t(frames))) : 0;
  e.rms_position = n > 0 && frames > 0 ? std::sqrt(sum_position / double(n * std::size_t(frames))) : 0;
  return e;
}

Motion_compression compress_motion(const Bvh_motion& motion, const Motion_options& o)
{
  const auto start = std::chrono::steady_clock::now();
  check_options(motion, o);
  const Eigen::Index frames = motion.number_of_frames();
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(frames, 0.0, double(frames - 1)) * motion.frame_time;
  const double max_position = o.max_position ? *o.max_position : 2 * longest_bone(motion) * std::sin(o.max_degrees * pi / 360);
  Motion_compression out;
  out.motion = motion;
  Eigen::MatrixXd& written = out.motion.frames;
  for(std::size_t j = 0; j < motion.joints.size(); ++j) {
    const Bvh_joint& joint = motion.joints[j];
    const std::vector<std::size_t> rotation = columns_of(joint, true), position = columns_of(joint, false);
    const bool rms = bool(o.rms_degrees);
    const double degrees = rms ? *o.rms_degrees : o.max_degrees;
    const auto rotation_error = [&] { return angle_error(motion, out.motion, j, rms); };
    if(!rotation.empty() && o.representation == Rotation_representation::quaternion) {
      const Eigen::MatrixXd Q = continuous_quaternions(motion, j);
      const auto store = [&](const Eigen::MatrixXd& fitted) {
        for(Eigen::Index f = 0; f < frames; ++f) {
          Eigen::Quaterniond q(fitted(f, 0), fitted(f, 1), fitted(f, 2), fitted(f, 3));
          const std::vector<double> angles = euler_angles(q.normalized(), joint.channels);
          for(std::size_t i = 0; i < rotation.size(); ++i)
            written(f, Eigen::Index(rotation[i])) = nearest_turn(angles[i], motion.frames(f, Eigen::Index(rotation[i])));
        }
      };
      out.curves.push_back(fit_within(Q, t, o, rms, chord_for(degrees), degrees, store, rotation_error));
    } else if(!rotation.empty()) {
      // Unwrapped: remove the 360-degree jumps, remembering them to put the fit back on the file's branch.
      Eigen::MatrixXd A = gather(motion.frames, rotation);
      const Eigen::MatrixXd original = A;
      for(Eigen::Index f = 1; f < frames; ++f)
        for(Eigen::Index c = 0; c < A.cols(); ++c) A(f, c) = nearest_turn(A(f, c), A(f - 1, c));
      const Eigen::MatrixXd shift = original - A;
      const auto store = [&](const Eigen::MatrixXd& fitted) {
        for(std::size_t i = 0; i < rotation.size(); ++i)
          written.col(Eigen::Index(rotation[i])) = fitted.col(Eigen::Index(i)) + shift.col(Eigen::Index(i));
      };
      out.curves.push_back(
          fit_within(A, t, o, rms, degrees / std::sqrt(double(rotation.size())), degrees, store, rotation_error));
    }
    if(!rotation.empty()) {
      out.curves.back().joint = j;
      out.curves.back().columns = rotation;
    }
    if(!position.empty()) {
      const auto store = [&](const Eigen::MatrixXd& fitted) {
        for(std::size_t i = 0; i < position.size(); ++i) written.col(Eigen::Index(position[i])) = fitted.col(Eigen::Index(i));
      };
      // The fit's own max error is the distance asked for: nothing to verify after it.
      Motion_curve c = fit_within(gather(motion.frames, position), t, o, false, max_position, 0.0, store, [] { return 0.0; });
      c.joint = j;
      c.rotation = false;
      c.columns = position;
      out.curves.push_back(std::move(c));
    }
  }
  for(const Motion_curve& c : out.curves) out.stored_values += c.stored_values();
  out.original_values = std::size_t(frames) * motion.number_of_channels();
  out.error = motion_error(motion, out.motion);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

} // namespace Spline_approximation
} // namespace CGAL
