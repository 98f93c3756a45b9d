# Runs an app (through WRAPPER, e.g. scripts/with-display.sh) with ARGS (one string, split at
# spaces), checks that it exits 0 and that its standard output matches the regex EXPECT; with
# SCREENSHOT, the app writes it (--screenshot) and CHECKER (e2d_image_check) checks it against
# CHECK (rules joined with '|').
# SPDX-License-Identifier: MIT
separate_arguments(args UNIX_COMMAND "${ARGS}")
if(SCREENSHOT)
  get_filename_component(folder "${SCREENSHOT}" DIRECTORY)
  file(MAKE_DIRECTORY "${folder}")
  file(REMOVE "${SCREENSHOT}")
  list(APPEND args --screenshot "${SCREENSHOT}")
endif()
execute_process(COMMAND ${WRAPPER} ${APP} ${args}
  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
message("${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${APP} exited with ${rc}:\n${err}")
endif()
if(NOT out MATCHES "${EXPECT}")
  message(FATAL_ERROR "the output does not match '${EXPECT}':\n${out}\n${err}")
endif()
if(SCREENSHOT)
  string(REPLACE "|" ";" rules "${CHECK}")
  execute_process(COMMAND ${CHECKER} ${SCREENSHOT} ${rules} RESULT_VARIABLE check_rc)
  if(NOT check_rc EQUAL 0)
    message(FATAL_ERROR "${SCREENSHOT} fails the image check")
  endif()
endif()
