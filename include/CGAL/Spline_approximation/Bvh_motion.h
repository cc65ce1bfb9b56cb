// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SPLINE_APPROXIMATION_BVH_MOTION_H
#define CGAL_SPLINE_APPROXIMATION_BVH_MOTION_H

/// \file Bvh_motion.h
/// Motion capture in the BVH format (Biovision Hierarchy): a skeleton of joints (ROOT, JOINT,
/// End Site) with offsets and channels, and one row of channel values per frame.  Reading with
/// the reason, line and column of every refusal; writing that reads back to the same numbers;
/// the rotations of the channels and forward kinematics (the joints' world positions).
///
/// Conventions (those of the format as commonly read):
/// - rotation channels are in degrees; a joint's local rotation is the product of its rotation
///   channels in the order listed, `R = R_first * R_second * R_third` (intrinsic rotations);
/// - a joint's local translation is its OFFSET plus its position channels (zero where absent);
/// - a joint's frame is `parent frame * Translate(local translation) * R`; its world position is
///   the translation of that frame.  End Sites have an offset and no channels.

#include <CGAL/Spline_approximation/errors.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

namespace CGAL {
namespace Spline_approximation {

/// The six channels of the format.
enum class Bvh_channel { x_position, y_position, z_position, x_rotation, y_rotation, z_rotation };

/// The name of a channel as written in files ("Xposition", ..., "Zrotation").
const char* channel_name(Bvh_channel c);
/// Whether `c` is one of the three rotation channels.
inline bool is_rotation(Bvh_channel c) { return c >= Bvh_channel::x_rotation; }
/// The axis of a channel: 0 (x), 1 (y) or 2 (z).
inline int channel_axis(Bvh_channel c) { return int(c) % 3; }

/// A joint of the skeleton (or an End Site: no name, no channels, no children).
struct Bvh_joint
{
  std::string name;                  ///< empty for an End Site
  int parent = -1;                   ///< index of the parent joint, -1 for a root
  bool end_site = false;             ///< an End Site (written as such, no channels)
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  std::vector<Bvh_channel> channels; ///< in the order of the file
  std::size_t first_channel = 0;     ///< column of its first channel in `Bvh_motion::frames`
};

/// A skeleton and its motion.  Joints are stored depth first as in the file: a parent
/// always comes before its children.
struct Bvh_motion
{
  std::vector<Bvh_joint> joints;
  double frame_time = 1.0 / 120.0; ///< seconds per frame, > 0
  Eigen::MatrixXd frames;          ///< one row per frame, one column per channel, in file order

  Eigen::Index number_of_frames() const { return frames.rows(); }
  std::size_t number_of_channels() const;
  /// Joints that are not End Sites.
  std::size_t number_of_named_joints() const;
};

/// Checks that `motion` is well formed: every parent before its child, End Sites with a parent,
/// no channels and no children, `first_channel` running through the channels in joint order, at
/// most 6 channels, finite offsets, one column of finite values per channel, a finite frame time > 0.
/// \throws Invalid_input naming `caller` and the joint otherwise.
void check_bvh_motion(const Bvh_motion& motion, const std::string& caller = "BVH motion");

/// Reads a BVH text.
/// \param source_name the name used in error messages (the file's path)
/// \throws Invalid_input with `'<source_name>' line L, column C: <reason>` for: a missing or
///         unexpected keyword or brace, a number that is not one or not finite, an unknown or
///         repeated channel name, a channel count outside 0..6 or not matching the names, a
///         frame line with the wrong number of values, a frame time that is not > 0, a frame count
///         that differs from the `Frames:` line (the line of the first extra or of `Frames:`).
Bvh_motion read_bvh(std::istream& in, const std::string& source_name = "<stream>");
/// Reads a BVH file.  \throws Invalid_input as above, and when the file cannot be opened.
Bvh_motion read_bvh(const std::string& path);

/// Writes `motion` as BVH text, every number with `significant_digits` digits (9 reproduces
/// what a float holds and reads back to the same text; 17 reproduces every double exactly).
/// \throws Invalid_input as `check_bvh_motion`.
void write_bvh(std::ostream& out, const Bvh_motion& motion, int significant_digits = 9);
/// Writes a BVH file.  \throws Invalid_input as above, and when the file cannot be written.
void write_bvh(const std::string& path, const Bvh_motion& motion, int significant_digits = 9);

/// The local rotation of `joint` at `frame` (identity without rotation channels).
Eigen::Quaterniond local_rotation(const Bvh_motion& motion, std::size_t joint, Eigen::Index frame);
/// The local translation of `joint` at `frame`: its offset plus its position channels.
Eigen::Vector3d local_translation(const Bvh_motion& motion, std::size_t joint, Eigen::Index frame);

/// The angles in degrees, one per rotation channel of `channels` in their order, whose product
/// `R_first * R_second * R_third` is `r`.  Needs three distinct rotation axes (any order), or a
/// single one (then `r` must be a rotation about that axis; its angle is returned).  Angles
/// lie in (-180, 180].
/// \throws Invalid_input for two rotation channels, or a repeated axis.
std::vector<double> euler_angles(const Eigen::Quaterniond& r, const std::vector<Bvh_channel>& channels);

/// Forward kinematics: the world position of every joint (End Sites included) at every frame,
/// one row per frame, columns `3 * joint .. 3 * joint + 2`.  \throws Invalid_input as `check_bvh_motion`.
Eigen::MatrixXd joint_positions(const Bvh_motion& motion);

} // namespace Spline_approximation
} // namespace CGAL

#endif
