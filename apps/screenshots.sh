#!/usr/bin/env bash
# Remakes the README gallery of the examples and the platformer: each app's own --screenshot, headless.
#   apps/screenshots.sh [build dir, default build/dev]
# Writes docs/screenshots/<app>.png. Needs the apps built (ninja -C <build dir> e2d_<app>).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:-$root/build/dev}" && pwd)"
out="$root/docs/screenshots"
mkdir -p "$out"
shoot() { # app, then the app's arguments
  local app="$1"; shift
  (cd "$build/apps/$app" && "$root/scripts/with-display.sh" "./e2d_$app" --seed 1 "$@" \
     --screenshot "$out/$app.png" >/dev/null 2>&1) || { echo "e2d_$app failed" >&2; exit 1; }
  echo "$out/$app.png"
}
shoot hello --frames 60
shoot sprites --frames 30
shoot parallax --frames 240
shoot text --frames 60
shoot audio_spatial --frames 60
shoot audio_listener --frames 60
shoot physics_polygons --frames 75 --input-script "$root/apps/physics_polygons/tests/gallery.script"
shoot physics_materials --frames 150
shoot platformer --frames 120 --input-script "$root/apps/platformer/tests/win.script"
