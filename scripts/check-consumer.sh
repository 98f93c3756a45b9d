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
