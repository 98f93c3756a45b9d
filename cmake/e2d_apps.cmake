# Apps built on e2d::engine: e2d_add_app() and e2d_add_app_test(). Included by
# libs/engine/CMakeLists.txt (CMake functions are global), so every apps/<name>/CMakeLists.txt
# configured after the engine can use them.
# SPDX-License-Identifier: MIT
set(E2D_APPS_CMAKE_DIR "${CMAKE_CURRENT_LIST_DIR}" CACHE INTERNAL "")

# e2d_add_app(<name> SOURCES ... [DATA <files or folders>...] [LIBRARIES ...])
# Executable e2d_<name> linking e2d::engine. DATA (paths relative to the calling folder) are
# copied next to the binary on every build: a file keeps its name, a folder is copied with
# its contents (`DATA config.txt assets` gives <bin>/config.txt and <bin>/assets/...).
#
# Under AddressSanitizer (the asan preset) each app also gets the render tests'
# keep_gl_driver_loaded.cpp: Mesa dlclose()s its driver (swrast_dri.so) when GLFW closes the
# display, and LeakSanitizer then reports the driver's own one-time allocations (240 bytes, 3
# blocks, from "<unknown module>") as leaks. Kept loaded, the driver's globals still point to
# them and nothing is reported; the same binary run with the driver preloaded reports nothing
# either, so the blocks belong to the driver, not to e2d. No suppression file is needed.
function(e2d_add_app name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DATA;LIBRARIES" ${ARGN})
  set(target e2d_${name})
  add_executable(${target} ${ARG_SOURCES})
  if(CMAKE_CXX_FLAGS MATCHES "-fsanitize=[^ ]*address")
    target_sources(${target} PRIVATE "${PROJECT_SOURCE_DIR}/libs/render/tests/keep_gl_driver_loaded.cpp")
  endif()
  target_link_libraries(${target} PRIVATE e2d::engine ${ARG_LIBRARIES} e2d_warnings)
  set(copies "")
  foreach(item IN LISTS ARG_DATA)
    get_filename_component(source "${item}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    get_filename_component(item_name "${source}" NAME)
    if(IS_DIRECTORY "${source}")
      list(APPEND copies COMMAND ${CMAKE_COMMAND} -E copy_directory "${source}"
        "$<TARGET_FILE_DIR:${target}>/${item_name}")
    else()
      list(APPEND copies COMMAND ${CMAKE_COMMAND} -E copy_if_different "${source}"
        "$<TARGET_FILE_DIR:${target}>/${item_name}")
    endif()
  endforeach()
  if(copies)
    add_custom_target(${target}_data ${copies} COMMENT "Copying the data of ${target}" VERBATIM)
    add_dependencies(${target} ${target}_data)
  endif()
endfunction()

# e2d_add_app_test(<name> <test> [ARGS <app arguments>...] [CHECK <image rules>...]
#                  [LABELS ...] [TIMEOUT seconds])
# CTest test app_<name>_<test>: runs e2d_<name> through scripts/with-display.sh (a private
# Xvfb when DISPLAY is unset; OpenAL's silent null device) with ARGS plus `--screenshot <build>/screenshots/<name>_<test>.png`
# (and `--frames 120` unless ARGS has --frames); the app must exit 0. Then, when CHECK is
# given, e2d_image_check (apps/tools) checks the screenshot against the rules, one argument
# each (see apps/tools/image_check.cpp):
#   size:W,H                   the image is W x H pixels
#   colour:X,Y,W,H:R,G,B:T:P   at least P % of the region's pixels are within T of R,G,B
#   ink:X,Y,W,H[:P]            at least P % (default 0.5) differ from the region's commonest colour
#   empty:X,Y,W,H              fewer than 0.1 % do
# Regions are pixels from the image's top-left corner.
function(e2d_add_app_test name test)
  if(NOT E2D_BUILD_TESTS)
    return()
  endif()
  cmake_parse_arguments(ARG "" "TIMEOUT" "ARGS;CHECK;LABELS" ${ARGN})
  set(args ${ARG_ARGS})
  if(NOT "--frames" IN_LIST args)
    list(APPEND args --frames 120)
  endif()
  set(shot "${PROJECT_BINARY_DIR}/screenshots/${name}_${test}.png")
  # Lists cross the command line joined with '|' (e2d_run_app_test.cmake splits them).
  string(REPLACE ";" "|" args_escaped "${args}")
  string(REPLACE ";" "|" check_escaped "${ARG_CHECK}")
  set(checker "")
  if(ARG_CHECK)
    set(checker "$<TARGET_FILE:e2d_image_check>")
  endif()
  add_test(NAME app_${name}_${test}
    COMMAND ${CMAKE_COMMAND}
      "-DAPP=$<TARGET_FILE:e2d_${name}>"
      "-DARGS=${args_escaped}"
      "-DSCREENSHOT=${shot}"
      "-DCHECKER=${checker}"
      "-DCHECK=${check_escaped}"
      "-DWITH_DISPLAY=${PROJECT_SOURCE_DIR}/scripts/with-display.sh"
      -P "${E2D_APPS_CMAKE_DIR}/e2d_run_app_test.cmake"
    WORKING_DIRECTORY "$<TARGET_FILE_DIR:e2d_${name}>")
  set(labels apps)
  if(ARG_LABELS)
    set(labels ${ARG_LABELS})
  endif()
  set(timeout 300)
  if(ARG_TIMEOUT)
    set(timeout ${ARG_TIMEOUT})
  endif()
  # OpenAL Soft's null backend: a silent real-time device, so the mixer runs as with a sound
  # card (and ALSA does not complain on machines without one).
  set_tests_properties(app_${name}_${test} PROPERTIES LABELS "${labels}" TIMEOUT ${timeout}
    ENVIRONMENT "ALSOFT_DRIVERS=null")
endfunction()
