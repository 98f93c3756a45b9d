# FindSndFile: libsndfile through pkg-config (Debian ships no CMake package file for it).
# Defines SndFile::sndfile. Installed next to e2dConfig.cmake so that an installed e2d::audio
# (a static library links libsndfile into its users) can find it again.
# SPDX-License-Identifier: MIT
include(FindPackageHandleStandardArgs)
find_package(PkgConfig QUIET)
if(PkgConfig_FOUND)
  pkg_check_modules(SNDFILE QUIET IMPORTED_TARGET sndfile)
endif()
find_package_handle_standard_args(SndFile
  REQUIRED_VARS SNDFILE_LINK_LIBRARIES
  VERSION_VAR SNDFILE_VERSION)
if(SndFile_FOUND AND NOT TARGET SndFile::sndfile)
  add_library(SndFile::sndfile INTERFACE IMPORTED)
  target_link_libraries(SndFile::sndfile INTERFACE PkgConfig::SNDFILE)
endif()
