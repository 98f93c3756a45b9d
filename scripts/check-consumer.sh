#!/usr/bin/env bash
# Installs the build in $1 to a fresh prefix, builds tests/consumer against it and checks that
# the consumer, which asks only for e2d::physics, links no graphics, windowing or audio library.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build="${1:?usage: check-consumer.sh BUILD_DIR}"
prefix="$PWD/build/consumer-prefix"
out="$PWD/build/consumer"
rm -rf "$prefix" "$out"
cmake --install "$build" --prefix "$prefix" >/dev/null
cmake -S tests/consumer -B "$out" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$out" >/dev/null
"$out/e2d_consumer"
# What the binary needs at run time, and what the link step was told to link.
libs=$(ldd "$out/e2d_consumer")
link=$(ninja -C "$out" -t commands e2d_consumer | tail -n 1)
for forbidden in libGL libGLEW libglfw libopenal libfreeimage libfreetype libsndfile libbox2d; do
  if grep -q "$forbidden" <<<"$libs$link"; then
    echo "consumer links $forbidden although it asked only for e2d::physics" >&2
    exit 1
  fi
done
echo "consumer: built against the install, runs, links none of GL/GLEW/GLFW/OpenAL/FreeImage/FreeType/libsndfile/Box2D"

# The same for audio alone, when the build has it: finds OpenAL and libsndfile (FindSndFile.cmake
# is installed with e2d), plays a tone through the loopback device, links no graphics library.
if compgen -G "$prefix/lib*/cmake/e2d/e2d_audio_targets.cmake" >/dev/null; then
  out_audio="$PWD/build/consumer-audio"
  rm -rf "$out_audio"
  cmake -S tests/consumer_audio -B "$out_audio" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$out_audio" >/dev/null
  ALSOFT_DRIVERS=null "$out_audio/e2d_consumer_audio"
  libs=$(ldd "$out_audio/e2d_consumer_audio")
  for forbidden in libGL libGLEW libglfw libfreeimage libfreetype libbox2d; do
    if grep -q "$forbidden" <<<"$libs"; then
      echo "consumer_audio links $forbidden although it asked only for e2d::audio" >&2
      exit 1
    fi
  done
  echo "consumer_audio: find_package(e2d COMPONENTS audio) from the install builds, plays, links no graphics"
fi
