// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The curve readers of Spline_approximation: BVH motion capture and SVG documents (paths, basic
// shapes, <use>, viewports).  An input
// starting with "HIERARCHY" (after white space) is BVH, anything else SVG.  What a reader
// accepts must hold what its checks promise, write and read back the same (BVH, at 17
// significant digits), and, when small, be fitted: the compressed motion or the sampled
// contours' splines finite (a contour's fit within its bound when it says so), or refused with
// Invalid_input.  Linked
// against the Spline_approximation library alone, so it builds in a minute.  (The motion's
// bound is not asserted: compress_motion tightens a joint's bound at most 8 times.)

#include <CGAL/Spline_approximation/Bezier_contour.h>
#include <CGAL/Spline_approximation/Bvh_motion.h>
#include <CGAL/Spline_approximation/Spline_fit.h>
#include <CGAL/Spline_approximation/Svg_paths.h>
#include <CGAL/Spline_approximation/compress_motion.h>
#include <CGAL/Spline_approximation/errors.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

namespace SA = CGAL::Spline_approximation;

// Every UBSan report ends the run, as for the other targets (fuzz_support.cpp).
extern "C" const char* __ubsan_default_options() { return "halt_on_error=1:print_stacktrace=1"; }

namespace {

[[noreturn]] void fail(const std::string& what)
{
  std::fprintf(stderr, "curves fuzz: %s\n", what.c_str());
  std::abort();
}

void bvh(const std::string& text)
{
  std::istringstream in(text);
  SA::Bvh_motion motion;
  try { motion = SA::read_bvh(in, "fuzz.bvh"); }
  catch(const SA::Invalid_input&) { return; }
  try { SA::check_bvh_motion(motion, "fuzz"); }
  catch(const SA::Invalid_input& e) { fail(std::string("read_bvh accepted what check_bvh_motion refuses: ") + e.what()); }
  std::ostringstream out;
  SA::write_bvh(out, motion, 17);
  std::istringstream again(out.str());
  SA::Bvh_motion back;
  try { back = SA::read_bvh(again, "written.bvh"); }
  catch(const SA::Invalid_input& e) { fail(std::string("the written motion is refused: ") + e.what()); }
  if(back.joints.size() != motion.joints.size() || back.frames.rows() != motion.frames.rows() ||
     back.frames.cols() != motion.frames.cols() || !(back.frames == motion.frames) ||
     back.frame_time != motion.frame_time)
    fail("the written motion reads back different");
  // Small motions are compressed: within the bound, or refused with the reason.
  if(motion.number_of_frames() < 2 || motion.number_of_frames() > 64 || motion.joints.size() > 8) return;
  SA::Motion_options o;
  o.max_degrees = 1.0;
  try {
    const SA::Motion_compression c = SA::compress_motion(motion, o);
    if(!c.motion.frames.allFinite()) fail("the compressed motion has non-finite channels");
    if(!(c.error.max_degrees >= 0)) fail("the compressed motion's error is not a number");
  } catch(const SA::Invalid_input&) {
  } catch(const SA::Numerical_failure&) {
  }
}

void svg(const std::string& text)
{
  SA::Svg_paths paths;
  try { paths = SA::parse_svg_paths(text, "fuzz.svg"); }
  catch(const SA::Invalid_input&) { return; }
  std::size_t fitted = 0;
  for(const SA::Bezier_contour& contour : paths.contours) {
    if(contour.segments.empty() || contour.segments.size() > 32 || fitted >= 4) continue;
    SA::Sampled_contour s;
    try { s = SA::sample_contour(contour, 8); }
    catch(const SA::Invalid_input&) { continue; }
    if(!s.points.allFinite()) fail("sampled contour with a non-finite point");
    SA::Fit_options o;
    o.degree = 3;
    o.algorithm = SA::Fit_algorithm::greedy_removal;
    o.max_error = 1e-3;
    o.closed_curve = s.closed;
    try {
      const SA::Spline_fit f = SA::fit_spline(s.points, o);
      ++fitted;
      if(!f.spline.control_points.allFinite()) fail("a fit with non-finite control points");
      if(f.within_bound && !(f.max_error <= 1e-3)) fail("a fit said within its bound is not");
    } catch(const SA::Invalid_input&) {
    } catch(const SA::Numerical_failure&) {
    }
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if(first != std::string::npos && text.compare(first, 9, "HIERARCHY") == 0) bvh(text);
  else svg(text);
  return 0;
}
