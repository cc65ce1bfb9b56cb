# Runs of `tvf fit` (included by test/tangent_vector_fields/tool/CMakeLists.txt, which defines
# tvf_cli_test and CLI_OUT).  Inputs written here with known answers: a closed square polygon
# (degree 1: its 4 corners and nothing else), a straight line with a header row (no knot at all).

set(square "")
foreach(side 0 1 2 3)
  foreach(j RANGE 0 24)
    math(EXPR a "4 * ${j}")
    math(EXPR b "100 - 4 * ${j}")
    if(side EQUAL 0)
      string(APPEND square "v ${a} 0 0\n")
    elseif(side EQUAL 1)
      string(APPEND square "v 100 ${a} 0\n")
    elseif(side EQUAL 2)
      string(APPEND square "v ${b} 100 0\n")
    else()
      string(APPEND square "v 0 ${b} 0\n")
    endif()
  endforeach()
endforeach()
string(APPEND square "l")
foreach(i RANGE 1 100)
  string(APPEND square " ${i}")
endforeach()
file(WRITE ${CLI_OUT}/square.obj "${square}\n")
set(line "x, y # a header row, then y = 2x + 1\n")
foreach(x RANGE 0 49)
  math(EXPR y "2 * ${x} + 1")
  string(APPEND line "${x}, ${y}\n")
endforeach()
file(WRITE ${CLI_OUT}/line.csv "${line}")
file(WRITE ${CLI_OUT}/ragged.csv "0 0\n1 1\n2 2 2\n")
file(WRITE ${CLI_OUT}/not_a_number.csv "0, 0\n1, 1e\n")

tvf_cli_test(fit.closed_square_corners success
             ARGS fit ${CLI_OUT}/square.obj --degree 1 --closed --max-error 1e-9 -o ${CLI_OUT}/square_fit.json
                  -o ${CLI_OUT}/square_fit.svg -o ${CLI_OUT}/square_fit.obj
             OUTPUTS ${CLI_OUT}/square_fit.json ${CLI_OUT}/square_fit.svg ${CLI_OUT}/square_fit.obj
             STDOUT "100 samples in 3 dimensions, closed.*greedy: 4 knots, 4 control points; max error [0-9.]+e-1[0-9]")
tvf_cli_test(fit.line_needs_no_knot success
             ARGS fit ${CLI_OUT}/line.csv --rms-error 1e-6 --algorithm penalty
             STDOUT "50 samples in 2 dimensions.*degree 3, penalty: 0 knots, 4 control points")
tvf_cli_test(fit.exact_degree_one success
             ARGS fit ${CLI_OUT}/square.obj --degree 1 --lambda 1 --algorithm exact
             STDOUT "degree 1, dp: [0-9]+ knots")
tvf_cli_test(fit.one_bound usage ARGS fit ${CLI_OUT}/line.csv
             STDERR "give exactly one of '--max-error', '--rms-error' and '--lambda'")
tvf_cli_test(fit.ragged_table failure ARGS fit ${CLI_OUT}/ragged.csv --max-error 1
             STDERR "ragged.csv' line 3: 3 numbers where the first row has 2")
tvf_cli_test(fit.not_a_number failure ARGS fit ${CLI_OUT}/not_a_number.csv --max-error 1
             STDERR "not_a_number.csv' line 2, column 2: '1e' is not a number")
tvf_cli_test(fit.zero_tolerance failure ARGS fit ${CLI_OUT}/line.csv --max-error 0
             STDERR "must be finite and > 0")

# tvf fit-motion (BVH motion capture)
include(${CMAKE_CURRENT_LIST_DIR}/motion_cli_tests.cmake)
