#!/usr/bin/env bash
# Creates a body with a real mouse and keyboard (xdotool against the visible window under
# Xvfb): M picks the heavy mass, a left click at pixel (900, 200) (world (9.7, 12) m) creates a
# polygon there, which falls onto the empty ground on the right. Then checks the last frame:
# the heavy (dark blue) polygon rests on the ground below the click.
#   click.sh <e2d_physics_polygons> <e2d_image_check> <screenshot.png>   (run through with-display.sh)
set -euo pipefail
app="$1"; checker="$2"; shot="$3"
rm -f "$shot"
# Enough frames (a few ms each) for the click to happen early and the fall (1.6 s) to end.
"$app" --frames 1800 --show --screenshot "$shot" >/dev/null 2>&1 &
pid=$!
wid=$("$(dirname "$0")/../../tools/focus_window.sh" "e2d physics polygons")
# Let it settle (focus_window.sh focused it: no window manager here).
sleep 1
xdotool key m
sleep 0.2
xdotool mousemove --window "$wid" 900 200
sleep 0.1
xdotool click 1
wait "$pid"
# A 5-sided polygon of circumradius 0.6 m resting on the ground (pixel row 680) at x 9.7 m.
"$checker" "$shot" colour:885,645,30,30:38,64,179:30:40 empty:860,150,80,100
