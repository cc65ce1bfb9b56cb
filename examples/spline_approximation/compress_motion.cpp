// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Compresses a motion capture: a generated arm (a root that walks and turns, a shoulder, an elbow
// and a wrist, 6 seconds at 120 Hz) written as BVH and read back, every joint's rotation fitted
// as a unit-quaternion spline within a bound in degrees; prints the stored values against the
// original's and the errors, writes the compressed motion and checks that it reads back the same.
//
// Usage: compress_motion [max-degrees] [output.bvh]

#include <CGAL/Spline_approximation/compress_motion.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace SA = CGAL::Spline_approximation;

int main(int argc, char** argv)
{
  const double max_degrees = argc > 1 ? std::atof(argv[1]) : 1.0;
  const char* output = argc > 2 ? argv[2] : nullptr;
  // The motion as a BVH text: a 6-channel root, three joints with three rotations each.
  std::ostringstream text;
  text << "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
          " JOINT Shoulder\n {\n  OFFSET 0 50 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n"
          "  JOINT Elbow\n  {\n   OFFSET 30 0 0\n   CHANNELS 3 Zrotation Xrotation Yrotation\n"
          "   JOINT Wrist\n   {\n    OFFSET 25 0 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n"
          "    End Site\n    {\n     OFFSET 8 0 0\n    }\n   }\n  }\n }\n}\nMOTION\nFrames: 720\nFrame Time: 0.0083333333\n";
  const double pi = 3.14159265358979323846;
  for(int f = 0; f < 720; ++f) {
    const double t = f / 120.0, g = 2 * pi * t;
    text << 100 * t << ' ' << 90 + 2 * std::sin(2 * g) << " 0 " << 0.5 * std::sin(g) << ' ' << 3 * std::sin(g + 1) << ' '
         << 30 * t; // the root turns through 180 degrees
    for(int j = 0; j < 3; ++j)
      text << ' ' << 40 * std::sin(g + j) << ' ' << 15 * std::sin(2 * g + j) << ' ' << 10 * std::cos(g + 2 * j);
    text << '\n';
  }
  std::istringstream in(text.str());
  const SA::Bvh_motion motion = SA::read_bvh(in, "arm.bvh");

  SA::Motion_options options; // cubic, greedy removal, unit quaternions
  options.max_degrees = max_degrees;
  const SA::Motion_compression c = SA::compress_motion(motion, options);
  std::printf("%zu joints, %ld frames, %zu channels; within %g degrees\n", motion.number_of_named_joints(),
              long(motion.number_of_frames()), motion.number_of_channels(), max_degrees);
  for(const SA::Motion_curve& curve : c.curves)
    std::printf("  %-9s %-8s %3zu knots, %4zu values\n", motion.joints[curve.joint].name.c_str(),
                curve.rotation ? "rotation" : "position", curve.fit.number_of_knots(), curve.stored_values());
  std::printf("stored values %zu of %zu: ratio %.2f\n", c.stored_values, c.original_values, c.ratio());
  std::printf("rotation error: max %.4f, RMS %.4f degrees; joint positions: max %.4f, RMS %.4f\n", c.error.max_degrees,
              c.error.rms_degrees, c.error.max_position, c.error.rms_position);

  // Written and read back: the same motion to the printed digits.
  std::stringstream file;
  SA::write_bvh(file, c.motion);
  const SA::Motion_error again = SA::motion_error(motion, SA::read_bvh(file, "compressed.bvh"));
  std::printf("read back: max %.4f degrees (bound met: %s)\n", again.max_degrees,
              again.max_degrees <= max_degrees * (1 + 1e-6) ? "yes" : "no");
  if(output) {
    SA::write_bvh(std::string(output), c.motion);
    std::printf("wrote %s\n", output);
  }
  return again.max_degrees <= max_degrees * (1 + 1e-6) ? 0 : 1;
}
