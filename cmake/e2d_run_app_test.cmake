# Runs one app test (see e2d_add_app_test in e2d_apps.cmake): the app headless with a
# screenshot, then the image checker on it. cmake -P with APP, ARGS, SCREENSHOT, CHECKER,
# CHECK, WITH_DISPLAY defined.
# SPDX-License-Identifier: MIT
string(REPLACE "|" ";" ARGS "${ARGS}")
string(REPLACE "|" ";" CHECK "${CHECK}")
get_filename_component(shot_dir "${SCREENSHOT}" DIRECTORY)
file(MAKE_DIRECTORY "${shot_dir}")
file(REMOVE "${SCREENSHOT}")
execute_process(COMMAND "${WITH_DISPLAY}" "${APP}" ${ARGS} --screenshot "${SCREENSHOT}"
  RESULT_VARIABLE app_result)
if(NOT app_result EQUAL 0)
  message(FATAL_ERROR "${APP} ${ARGS} exited with ${app_result}")
endif()
if(NOT EXISTS "${SCREENSHOT}")
  message(FATAL_ERROR "${APP} exited 0 but wrote no screenshot ${SCREENSHOT}")
endif()
if(CHECKER)
  execute_process(COMMAND "${CHECKER}" "${SCREENSHOT}" ${CHECK} RESULT_VARIABLE check_result)
  if(NOT check_result EQUAL 0)
    message(FATAL_ERROR "image check of ${SCREENSHOT} failed")
  endif()
endif()
