// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// tvf fit-motion: a BVH motion compressed by fewest-knot splines (Chapter 6, issue 37): every
// joint's rotation and position channels fitted within bounds in degrees and skeleton units,
// the report table printed and the resampled motion written back as BVH.

#include "tool.h"

#include <CGAL/Spline_approximation/compress_motion.h>

#include <cstdio>
#include <map>
#include <set>

namespace tvf_tool {

namespace SA = CGAL::Spline_approximation;

namespace {

// `tvf fit-motion in.bvh out.bvh`: the tool's parser reads one positional argument, so a second
// one (the output) is passed on as `-o`.
Arguments with_output_positional(const Arguments& args, const std::set<std::string>& valued_options)
{
  Arguments out;
  int positionals = 0;
  for(std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if(a.size() > 1 && a[0] == '-') {
      out.push_back(a);
      if(valued_options.count(a) && i + 1 < args.size()) out.push_back(args[++i]); // its value, whatever it looks like
      continue;
    }
    if(++positionals == 2) out.push_back("--output");
    out.push_back(a);
  }
  return out;
}

std::string joint_label(const SA::Bvh_motion& m, std::size_t j)
{
  return m.joints[j].end_site ? "End Site of " + m.joints[std::size_t(m.joints[j].parent)].name : m.joints[j].name;
}

} // namespace

int fit_motion_command(const Arguments& raw_args)
{
  Command_line command(
      "tvf fit-motion <in.bvh> <out.bvh> (--max-degrees X | --rms-degrees X) [--max-position Y] [--degree K] "
      "[--algorithm greedy|penalty] [--representation quaternion|euler]",
      "Compresses a BVH motion capture (Chapter 6, SPEC 14): every joint's rotation becomes one spline with the\n"
      "fewest knots over the frame times (a unit-quaternion curve, signs made continuous, renormalised; or the\n"
      "joint's Euler angles unwrapped), every joint's position channels (the root translation) one more.\n"
      "Rotations stay within --max-degrees of the input at every frame (geodesic angle, verified after\n"
      "renormalising), or within --rms-degrees root-mean-square over the frames (give the noise's RMS to\n"
      "smooth a jittery capture); positions within --max-position skeleton units (default: the displacement\n"
      "the rotation bound causes at the end of the longest bone).  Prints per joint the knots, stored values\n"
      "and errors, and in total the stored values (knots + control point coordinates) against the original's\n"
      "frames x channels, the rotation error in degrees and the joint position error through forward\n"
      "kinematics; writes the splines resampled at every frame as BVH (same skeleton and channels).",
      false);
  command.positional("in.bvh", "the motion to compress; the second argument: the BVH file to write (or -o)");
  command.group("fit").add_options()
    ("max-degrees", po::value<double>()->value_name("X"), "every joint's rotation within X degrees at every frame")
    ("rms-degrees", po::value<double>()->value_name("X"), "every joint's RMS rotation error within X degrees")
    ("max-position", po::value<double>()->value_name("Y"), "position channels within Y skeleton units")
    ("degree", po::value<int>()->value_name("K")->default_value(3), "1 (linear) to 3 (cubic)")
    ("algorithm", po::value<std::string>()->value_name("A")->default_value("greedy"),
     "greedy (knot removal) or penalty (penalty decomposition)")
    ("representation", po::value<std::string>()->value_name("R")->default_value("quaternion"),
     "quaternion (unit quaternions, 4 channels) or euler (the joint's angles, unwrapped)")
    ("candidate-grid", po::value<std::size_t>()->value_name("G")->default_value(0),
     "0: every frame a candidate knot; G: a uniform grid of G")
    ("digits", po::value<int>()->value_name("D")->default_value(9), "significant digits of the written numbers")
    ("output,o", po::value<std::string>()->value_name("FILE"), "the BVH file to write");
  const Arguments args = with_output_positional(
      raw_args, {"--max-degrees", "--rms-degrees", "--max-position", "--degree", "--algorithm", "--representation",
                 "--candidate-grid", "--digits", "--output", "-o"});
  if(!command.parse(args)) return 0; // --help
  command.exactly_one({"max-degrees", "rms-degrees"});
  const std::string path = command.positional_value();

  SA::Motion_options options;
  options.degree = command.get<int>("degree");
  if(command.has("max-degrees")) options.max_degrees = command.get<double>("max-degrees");
  if(command.has("rms-degrees")) options.rms_degrees = command.get<double>("rms-degrees");
  if(command.has("max-position")) options.max_position = command.get<double>("max-position");
  options.candidate_grid_size = command.get<std::size_t>("candidate-grid");
  const std::map<std::string, SA::Fit_algorithm> algorithms = {{"greedy", SA::Fit_algorithm::greedy_removal},
                                                               {"penalty", SA::Fit_algorithm::penalty_decomposition}};
  const auto algorithm = algorithms.find(command.get<std::string>("algorithm"));
  if(algorithm == algorithms.end())
    throw Usage_error("'--algorithm' must be greedy or penalty, not '" + command.get<std::string>("algorithm") + "'");
  options.algorithm = algorithm->second;
  const std::string representation = command.get<std::string>("representation");
  if(representation != "quaternion" && representation != "euler")
    throw Usage_error("'--representation' must be quaternion or euler, not '" + representation + "'");
  if(representation == "euler") options.representation = SA::Rotation_representation::euler_angles;

  SA::Bvh_motion motion;
  SA::Motion_compression result;
  try {
    motion = SA::read_bvh(path);
    result = SA::compress_motion(motion, options);
  } catch(const SA::Invalid_input& e) {
    throw Tool_error(one_line(e.what()));
  }
  const std::size_t joints = motion.number_of_named_joints(), end_sites = motion.joints.size() - joints;
  say("motion: %s, %zu joints and %zu End Sites, %ld frames at %.6g Hz, %zu channels\n", path.c_str(), joints, end_sites,
      long(motion.number_of_frames()), 1.0 / motion.frame_time, motion.number_of_channels());
  const double position_bound = [&] {
    for(const SA::Motion_curve& c : result.curves)
      if(!c.rotation) return c.bound;
    return 0.0;
  }();
  char positions[64] = "";
  if(position_bound > 0) std::snprintf(positions, sizeof positions, ", positions within %.6g units", position_bound);
  say("fit: degree %d, %s, %s; rotations within %.6g degrees (%s)%s\n", options.degree,
      SA::algorithm_name(options.algorithm), representation == "euler" ? "Euler angles unwrapped" : "unit quaternions",
      options.rms_degrees ? *options.rms_degrees : options.max_degrees, options.rms_degrees ? "RMS" : "max", positions);
  say("%-24s %8s %9s %8s %11s %11s %12s\n", "joint", "channels", "rot.knots", "pos.knots", "stored", "max deg", "max position");
  std::vector<std::size_t> rotation_knots(motion.joints.size(), 0), position_knots(motion.joints.size(), 0),
      stored(motion.joints.size(), 0);
  for(const SA::Motion_curve& c : result.curves) {
    (c.rotation ? rotation_knots : position_knots)[c.joint] = c.fit.number_of_knots();
    stored[c.joint] += c.stored_values();
  }
  for(std::size_t j = 0; j < motion.joints.size(); ++j)
    say("%-24s %8zu %9zu %8zu %11zu %11.4g %12.4g\n", joint_label(motion, j).substr(0, 24).c_str(),
        motion.joints[j].channels.size(), rotation_knots[j], position_knots[j], stored[j],
        result.error.joint_max_degrees[Eigen::Index(j)], result.error.joint_max_position[Eigen::Index(j)]);
  say("stored values %zu of %zu (frames x channels): ratio %.2f\n", result.stored_values, result.original_values,
      result.ratio());
  say("rotation error: max %.4g, RMS %.4g degrees; joint position error: max %.4g, RMS %.4g units; %.3f s\n",
      result.error.max_degrees, result.error.rms_degrees, result.error.max_position, result.error.rms_position,
      result.seconds);
  int refits = 0;
  for(const SA::Motion_curve& c : result.curves) refits += c.refits;
  if(refits > 0) say("(%d refits with a tighter bound: renormalising had crossed the rotation bound)\n", refits);
  if(command.has("output")) {
    const std::string out = command.get<std::string>("output");
    try {
      SA::write_bvh(out, result.motion, command.get<int>("digits"));
    } catch(const SA::Invalid_input& e) {
      throw Tool_error(one_line(e.what()));
    }
    say("wrote %s\n", out.c_str());
  } else {
    say("(no output file given: nothing written)\n");
  }
  return 0;
}

} // namespace tvf_tool
