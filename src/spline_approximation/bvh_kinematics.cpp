// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Rotations of BVH channels, their Euler angles back, and forward kinematics.

#include <CGAL/Spline_approximation/Bvh_motion.h>

#include <cmath>

namespace CGAL {
namespace Spline_approximation {
namespace {

constexpr double degrees_per_radian = 180.0 / 3.14159265358979323846;

Eigen::Vector3d unit_axis(int axis)
{
  Eigen::Vector3d e = Eigen::Vector3d::Zero();
  e[axis] = 1;
  return e;
}

} // namespace

Eigen::Quaterniond local_rotation(const Bvh_motion& motion, std::size_t joint, Eigen::Index frame)
{
  const Bvh_joint& j = motion.joints[joint];
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  for(std::size_t c = 0; c < j.channels.size(); ++c)
    if(is_rotation(j.channels[c])) {
      const double angle = motion.frames(frame, Eigen::Index(j.first_channel + c)) / degrees_per_radian;
      q = q * Eigen::Quaterniond(Eigen::AngleAxisd(angle, unit_axis(channel_axis(j.channels[c]))));
    }
  return q;
}

Eigen::Vector3d local_translation(const Bvh_motion& motion, std::size_t joint, Eigen::Index frame)
{
  const Bvh_joint& j = motion.joints[joint];
  Eigen::Vector3d t = j.offset;
  for(std::size_t c = 0; c < j.channels.size(); ++c)
    if(!is_rotation(j.channels[c])) t[channel_axis(j.channels[c])] += motion.frames(frame, Eigen::Index(j.first_channel + c));
  return t;
}

std::vector<double> euler_angles(const Eigen::Quaterniond& r, const std::vector<Bvh_channel>& channels)
{
  std::vector<int> axes;
  for(Bvh_channel c : channels)
    if(is_rotation(c)) axes.push_back(channel_axis(c));
  if(axes.empty()) return {};
  if(axes.size() == 1) { // a rotation about that axis: its angle from the quaternion's two components there
    const double angle = 2 * std::atan2(r.vec()[axes[0]], r.w()) * degrees_per_radian;
    return {angle > 180 ? angle - 360 : (angle <= -180 ? angle + 360 : angle)};
  }
  if(axes.size() != 3 || axes[0] == axes[1] || axes[1] == axes[2] || axes[0] == axes[2])
    throw Invalid_input("Euler angles: the rotation channels must name three distinct axes (or one), not " +
                        std::to_string(axes.size()) + " channels with these axes");
  // R = R_i(a) R_j(b) R_k(c) with (i, j, k) a permutation of the axes; s = +1 for the cyclic
  // orders (xyz, yzx, zxy), -1 for the others.  Then R(i, k) = s sin b, and a, c follow from
  // the entries beside it (the usual Tait-Bryan formulas, written for every order at once).
  const int i = axes[0], j = axes[1], k = axes[2];
  const double s = ((j - i + 3) % 3 == 1) ? 1.0 : -1.0;
  const Eigen::Matrix3d R = r.normalized().toRotationMatrix();
  const double sb = std::max(-1.0, std::min(1.0, s * R(i, k)));
  const double b = std::asin(sb);
  double a, c;
  if(std::abs(sb) < 1 - 1e-12) {
    a = std::atan2(-s * R(j, k), R(k, k));
    c = std::atan2(-s * R(i, j), R(i, i));
  } else { // gimbal lock: only a +- c is determined; put it all into a
    c = 0;
    a = std::atan2(s * R(k, j), R(j, j));
  }
  return {a * degrees_per_radian, b * degrees_per_radian, c * degrees_per_radian};
}

Eigen::MatrixXd joint_positions(const Bvh_motion& motion)
{
  check_bvh_motion(motion, "joint positions");
  const std::size_t n = motion.joints.size();
  Eigen::MatrixXd P(motion.number_of_frames(), Eigen::Index(3 * n));
  std::vector<Eigen::Quaterniond> rotation(n);
  std::vector<Eigen::Vector3d> position(n);
  for(Eigen::Index f = 0; f < motion.number_of_frames(); ++f)
    for(std::size_t j = 0; j < n; ++j) {
      const int parent = motion.joints[j].parent;
      const Eigen::Vector3d t = local_translation(motion, j, f);
      const Eigen::Quaterniond r = local_rotation(motion, j, f);
      position[j] = parent < 0 ? t : Eigen::Vector3d(position[std::size_t(parent)] + rotation[std::size_t(parent)] * t);
      rotation[j] = parent < 0 ? r : rotation[std::size_t(parent)] * r;
      P.block<1, 3>(f, Eigen::Index(3 * j)) = position[j].transpose();
    }
  return P;
}

} // namespace Spline_approximation
} // namespace CGAL
