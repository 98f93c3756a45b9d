# Sprite sheets, animation, text and debug drawing of e2d::render (the "content" half of the
# library): their extra dependency, tests and fuzzer. Included from CMakeLists.txt, so
# CMAKE_CURRENT_SOURCE_DIR is libs/render. Their sources are in src/ with the rest.
e2d_find_package(render nlohmann_json CONFIG)
target_link_libraries(e2d_render PRIVATE nlohmann_json::nlohmann_json)

# No OpenGL context needed: sheet parsing, animation timing, UTF-8, fonts, layout, debug shapes.
e2d_add_tests(render SUFFIX content LABEL render SOURCES
  tests/content/sprite_sheet_test.cpp
  tests/content/animation_test.cpp
  tests/content/text_layout_test.cpp
  tests/content/drawer_test.cpp)

if(E2D_BUILD_FUZZ AND EXISTS "${CMAKE_CURRENT_SOURCE_DIR}/fuzz/CMakeLists.txt")
  add_subdirectory(fuzz)
endif()

# With a real OpenGL context (Mesa llvmpipe under Xvfb when there is no display).
e2d_add_tests(render SUFFIX content_gl LABEL render NEEDS_DISPLAY SOURCES
  tests/content/content_gl_test.cpp)
