// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Motion tables of bench_spline_approximation: a generated walk (21 joints, a humanoid tree,
// sums of sinusoids of a 1 Hz gait with harmonics, a slow turn through 180 degrees, capture
// jitter) and any BVH files given, compressed by compress_motion at several bounds in degrees.

#include "bench_motion.h"

#include <CGAL/Spline_approximation/compress_motion.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace SA = CGAL::Spline_approximation;

namespace {

constexpr double pi = 3.14159265358979323846;

// The humanoid: hips (6 channels), spine to head, two arms and two legs, every other joint ZXY.
SA::Bvh_motion walk_skeleton()
{
  using C = SA::Bvh_channel;
  SA::Bvh_motion m;
  auto add = [&](const char* name, int parent, Eigen::Vector3d offset) {
    SA::Bvh_joint j;
    j.name = name;
    j.parent = parent;
    j.offset = offset;
    j.channels = parent < 0 ? std::vector<C>{C::x_position, C::y_position, C::z_position, C::z_rotation, C::x_rotation, C::y_rotation}
                            : std::vector<C>{C::z_rotation, C::x_rotation, C::y_rotation};
    m.joints.push_back(j);
    return int(m.joints.size()) - 1;
  };
  auto end = [&](int parent, Eigen::Vector3d offset) {
    SA::Bvh_joint j;
    j.parent = parent;
    j.end_site = true;
    j.offset = offset;
    m.joints.push_back(j);
  };
  const int hips = add("Hips", -1, {0, 0, 0});
  int s = add("Spine", hips, {0, 10, 0});
  s = add("Spine1", s, {0, 12, 0});
  const int chest = s;
  s = add("Neck", s, {0, 15, 0});
  s = add("Head", s, {0, 8, 0});
  end(s, {0, 10, 0});
  for(double side : {1.0, -1.0}) {
    int a = add(side > 0 ? "LeftShoulder" : "RightShoulder", chest, {side * 4, 12, 0});
    a = add(side > 0 ? "LeftArm" : "RightArm", a, {side * 12, 0, 0});
    a = add(side > 0 ? "LeftForeArm" : "RightForeArm", a, {side * 26, 0, 0});
    a = add(side > 0 ? "LeftHand" : "RightHand", a, {side * 24, 0, 0});
    end(a, {side * 8, 0, 0});
    int l = add(side > 0 ? "LeftUpLeg" : "RightUpLeg", hips, {side * 9, -5, 0});
    l = add(side > 0 ? "LeftLeg" : "RightLeg", l, {0, -42, 0});
    l = add(side > 0 ? "LeftFoot" : "RightFoot", l, {0, -40, 0});
    l = add(side > 0 ? "LeftToeBase" : "RightToeBase", l, {0, -6, 12});
    end(l, {0, 0, 5});
  }
  std::size_t column = 0;
  for(SA::Bvh_joint& j : m.joints) {
    j.first_channel = column;
    column += j.channels.size();
  }
  return m;
}

// Every angle: a 1 Hz gait with two harmonics (amplitudes by joint), a slow sway, and jitter;
// the root walks forward, bobs twice a cycle and turns 6 degrees a second.
SA::Bvh_motion walk(long frames, double noise_degrees, unsigned seed = 1)
{
  SA::Bvh_motion m = walk_skeleton();
  m.frame_time = 1.0 / 120;
  const Eigen::Index channels = Eigen::Index(m.number_of_channels());
  m.frames.resize(frames, channels);
  std::mt19937 gen(seed);
  std::normal_distribution<double> jitter(0.0, noise_degrees > 0 ? noise_degrees : 1.0);
  for(Eigen::Index f = 0; f < frames; ++f) {
    const double t = double(f) * m.frame_time, gait = 2 * pi * 1.0 * t;
    m.frames.row(f).head(3) << 100 * t, 90 + 2 * std::sin(2 * gait), 5 * std::sin(0.3 * gait);
    for(Eigen::Index c = 3; c < channels; ++c) {
      const double k = double(c), amplitude = 5 + 25 * std::fabs(std::sin(1.7 * k));
      double a = amplitude * std::sin(gait + 0.9 * k) + 0.3 * amplitude * std::sin(2 * gait + 1.3 * k) +
                 0.1 * amplitude * std::sin(3 * gait + 0.4 * k) + 4 * std::sin(0.05 * gait + k);
      if(c == 5) a += 6 * t; // the root's heading turns
      m.frames(f, c) = a + (noise_degrees > 0 ? jitter(gen) : 0.0);
    }
  }
  return m;
}

std::size_t total_knots(const SA::Motion_compression& c)
{
  std::size_t k = 0;
  for(const SA::Motion_curve& curve : c.curves) k += curve.fit.number_of_knots();
  return k;
}

void compression_rows(const char* name, const SA::Bvh_motion& m, const Motion_bench_options& o)
{
  for(double bound : o.bounds)
    for(SA::Rotation_representation r : {SA::Rotation_representation::quaternion, SA::Rotation_representation::euler_angles})
      for(SA::Fit_algorithm a : {SA::Fit_algorithm::greedy_removal, SA::Fit_algorithm::penalty_decomposition}) {
        if(a == SA::Fit_algorithm::penalty_decomposition && !o.penalty) continue;
        SA::Motion_options mo;
        mo.max_degrees = bound;
        mo.representation = r;
        mo.algorithm = a;
        SA::Motion_compression c;
        try {
          c = SA::compress_motion(m, mo);
        } catch(const SA::Invalid_input& e) {
          std::printf("%-14s %6.2g | %-5s %-7s | refused: %s\n", name, bound, r == SA::Rotation_representation::quaternion ? "quat" : "euler",
                      SA::algorithm_name(a), e.what());
          continue;
        }
        int refits = 0;
        for(const SA::Motion_curve& curve : c.curves) refits += curve.refits;
        std::printf("%-14s %6.2g | %-5s %-7s | %7zu %9zu %7.2fx | %9.4f %9.4f | %9.4f %9.4f | %8.2f %6d\n", name, bound,
                    r == SA::Rotation_representation::quaternion ? "quat" : "euler", SA::algorithm_name(a), total_knots(c),
                    c.stored_values, c.ratio(), c.error.max_degrees, c.error.rms_degrees, c.error.max_position,
                    c.error.rms_position, c.seconds, refits);
        std::fflush(stdout);
      }
}

} // namespace

void motion_compression_table(const Motion_bench_options& o)
{
  std::printf("\n5. motion compression: fewest knots within a rotation bound (max geodesic angle per joint and\n"
              "   frame); positions within the default bound (the rotation bound's displacement at the longest bone);\n"
              "   ratio = frames x channels / (knots + control point values); errors in degrees and in joint\n"
              "   positions (forward kinematics, skeleton units); cubic, every frame a candidate knot\n");
  std::printf("%-14s %6s | %-5s %-7s | %7s %9s %8s | %9s %9s | %9s %9s | %8s %6s\n", "motion", "bound", "rot.", "algo",
              "knots", "stored", "ratio", "max deg", "rms deg", "max pos", "rms pos", "seconds", "refits");
  const SA::Bvh_motion generated = walk(o.frames, o.noise_degrees);
  std::printf("(walk: %zu joints, %ld frames at 120 Hz, %zu channels, jitter %g degrees)\n", generated.number_of_named_joints(),
              o.frames, generated.number_of_channels(), o.noise_degrees);
  compression_rows("walk", generated, o);
  for(const std::string& path : o.bvh_files) {
    SA::Bvh_motion m;
    try {
      m = SA::read_bvh(path);
    } catch(const SA::Invalid_input& e) {
      std::printf("%s: %s\n", path.c_str(), e.what());
      continue;
    }
    std::printf("(%s: %zu joints, %ld frames at %.4g Hz, %zu channels)\n", path.c_str(), m.number_of_named_joints(),
                long(m.number_of_frames()), 1.0 / m.frame_time, m.number_of_channels());
    const std::size_t slash = path.find_last_of('/');
    compression_rows(path.substr(slash == std::string::npos ? 0 : slash + 1).substr(0, 14).c_str(), m, o);
  }
}

void motion_jitter_table(const Motion_bench_options& o)
{
  std::printf("\n6. a jittery walk regularised: the fit of walk + noise against the clean walk (no jitter), bound\n"
              "   at the noise level (max: the noise's max angle; RMS: its RMS), quaternions, cubic, greedy;\n"
              "   candidates: every frame, or a grid of one candidate per 8 frames (grid); with\n"
              "   --motion-algorithms penalty also the penalty decomposition at the RMS bound (penalty)\n");
  std::printf("%6s %9s | %9s %9s | %9s %9s | %9s %9s | %8s\n", "noise", "bound", "noisy rms", "noisy max", "fit rms",
              "fit max", "fit/noisy", "pos f/n", "ratio");
  const long frames = std::min(o.frames, 2400L);
  const SA::Bvh_motion clean = walk(frames, 0);
  for(double sigma : {0.1, 0.5, 2.0}) {
    const SA::Bvh_motion noisy = walk(frames, sigma, 11);
    const SA::Motion_error noise = SA::motion_error(clean, noisy);
    for(int row = 0; row < (o.penalty ? 5 : 4); ++row) {
      const bool rms = row % 2 == 1 || row == 4, grid = row == 2 || row == 3, penalty = row == 4;
      SA::Motion_options mo;
      if(penalty) mo.algorithm = SA::Fit_algorithm::penalty_decomposition;
      if(rms) mo.rms_degrees = noise.rms_degrees;
      else mo.max_degrees = noise.max_degrees;
      if(grid) mo.candidate_grid_size = std::size_t(frames / 8);
      const SA::Motion_compression c = SA::compress_motion(noisy, mo);
      const SA::Motion_error left = SA::motion_error(clean, c.motion);
      std::printf("%6.2g %9s | %9.4f %9.4f | %9.4f %9.4f | %9.3f %9.3f | %7.2fx\n", sigma,
                  penalty ? "RMS pen." : rms ? (grid ? "RMS grid" : "RMS") : (grid ? "max grid" : "max"),
                  noise.rms_degrees, noise.max_degrees, left.rms_degrees, left.max_degrees, left.rms_degrees / noise.rms_degrees,
                  left.rms_position / noise.rms_position, c.ratio());
      std::fflush(stdout);
    }
  }
}
