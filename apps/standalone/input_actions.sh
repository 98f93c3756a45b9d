#!/usr/bin/env bash
# Test of input_actions: real key presses (xdotool on the focused window under Xvfb):
# space twice, right arrow held then released, Escape. The example must print both jumps,
# the moves and quit on Escape (not by its own time limit).
#   input_actions.sh <e2d_input_actions>   (run through with-display.sh)
set -euo pipefail
app="$1"
log=$(mktemp)
trap 'rm -f "$log"' EXIT
"$app" 30 >"$log" 2>&1 &
pid=$!
"$(dirname "$0")/../tools/focus_window.sh" "e2d input actions" >/dev/null
sleep 0.3
xdotool key space
sleep 0.2
xdotool key space
sleep 0.2
xdotool keydown Right
sleep 0.2
xdotool keyup Right
sleep 0.2
start=$SECONDS
xdotool key Escape
wait "$pid"
elapsed=$((SECONDS - start))
cat "$log"
expected=$'jump 1\njump 2\nmoving right\nmoving nowhere\n2 jumps'
if [ "$(cat "$log")" != "$expected" ] || [ "$elapsed" -gt 10 ]; then
  echo "input_actions.sh: expected (and an exit on Escape, not after 30 s):" >&2
  echo "$expected" >&2
  exit 1
fi
