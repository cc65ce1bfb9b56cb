# Runs an example and checks what it printed, not only its exit code (cmake -P run_example.cmake).
#   -DPROGRAM=<path>  -DARGS=<arguments, separated by |>  -DEXPECT=<regular expression over stdout>
string(REPLACE "|" ";" arguments "${ARGS}")
execute_process(COMMAND "${PROGRAM}" ${arguments} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "${out}")
if(NOT code STREQUAL "0")
  message(FATAL_ERROR "${PROGRAM} ended with '${code}'\nstderr:\n${err}")
endif()
if(NOT out MATCHES "${EXPECT}")
  message(FATAL_ERROR "${PROGRAM}: the output does not show '${EXPECT}'")
endif()
