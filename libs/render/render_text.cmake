# Sprite sheets, animation, text and debug drawing of e2d::render: their tests and fuzzer.
# Included from CMakeLists.txt (so CMAKE_CURRENT_SOURCE_DIR is libs/render).

# Tests that need no OpenGL context: sheet parsing, animation timing, UTF-8, fonts and layout.
e2d_add_tests(render SUFFIX text SOURCES
  tests/sprite_sheet_test.cpp
  tests/animation_test.cpp
  tests/text_layout_test.cpp
  tests/drawer_test.cpp
  LABEL render)

if(E2D_BUILD_FUZZ AND EXISTS "${CMAKE_CURRENT_SOURCE_DIR}/fuzz/CMakeLists.txt")
  add_subdirectory(fuzz)
endif()
