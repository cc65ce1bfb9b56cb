# Runs of `tvf fit-motion` (included by cli_tests.cmake, which test/tangent_vector_fields/tool
# includes; tvf_cli_test and CLI_OUT come from there).  Inputs written here with known answers:
# a two-joint skeleton whose rotations never change and whose root moves along a straight line,
# so every spline needs no knot: degree 3 stores 4 control points per curve (a quaternion curve:
# 16 values, the root translation: 12), 44 values for 100 frames x 9 channels; degree 1 half.

set(bvh_header "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n  JOINT Spine\n  {\n    OFFSET 0 10 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n    End Site\n    {\n      OFFSET 0 5 0\n    }\n  }\n}\nMOTION\n")
set(still "${bvh_header}Frames: 100\nFrame Time: 0.0083333333\n")
foreach(f RANGE 0 99)
  math(EXPR y "90 - ${f}")
  string(APPEND still "${f} ${y} 0 10 20 30 5 -15 45\n")
endforeach()
file(WRITE ${CLI_OUT}/still.bvh "${still}")
# The file of the reader's tests: line 19 is the first frame.
set(two_frames "${bvh_header}Frames: 2\nFrame Time: 0.0083333\n")
file(WRITE ${CLI_OUT}/two_frames.bvh "${two_frames}1 2 3 10 20 30 40 50 60\n4 5 6 11 21 31 41 51 61\n")
file(WRITE ${CLI_OUT}/short_frame.bvh "${two_frames}1 2 3 10 20 30 40 50\n4 5 6 11 21 31 41 51 61\n")
file(WRITE ${CLI_OUT}/nan_value.bvh "${two_frames}1 2 3 10 20 30 40 50 60\nnan 5 6 11 21 31 41 51 61\n")
string(REPLACE "Zrotation Xrotation Yrotation\n    End" "Zrotation Wrotation Yrotation\n    End" unknown_channel "${two_frames}")
file(WRITE ${CLI_OUT}/unknown_channel.bvh "${unknown_channel}1 2 3 10 20 30 40 50 60\n4 5 6 11 21 31 41 51 61\n")

tvf_cli_test(fit_motion.still_needs_no_knot success
             ARGS fit-motion ${CLI_OUT}/still.bvh ${CLI_OUT}/still_fit.bvh --max-degrees 0.01
             OUTPUTS ${CLI_OUT}/still_fit.bvh SETUP still_fit
             STDOUT "2 joints and 1 End Sites, 100 frames at 120.* 9 channels.*Hips +6 +0 +0 +28 .*Spine +3 +0 +0 +16 .*stored values 44 of 900 \\(frames x channels\\): ratio 20.45\nrotation error: max (0|[0-9.]+e-1[0-9]), .*joint position error: max (0|[0-9.]+e-1[0-9]),")
# (Checked it can fail: with "45 of 900" expected, the first test failed.)
# The written motion read again: the same skeleton and the same answer.
tvf_cli_test(fit_motion.written_motion_reads_back success
             ARGS fit-motion ${CLI_OUT}/still_fit.bvh --max-degrees 0.01 --representation euler REQUIRES still_fit
             STDOUT "stored values 36 of 900 .*rotation error: max (0|[0-9.]+e-1[0-9]),")
tvf_cli_test(fit_motion.degree_one success
             ARGS fit-motion ${CLI_OUT}/still.bvh -o ${CLI_OUT}/still_linear.bvh --max-degrees 0.01 --degree 1 --algorithm penalty
             OUTPUTS ${CLI_OUT}/still_linear.bvh
             STDOUT "degree 1, penalty, unit quaternions.*stored values 22 of 900")
tvf_cli_test(fit_motion.short_frame failure ARGS fit-motion ${CLI_OUT}/short_frame.bvh --max-degrees 1
             STDERR "short_frame.bvh' line 19, column 21: frame 1 has 8 values; the skeleton has 9 channels")
tvf_cli_test(fit_motion.nan_value failure ARGS fit-motion ${CLI_OUT}/nan_value.bvh --max-degrees 1
             STDERR "nan_value.bvh' line 20, column 1: 'nan' is not a finite number")
tvf_cli_test(fit_motion.unknown_channel failure ARGS fit-motion ${CLI_OUT}/unknown_channel.bvh --max-degrees 1
             STDERR "unknown_channel.bvh' line 9, column 26: unknown channel 'Wrotation'")
tvf_cli_test(fit_motion.missing_file failure ARGS fit-motion ${CLI_OUT}/no_such.bvh --max-degrees 1
             STDERR "cannot open BVH file .*no_such.bvh")
tvf_cli_test(fit_motion.one_bound usage ARGS fit-motion ${CLI_OUT}/still.bvh
             STDERR "one of '--max-degrees', '--rms-degrees' is required")
tvf_cli_test(fit_motion.zero_bound failure ARGS fit-motion ${CLI_OUT}/still.bvh --max-degrees 0
             STDERR "the rotation bound in degrees must be finite and > 0")
tvf_cli_test(fit_motion.too_few_frames failure ARGS fit-motion ${CLI_OUT}/two_frames.bvh --max-degrees 1
             STDERR "the motion has 2 frames; a spline of degree 3 needs at least 4")
tvf_cli_test(fit_motion.bad_algorithm usage ARGS fit-motion ${CLI_OUT}/still.bvh --max-degrees 1 --algorithm exact
             STDERR "'--algorithm' must be greedy or penalty, not 'exact'")
