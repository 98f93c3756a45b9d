#!/usr/bin/env bash
# Drags the blue source with a real mouse (xdotool against the visible window under Xvfb):
# press on the source at pixel (732, 270), move to (300, 500), release. Then checks the last
# frame: the source where the mouse left it, nothing where it was.
#   drag.sh <e2d_audio1> <e2d_image_check> <screenshot.png>   (run through with-display.sh)
set -euo pipefail
app="$1"; checker="$2"; shot="$3"
rm -f "$shot"
# Enough frames (about 15 ms each under llvmpipe) for the drag to happen while it runs.
"$app" --frames 900 --show --screenshot "$shot" >/dev/null 2>&1 &
pid=$!
wid=$("$(dirname "$0")/../../tools/focus_window.sh" "e2d audio 1")
# Let it settle (focus_window.sh focused it: no window manager here).
sleep 0.5
xdotool mousemove --window "$wid" 732 270
sleep 0.2
xdotool mousedown 1
for step in 1 2 3 4 5 6 7 8; do
  xdotool mousemove --window "$wid" $((732 - step * 54)) $((270 + step * 29))
  sleep 0.05
done
xdotool mouseup 1
sleep 0.2
# Moving the mouse without a button must not move the source any more.
xdotool mousemove --window "$wid" 900 600
wait "$pid"
# Source at (300, 502) now (world (-212, -142)); its old place and the idle mouse's are empty.
"$checker" "$shot" colour:290,492,20,20:51,115,255:40:90 empty:722,260,20,20 empty:890,590,20,20
