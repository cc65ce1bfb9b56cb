# Runs the command-line tool once and checks how it ended (cmake -P run_tvf.cmake).
#
#   -DTVF=<path of tvf>
#   -DARGS=<arguments, separated by |>
#   -DEXPECT=success | failure | usage
#   -DOUTPUTS=<files, separated by |>   success: each must have been written (they are removed first)
#   -DSTDOUT=<regular expression>       success: the standard output must match it
#   -DSTDERR=<regular expression>       failure / usage: the reason on stderr must match it;
#                                       success: the warnings on stderr must match it
#
# success: exit code 0 and nothing on stderr (progress bars are drawn on terminals only), or
# with STDERR only lines "tvf: warning: ..." that match it.
# failure / usage: exit code 1 / 2, and stderr ends with exactly one line "tvf: error: <reason>"
# (after warnings "tvf: warning: ...", if any) -- never a crash, an abort or a stack trace.

string(REPLACE "|" ";" arguments "${ARGS}")
string(REPLACE "|" ";" outputs "${OUTPUTS}")
foreach(file IN LISTS outputs)
  file(REMOVE "${file}")
endforeach()

execute_process(COMMAND "${TVF}" ${arguments}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REPLACE ";" "|" shown "${arguments}")
set(what "tvf ${shown}")

if(EXPECT STREQUAL "success")
  if(NOT code STREQUAL "0")
    message(FATAL_ERROR "${what}\nexpected success, got exit code '${code}'\nstdout:\n${out}\nstderr:\n${err}")
  endif()
  if(DEFINED STDERR AND NOT STDERR STREQUAL "")
    if(NOT err MATCHES "^(tvf: warning: [^\n]+\n)+$" OR NOT err MATCHES "${STDERR}")
      message(FATAL_ERROR "${what}\nexpected warnings matching '${STDERR}' on stderr, got:\n${err}")
    endif()
  elseif(NOT err STREQUAL "")
    message(FATAL_ERROR "${what}\nexpected an empty stderr, got:\n${err}")
  endif()
  foreach(file IN LISTS outputs)
    if(NOT EXISTS "${file}")
      message(FATAL_ERROR "${what}\ndid not write ${file}\nstdout:\n${out}")
    endif()
    file(SIZE "${file}" size)
    if(size EQUAL 0)
      message(FATAL_ERROR "${what}\nwrote an empty ${file}")
    endif()
    # A result is never a NaN or an infinity: text outputs are read back for them.
    if(file MATCHES "\\.(tvf|obj|rawfield)$")
      file(STRINGS "${file}" bad REGEX "(^|[ \t])[-+]?(nan|inf)" LIMIT_COUNT 1)
      if(bad)
        message(FATAL_ERROR "${what}\nwrote a non-finite number to ${file}: ${bad}")
      endif()
    endif()
  endforeach()
  if(DEFINED STDOUT AND NOT STDOUT STREQUAL "" AND NOT out MATCHES "${STDOUT}")
    message(FATAL_ERROR "${what}\nstdout does not match '${STDOUT}':\n${out}")
  endif()
  message(STATUS "${what}\n${out}")
else()
  if(EXPECT STREQUAL "usage")
    set(expected_code 2)
  else()
    set(expected_code 1)
  endif()
  if(NOT code STREQUAL "${expected_code}")
    message(FATAL_ERROR "${what}\nexpected exit code ${expected_code} (${EXPECT}), got '${code}'\nstderr:\n${err}")
  endif()
  if(NOT err MATCHES "^(tvf: warning: [^\n]+\n)*tvf: error: [^\n]+\n$")
    message(FATAL_ERROR "${what}\nexpected one line 'tvf: error: ...' on stderr (after warnings), got:\n${err}")
  endif()
  if(DEFINED STDERR AND NOT STDERR STREQUAL "" AND NOT err MATCHES "${STDERR}")
    message(FATAL_ERROR "${what}\nthe reason does not match '${STDERR}':\n${err}")
  endif()
  message(STATUS "${what}\n${err}")
endif()
