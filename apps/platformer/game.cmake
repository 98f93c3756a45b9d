# The game itself (included by CMakeLists.txt once e2d::engine and e2d_add_app exist).
e2d_add_app(platformer
  SOURCES src/main.cpp src/scenes.cpp
  DATA data/config.txt data/bindings.txt)
target_link_libraries(e2d_platformer PRIVATE e2d_platformer_rules)
e2d_app_assets(e2d_platformer SET platformer FILES
  player.png player.json grass.png spikes.png plank.png platform.png coin.png flag.png
  sky.png hills.png trees.png coin.wav jump.wav hurt.wav win.wav music.ogg)

if(E2D_BUILD_TESTS)
  set(scripts ${CMAKE_CURRENT_SOURCE_DIR}/tests)
  # Screenshots (1280 x 720), checked by e2d_image_check. The sky's blue fills the top rows of
  # every scene; the headings are ink in the centre; the level's coin counter is yellow ink at
  # the top left.
  e2d_add_app_test(platformer title ARGS --frames 30
    CHECK size:1280,720
          colour:0,0,1280,60:90,160,235:40:90
          ink:340,140,600,110:3)
  # The scripted run at 2 s: the player jumping onto the lift, the spike pit, the cliff, coins.
  e2d_add_app_test(platformer level ARGS --frames 120 --input-script ${scripts}/win.script
    CHECK size:1280,720
          colour:0,0,1280,60:90,160,235:40:60
          colour:10,10,200,40:255,230,90:60:3)

  # The scripted runs, each checked twice: the state line the game prints at exit, and the
  # screenshot of the scene it ends on. The winning run collects the three coins (each starting
  # a coin sound on a voice), rides the lift, lands on the one-way platform and reaches the flag
  # (about frame 445; the win scene follows a second later). Running right without jumping ends
  # on the spikes: game over, one coin.
  function(platformer_run test frames script expect)
    add_test(NAME app_platformer_${test}
      COMMAND ${CMAKE_COMMAND} -DAPP=$<TARGET_FILE:e2d_platformer>
        -DWRAPPER=${PROJECT_SOURCE_DIR}/scripts/with-display.sh
        "-DARGS=--frames ${frames} --input-script ${scripts}/${script}"
        "-DEXPECT=${expect}"
        -DSCREENSHOT=${PROJECT_BINARY_DIR}/screenshots/platformer_${test}.png
        -DCHECKER=$<TARGET_FILE:e2d_image_check>
        "-DCHECK=${ARGN}"
        -P ${scripts}/run_and_check.cmake)
    # apps-long: left out of the asan test preset (CI time; the level test plays the same
    # script's first 2 s there).
    set_tests_properties(app_platformer_${test} PROPERTIES LABELS "apps;apps-long" TIMEOUT 300
      ENVIRONMENT "ALSOFT_DRIVERS=null;MESA_SHADER_CACHE_DISABLE=true")
  endfunction()
  platformer_run(win 540 win.script
    "scene=WinScene score=3/4 coin_voices=3 jumps=3 runs=1 deaths=0 wins=1 steps_on_moving_platform=[1-9][0-9]+ steps_on_one_way=[1-9][0-9]* music_streaming=1 level_bodies=19"
    "colour:340,140,600,110:120,240,120:40:3|ink:200,260,880,120:1")
  platformer_run(game_over 180 spikes.script
    "scene=GameOverScene score=1/4 coin_voices=1 jumps=0 runs=1 deaths=1 wins=0"
    "colour:340,140,600,110:255,90,80:40:3|ink:200,260,880,120:1")
  # Game over, then a second run: the new level finds the world holding only its own 19 bodies
  # (the first run's went with its scene); the coin counter is back, yellow, top left.
  platformer_run(retry 300 retry.script
    "scene=LevelScene score=1/4 coin_voices=2 jumps=1 runs=2 deaths=1 wins=0 .* level_bodies=19"
    "colour:10,10,200,40:255,230,90:60:3")
endif()
