#!/usr/bin/env bash
# Drags the blue source with a real mouse (xdotool against the visible window under Xvfb):
# press on the source at pixel (732, 270), move to (300, 500), release. Then checks the last
# frame: the source where the mouse left it, nothing where it was.
#   drag.sh <e2d_audio_spatial> <e2d_image_check> <screenshot.png>   (run through with-display.sh)
set -euo pipefail
app="$1"; checker="$2"; shot="$3"
rm -f "$shot"
log="${shot%.png}.log"
# The frame budget is the app's lifetime: 2 000 frames are about 12 s at llvmpipe's 6 ms per
# frame on a quiet machine, several times what the drag needs even when the machine is loaded.
"$app" --frames 2000 --show --screenshot "$shot" >"$log" 2>&1 &
pid=$!
focus="$(dirname "$0")/../../tools/focus_window.sh"

# One press-move-release; fails (without leaving the button down) if the window went away.
drag() {
  local wid="$1"
  xdotool mousemove --window "$wid" 732 270 || return 1
  sleep 0.2
  xdotool mousedown 1
  local step
  for step in 1 2 3 4 5 6 7 8; do
    if ! xdotool mousemove --window "$wid" $((732 - step * 54)) $((270 + step * 29)); then
      xdotool mouseup 1
      return 1
    fi
    sleep 0.05
  done
  xdotool mouseup 1
  sleep 0.2
  # Moving the mouse without a button must not move the source any more.
  xdotool mousemove --window "$wid" 900 600
}

done_drag=0
for attempt in 1 2 3; do
  if ! kill -0 "$pid" 2>/dev/null; then
    break
  fi
  wid=$("$focus" "e2d audio spatial") || break
  # Let it settle (focus_window.sh focused it: no window manager here).
  sleep 0.5
  if drag "$wid"; then
    done_drag=1
    break
  fi
  echo "drag.sh: attempt $attempt: window $wid went away during the drag; searching again" >&2
done
status=0
wait "$pid" || status=$?
if [ "$done_drag" != 1 ] || [ "$status" != 0 ]; then
  echo "drag.sh: drag done: $done_drag, app exit status: $status; the app's log:" >&2
  cat "$log" >&2
  exit 1
fi
# Source at (300, 502) now (world (-212, -142)); its old place and the idle mouse's are empty.
"$checker" "$shot" colour:290,492,20,20:51,115,255:40:90 empty:722,260,20,20 empty:890,590,20,20
