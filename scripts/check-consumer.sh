#!/usr/bin/env bash
# Installs the build in $1 to a fresh prefix, then for each library component that was built
# (physics, render, audio, input, engine) builds tests/consumer against the install asking for that
# component alone, runs it (under scripts/with-display.sh, so render and input get an X display)
# and checks that it links none of the third-party libraries of the components it did not ask for.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build="${1:?usage: check-consumer.sh BUILD_DIR}"
prefix="$PWD/build/consumer-prefix"
rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null

# The third-party libraries each component may link; anything else on the list is forbidden.
declare -A allowed=(
  [physics]=""
  [render]="libGL libGLEW libglfw libfreeimage libfreetype"
  [audio]="libopenal libsndfile"
  [input]="libglfw"
  [engine]="libGL libGLEW libglfw libfreeimage libfreetype libopenal libsndfile"
)
all="libGL libGLEW libglfw libopenal libfreeimage libfreetype libsndfile libbox2d libsfml"
checked=0
for component in physics render audio input engine; do
  [ -f "$prefix/lib/cmake/e2d/e2d_${component}_targets.cmake" ] || continue
  [ -f "tests/consumer/$component.cpp" ] || { echo "consumer: no tests/consumer/$component.cpp" >&2; exit 1; }
  out="$PWD/build/consumer-$component"
  rm -rf "$out"
  cmake -S tests/consumer -B "$out" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
    -DE2D_CONSUMER_COMPONENT="$component" >/dev/null
  cmake --build "$out" >/dev/null
  ./scripts/with-display.sh "$out/e2d_consumer"
  # What the binary needs at run time, and what the link step was told to link.
  libs=$(ldd "$out/e2d_consumer")
  link=$(ninja -C "$out" -t commands e2d_consumer | tail -n 1)
  for forbidden in $all; do
    case " ${allowed[$component]} " in *" $forbidden "*) continue ;; esac
    if grep -q "$forbidden[.-]" <<<"$libs$link"; then
      echo "consumer: e2d::$component links $forbidden although it asked only for e2d::$component" >&2
      exit 1
    fi
  done
  echo "consumer: e2d::$component alone builds against the install, runs, links only its own third-party libraries"
  checked=$((checked + 1))
done
[ "$checked" -gt 0 ] || { echo "consumer: no component installed in $prefix" >&2; exit 1; }
