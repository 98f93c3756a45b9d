#!/usr/bin/env bash
# Prints the id of the visible window whose name is exactly NAME once it has the input focus,
# for app tests that drive an app with xdotool (there is no window manager under Xvfb).
#   focus_window.sh NAME [SECONDS]   (default 20 s)
# Only mapped windows count (--onlyvisible), and a window that goes away between the search
# and the focus (a BadWindow error) is searched for again, so a short-lived helper window of
# the same name is never the one returned.
set -uo pipefail
name="$1"
deadline=$((SECONDS + ${2:-20}))
while [ "$SECONDS" -lt "$deadline" ]; do
  wid=$(timeout 5 xdotool search --sync --onlyvisible --name "^${name}\$" 2>/dev/null | tail -1)
  if [ -n "$wid" ] && xdotool windowfocus --sync "$wid" 2>/dev/null; then
    echo "$wid"
    exit 0
  fi
  sleep 0.1
done
echo "focus_window.sh: no visible window named '$name' took the focus" >&2
exit 1
