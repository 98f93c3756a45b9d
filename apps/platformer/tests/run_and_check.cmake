# Runs an app (through WRAPPER, e.g. scripts/with-display.sh) with ARGS (one string, split at
# spaces) and checks that it exits 0 and that its standard output matches the regex EXPECT.
# SPDX-License-Identifier: MIT
separate_arguments(args UNIX_COMMAND "${ARGS}")
execute_process(COMMAND ${WRAPPER} ${APP} ${args}
  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
message("${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${APP} exited with ${rc}:\n${err}")
endif()
if(NOT out MATCHES "${EXPECT}")
  message(FATAL_ERROR "the output does not match '${EXPECT}':\n${out}\n${err}")
endif()
