# e2d_app_assets(<target> SET <set> FILES <file>... [FOLDER <dir>])
# Runs `e2d_assetgen <set> <dir>` at build time (dir: the target's build folder /assets by
# default, where the engine's GameSystem::asset() finds "assets/<file>" beside config.txt) and
# makes <target> depend on the files. FILES lists what the set writes, relative to the folder.
# SPDX-License-Identifier: MIT
function(e2d_app_assets target)
  cmake_parse_arguments(ARG "" "SET;FOLDER" "FILES" ${ARGN})
  if(NOT ARG_SET OR NOT ARG_FILES)
    message(FATAL_ERROR "e2d_app_assets(${target}): SET and FILES are required")
  endif()
  if(NOT ARG_FOLDER)
    set(ARG_FOLDER ${CMAKE_CURRENT_BINARY_DIR}/assets)
  endif()
  list(TRANSFORM ARG_FILES PREPEND ${ARG_FOLDER}/ OUTPUT_VARIABLE outputs)
  add_custom_command(OUTPUT ${outputs}
    COMMAND e2d_assetgen ${ARG_SET} ${ARG_FOLDER}
    DEPENDS e2d_assetgen
    COMMENT "Generating ${target}'s asset set '${ARG_SET}'"
    VERBATIM)
  add_custom_target(${target}_assets DEPENDS ${outputs})
  add_dependencies(${target} ${target}_assets)
endfunction()
