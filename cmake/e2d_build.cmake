# One way to define every e2d library, its tests and its package files.
# SPDX-License-Identifier: MIT
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

if(NOT CMAKE_CXX_COMPILER_LAUNCHER)
  find_program(E2D_CCACHE ccache)
  if(E2D_CCACHE)
    set(CMAKE_CXX_COMPILER_LAUNCHER "${E2D_CCACHE}" CACHE STRING "" FORCE)
  endif()
endif()

# Warnings for e2d's own code only: linked privately and never exported, and third-party
# headers come in through imported targets, which are SYSTEM includes.
add_library(e2d_warnings INTERFACE)
target_compile_options(e2d_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wcast-align -Woverloaded-virtual
  $<$<BOOL:${E2D_WARNINGS_AS_ERRORS}>:-Werror>)

set(E2D_PACKAGE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/e2d")

# e2d_find_package(<component> <package> [find_package args...])
# Finds a third-party package for a library and records it, so that the installed
# package config of that component (and only that one) calls find_dependency for it.
macro(e2d_find_package component package)
  find_package(${package} ${ARGN} REQUIRED)
  set_property(GLOBAL APPEND PROPERTY E2D_${component}_PACKAGES "${package} ${ARGN}")
endmacro()

# e2d_add_library(<name> SOURCES ... [PUBLIC deps...] [PRIVATE deps...])
# Defines target e2d_<name>, alias e2d::<name>, exported as e2d::<name> in component <name>.
function(e2d_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
  set(target e2d_${name})
  add_library(${target} ${ARG_SOURCES})
  add_library(e2d::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES
    EXPORT_NAME ${name}
    POSITION_INDEPENDENT_CODE ON
    CXX_EXTENSIONS OFF
    VERSION ${PROJECT_VERSION})
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_include_directories(${target}
    PUBLIC
      $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
      $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
    PRIVATE
      ${CMAKE_CURRENT_SOURCE_DIR}/src)
  target_link_libraries(${target}
    PUBLIC ${ARG_PUBLIC}
    PRIVATE ${ARG_PRIVATE} $<BUILD_INTERFACE:e2d_warnings>)

  # The e2d components this one needs, derived from its link lists.
  set(components "")
  foreach(dep IN LISTS ARG_PUBLIC ARG_PRIVATE)
    if(dep MATCHES "^e2d::(.+)$")
      list(APPEND components ${CMAKE_MATCH_1})
    endif()
  endforeach()
  set_property(GLOBAL PROPERTY E2D_${name}_COMPONENTS "${components}")
  set_property(GLOBAL APPEND PROPERTY E2D_LIBRARIES ${name})

  install(TARGETS ${target} EXPORT e2d_${name}_targets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT e2d_${name}_targets NAMESPACE e2d::
    FILE e2d_${name}_targets.cmake DESTINATION ${E2D_PACKAGE_DIR})
endfunction()

# e2d_add_tests(<lib> SOURCES ... [SUFFIX name] [LIBRARIES ...] [LABEL label] [NEEDS_DISPLAY])
# One GoogleTest executable per library (e2d_<lib>_tests, or e2d_<lib>_<suffix>_tests), linking
# only that library; every test is a CTest test labelled with the library's name (or LABEL).
# NEEDS_DISPLAY: the tests open windows, so CTest runs them through scripts/with-display.sh
# (a private Xvfb when DISPLAY is not set).
function(e2d_add_tests lib)
  if(NOT E2D_BUILD_TESTS)
    return()
  endif()
  cmake_parse_arguments(ARG "NEEDS_DISPLAY" "SUFFIX;LABEL" "SOURCES;LIBRARIES" ${ARGN})
  set(target e2d_${lib}_tests)
  if(ARG_SUFFIX)
    set(target e2d_${lib}_${ARG_SUFFIX}_tests)
  endif()
  add_executable(${target} ${ARG_SOURCES})
  target_link_libraries(${target} PRIVATE e2d::${lib} ${ARG_LIBRARIES} GTest::gmock
    GTest::gtest_main e2d_warnings)
  target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
  # One label per executable: gtest_discover_tests flattens a label list into separate
  # property arguments, so LABELS a;b would not survive it.
  set(label ${lib})
  if(ARG_LABEL)
    set(label ${ARG_LABEL})
  endif()
  if(ARG_NEEDS_DISPLAY)
    # gtest_discover_tests runs the listing and every test through the emulator.
    set_target_properties(${target} PROPERTIES
      CROSSCOMPILING_EMULATOR "${PROJECT_SOURCE_DIR}/scripts/with-display.sh")
  endif()
  gtest_discover_tests(${target}
    DISCOVERY_MODE PRE_TEST
    PROPERTIES LABELS ${label})
endfunction()

# Writes e2dConfig.cmake and one dependency file per component. Called once, last.
function(e2d_write_package_files)
  get_property(libraries GLOBAL PROPERTY E2D_LIBRARIES)
  foreach(name IN LISTS libraries)
    get_property(components GLOBAL PROPERTY E2D_${name}_COMPONENTS)
    get_property(packages GLOBAL PROPERTY E2D_${name}_PACKAGES)
    set(text "# Generated: what component '${name}' needs before its targets load.\n")
    foreach(component IN LISTS components)
      string(APPEND text "_e2d_load_component(${component})\n")
    endforeach()
    foreach(package IN LISTS packages)
      string(APPEND text "find_dependency(${package})\n")
    endforeach()
    file(WRITE "${PROJECT_BINARY_DIR}/package/e2d_${name}_dependencies.cmake" "${text}")
    install(FILES "${PROJECT_BINARY_DIR}/package/e2d_${name}_dependencies.cmake"
      DESTINATION ${E2D_PACKAGE_DIR})
  endforeach()
  set(E2D_COMPONENTS "${libraries}")
  configure_package_config_file("${PROJECT_SOURCE_DIR}/cmake/e2dConfig.cmake.in"
    "${PROJECT_BINARY_DIR}/package/e2dConfig.cmake" INSTALL_DESTINATION ${E2D_PACKAGE_DIR})
  write_basic_package_version_file("${PROJECT_BINARY_DIR}/package/e2dConfigVersion.cmake"
    COMPATIBILITY SameMinorVersion)
  install(FILES "${PROJECT_BINARY_DIR}/package/e2dConfig.cmake"
    "${PROJECT_BINARY_DIR}/package/e2dConfigVersion.cmake" DESTINATION ${E2D_PACKAGE_DIR})
endfunction()

# e2d_add_fuzzers(<lib> <name>...): libFuzzer targets <name> from <name>.cpp in the calling
# folder (libs/<lib>/fuzz/), linking the library target e2d_<lib> (e2d::<lib>; for the
# validation harness, e2d_validation_harness). The library itself is instrumented for coverage
# and checked by ASan + UBSan; only the fuzz executables link the fuzzer runtime. Called only
# when E2D_BUILD_FUZZ is ON (the `fuzz` preset); scripts/test.sh runs every fuzz_* it finds
# under build/fuzz/libs/<lib>/fuzz/ with seeds from libs/<lib>/fuzz/corpus/<name>/, and
# build/fuzz/validation/fuzz/fuzz_* with the shipped scenarios as seeds.
function(e2d_add_fuzzers lib)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "E2D_BUILD_FUZZ needs clang (libFuzzer), got ${CMAKE_CXX_COMPILER_ID}")
  endif()
  set(sanitizers address,undefined)
  target_compile_options(e2d_${lib} PRIVATE
    -fsanitize=fuzzer-no-link,${sanitizers} -fno-sanitize-recover=all -fno-omit-frame-pointer)
  foreach(name IN LISTS ARGN)
    add_executable(${name} ${name}.cpp)
    target_link_libraries(${name} PRIVATE e2d_${lib} e2d_warnings)
    target_compile_options(${name} PRIVATE
      -fsanitize=fuzzer,${sanitizers} -fno-sanitize-recover=all -fno-omit-frame-pointer)
    target_link_options(${name} PRIVATE -fsanitize=fuzzer,${sanitizers})
  endforeach()
endfunction()
